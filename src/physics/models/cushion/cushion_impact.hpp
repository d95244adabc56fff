// A ball-cushion impact followed through the normal impulse at the nose (Mathavan, Jackson and
// Parkin 2010). Private to the cushion models.
//
// Rigid bodies make every velocity during the impact linear in the impulses so far: the normal
// impulse P at the nose, the friction there (2 components in the tangent plane at the nose) and
// the friction at the cloth (2 horizontal components); the cloth's normal push takes whatever
// vertical impulse the nose gives, so the ball stays level. Those five numbers are the state;
// the slips at the two contacts and the closing speed are fixed linear maps of them, set up
// once per impact.
#pragma once

#include <Eigen/Dense>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
class CushionImpact
{
public:
  /// `normal`: the cushion's unit xy normal into play. The nose touches the ball
  /// alpha = asin(cushion_height/R - 1) above its equator.
  CushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p);

  /// The closing speed of the ball on the nose, along the contact normal (> 0 while closing).
  S approach() const { return approachAt(impulses_); }

  /// Compression until the ball stops closing on the nose, then restitution until the normal
  /// force has given back e_work^2 of the compression's work. The normal impulse grows in midpoint
  /// steps whose error, one step against two half steps, stays within `tolerance` of the
  /// impact's speed scale (|v| + R |w|); a step also ends where a slip turns, and is halved
  /// where a friction would work with its slip. A contact whose slip friction can stop and hold
  /// sticks (Coulomb); one that keeps slipping slides against its slip half way through the
  /// step. The ball is jammed when its closing speed stops changing for kJammedSteps steps
  /// (friction pressing it on as fast as the normal impulse pushes it back, mu_nose beyond
  /// about cot(alpha); or both contacts held so that it cannot move off), or when compression
  /// has taken kJammedImpulse times the frictionless impulse. Jammed, or after kMaxSteps, it
  /// leaves with its remaining normal velocity reversed and scaled by e_work.
  void integrate(S e_work, S mu_nose, S mu_cloth, S tolerance);

  Vec3<S> velocity() const;
  Vec3<S> spin() const;

private:
  /// A compression that has taken this many times the frictionless impulse is jammed: friction
  /// at the nose can slow the normal push by (cos(alpha) - mu sin(alpha)) / cos(alpha), which is
  /// above 1/16 unless mu_nose is within 6 % of cot(alpha).
  static constexpr double kJammedImpulse = 16;
  /// Steps in a row whose closing speed falls slower than kJammedRate of the frictionless rate
  /// (cos^2(alpha) / m per unit impulse) that mark a jam sooner.
  static constexpr int kJammedSteps = 4;
  static constexpr double kJammedRate = 1e-3;
  /// Halvings of a step before it is taken whatever its error (frictionless if a friction would
  /// work with its slip): 2^-12 of a step.
  static constexpr int kMaxHalvings = 12;
  /// Gauss-Seidel sweeps over the two frictions of a step at most, and the relative change at
  /// which they have settled (a sticking contact's impulse is linear in the other's: the
  /// sweeps contract, a few tens reach rounding).
  static constexpr int kMaxFrictionSweeps = 64;
  static constexpr double kSweepSettled = 1e-15;
  /// The first step: this share of the frictionless impulse.
  static constexpr int kFirstSteps = 16;
  /// Steps an impact may take.
  static constexpr int kMaxSteps = 16384;
  /// A friction's work within rounding of none, per unit impulse and unit of the impact's speed
  /// scale (|v| + R |w| before it): a sticking contact's slip is rounding of that scale.
  static constexpr double kWorkRounding = 1e-12;
  /// The shortest step to a slip's turning, as a fraction of the step: a slip that turns at the
  /// step's very start turns within rounding of it.
  static constexpr double kShortestReversalStep = 1e-3;
  /// A sliding direction from a slip below this share of the slip the step would end with
  /// without friction is taken from the latter: the slip has only begun.
  static constexpr double kUnsettledSlip = 1e-2;

  using Impulses = Eigen::Matrix<S, 5, 1>;  ///< P, nose friction (2), cloth friction (2)
  using Slips = Eigen::Matrix<S, 4, 1>;     ///< at the nose (2), at the cloth (2)
  using Vec2 = Eigen::Matrix<S, 2, 1>;

  Slips slipsAt(const Impulses& y) const { return slip0_ + slip_per_impulse_ * y; }
  S approachAt(const Impulses& y) const { return approach0_ + approach_per_impulse_.dot(y); }
  /// The impulses one step of normal impulse dp adds, the frictions sliding against `sliding`.
  Impulses pushed(const Impulses& from, S dp, const Slips& sliding) const;
  /// One midpoint step.
  Impulses step(const Impulses& from, S dp) const;
  /// Whether neither friction does positive work on the straight way from `from` to `to`.
  bool frictionWorksAgainstTheSlips(const Impulses& from, const Impulses& to) const;
  /// The fraction of the step from `from` to `to` at which a contact's slip, passing through
  /// zero, turns; 1 if none does.
  S reversalFraction(const Impulses& from, const Impulses& to) const;
  /// One step of at most dp within the tolerance (see integrate); dp is set to the step taken
  /// and `error` to its estimated error.
  Impulses controlledStep(const Impulses& from, S& dp, S tolerance, S& error) const;
  /// Coulomb friction at one contact over a step that starts with `slip_from` and would end with
  /// `slip_without` with no friction there: the impulse that stops the slip if friction within
  /// `limit` can stop it and then hold it, else `limit` against `sliding`. Sets `sticks`.
  static Vec2 friction(const Eigen::Matrix<S, 2, 2>& stop_per_slip, const Vec2& slip_from, const Vec2& slip_without,
                       const Vec2& sliding, S limit, bool& sticks);
  /// Whether the closing speed, from `before` to `after` over normal impulse dp, fell slower than
  /// kJammedRate of its frictionless rate.
  bool closingStalls(S before, S after, S dp) const;
  void leaveWithRestitution(S e_work);

  S mass_, radius_, inertia_;
  Vec3<S> normal_, nose_, cloth_, contact_normal_;
  Eigen::Matrix<S, 3, 2> nose_plane_, cloth_plane_;  ///< orthonormal tangent bases
  Vec3<S> v0_, w0_;
  Eigen::Matrix<S, 3, 5> velocity_per_impulse_, spin_per_impulse_;
  Slips slip0_;
  Eigen::Matrix<S, 4, 5> slip_per_impulse_;
  S approach0_ = 0;
  S speed_scale_ = 0;
  Impulses approach_per_impulse_;
  Eigen::Matrix<S, 2, 2> nose_stop_, cloth_stop_;  ///< friction impulse per unit slip that stops it
  S mu_nose_ = 0, mu_cloth_ = 0;
  Impulses impulses_ = Impulses::Zero();
  Vec3<S> correction_ = Vec3<S>::Zero();  ///< the fallback's velocity change
};

}  // namespace physics
}  // namespace cue_sim
