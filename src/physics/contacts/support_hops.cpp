#include "physics/contacts/support_hops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/models/ball_table/slate_landing.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// An impulse per unit mass between a flying ball and a ball on the cloth: `q` on the flying one,
/// its horizontal part against the one on the cloth (the slate takes the vertical part).
template <typename S>
struct PairOnCloth
{
  Vec3<S> flying, support;

  void push(const Vec3<S>& q)
  {
    flying += q;
    support.x() -= q.x();
    support.y() -= q.y();
  }
  S energy() const { return S(0.5) * (flying.squaredNorm() + support.squaredNorm()); }
  Vec3<S> relative() const { return flying - support; }
};

/// Pushes the pair `hop` apart along `n` and drains the energy that costs from their sliding
/// along the support; false, and the pair unchanged, if their sliding cannot pay for it.
template <typename S>
bool pushApart(PairOnCloth<S>& pair, const Vec3<S>& n, S hop)
{
  PairOnCloth<S> pushed = pair;
  const S before = pair.energy();
  // An impulse q changes the relative velocity by q plus its horizontal part.
  const S horizontal = n.x() * n.x() + n.y() * n.y();
  pushed.push((hop - pushed.relative().dot(n)) / (S(1) + horizontal) * n);
  const S cost = pushed.energy() - before;
  if (cost > S(0))
  {
    // The impulse u changes the relative velocity by exactly its sliding t, so -b u slows the
    // sliding by the fraction b and leaves the separation along n as it is.
    const Vec3<S> rel = pushed.relative();
    const Vec3<S> t = rel - rel.dot(n) * n;
    const Vec3<S> u(S(0.5) * t.x(), S(0.5) * t.y(), t.z());
    const S g = u.dot(rel);
    const S c = u.squaredNorm() + u.x() * u.x() + u.y() * u.y();
    // Energy change -b g + b^2 c / 2 must take away the cost (and a rounding's worth more).
    const S needed = cost + S(64) * std::numeric_limits<S>::epsilon() * before;
    const S discriminant = g * g - S(2) * c * needed;
    if (!(c > S(0)) || !(discriminant >= S(0)))
      return false;
    pushed.push(-((g - std::sqrt(discriminant)) / c) * u);
  }
  if (!(pushed.energy() <= before) || !(pushed.relative().dot(n) > S(0)))
    return false;
  pair = pushed;
  return true;
}

/// Whether a ball closing on a support at `closing` along the normal `n` (up from the support)
/// is held on it by gravity in a sustained contact.
template <typename S>
bool sustained(const Vec3<S>& n, S closing)
{
  return n.z() > S(0) && closing > S(0) && closing < S(kSustainedContactSpeed);
}
}  // namespace

template <typename S>
bool bounceOffBallOnCloth(Ball<S>& flying, Ball<S>& support, const Vec3<S>& n)
{
  const PairOnCloth<S> pair{flying.v, support.v};
  const S closing = -pair.relative().dot(n);
  if (!sustained(n, closing))
    return false;
  // An impulse giving `hop` apart changes the energy by (hop^2 - closing^2) / (2 k), k the
  // relative velocity's change per unit impulse: none for hop = closing. Rounding's excess, if
  // any, is taken off the hop.
  const S k = S(1) + n.x() * n.x() + n.y() * n.y();
  const S before = pair.energy();
  S hop = closing;
  for (int attempt = 0; attempt < 2; ++attempt)
  {
    PairOnCloth<S> pushed = pair;
    pushed.push((hop - pushed.relative().dot(n)) / k * n);
    const S excess = pushed.energy() - before;
    if (excess <= S(0) && pushed.relative().dot(n) > S(0))
    {
      flying.v = pushed.flying;
      support.v = pushed.support;
      return true;
    }
    hop = std::sqrt(std::max(
        hop * hop - S(2) * k * (std::max(excess, S(0)) + S(64) * std::numeric_limits<S>::epsilon() * before), S(0)));
  }
  return false;
}

template <typename S>
bool bounceOffFixedSupport(Ball<S>& ball, const Vec3<S>& n)
{
  const S closing = -ball.v.dot(n);
  if (!sustained(n, closing))
    return false;
  const S speed = ball.v.norm();
  Vec3<S> v = ball.v + S(2) * closing * n;
  const S after = v.norm();
  if (after > speed)
    v *= speed / after;  // rounding
  ball.v = v;
  return true;
}

template <typename S>
bool hopOffFixedSupport(Ball<S>& ball, const Vec3<S>& n)
{
  if (!(n.z() > S(0)))
    return true;  // gravity does not press it on
  const S along_normal = ball.v.dot(n);
  if (!(along_normal < S(kSettleSpeed)))
    return true;
  const S speed = ball.v.norm();
  const S hop = std::min(S(kSettleSpeed), speed);
  const Vec3<S> tangent = ball.v - along_normal * n;
  const S tangential = tangent.norm();
  const Vec3<S> sent = tangential > S(0)
                           ? Vec3<S>(tangent * (std::sqrt(std::max(speed * speed - hop * hop, S(0))) / tangential))
                           : Vec3<S>::Zero();
  Vec3<S> v = sent + hop * n;
  const S after = v.norm();
  if (after > speed)
    v *= speed / after;  // rounding
  ball.v = v;
  return hop >= S(kSettleSpeed);
}

template <typename S>
bool hopOffBallOnCloth(Ball<S>& flying, Ball<S>& support, const Vec3<S>& n, S most, S least)
{
  if (!(n.z() > S(0)))
    return true;  // gravity does not press it on
  PairOnCloth<S> pair{flying.v, support.v};
  if (!(pair.relative().dot(n) < S(kSettleSpeed)))
    return true;
  for (S hop = most; hop >= least; hop *= S(0.5))
    if (pushApart(pair, n, hop))
    {
      flying.v = pair.flying;
      support.v = pair.support;
      return true;
    }
  return false;
}

#define CUE_SIM_INSTANTIATE_SUPPORT_HOPS(S)                                                                            \
  template bool hopOffFixedSupport(Ball<S>&, const Vec3<S>&);                                                          \
  template bool hopOffBallOnCloth(Ball<S>&, Ball<S>&, const Vec3<S>&, S, S);                                           \
  template bool bounceOffBallOnCloth(Ball<S>&, Ball<S>&, const Vec3<S>&);                                              \
  template bool bounceOffFixedSupport(Ball<S>&, const Vec3<S>&);
CUE_SIM_INSTANTIATE_SUPPORT_HOPS(double)
CUE_SIM_INSTANTIATE_SUPPORT_HOPS(long double)

}  // namespace physics
}  // namespace cue_sim
