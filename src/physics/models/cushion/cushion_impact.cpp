#include "physics/models/cushion/cushion_impact.hpp"

#include <algorithm>
#include <cmath>

#include "physics/models/friction_impulse.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
CushionImpact<S>::CushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p)
  : mass_(p.ball_mass), radius_(p.ball_radius), inverse_mass_(S(1) / p.ball_mass),
    inverse_inertia_(S(1) / (S(0.4) * p.ball_mass * p.ball_radius * p.ball_radius))
{
  const S sin_a = std::clamp(p.cushion_height / radius_ - S(1), S(-1), S(1));
  const S cos_a = std::sqrt(S(1) - sin_a * sin_a);
  const Vec3<S> z = Vec3<S>::UnitZ();
  normal_ = normal;
  nose_ = -radius_ * cos_a * normal + radius_ * sin_a * z;
  cloth_ = -radius_ * z;
  contact_normal_ = cos_a * normal - sin_a * z;
  state_ = {ball.v, ball.w};
  state_.v.z() = S(0);
}

template <typename S>
Vec3<S> CushionImpact<S>::noseSlip(const State& s) const
{
  Vec3<S> slip = s.v + s.w.cross(nose_);
  return slip - slip.dot(contact_normal_) * contact_normal_;
}

template <typename S>
Vec3<S> CushionImpact<S>::clothSlip(const State& s) const
{
  Vec3<S> slip = s.v + s.w.cross(cloth_);
  slip.z() = S(0);
  return slip;
}

template <typename S>
Vec3<S> CushionImpact<S>::friction(const Vec3<S>& slip_without, const Vec3<S>& sliding_direction, S limit,
                                   bool& sticks) const
{
  // A tangential impulse f at a contact changes that contact's slip by 7 f / (2m) (1/m for the
  // centre, R^2/I for the spin), so -slip 2m/7 stops it.
  const Vec3<S> stopping = -slip_without * (mass_ / S(3.5));
  sticks = stopping.squaredNorm() <= limit * limit;
  if (sticks)
    return stopping;  // the contact sticks by the end of the step
  return frictionAlong(sliding_direction, limit);
}

template <typename S>
typename CushionImpact<S>::State CushionImpact<S>::pushed(const State& from, const State& sliding, S dp) const
{
  // The normal impulse dp at the nose; the cloth takes the nose's push down (the paper's P_C),
  // so the ball stays on it. A contact still slipping at the end of the step slides against
  // `sliding`'s slip there; one whose slip the friction allowed would stop sticks. The two
  // frictions change each other's slips, so they are found in turn a few times (Gauss-Seidel).
  const Vec3<S> nose_direction = noseSlip(sliding), cloth_direction = clothSlip(sliding);
  Vec3<S> at_nose = Vec3<S>::Zero(), at_cloth = Vec3<S>::Zero();
  State to = from;
  bool nose_sticks = false, cloth_sticks = false;
  for (int sweep = 0; sweep < kFrictionSweeps; ++sweep)
  {
    to = applied(from, dp, Vec3<S>::Zero(), at_cloth);
    at_nose = friction(noseSlip(to), nose_direction, mu_nose_ * dp, nose_sticks);
    const S cloth_normal = std::max(S(0), -(dp * contact_normal_ + at_nose).z());
    to = applied(from, dp, at_nose, Vec3<S>::Zero());
    at_cloth = friction(clothSlip(to), cloth_direction, mu_cloth_ * cloth_normal, cloth_sticks);
    if (!nose_sticks && !cloth_sticks)
      break;  // both slide: neither friction depends on the other's
  }
  return applied(from, dp, at_nose, at_cloth);
}

template <typename S>
typename CushionImpact<S>::State CushionImpact<S>::applied(const State& from, S dp, const Vec3<S>& at_nose,
                                                           const Vec3<S>& at_cloth) const
{
  // The vertical parts (the nose's push down, the cloth's push up) cancel: v stays level.
  State to = from;
  to.v += (dp * contact_normal_ + at_nose + at_cloth) * inverse_mass_;
  to.v.z() = S(0);
  to.w += (nose_.cross(at_nose) + cloth_.cross(at_cloth)) * inverse_inertia_;
  return to;
}

template <typename S>
typename CushionImpact<S>::State CushionImpact<S>::step(const State& from, S dp) const
{
  // Midpoint: the sliding directions of the whole step are those half way through it.
  return pushed(from, pushed(from, from, dp / S(2)), dp);
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
  int n = 0;
  for (; n < max_steps && before > S(0); ++n)
  {
    const State next = step(state_, dp);
    const S after = approachOf(next);
    if (after > S(0))
    {
      compression_work += dp * (before + after) / S(2);
      state_ = next;
      impulse_ += dp;
      before = after;
      continue;
    }
    // The closing speed falls (nearly) linearly in P over a step: end where it reaches 0.
    const S fraction = before / (before - after);
    state_ = step(state_, fraction * dp);
    impulse_ += fraction * dp;
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
  for (n = 0; n < max_steps && released < target; ++n)
  {
    const State next = step(state_, dp);
    const S a0 = approach(), a1 = approachOf(next);
    const S work = -dp * (a0 + a1) / S(2);
    if (released + work < target)
    {
      released += work;
      state_ = next;
      impulse_ += dp;
      continue;
    }
    // Over a fraction f of the step the work is -dp (a0 f + (a1 - a0) f^2 / 2).
    const S quadratic = -dp * (a1 - a0) / S(2), linear = -dp * a0, rest = target - released;
    S fraction = quadratic > S(0)
                   ? (-linear + std::sqrt(linear * linear + S(4) * quadratic * rest)) / (S(2) * quadratic)
                   : (linear > S(0) ? rest / linear : S(1));
    fraction = std::clamp(fraction, S(0), S(1));
    state_ = step(state_, fraction * dp);
    impulse_ += fraction * dp;
    released = target;
  }
}

template <typename S>
void CushionImpact<S>::leaveWithRestitution(S e_work)
{
  const S closing = -state_.v.dot(normal_);
  if (closing > S(0))
    state_.v += (S(1) + e_work) * closing * normal_;
}

template class CushionImpact<double>;
template class CushionImpact<long double>;

}  // namespace physics
}  // namespace cue_sim
