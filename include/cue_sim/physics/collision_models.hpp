// Swappable models of what happens at a contact. The event loop only finds when a contact
// happens; what it does to the balls is one of these, chosen per scene by name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
/// Resolves a ball-ball impact. Both balls are at the contact time, touching, with the line of
/// centres from a to b. Changes v and w of both; the engine then settles their motion states.
template <typename S>
class BallBallModel
{
public:
  virtual ~BallBallModel() = default;
  virtual void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const = 0;
};

/// Resolves a ball-cushion impact. `normal` is the unit xy normal of the contact, pointing from
/// the cushion into play; the ball moves against it.
template <typename S>
class CushionModel
{
public:
  virtual ~CushionModel() = default;
  virtual void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const = 0;
};

/// Lander 1999, "Physics on the Back of a Cocktail Napkin", Eq. 1-5: an impulse along the line
/// of centres with restitution e_ball; tangential velocities and spins are unchanged.
template <typename S>
class FrictionlessBallBall : public BallBallModel<S>
{
public:
  void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const override;
};

/// The normal velocity is reversed and scaled by e_cushion; tangential velocity and spin are
/// kept (the article's restitution model applied to a fixed wall).
template <typename S>
class SimpleCushion : public CushionModel<S>
{
public:
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override;
};

/// Frictional inelastic impacts of equal spheres (Alciatore, TP ): the normal
/// impulse as in the frictionless model; at the contact point the surfaces slide past each
/// other and a friction impulse mu_b(v) times the normal impulse opposes that slip, capped by
/// the impulse that stops it. It changes both balls' velocities and spins: cut- and
/// spin-induced throw and spin transfer.
template <typename S>
class FrictionalBallBall : public BallBallModel<S>
{
public:
  void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const override;
};

/// Han 2005 ("Dynamics in carom and three cushion billiards", J. Mech. Sci. Technol. 19(4)):
/// one impulse where the cushion's nose, cushion_height above the cloth, touches the ball.
/// Normal impulse from e_cushion along the contact normal; friction f_cushion times it against
/// the contact point's slip, capped by the no-slip impulse. Spin changes the rebound.
template <typename S>
class HanCushion : public CushionModel<S>
{
public:
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override;
};

/// Which model to use for each contact kind, by name (see ballBallModelNames() and
/// cushionModelNames()).
struct ModelChoice
{
  std::string ball_ball = "frictional";
  std::string cushion = "han2005";
};

/// The names accepted for each kind.
std::vector<std::string> ballBallModelNames();
std::vector<std::string> cushionModelNames();

/// Throws std::invalid_argument naming the unknown model and the known ones.
template <typename S>
std::unique_ptr<BallBallModel<S>> makeBallBallModel(const std::string& name);
template <typename S>
std::unique_ptr<CushionModel<S>> makeCushionModel(const std::string& name);

}  // namespace physics
}  // namespace cue_sim
