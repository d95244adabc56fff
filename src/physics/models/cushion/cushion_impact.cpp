#include "physics/models/cushion/cushion_impact.hpp"

#include <algorithm>
#include <cmath>

#include "physics/models/cushion/nose_contact.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
CushionImpact<S>::CushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p)
  : mass_(p.ball_mass),
    radius_(p.ball_radius),
    inertia_(S(0.4) * p.ball_mass * p.ball_radius * p.ball_radius),
    normal_(normal)
{
  const S R = p.ball_radius;
  const NoseContact<S> nose(normal, p);
  const Vec3<S> along = normal.cross(Vec3<S>::UnitZ());  // along the cushion
  nose_ = nose.offset;
  cloth_ = -R * Vec3<S>::UnitZ();
  contact_normal_ = nose.normal;
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
  speed_scale_ = v0_.norm() + R * w0_.norm();
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
                                                           const Vec2& slip_from, const Vec2& slip_without,
                                                           const Vec2& sliding, S limit, bool& sticks)
{
  // It sticks if friction within its limit can stop the slip by the step's end and then hold
  // it against what drives it; a slip friction stops but cannot hold turns (reversalFraction
  // ends the step there) and slides the other way.
  const Vec2 stopping = stop_per_slip * slip_without;
  const Vec2 holding = stop_per_slip * (slip_without - slip_from);
  sticks = stopping.squaredNorm() <= limit * limit && holding.squaredNorm() <= limit * limit;
  if (sticks)
    return stopping;
  // A slip that starts from (nearly) nothing heads where it would go without friction; any
  // direction it has now is rounding.
  const Vec2& heading = sliding.norm() > S(kUnsettledSlip) * slip_without.norm() ? sliding : slip_without;
  const S speed = heading.norm();
  if (!(speed > zeroSpeed<S>()))
    return Vec2::Zero();
  return -(limit / speed) * heading;
}

template <typename S>
typename CushionImpact<S>::Impulses CushionImpact<S>::pushed(const Impulses& from, S dp, const Slips& sliding) const
{
  // The two frictions change each other's slips: each is found with the other's from the last
  // sweep (Gauss-Seidel) until they settle; when both slide neither depends on the other, and
  // one sweep is all.
  Impulses add = Impulses::Zero();
  add(0) = dp;
  const Slips start = slipsAt(from), without_friction = slipsAt(from + add);
  const S nose_down = -dp * contact_normal_.z();
  bool nose_sticks = false, cloth_sticks = false;
  for (int sweep = 0; sweep < kMaxFrictionSweeps; ++sweep)
  {
    const Impulses before = add;
    const Slips nose_without = without_friction + slip_per_impulse_.template rightCols<2>() * add.template tail<2>();
    add.template segment<2>(1) = friction(nose_stop_, start.template head<2>(), nose_without.template head<2>(),
                                          sliding.template head<2>(), mu_nose_ * dp, nose_sticks);
    // The cloth pushes up with what the nose pushes down, its friction's part included.
    const S cloth_normal = std::max(S(0), nose_down - (nose_plane_ * add.template segment<2>(1)).z());
    const Slips cloth_without =
        without_friction + slip_per_impulse_.template middleCols<2>(1) * add.template segment<2>(1);
    add.template tail<2>() = friction(cloth_stop_, start.template tail<2>(), cloth_without.template tail<2>(),
                                      sliding.template tail<2>(), mu_cloth_ * cloth_normal, cloth_sticks);
    if (!nose_sticks && !cloth_sticks)
      break;
    if ((add - before).norm() <= S(kSweepSettled) * add.norm())
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
bool CushionImpact<S>::frictionWorksAgainstTheSlips(const Impulses& from, const Impulses& to) const
{
  // Along the straight way from one impulse state to the other every slip changes linearly, so
  // a friction impulse's work is its dot product with the mean of the slip it met.
  // A sticking contact's slips are rounding, and so is the sign of its work: work below
  // kWorkRounding of the friction times the impact's speed counts as none.
  const Impulses change = to - from;
  const Slips mean = (slipsAt(from) + slipsAt(to)) / S(2);
  const Vec2 at_nose = change.template segment<2>(1), at_cloth = change.template tail<2>();
  const S rounding = S(kWorkRounding) * speed_scale_;
  return at_nose.dot(mean.template head<2>()) <= rounding * at_nose.norm() &&
         at_cloth.dot(mean.template tail<2>()) <= rounding * at_cloth.norm();
}

template <typename S>
S CushionImpact<S>::reversalFraction(const Impulses& from, const Impulses& to) const
{
  // A slip that passes through zero and goes on the other way turns its friction round there:
  // the step ends where the slip along its first direction has fallen to zero (it falls nearly
  // linearly over a step), and the next step slides the new way.
  const Slips start = slipsAt(from), end = slipsAt(to);
  S fraction = 1;
  for (int contact = 0; contact < 2; ++contact)
  {
    const Vec2 s0 = start.template segment<2>(2 * contact), s1 = end.template segment<2>(2 * contact);
    const S along0 = s0.squaredNorm(), along1 = s1.dot(s0);
    if (along1 < S(0) && along0 > S(kWorkRounding) * speed_scale_ * speed_scale_)
      fraction = std::min(fraction, std::max(along0 / (along0 - along1), S(kShortestReversalStep)));
  }
  return fraction;
}

template <typename S>
typename CushionImpact<S>::Impulses CushionImpact<S>::controlledStep(const Impulses& from, S& dp, S tolerance,
                                                                     S& error) const
{
  // One step against two half steps: their difference is the step's error (step doubling). A
  // step is halved until that is within the tolerance and neither friction works with its
  // slip; the two half steps are taken. The shortest step is taken as it is, or without
  // friction if that would work with a slip.
  for (int halving = 0;; ++halving, dp /= S(2))
  {
    Impulses full = step(from, dp);
    const S reversal = reversalFraction(from, full);
    if (reversal < S(1))
    {
      dp *= reversal;
      full = step(from, dp);
    }
    const Impulses halves = step(step(from, dp / S(2)), dp / S(2));
    const Impulses difference = halves - full;
    error = ((velocity_per_impulse_ * difference).norm() + radius_ * (spin_per_impulse_ * difference).norm()) /
            speed_scale_;
    const bool dissipative = frictionWorksAgainstTheSlips(from, halves);
    if (dissipative && (error <= tolerance || halving >= kMaxHalvings))
      return halves;
    if (halving >= kMaxHalvings)
    {
      Impulses next = from;
      next(0) += dp;
      error = 0;
      return next;
    }
  }
}

template <typename S>
void CushionImpact<S>::integrate(S e_work, S mu_nose, S mu_cloth, S tolerance)
{
  mu_nose_ = mu_nose;
  mu_cloth_ = mu_cloth;
  const S approach0 = approach();
  if (!(approach0 > S(0)))
    return;
  const S cos_a = contact_normal_.template head<2>().norm();
  const S total = (S(1) + e_work) * mass_ * approach0 / (cos_a * cos_a);  // without friction
  S next_step = total / S(kFirstSteps);

  // W, the work the normal force has taken: approach * dP summed. Each step goes straight from
  // one impulse state to the next, along which the closing speed changes linearly, so the
  // trapezoid is exact and the kinetic energy the ball ends with is exactly what W and the
  // frictions' (never positive) work make it. Compression ends at W's peak W_c, where the
  // closing speed is 0; restitution where W has fallen to (1 - e^2) W_c. A ball whose closing
  // speed stops falling is jammed: friction at the nose presses it on about as fast as the
  // normal impulse pushes it back (rigid bodies with Coulomb friction have no answer there).
  S work = 0, peak = -1, target = 0;
  int jammed_steps = 0;
  for (int n = 0; n < kMaxSteps; ++n)
  {
    S dp = next_step, error = 0;
    const Impulses next = controlledStep(impulses_, dp, tolerance, error);
    // A step well within the tolerance lets the next be twice as long, up to a quarter of the
    // frictionless impulse.
    next_step = std::min(total / S(4), error < tolerance / S(4) ? S(2) * dp : dp);
    const S a0 = approach(), a1 = approachAt(next);
    S from_fraction = 0;
    if (peak < S(0))
    {
      if (a1 > S(0))
      {
        jammed_steps = closingStalls(a0, a1, dp) ? jammed_steps + 1 : 0;
        if (jammed_steps >= kJammedSteps || next(0) > S(kJammedImpulse) * total)
          break;
        work += dp * (a0 + a1) / S(2);
        impulses_ = next;
        continue;
      }
      from_fraction = a0 / (a0 - a1);  // the closing speed is 0 here
      jammed_steps = 0;
      peak = work + from_fraction * dp * a0 / S(2);
      target = (S(1) - e_work * e_work) * peak;
    }
    const S after = work + dp * (a0 + a1) / S(2);
    if (after > target)
    {
      // Both contacts held by friction can keep the ball from moving off too: jammed again.
      jammed_steps = closingStalls(a0, a1, dp) ? jammed_steps + 1 : 0;
      if (jammed_steps >= kJammedSteps)
        break;
      work = after;
      impulses_ = next;
      continue;
    }
    // Where on this step W falls to the target: dp (a0 f + (a1 - a0) f^2 / 2) = target - W,
    // the root past the peak.
    const S quadratic = dp * (a1 - a0) / S(2), linear = dp * a0, constant = work - target;
    S fraction =
        quadratic < S(0)
            ? (-linear - std::sqrt(std::max(S(0), linear * linear - S(4) * quadratic * constant))) / (S(2) * quadratic)
            : (linear < S(0) ? -constant / linear : S(1));
    fraction = std::clamp(fraction, from_fraction, S(1));
    impulses_ += fraction * (next - impulses_);
    return;
  }
  leaveWithRestitution(e_work);
}

template <typename S>
bool CushionImpact<S>::closingStalls(S before, S after, S dp) const
{
  // The closing speed falls by cos^2(alpha) / m per unit normal impulse without friction.
  const S frictionless_rate = contact_normal_.template head<2>().squaredNorm() / mass_;
  return (after - before) / dp > -S(kJammedRate) * frictionless_rate;
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
