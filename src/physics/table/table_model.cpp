#include "cue_sim/physics/table_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cue_sim
{
namespace physics
{
namespace
{
double distanceToSegment(const Eigen::Vector2d& p, const CushionSegment& s)
{
  const double along = std::clamp((p - s.start).dot(s.direction), 0.0, s.length);
  return (s.start + along * s.direction - p).norm();
}

/// A straight cushion's free end, one that no other cushion or jaw continues, would let a ball
/// through the corner of the segment; a zero-radius circular cushion there closes it.
std::vector<CircularCushion> withEndCaps(const std::vector<CushionSegment>& segments,
                                         std::vector<CircularCushion> circles)
{
  const double join_tolerance = 1e-9;
  std::vector<CircularCushion> caps;
  for (const auto& s : segments)
  {
    for (const auto* end : {&s.start, &s.end})
    {
      bool joined = false;
      for (const auto& other : segments)
        if (&other != &s &&
            ((other.start - *end).norm() < join_tolerance || (other.end - *end).norm() < join_tolerance))
          joined = true;
      for (const auto& c : circles)
        if ((c.centre - *end).norm() <= c.radius + join_tolerance)
          joined = true;
      if (!joined)
        caps.push_back({s.name + (end == &s.start ? "_start" : "_end"), *end, 0.0});
    }
  }
  circles.insert(circles.end(), caps.begin(), caps.end());
  return circles;
}
}  // namespace

TableModel::TableModel(std::string name, Eigen::Vector2d cloth_centre, double cloth_length, double cloth_width,
                       std::vector<CushionSegment> segments, std::vector<CircularCushion> circles,
                       std::vector<Pocket> pockets, std::optional<TableEdge> edge, std::optional<TableBalls> balls)
  : name_(std::move(name)),
    cloth_centre_(std::move(cloth_centre)),
    cloth_length_(cloth_length),
    cloth_width_(cloth_width),
    segments_(std::move(segments)),
    circles_(withEndCaps(segments_, std::move(circles))),
    pockets_(std::move(pockets)),
    balls_(balls)
{
  if (edge)
    edge_ = *edge;
  else
  {
    const Eigen::Vector2d half(cloth_length_ / 2 + kCushionAndRailWidth, cloth_width_ / 2 + kCushionAndRailWidth);
    edge_.low = cloth_centre_ - half;
    edge_.high = cloth_centre_ + half;
  }
}

CushionSegment TableModel::makeSegment(std::string name, const Eigen::Vector2d& start, const Eigen::Vector2d& end)
{
  CushionSegment s;
  s.name = std::move(name);
  s.start = start;
  s.end = end;
  s.length = (end - start).norm();
  s.direction = (end - start) / s.length;
  s.normal = Eigen::Vector2d(-s.direction.y(), s.direction.x());
  return s;
}

namespace
{
/// A pocket's capture circle through its two jaw centres, its centre `outward` of their chord:
/// every ball that leaves the cloth between the jaws crosses the chord, inside the circle.
Pocket captureCircle(std::string name, const Eigen::Vector2d& jaw1, const Eigen::Vector2d& jaw2,
                     const Eigen::Vector2d& outward, double radius)
{
  const double half_chord = (jaw2 - jaw1).norm() / 2;
  const Eigen::Vector2d middle = (jaw1 + jaw2) / 2;
  return {std::move(name), middle + std::sqrt(radius * radius - half_chord * half_chord) * outward.normalized(),
          radius};
}
}  // namespace

TableModel TableModel::pool(const std::string& name, double cloth_length, double cloth_width, double corner_mouth,
                            double side_mouth, double jaw_radius, double capture_radius)
{
  const double hx = cloth_length / 2, hy = cloth_width / 2;
  // A corner pocket's mouth spans the two cushion ends, each d from the corner, at 45 degrees.
  const double d = corner_mouth / std::sqrt(2.0);
  const double s = side_mouth / 2;
  const double j = jaw_radius;
  using V = Eigen::Vector2d;
  // Counter-clockwise round the cloth, so play is on each segment's left. Head end: x < 0.
  std::vector<CushionSegment> segments = {
      makeSegment("cushion_yneg_head", V(-hx + d, -hy), V(-s, -hy)),
      makeSegment("cushion_yneg_foot", V(s, -hy), V(hx - d, -hy)),
      makeSegment("cushion_foot", V(hx, -hy + d), V(hx, hy - d)),
      makeSegment("cushion_ypos_foot", V(hx - d, hy), V(s, hy)),
      makeSegment("cushion_ypos_head", V(-s, hy), V(-hx + d, hy)),
      makeSegment("cushion_head", V(-hx, hy - d), V(-hx, -hy + d)),
  };
  // Jaws: circles tangent to the cushion where it ends, behind its nose line.
  std::vector<CircularCushion> jaws;
  std::vector<Pocket> pockets;
  for (const double sy : {-1.0, 1.0})
  {
    const std::string side = sy < 0 ? "yneg" : "ypos";
    for (const double sx : {-1.0, 1.0})
    {
      const std::string end = sx < 0 ? "head" : "foot";
      const V long_rail_jaw(sx * (hx - d), sy * (hy + j)), end_rail_jaw(sx * (hx + j), sy * (hy - d));
      jaws.push_back({"jaw_" + end + "_" + side + "_long", long_rail_jaw, j});
      jaws.push_back({"jaw_" + end + "_" + side + "_end", end_rail_jaw, j});
      pockets.push_back(
          captureCircle("pocket_" + end + "_" + side, long_rail_jaw, end_rail_jaw, V(sx, sy), capture_radius));
    }
    const V head_jaw(-s, sy * (hy + j)), foot_jaw(s, sy * (hy + j));
    jaws.push_back({"jaw_side_" + side + "_head", head_jaw, j});
    jaws.push_back({"jaw_side_" + side + "_foot", foot_jaw, j});
    pockets.push_back(captureCircle("pocket_side_" + side, head_jaw, foot_jaw, V(0, sy), capture_radius));
  }
  return TableModel(name, V::Zero(), cloth_length, cloth_width, std::move(segments), std::move(jaws),
                    std::move(pockets));
}

bool isBallSetName(const std::string& name)
{
  for (const char* set : kBallSetNames)
    if (name == set)
      return true;
  return false;
}

std::string ballSetNameList()
{
  std::string list;
  for (std::size_t i = 0; i < kBallSetNames.size(); ++i)
    list += (i == 0 ? "" : i + 1 == kBallSetNames.size() ? " or " : ", ") + std::string(kBallSetNames[i]);
  return list;
}

TableModel TableModel::carom(const std::string& name, double cloth_length, double cloth_width)
{
  const double hx = cloth_length / 2, hy = cloth_width / 2;
  using V = Eigen::Vector2d;
  std::vector<CushionSegment> segments = {
      makeSegment("cushion_yneg", V(-hx, -hy), V(hx, -hy)),
      makeSegment("cushion_foot", V(hx, -hy), V(hx, hy)),
      makeSegment("cushion_ypos", V(hx, hy), V(-hx, hy)),
      makeSegment("cushion_head", V(-hx, hy), V(-hx, -hy)),
  };
  return TableModel(name, V::Zero(), cloth_length, cloth_width, std::move(segments), {}, {});
}

namespace
{
/// Where the straight way from p to q first meets a cushion's face, a jaw or a pocket, as a ball's
/// centre sees them (faces moved R into play, circles grown by R, capture circles as they are):
/// the name of what it meets, or empty if nothing. p is clear of everything, within `tolerance`.
std::string firstCrossed(const TableModel& table, const Eigen::Vector2d& p, const Eigen::Vector2d& q, double R,
                         double tolerance)
{
  const Eigen::Vector2d d = q - p;
  for (const auto& s : table.segments())
  {
    // The face's line, R into play: p beside the segment behind it would not be clear.
    const double from = (p - s.start).dot(s.normal) - R, to = (q - s.start).dot(s.normal) - R;
    if (!(from < -tolerance && to > 0))
      continue;
    const Eigen::Vector2d crossing = p + (from / (from - to)) * d;
    const double along = (crossing - s.start).dot(s.direction);
    if (along >= 0 && along <= s.length)
      return s.name;
  }
  // A circle of radius `reach` meets the way if its centre comes within reach of it.
  const auto meets = [&](const Eigen::Vector2d& centre, double reach) {
    const double t = d.squaredNorm() > 0 ? std::clamp((centre - p).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return (p + t * d - centre).norm() < reach - tolerance;
  };
  for (const auto& c : table.circles())
    if (meets(c.centre, R + c.radius))
      return c.name;
  for (const auto& k : table.pockets())
    if (meets(k.centre, k.radius))
      return k.name;
  return {};
}
}  // namespace

namespace
{
/// The start of a refusal: the position, written only when there is one to refuse (every ball of
/// every state checked comes here, and writing two numbers costs more than the checks).
std::string positionOf(const Eigen::Vector2d& p)
{
  std::ostringstream why;
  why << "position (" << p.x() << ", " << p.y() << ") ";
  return why.str();
}
}  // namespace

std::string TableModel::whyNotPlaceable(const Eigen::Vector2d& p, double R, double tolerance) const
{
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
    return "position is not finite";
  for (const auto& s : segments_)
  {
    const double along = (p - s.start).dot(s.direction);
    if (along >= 0 && along <= s.length && (p - s.start).dot(s.normal) < -tolerance)
      return positionOf(p) + "is off the cloth, behind " + s.name +
             ": the centre must be on its playing side, at least R = " + std::to_string(R) + " m from its face";
    if (distanceToSegment(p, s) < R - tolerance)
      return positionOf(p) + "overlaps " + s.name + ": the centre must be at least R = " + std::to_string(R) +
             " m from its face";
  }
  for (const auto& c : circles_)
    if ((p - c.centre).norm() < R + c.radius - tolerance)
      return positionOf(p) + "overlaps " + c.name +
             ": the centre must be at least R + its radius = " + std::to_string(R + c.radius) + " m from its centre";
  for (const auto& k : pockets_)
    if ((p - k.centre).norm() < k.radius - tolerance)
      return positionOf(p) + "is over " + k.name + ": the centre must be outside its capture circle (radius " +
             std::to_string(k.radius) + " m)";
  // Within the rails' reach (R from the cloth's edges) the ball is on the cloth. Beyond it, only in
  // a pocket's mouth: between its jaws, in front of its capture circle. A centre there reaches
  // the cloth in a straight line without meeting a cushion, a jaw or a pocket; behind a cushion,
  // a jaw or a pocket that way meets one of them (the cushions, jaws and capture circles close
  // the playing area).
  const Eigen::Vector2d half_reach(cloth_length_ / 2 - R, cloth_width_ / 2 - R);
  const Eigen::Vector2d offset = p - cloth_centre_;
  if (std::abs(offset.x()) <= half_reach.x() + tolerance && std::abs(offset.y()) <= half_reach.y() + tolerance)
    return {};
  // A point just inside the rails' reach, which nothing but a rail can be near.
  const Eigen::Vector2d inside = half_reach - Eigen::Vector2d::Constant(std::min(1e-6, half_reach.minCoeff() / 2));
  const Eigen::Vector2d q = cloth_centre_ + offset.cwiseMax(-inside).cwiseMin(inside);
  const std::string crossed = firstCrossed(*this, p, q, R, tolerance);
  if (crossed.empty())
    return {};
  return positionOf(p) + "is off the cloth: beyond the cushion lines (|x| <= " + std::to_string(half_reach.x()) +
         ", |y| <= " + std::to_string(half_reach.y()) +
         " m of the cloth centre) a ball can only stand in a pocket's mouth, and " + crossed +
         " lies between it and the cloth";
}

std::string TableModel::whyInTheWalls(const Eigen::Vector3d& r, double R, double h, double tolerance) const
{
  const Eigen::Vector2d c = r.head<2>();
  if ((c.array() < edge_.low.array()).any() || (c.array() > edge_.high.array()).any())
    return {};
  const bool flush = !std::isfinite(edge_.rail_height);
  const double up = r.z() - h;
  // From the wall, by how far the centre is out of its face (or beyond its axis's reach) and up
  // from its top; negative inside it.
  const auto distance = [&](double out) {
    if (out >= 0)
      return up > 0 ? std::hypot(out, up) : out;
    if (!flush)
      return R;  // behind the nose over a rail of another height: not looked at
    return up > 0 ? up : std::max(out, up);
  };
  std::ostringstream why;
  why.precision(17);
  for (const auto& s : segments_)
  {
    const double along = (c - s.start).dot(s.direction);
    const double d = distance((c - s.start).dot(s.normal));
    if (along >= 0 && along <= s.length && d < R - tolerance)
    {
      why << "in the air " << R - d << " m into " << s.name << " (its nose " << h << " m above the slate)";
      return why.str();
    }
  }
  for (const auto& post : circles_)
  {
    const double d = distance((c - post.centre).norm() - post.radius);
    if (d < R - tolerance)
    {
      why << "in the air " << R - d << " m into " << post.name << " (its top " << h << " m above the slate)";
      return why.str();
    }
  }
  return {};
}

std::string TableModel::whyNoPocket(const std::string& name, int& index) const
{
  index = -1;
  if (name.empty())
    return "";
  std::string names;
  for (std::size_t i = 0; i < pockets_.size(); ++i)
  {
    if (pockets_[i].name == name)
    {
      index = static_cast<int>(i);
      return "";
    }
    names += (names.empty() ? "" : ", ") + pockets_[i].name;
  }
  return "pocket must be one of " + (names.empty() ? std::string("(none on this table)") : names) +
         ", or empty for none; got '" + name + "'";
}

}  // namespace physics
}  // namespace cue_sim
