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
  /// force has given back e_work^2 of the compression's work. The normal impulse grows in
  /// `steps` equal parts of its frictionless total (1 + e) m approach / cos^2(alpha); each part
  /// is one midpoint step. A contact whose slip the step's friction can stop sticks (Coulomb);
  /// one that keeps slipping slides against its slip half way through the step. At most
  /// 8 steps + 8 per phase: a ball friction keeps pressing on (mu_nose beyond cot(alpha)) leaves
  /// with its remaining normal velocity reversed and scaled by e_work.
  void integrate(S e_work, S mu_nose, S mu_cloth, int steps);

  Vec3<S> velocity() const;
  Vec3<S> spin() const;
  /// The normal impulse at the nose so far [N s].
  S normalImpulse() const { return impulses_(0); }

private:
  using Impulses = Eigen::Matrix<S, 5, 1>;  ///< P, nose friction (2), cloth friction (2)
  using Slips = Eigen::Matrix<S, 4, 1>;     ///< at the nose (2), at the cloth (2)
  using Vec2 = Eigen::Matrix<S, 2, 1>;

  Slips slipsAt(const Impulses& y) const { return slip0_ + slip_per_impulse_ * y; }
  S approachAt(const Impulses& y) const { return approach0_ + approach_per_impulse_.dot(y); }
  /// The impulses one step of normal impulse dp adds, the frictions sliding against `sliding`.
  Impulses pushed(const Impulses& from, S dp, const Slips& sliding) const;
  /// One midpoint step.
  Impulses step(const Impulses& from, S dp) const;
  /// Coulomb friction at one contact: the impulse that stops `slip_without` (the slip the step
  /// ends with if this contact has none) if it is at most `limit`, else `limit` against
  /// `sliding`. Sets `sticks`.
  static Vec2 friction(const Eigen::Matrix<S, 2, 2>& stop_per_slip, const Vec2& slip_without, const Vec2& sliding,
                       S limit, bool& sticks);
  void leaveWithRestitution(S e_work);

  S mass_, inertia_;
  Vec3<S> normal_, nose_, cloth_, contact_normal_;
  Eigen::Matrix<S, 3, 2> nose_plane_, cloth_plane_;  ///< orthonormal tangent bases
  Vec3<S> v0_, w0_;
  Eigen::Matrix<S, 3, 5> velocity_per_impulse_, spin_per_impulse_;
  Slips slip0_;
  Eigen::Matrix<S, 4, 5> slip_per_impulse_;
  S approach0_ = 0;
  Impulses approach_per_impulse_;
  Eigen::Matrix<S, 2, 2> nose_stop_, cloth_stop_;  ///< friction impulse per unit slip that stops it
  S mu_nose_ = 0, mu_cloth_ = 0;
  Impulses impulses_ = Impulses::Zero();
  Vec3<S> correction_ = Vec3<S>::Zero();  ///< the fallback's velocity change
};

}  // namespace physics
}  // namespace cue_sim
