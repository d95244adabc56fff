#include "physics/models/frictional_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cue_sim
{
namespace physics
{
template <typename S, int Contacts, int Bodies>
FrictionalImpact<S, Contacts, Bodies>::FrictionalImpact(const Setup& setup)
  : velocity0_(setup.velocity0),
    spin0_(setup.spin0),
    velocity_per_impulse_(setup.velocity_per_impulse),
    spin_per_impulse_(setup.spin_per_impulse),
    slip0_(setup.slip0),
    slip_per_impulse_(setup.slip_per_impulse),
    approach0_(setup.approach0),
    approach_per_impulse_(setup.approach_per_impulse),
    load_(setup.load),
    mu_(setup.mu),
    radius_(setup.radius),
    speed_scale_(setup.velocity0.norm() + setup.radius * setup.spin0.norm())
{
  for (int c = 0; c < Contacts; ++c)
    stop_[c] = -slip_per_impulse_.template block<2, 2>(2 * c, 1 + 2 * c).inverse();
}

template <typename S, int Contacts, int Bodies>
typename FrictionalImpact<S, Contacts, Bodies>::Vec2 FrictionalImpact<S, Contacts, Bodies>::friction(
    const Eigen::Matrix<S, 2, 2>& stop_per_slip, const Vec2& slip_from, const Vec2& slip_without, const Vec2& sliding,
    S limit, bool& sticks) const
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
  // direction it has now is rounding. A slip without a direction is one within rounding of
  // zeroSpeed, or of the impact's own speed scale when that is itself near rounding (a ball
  // pressed on a cushion at 1e-12 m/s): a fixed floor there would stop friction half way
  // through every step and the step would be halved to nothing.
  const Vec2& heading = sliding.norm() > S(kUnsettledSlip) * slip_without.norm() ? sliding : slip_without;
  const S speed = heading.norm();
  if (!(speed > slipFloor()))
    return Vec2::Zero();
  return -(limit / speed) * heading;
}

template <typename S, int Contacts, int Bodies>
typename FrictionalImpact<S, Contacts, Bodies>::Vec2 FrictionalImpact<S, Contacts, Bodies>::frictionAt(
    int c, const Slips& start, const Impulses& add, const Slips& sliding, bool& sticks) const
{
  // The slip at c by the step's end with everything but c's own friction.
  const auto rows = slip_per_impulse_.template middleRows<2>(2 * c);
  const Vec2 own = add.template segment<2>(1 + 2 * c);
  const Vec2 without = start.template segment<2>(2 * c) + rows * add - rows.template middleCols<2>(1 + 2 * c) * own;
  const S limit = mu_[c] * std::max(S(0), load_.row(c).dot(add));
  return friction(stop_[c], start.template segment<2>(2 * c), without, sliding.template segment<2>(2 * c), limit,
                  sticks);
}

template <typename S, int Contacts, int Bodies>
typename FrictionalImpact<S, Contacts, Bodies>::Impulses FrictionalImpact<S, Contacts, Bodies>::pushed(
    const Impulses& from, S dp, const Slips& sliding) const
{
  // The frictions change each other's slips and loads: each is found with the others' from the
  // last sweep (Gauss-Seidel) until they settle. A sliding friction depends only on its load,
  // which comes from the contacts before it, so when all slide one sweep is all.
  Impulses add = Impulses::Zero();
  add(0) = dp;
  const Slips start = slipsAt(from);
  for (int sweep = 0; sweep < kMaxFrictionSweeps; ++sweep)
  {
    const Impulses before = add;
    bool any_sticks = false;
    for (int c = 0; c < Contacts; ++c)
    {
      bool sticks = false;
      add.template segment<2>(1 + 2 * c) = frictionAt(c, start, add, sliding, sticks);
      any_sticks = any_sticks || sticks;
    }
    if (!any_sticks || (add - before).norm() <= S(kSweepSettled) * add.norm())
      return add;
  }
  // The sweeps did not settle: the frictions are coupled too strongly for them to contract
  // (a sticking contact whose friction loads a sliding one that feeds back into it). Which
  // contacts stick, slide or are unloaded is then found by trying each, as below.
  Impulses exact;
  return solvedContactByContact(start, dp, sliding, exact) ? exact : add;
}

template <typename S, int Contacts, int Bodies>
bool FrictionalImpact<S, Contacts, Bodies>::solvedContactByContact(const Slips& start, S dp, const Slips& sliding,
                                                                   Impulses& solved) const
{
  // Given what each contact does, its friction is linear in the step's impulses: a sticking
  // contact's slip ends at zero, a sliding one's friction is mu times its load against its
  // heading, an unloaded one has none. Each assignment is one linear system; the first whose
  // answer friction() gives back, contact by contact, is Coulomb's.
  constexpr int kFrictions = 2 * Contacts;
  int assignments = 1;
  for (int c = 0; c < Contacts; ++c)
    assignments *= 3;
  // The assignment that held at the last step is tried first: contacts change what they do a
  // few times in an impact.
  for (int tried = 0; tried < assignments; ++tried)
  {
    const int assignment = (assignment_hint_ + tried) % assignments;
    Eigen::Matrix<S, kFrictions, kFrictions> a = Eigen::Matrix<S, kFrictions, kFrictions>::Zero();
    Eigen::Matrix<S, kFrictions, 1> b = Eigen::Matrix<S, kFrictions, 1>::Zero();
    std::array<ContactDoes, Contacts> does{};
    for (int c = 0, code = assignment; c < Contacts; ++c, code /= 3)
    {
      does[c] = static_cast<ContactDoes>(code % 3);
      const auto rows = slip_per_impulse_.template middleRows<2>(2 * c);
      if (does[c] == ContactDoes::kStick)
      {
        a.template middleRows<2>(2 * c) = rows.template rightCols<kFrictions>();
        b.template segment<2>(2 * c) = -start.template segment<2>(2 * c) - dp * rows.col(0);
        continue;
      }
      a.template block<2, 2>(2 * c, 2 * c).setIdentity();
      const Vec2 heading = sliding.template segment<2>(2 * c);
      if (does[c] == ContactDoes::kUnloaded || !(heading.norm() > slipFloor()))
        continue;
      const Vec2 against = (mu_[c] / heading.norm()) * heading;
      a.template middleRows<2>(2 * c) += against * load_.row(c).template rightCols<kFrictions>();
      b.template segment<2>(2 * c) = -dp * load_(c, 0) * against;
    }
    const Eigen::FullPivLU<Eigen::Matrix<S, kFrictions, kFrictions>> lu(a);
    if (!lu.isInvertible())
      continue;
    solved(0) = dp;
    solved.template tail<kFrictions>() = lu.solve(b);
    if (isCoulomb(start, solved, sliding))
    {
      assignment_hint_ = assignment;
      return true;
    }
  }
  return false;
}

template <typename S, int Contacts, int Bodies>
bool FrictionalImpact<S, Contacts, Bodies>::isCoulomb(const Slips& start, const Impulses& add,
                                                      const Slips& sliding) const
{
  const S scale = add.norm();
  for (int c = 0; c < Contacts; ++c)
  {
    bool sticks = false;
    if ((frictionAt(c, start, add, sliding, sticks) - add.template segment<2>(1 + 2 * c)).norm() >
        S(kCoulombAgreement) * scale)
      return false;
  }
  return true;
}

template <typename S, int Contacts, int Bodies>
typename FrictionalImpact<S, Contacts, Bodies>::Impulses FrictionalImpact<S, Contacts, Bodies>::step(
    const Impulses& from, S dp) const
{
  const Impulses half = from + pushed(from, dp / S(2), slipsAt(from));
  return from + pushed(from, dp, slipsAt(half));
}

template <typename S, int Contacts, int Bodies>
bool FrictionalImpact<S, Contacts, Bodies>::frictionWorksAgainstTheSlips(const Impulses& from, const Impulses& to) const
{
  // Along the straight way from one impulse state to the other every slip changes linearly, so
  // a friction impulse's work is its dot product with the mean of the slip it met.
  // A sticking contact's slips are rounding, and so is the sign of its work: work below
  // kWorkRounding of the friction times the impact's speed counts as none.
  const Impulses change = to - from;
  const Slips mean = (slipsAt(from) + slipsAt(to)) / S(2);
  const S rounding = S(kWorkRounding) * speed_scale_;
  for (int c = 0; c < Contacts; ++c)
  {
    const Vec2 impulse = change.template segment<2>(1 + 2 * c);
    if (impulse.dot(mean.template segment<2>(2 * c)) > rounding * impulse.norm())
      return false;
  }
  return true;
}

template <typename S, int Contacts, int Bodies>
S FrictionalImpact<S, Contacts, Bodies>::reversalFraction(const Impulses& from, const Impulses& to) const
{
  // A slip that passes through zero and goes on the other way turns its friction round there:
  // the step ends where the slip along its first direction has fallen to zero (it falls nearly
  // linearly over a step), and the next step slides the new way.
  const Slips start = slipsAt(from), end = slipsAt(to);
  S fraction = 1;
  for (int c = 0; c < Contacts; ++c)
  {
    const Vec2 s0 = start.template segment<2>(2 * c), s1 = end.template segment<2>(2 * c);
    const S along0 = s0.squaredNorm(), along1 = s1.dot(s0);
    if (along1 < S(0) && along0 > S(kWorkRounding) * speed_scale_ * speed_scale_)
      fraction = std::min(fraction, std::max(along0 / (along0 - along1), S(kShortestReversalStep)));
  }
  return fraction;
}

template <typename S, int Contacts, int Bodies>
typename FrictionalImpact<S, Contacts, Bodies>::Impulses FrictionalImpact<S, Contacts, Bodies>::controlledStep(
    const Impulses& from, S& dp, S tolerance, S& error) const
{
  // One step against two half steps: their difference is the step's error (step doubling). A
  // step is halved until that is within the tolerance and no friction works with its slip; the
  // two half steps are taken. The shortest step is taken as it is, or without friction if that
  // would work with a slip.
  S last_error = std::numeric_limits<S>::infinity();
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
    // An error that falls no faster than the step as it is halved (first order, not the
    // method's second) comes from a switch inside the step that halving cannot remove: contacts
    // switching between sticking, sliding and unloaded in a sliding mode. Below
    // kSlidingModeStep of the frictionless impulse such a step is taken as it is.
    const bool switching = error > last_error / S(kSecondOrderFall) && dp <= S(kSlidingModeStep) * total_;
    if (dissipative && (error <= tolerance || halving >= kMaxHalvings || switching))
      return halves;
    // One whose friction would work with a slip however short it is made is taken without
    // friction after kMaxHalvings.
    if (halving >= kMaxHalvings)
    {
      Impulses next = from;
      next(0) += dp;
      error = 0;
      return next;
    }
    last_error = error;
  }
}

template <typename S, int Contacts, int Bodies>
void FrictionalImpact<S, Contacts, Bodies>::integrate(S e_work, S tolerance)
{
  const S approach0 = approach();
  if (!(approach0 > S(0)))
    return;
  const S total = (S(1) + e_work) * approach0 / frictionlessRate();  // without friction
  total_ = total;
  S next_step = total / S(kFirstSteps);

  // W, the work the normal force has taken: approach * dP summed. Each step goes straight from
  // one impulse state to the next, along which the closing speed changes linearly, so the
  // trapezoid is exact and the kinetic energy the bodies end with is exactly what W and the
  // frictions' (never positive) work make it. Compression ends at W's peak W_c, where the
  // closing speed is 0; restitution where W has fallen to (1 - e^2) W_c. An impact whose closing
  // speed stops falling is jammed: friction presses the bodies on about as fast as P pushes
  // them apart (rigid bodies with Coulomb friction have no answer there).
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
      // Contacts held by friction can keep the bodies from parting too: jammed again.
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

template <typename S, int Contacts, int Bodies>
bool FrictionalImpact<S, Contacts, Bodies>::closingStalls(S before, S after, S dp) const
{
  return (after - before) / dp > -S(kJammedRate) * frictionlessRate();
}

template <typename S, int Contacts, int Bodies>
void FrictionalImpact<S, Contacts, Bodies>::leaveWithRestitution(S e_work)
{
  // P alone, which turns no body (it points at the centres), reverses what is left of the
  // closing speed, scaled by e_work.
  const S closing = approach();
  if (closing > S(0))
    impulses_(0) += (S(1) + e_work) * closing / frictionlessRate();
}

template class FrictionalImpact<double, 2, 1>;
template class FrictionalImpact<long double, 2, 1>;
template class FrictionalImpact<double, 3, 2>;
template class FrictionalImpact<long double, 3, 2>;

}  // namespace physics
}  // namespace cue_sim
