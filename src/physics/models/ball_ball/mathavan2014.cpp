// Mathavan, Jackson and Parkin 2014, "Numerical simulations of the frictional collisions of solid
// balls on a rough surface", Sports Engineering 17, 227-237.
//
// Two balls on the cloth meet; the impact is followed in the normal impulse P between them,
// through compression and restitution until the normal force has given back e_ball^2 of its
// work (the paper's work-done restitution). Coulomb friction mu_b acts against the slip between
// the balls, and mu_slide against each ball's slip on the cloth, loaded by what the balls'
// friction presses into it. Both balls stay level, as in the paper. Without cloth friction the
// closing speed depends on P alone, the work-done restitution is Newton's, and a slip that keeps
// its direction gives the frictional model's impulse; without friction between the balls it is
// the frictionless model. mu_b is the frictional model's mu_b(v) at the slip the balls meet
// with (constant over the impact, as the paper's).
#include <cmath>

#include "physics/models/ball_ball/ball_pair_impact.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class MathavanBallBall : public BallBallModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>& p) const override { return p.mu_ball_a + p.mu_ball_b; }
  bool needsCloth() const override { return true; }
  void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const override
  {
    Vec3<S> n = b.r - a.r;
    n.z() = S(0);
    n.normalize();
    if (!((a.v - b.v).dot(n) > S(0)))
      return;
    Vec3<S> slip = a.v - b.v + p.ball_radius * (a.w + b.w).cross(n);
    slip -= slip.dot(n) * n;
    const S mu = p.mu_ball_a + p.mu_ball_b * std::exp(-p.mu_ball_c * slip.norm());
    BallPairImpact<S> impact(ballPairImpact(a, b, n, p, mu, p.mu_slide));
    impact.integrate(p.e_ball, p.ball_impact_tolerance);
    const auto v = impact.velocities(), w = impact.spins();
    a.v = v.template head<3>();
    b.v = v.template tail<3>();
    a.w = w.template head<3>();
    b.w = w.template tail<3>();
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(ball_ball, mathavan2014, MathavanBallBall)

}  // namespace physics
}  // namespace cue_sim
