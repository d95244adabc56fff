// Whether a table's cushions, jaws and pockets close the playing area: a table description with
// a cushion missing, a cushion of almost no length, or pockets missing from the mouths its
// cushions leave would let balls leave the table and travel on without end.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// Shorter than this [m], a straight cushion is a slip of the description: no table has one
/// (the bundled tables' shortest is about 0.8 m), and a ball meets only its two ends.
constexpr double kMinCushionLength = 0.01;
/// Spacing [m] of the directions checked along the cloth's edge: finer than the smallest ball
/// (ball_radius >= 1 mm), so no gap a ball could pass goes unseen.
constexpr double kClosureSpacing = 1e-3;
/// How far beyond the cloth's edge [m] a cushion, jaw or pocket may close it: pockets lie
/// behind their mouths.
constexpr double kClosureReach = 1.0;
/// Gaps narrower than this [m] between the pieces count as closed: a tenth of the smallest
/// ball's radius, so the rounding of a description's angles (cushions meeting at a corner a
/// micrometre apart) is not an opening, and no ball fits through one.
constexpr double kClosedGap = 1e-4;

bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const CushionSegment& s)
{
  const Eigen::Vector2d d = b - a, e = s.end - s.start;
  const double denom = d.x() * e.y() - d.y() * e.x();
  if (denom == 0)
    return false;
  const Eigen::Vector2d w = s.start - a;
  const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
  const double u = (w.x() * d.y() - w.y() * d.x()) / denom;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

bool meetsCircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& centre, double radius)
{
  const Eigen::Vector2d d = b - a;
  const double along = std::clamp((centre - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + along * d - centre).norm() <= radius;
}

/// The point a fraction s in [0, 1) of the way round the cloth's edge.
Eigen::Vector2d edgePoint(const TableModel& table, double s)
{
  const double L = table.clothLength(), W = table.clothWidth(), perimeter = 2 * (L + W);
  double d = s * perimeter;
  const Eigen::Vector2d c = table.clothCentre();
  if (d < L)
    return c + Eigen::Vector2d(-L / 2 + d, -W / 2);
  d -= L;
  if (d < W)
    return c + Eigen::Vector2d(L / 2, -W / 2 + d);
  d -= W;
  if (d < L)
    return c + Eigen::Vector2d(L / 2 - d, W / 2);
  return c + Eigen::Vector2d(-L / 2, W / 2 - (d - L));
}
}  // namespace

std::string TableModel::whyOpen() const
{
  std::ostringstream why;
  for (const auto& s : segments_)
    if (!(s.length >= kMinCushionLength))
    {
      why << "cushion '" << s.name << "' is " << s.length << " m long, at least " << kMinCushionLength
          << " m (a straight cushion along the nose line)";
      return why.str();
    }
  // From the cloth's centre, every way out across its edge must meet a cushion, a jaw or a pocket.
  const Eigen::Vector2d centre = cloth_centre_;
  const long count = static_cast<long>(std::ceil(2 * (cloth_length_ + cloth_width_) / kClosureSpacing));
  long first_open = -1, last_open = -1;
  for (long k = 0; k < count; ++k)
  {
    const Eigen::Vector2d edge = edgePoint(*this, static_cast<double>(k) / count);
    const Eigen::Vector2d out = edge + (edge - centre).normalized() * kClosureReach;
    bool closed = false;
    for (const auto& s : segments_)
      closed = closed || segmentsCross(centre, out, s) || meetsCircle(centre, out, s.start, kClosedGap / 2) ||
               meetsCircle(centre, out, s.end, kClosedGap / 2);
    for (const auto& c : circles_)
      closed = closed || meetsCircle(centre, out, c.centre, c.radius + kClosedGap / 2);
    for (const auto& p : pockets_)
      closed = closed || meetsCircle(centre, out, p.centre, p.radius + kClosedGap / 2);
    if (closed)
    {
      if (first_open >= 0)
        break;
      continue;
    }
    if (first_open < 0)
      first_open = k;
    last_open = k;
  }
  if (first_open < 0)
    return "";
  const Eigen::Vector2d from = edgePoint(*this, static_cast<double>(first_open) / count);
  const Eigen::Vector2d to = edgePoint(*this, static_cast<double>(last_open) / count);
  why << "the cushions, jaws and pockets leave the table open at its edge from (" << from.x() << ", " << from.y()
      << ") to (" << to.x() << ", " << to.y()
      << ") m: a ball there would leave the table; a cushion_*, jaw_* or pocket_* link is missing there";
  return why.str();
}

}  // namespace physics
}  // namespace cue_sim
