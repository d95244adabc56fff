// When bodies on closed-form paths meet: the gap polynomials of a ball against a ball, a line or
// a circle, the moment a gap closes, and cheap bounds that spare solving pairs that cannot meet
// (internal to the event search).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "cue_sim/physics/polynomial.hpp"
#include "cue_sim/physics/types.hpp"
#include "physics/engine/table_geometry.hpp"

namespace cue_sim
{
namespace physics
{
/// Horizon for balls whose motion never ends (no friction): far beyond any shot, and fixed,
/// so that predictions never depend on how far a caller asks to advance.
template <typename S>
constexpr S kEndlessHorizon = S(1e7);

/// Time from the base at which a gap function (positive while apart) closes with the bodies
/// approaching, within (0, limit]; 0 if they touch and approach now; +inf if never.
/// `approach_slope` is the gap's rate of change that counts as approaching; `touch` is the gap
/// within which two bodies count as touching (the rounding of the gap's constant term).
///
/// Bodies that touch and separate slowly may be pushed back together by their accelerations
/// (two slow balls rolling in slightly different directions) before the computed gap ever
/// becomes positive. For them the contact is when the gap returns to its starting value: the
/// down-crossing of (gap(tau) - gap(0)) / tau, which has no cancellation.
///
/// With `pressing_is_contact`, touching bodies that do not separate while their accelerations
/// press them together are in contact now: ball pairs, which the engine then joins, and a ball
/// on a wall, which it holds there.
template <typename S>
S contactTime(const Poly4<S>& gap, S limit, S approach_slope, S touch, bool pressing_is_contact = false)
{
  if (gap[0] > touch)
    return firstDownCrossing(gap, S(0), limit);
  if (gap[1] < approach_slope || (pressing_is_contact && gap[1] <= S(0) && gap[2] < S(0)))
    return S(0);
  // Closing within rounding (or not at all): the gap goes as gap[2] + gap[3] tau + gap[4] tau^2
  // times tau^2. Pressing at once, they are in contact now; else they slide past each other, and the
  // gap returns to its start where that turns negative. (By the form below, a rounding's closing
  // left (gap(tau) - gap(0)) / tau negative from the start, with no down-crossing to find: two balls
  // rolling past each other went 2e-8 m into each other,
  // TouchingBallsRollingPastEachOtherMeetAtTheTouch.)
  if (pressing_is_contact && gap[1] <= S(0))
  {
    const bool closes_at_once =
        gap[2] < S(0) || (gap[2] == S(0) && (gap[3] < S(0) || (gap[3] == S(0) && gap[4] < S(0))));
    if (closes_at_once)
      return S(0);
    const Poly4<S> curvature = {gap[2], gap[3], gap[4], S(0), S(0)};
    return firstDownCrossing(curvature, S(0), limit);
  }
  const Poly4<S> relative = {gap[1], gap[2], gap[3], gap[4], S(0)};
  return firstDownCrossing(relative, S(0), limit);
}

/// Gap values within this of zero are rounding: 64 ulps of the gap's scale, the contact
/// distance for a gap in metres, its square for a squared distance.
template <typename S>
S touchTolerance(S scale)
{
  return S(64) * std::numeric_limits<S>::epsilon() * scale;
}

/// |d(tau)|^2 - reach^2 for the relative position d(tau) = c0 + c1 tau + c2 tau^2.
template <typename S>
Poly4<S> distanceGap(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S reach)
{
  return {c0.squaredNorm() - reach * reach, S(2) * c0.dot(c1), c1.squaredNorm() + S(2) * c0.dot(c2), S(2) * c1.dot(c2),
          c2.squaredNorm()};
}

/// |d(tau)|^2 + h(tau)^2 - reach^2 for a relative position with a height part too,
/// h(tau) = h0 + h1 tau + h2 tau^2 (a ball in the air).
template <typename S>
Poly4<S> distanceGap(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S h0, S h1, S h2, S reach)
{
  Poly4<S> gap = distanceGap<S>(c0, c1, c2, reach);
  gap[0] += h0 * h0;
  gap[1] += S(2) * h0 * h1;
  gap[2] += h1 * h1 + S(2) * h0 * h2;
  gap[3] += S(2) * h1 * h2;
  gap[4] += h2 * h2;
  return gap;
}

/// True if two bodies whose relative position is d(tau) = c0 + c1 tau + c2 tau^2 cannot come
/// within `reach` for tau in [0, limit] (in the plane, and so in space whatever their heights): a
/// cheap bound, so that pairs that pass wide or part
/// never reach the quartic solver. The straight part c0 + c1 tau comes no closer than its
/// closest approach within the interval, and the curved part adds at most |c2| limit^2. When
/// only that curved part keeps the bound from holding, the interval is halved (each half
/// re-expanded about its start), which quarters it: sliding balls bend by up to about 1 m/s^2,
/// so over a long window the single bound would let most passing pairs through. A nanometre
/// of margin keeps rounding from dismissing a grazing contact.
template <typename S>
bool cannotMeetWithin(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S c2_norm, S reach, S limit,
                      int halvings)
{
  const S speed2 = c1.squaredNorm();
  S tau = speed2 > S(0) ? -c0.dot(c1) / speed2 : S(0);
  tau = std::min(std::max(tau, S(0)), limit);
  const S closest2 = (c0 + tau * c1).squaredNorm();
  const S needed = reach + limit * limit * c2_norm;
  if (closest2 > needed * needed)
    return true;
  if (halvings == 0 || !(closest2 > reach * reach) || !std::isfinite(static_cast<double>(limit)))
    return false;
  const S half = limit / S(2);
  return cannotMeetWithin<S>(c0, c1, c2, c2_norm, reach, half, halvings - 1) &&
         cannotMeetWithin<S>(c0 + half * (c1 + half * c2), c1 + S(2) * half * c2, c2, c2_norm, reach, limit - half,
                             halvings - 1);
}

template <typename S>
bool cannotMeet(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S reach, S limit)
{
  return cannotMeetWithin<S>(c0, c1, c2, c2.norm(), reach + S(kBoxMargin), limit, 3);
}

/// A time no later than the first at which bodies whose relative position is
/// d(tau) = c0 + c1 tau + c2 tau^2 come within `reach`: |d| >= |c0| - |c1| tau - |c2| tau^2, so
/// they stay apart at least until that bound falls to reach. The bound is taken down to a
/// nanometre beyond reach, plus 1e-11 |c0|^2 for the rounding of the gap quartic's coefficients
/// (some 200 ulps of |c0|^2, which is under 1e-12 |c0|^2 m once divided by 2 reach): the contact
/// the quartic's solver finds is never earlier. 0 if they are that close now; +inf if they never
/// move relative to each other.
template <typename S>
S earliestMeeting(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S reach)
{
  const S distance = c0.norm();
  const S apart = distance - reach - S(kBoxMargin) - S(1e-11) * distance * distance;
  if (!(apart > S(0)))
    return S(0);
  // The positive root of |c2| tau^2 + |c1| tau - apart, in the form without cancellation.
  const S speed = c1.norm();
  return S(2) * apart / (speed + std::sqrt(speed * speed + S(4) * c2.norm() * apart));
}

}  // namespace physics
}  // namespace cue_sim
