#include "cue_sim/physics/cue_sweep.hpp"

#include <cmath>

namespace cue_sim
{
namespace physics
{
namespace
{
/// The first fraction s in [0, 1] at which |start + s * way - centre| = reach, the distance
/// closing, or a negative number if there is none. `start` is outside the reach.
double firstReach(const Vec3<double>& start, const Vec3<double>& way, const Vec3<double>& centre, double reach)
{
  const Vec3<double> w = start - centre;
  const double a = way.squaredNorm();
  const double half_b = way.dot(w);
  const double c = w.squaredNorm() - reach * reach;
  if (!(a > 0) || half_b >= 0)
    return -1;  // standing still, or not closing
  const double discriminant = half_b * half_b - a * c;
  if (discriminant < 0)
    return -1;  // passes by
  // The smaller root, c / (-half_b + sqrt(...)): no cancellation when the way is short.
  const double s = c / (-half_b + std::sqrt(discriminant));
  return s <= 1 ? s : -1;
}
}  // namespace

Vec3<double> tipCentre(const CueStick& cue, const PhysicsParams<double>& params)
{
  return cue.tip - cue.axis.normalized() * params.cue_tip_radius;
}

CueStick cueBetween(const CuePose& from, const CuePose& to, double fraction, const PhysicsParams<double>& params)
{
  const Vec3<double> u0 = from.cue.axis.normalized(), u1 = to.cue.axis.normalized();
  CueStick cue = from.cue;
  Vec3<double> axis = u0 + fraction * (u1 - u0);
  cue.axis = axis.norm() > 0 ? Vec3<double>(axis.normalized()) : u0;
  const Vec3<double> c0 = tipCentre(from.cue, params), c1 = tipCentre(to.cue, params);
  cue.tip = c0 + fraction * (c1 - c0) + cue.axis * params.cue_tip_radius;
  return cue;
}

std::optional<CueTouch> firstTouch(const CuePose& from, const CuePose& to, const std::vector<Ball<double>>& balls,
                                   const PhysicsParams<double>& params)
{
  if (!isCue(from.cue) || !isCue(to.cue))
    return std::nullopt;  // no pose to sweep: the follower refuses such a sample before it gets here
  const Vec3<double> start = tipCentre(from.cue, params);
  const Vec3<double> way = tipCentre(to.cue, params) - start;
  const double reach = params.ball_radius + params.cue_tip_radius;
  std::optional<CueTouch> first;
  for (const Ball<double>& ball : balls)
  {
    if (!ball.inPlay() || (start - ball.r).norm() <= reach)
      continue;  // out of play, or touched already
    const double s = firstReach(start, way, ball.r, reach);
    if (s < 0 || (first && s >= first->fraction))
      continue;
    CueTouch touch;
    touch.ball_id = ball.id;
    touch.fraction = s;
    first = touch;
  }
  if (first)
  {
    first->stamp = from.stamp + first->fraction * (to.stamp - from.stamp);
    first->cue = cueBetween(from, to, first->fraction, params);
  }
  return first;
}

}  // namespace physics
}  // namespace cue_sim
