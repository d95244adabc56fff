// A ball at the slate coming down, after a flight, a collision or the cue (internal to the physics
// core): the ball-table model's impact, and the rule that ends a bounce sequence.
#pragma once

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
namespace physics
{
/// A ball that the slate would send back up slower than this [m/s] stays on the cloth instead:
/// its landing is perfectly inelastic (the normal impulse m U, friction at most mu_table m U),
/// and it slides on. That ends a bounce sequence, which would otherwise have infinitely many
/// impacts in a finite time. It is exact where it matters: with mu_table = mu_slide (the default)
/// the cloth's sliding friction over the rest of the sequence, 2 e U / (g (1 - e)) long, takes
/// 2 mu e U / (1 - e) of speed, and the remaining impacts would have taken mu (1 + e) e U / (1 - e):
/// the difference, mu e U, is the friction the inelastic impact takes beyond the elastic one's
/// mu (1 + e) U, so by the sequence's end the ball has the velocity and spin the exact sequence
/// gives it (bounceSeries, slate_bounce.hpp), the slip permitting; its centre is off by at most
/// 2 mu (e U)^2 / (g (1 - e)) meanwhile, 8e-8 m at mu = 0.2 and e = 0.5, and it skips hops lower
/// than (e U)^2 / 2g = 5e-8 m. A landing at 5 m/s bounces 12 times before this at e = 0.5.
constexpr double kSettleSpeed = 1e-3;

/// The ball at the slate (its centre put at R) with its v.z: if it comes down, the ball-table
/// model's impact with e_table, or the inelastic one that ends the bounces (kSettleSpeed); then its
/// motion settled (in the air if it rebounds).
template <typename S>
void landOnSlate(Ball<S>& ball, const BallTableModel<S>& model, const PhysicsParams<S>& p)
{
  const S R = p.ball_radius;
  ball.r.z() = R;
  const S incoming = -ball.v.z();
  if (incoming > S(0))
  {
    const S rebound = p.e_table * incoming;
    model.resolve(ball, rebound < S(kSettleSpeed) ? S(0) : p.e_table, p);
  }
  settleMotion(ball, R);
}

}  // namespace physics
}  // namespace cue_sim
