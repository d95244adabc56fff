// Swappable models of what happens at a contact. The event loop only finds when a contact
// happens; what it does to the balls is one of these, chosen per scene by name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
/// Resolves a ball-ball impact. Both balls are at the contact time, touching, with the line of
/// centres from a to b (in three dimensions when one is in the air). Changes v and w of both; the
/// engine then settles their motion states.
template <typename S>
class BallBallModel
{
public:
  using Scalar = S;
  virtual ~BallBallModel() = default;
  virtual void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const = 0;
  /// True for a model that needs both balls on the cloth (its friction under each): a pair with a
  /// ball in the air then meets by the default model instead (Engine::ballBallModelInAir).
  virtual bool needsCloth() const { return false; }
  /// The Coulomb friction between two balls in sustained contact (one resting on, rolling or sliding
  /// round the other: src/physics/supports/), where the slip is slow: the model's friction at zero
  /// slip speed.
  virtual S sustainedFriction(const PhysicsParams<S>& p) const = 0;
};

/// Resolves a ball-cushion impact. `normal` is the unit xy normal of the contact, pointing from
/// the cushion into play; the ball moves against it.
template <typename S>
class CushionModel
{
public:
  using Scalar = S;
  virtual ~CushionModel() = default;
  virtual void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const = 0;
  /// The Coulomb friction between a ball and the cushion in sustained contact (a ball resting on,
  /// rolling or sliding round a nose's edge or a post's rim, or pressed on a face:
  /// src/physics/supports/): the model's own friction coefficient at the cushion.
  virtual S sustainedFriction(const PhysicsParams<S>& p) const = 0;
};

/// Resolves one impact of a ball coming down onto the slate: the ball is at it (z = R) with
/// v.z < 0, and leaves with `restitution` times its normal speed (the engine passes e_table, or 0
/// for the impact that ends a bounce sequence: doc/physics.md). Changes v and w; the engine then
/// settles its motion state.
template <typename S>
class BallTableModel
{
public:
  using Scalar = S;
  virtual ~BallTableModel() = default;
  virtual void resolve(Ball<S>& ball, S restitution, const PhysicsParams<S>& p) const = 0;
};

/// What the cue does to the ball it strikes, on the cloth: its velocity and spin right after the
/// cue leaves it. A velocity into the slate (v.z < 0) is the slate's to answer: the engine lands
/// it through the ball-table model.
template <typename S>
class CueModel
{
public:
  using Scalar = S;
  virtual ~CueModel() = default;
  virtual void strike(Ball<S>& ball, const CueStrike<S>& strike, const PhysicsParams<S>& p) const = 0;
};

/// One contact model as include/cue_sim/physics/contact_models.def declares it.
struct ModelInfo
{
  const char* kind;          ///< "ball_ball", "cushion", "ball_table" or "cue"
  const char* name;          ///< the name physics.yaml, scene files and ~cushion_model take
  const char* summary;       ///< what it does, in a line
  const char* coefficients;  ///< the PhysicsParams it reads, space-separated
  const char* reference;     ///< where the model is published
};

/// Every contact model, in declaration order; the first of each kind is the default.
const std::vector<ModelInfo>& contactModels();

/// Which model to use for each contact kind, by name (see ballBallModelNames(),
/// cushionModelNames(), ballTableModelNames() and cueModelNames()). Default-constructed, or a
/// name left empty: the default of that kind.
struct ModelChoice
{
  ModelChoice();
  ModelChoice(std::string ball_ball_model, std::string cushion_model, std::string ball_table_model = "",
              std::string cue_model = "");
  std::string ball_ball;
  std::string cushion;
  std::string ball_table;
  std::string cue;
};

/// The names accepted for each kind, the default first.
std::vector<std::string> ballBallModelNames();
std::vector<std::string> cushionModelNames();
std::vector<std::string> ballTableModelNames();
std::vector<std::string> cueModelNames();

/// Throws std::invalid_argument naming the unknown model and the known ones.
template <typename S>
std::unique_ptr<BallBallModel<S>> makeBallBallModel(const std::string& name);
template <typename S>
std::unique_ptr<CushionModel<S>> makeCushionModel(const std::string& name);
template <typename S>
std::unique_ptr<BallTableModel<S>> makeBallTableModel(const std::string& name);
template <typename S>
std::unique_ptr<CueModel<S>> makeCueModel(const std::string& name);

}  // namespace physics
}  // namespace cue_sim
