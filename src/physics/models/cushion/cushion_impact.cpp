#include "physics/models/cushion/cushion_impact.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace physics
{
template <typename S>
CushionImpact<S>::CushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p)
  : mass_(p.ball_mass), inertia_(S(0.4) * p.ball_mass * p.ball_radius * p.ball_radius), normal_(normal)
{
  const S R = p.ball_radius;
  const S sin_a = std::clamp(p.cushion_height / R - S(1), S(-1), S(1));
  const S cos_a = std::sqrt(S(1) - sin_a * sin_a);
  const Vec3<S> z = Vec3<S>::UnitZ(), along = normal.cross(z);  // along the cushion
  nose_ = -R * cos_a * normal + R * sin_a * z;
  cloth_ = -R * z;
  contact_normal_ = cos_a * normal - sin_a * z;  // nose -> centre
  nose_plane_.col(0) = along;
  nose_plane_.col(1) = contact_normal_.cross(along);
  cloth_plane_.col(0) = along;
  cloth_plane_.col(1) = normal;
  v0_ = ball.v;
  v0_.z() = S(0);
  w0_ = ball.w;

  // What each unit impulse does to the centre's velocity (its vertical part taken by the cloth)
  // and to the spin (the normal impulse at the nose points at the centre: no torque).
  for (int k = 0; k < 5; ++k)
  {
    Vec3<S> at_nose = Vec3<S>::Zero(), at_cloth = Vec3<S>::Zero();
    if (k == 0)
      at_nose = contact_normal_;
    else if (k < 3)
      at_nose = nose_plane_.col(k - 1);
    else
      at_cloth = cloth_plane_.col(k - 3);
    Vec3<S> dv = (at_nose + at_cloth) / mass_;
    dv.z() = S(0);
    const Vec3<S> dw = (nose_.cross(at_nose) + cloth_.cross(at_cloth)) / inertia_;
    velocity_per_impulse_.col(k) = dv;
    spin_per_impulse_.col(k) = dw;
    slip_per_impulse_.col(k) << nose_plane_.transpose() * (dv + dw.cross(nose_)),
        cloth_plane_.transpose() * (dv + dw.cross(cloth_));
    approach_per_impulse_(k) = -dv.dot(contact_normal_);
  }
  slip0_ << nose_plane_.transpose() * (v0_ + w0_.cross(nose_)), cloth_plane_.transpose() * (v0_ + w0_.cross(cloth_));
  approach0_ = -v0_.dot(contact_normal_);
  nose_stop_ = -slip_per_impulse_.template block<2, 2>(0, 1).inverse();
  cloth_stop_ = -slip_per_impulse_.template block<2, 2>(2, 3).inverse();
}

template <typename S>
Vec3<S> CushionImpact<S>::velocity() const
{
  return v0_ + velocity_per_impulse_ * impulses_ + correction_;
}

template <typename S>
Vec3<S> CushionImpact<S>::spin() const
{
  return w0_ + spin_per_impulse_ * impulses_;
}

template <typename S>
typename CushionImpact<S>::Vec2 CushionImpact<S>::friction(const Eigen::Matrix<S, 2, 2>& stop_per_slip,
                                                           const Vec2& slip_without, const Vec2& sliding, S limit,
                                                           bool& sticks)
{
  const Vec2 stopping = stop_per_slip * slip_without;
  sticks = stopping.squaredNorm() <= limit * limit;
  if (sticks)
    return stopping;
  const S speed = sliding.norm();
  if (!(speed > zeroSpeed<S>()))
    return Vec2::Zero();
  return -(limit / speed) * sliding;
}

template <typename S>
typename CushionImpact<S>::Impulses CushionImpact<S>::pushed(const Impulses& from, S dp, const Slips& sliding) const
{
  // The two frictions change each other's slips: each is found with the other's from the last
  // sweep (Gauss-Seidel); when both slide neither depends on the other, and one sweep is all.
  Impulses add = Impulses::Zero();
  add(0) = dp;
  const Slips without_friction = slipsAt(from + add);
  const S nose_down = -dp * contact_normal_.z();
  bool nose_sticks = false, cloth_sticks = false;
  for (int sweep = 0; sweep < 4; ++sweep)
  {
    const Slips nose_without = without_friction + slip_per_impulse_.template rightCols<2>() * add.template tail<2>();
    add.template segment<2>(1) =
        friction(nose_stop_, nose_without.template head<2>(), sliding.template head<2>(), mu_nose_ * dp, nose_sticks);
    // The cloth pushes up with what the nose pushes down, its friction's part included.
    const S cloth_normal = std::max(S(0), nose_down - (nose_plane_ * add.template segment<2>(1)).z());
    const Slips cloth_without =
        without_friction + slip_per_impulse_.template middleCols<2>(1) * add.template segment<2>(1);
    add.template tail<2>() = friction(cloth_stop_, cloth_without.template tail<2>(), sliding.template tail<2>(),
                                      mu_cloth_ * cloth_normal, cloth_sticks);
    if (!nose_sticks && !cloth_sticks)
      break;
  }
  return add;
}

template <typename S>
typename CushionImpact<S>::Impulses CushionImpact<S>::step(const Impulses& from, S dp) const
{
  const Impulses half = from + pushed(from, dp / S(2), slipsAt(from));
  return from + pushed(from, dp, slipsAt(half));
}

template <typename S>
void CushionImpact<S>::integrate(S e_work, S mu_nose, S mu_cloth, int steps)
{
  mu_nose_ = mu_nose;
  mu_cloth_ = mu_cloth;
  const S approach0 = approach();
  if (!(approach0 > S(0)))
    return;
  const S cos_a = contact_normal_.template head<2>().norm();
  const S dp = (S(1) + e_work) * mass_ * approach0 / (cos_a * cos_a) / S(steps);
  const int max_steps = 8 * steps + 8;

  // Compression: the normal force takes work approach * dP until the ball stops closing.
  S compression_work = 0;
  S before = approach0;
  for (int n = 0; n < max_steps && before > S(0); ++n)
  {
    const Impulses next = step(impulses_, dp);
    const S after = approachAt(next);
    if (after > S(0))
    {
      compression_work += dp * (before + after) / S(2);
      impulses_ = next;
      before = after;
      continue;
    }
    // The closing speed falls (nearly) linearly in P over a step: end where it reaches 0.
    const S fraction = before / (before - after);
    impulses_ = step(impulses_, fraction * dp);
    compression_work += fraction * dp * before / S(2);
    before = approach();
  }
  if (before > S(0))
  {
    leaveWithRestitution(e_work);
    return;
  }

  // Restitution: the normal force gives back work -approach * dP until e^2 of it.
  const S target = e_work * e_work * compression_work;
  S released = 0;
  for (int n = 0; n < max_steps && released < target; ++n)
  {
    const Impulses next = step(impulses_, dp);
    const S a0 = approach(), a1 = approachAt(next);
    const S work = -dp * (a0 + a1) / S(2);
    if (released + work < target)
    {
      released += work;
      impulses_ = next;
      continue;
    }
    // Over a fraction f of the step the work is -dp (a0 f + (a1 - a0) f^2 / 2).
    const S quadratic = -dp * (a1 - a0) / S(2), linear = -dp * a0, rest = target - released;
    S fraction = quadratic > S(0)
                     ? (-linear + std::sqrt(linear * linear + S(4) * quadratic * rest)) / (S(2) * quadratic)
                     : (linear > S(0) ? rest / linear : S(1));
    fraction = std::clamp(fraction, S(0), S(1));
    impulses_ = step(impulses_, fraction * dp);
    released = target;
  }
}

template <typename S>
void CushionImpact<S>::leaveWithRestitution(S e_work)
{
  const S closing = -velocity().dot(normal_);
  if (closing > S(0))
    correction_ += (S(1) + e_work) * closing * normal_;
}

template class CushionImpact<double>;
template class CushionImpact<long double>;

}  // namespace physics
}  // namespace cue_sim
