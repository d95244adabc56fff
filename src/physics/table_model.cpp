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
                       std::vector<Pocket> pockets)
  : name_(std::move(name)),
    cloth_centre_(std::move(cloth_centre)),
    cloth_length_(cloth_length),
    cloth_width_(cloth_width),
    segments_(std::move(segments)),
    circles_(withEndCaps(segments_, std::move(circles))),
    pockets_(std::move(pockets))
{
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

std::string TableModel::whyNotPlaceable(const Eigen::Vector2d& p, double R) const
{
  const double tolerance = 1e-9;
  std::ostringstream why;
  const Eigen::Vector2d offset = p - cloth_centre_;
  // The slate goes on past the cushion line into each pocket's mouth, where a ball can hang in
  // the jaws without dropping: there, beyond the rectangle but near a pocket, the cushion,
  // jaw and pocket tests below are what bound the cloth.
  const auto inPocketMouth = [&] {
    for (const auto& k : pockets_)
      if ((p - k.centre).norm() < k.radius + 2 * R)
        return true;
    return false;
  };
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
    why << "position is not finite";
  else if ((std::abs(offset.x()) > cloth_length_ / 2 - R + tolerance ||
            std::abs(offset.y()) > cloth_width_ / 2 - R + tolerance) &&
           !inPocketMouth())
    why << "position (" << p.x() << ", " << p.y()
        << ") is off the cloth: the centre must be within |x| <= " << cloth_length_ / 2 - R
        << ", |y| <= " << cloth_width_ / 2 - R << " m of the cloth centre, or in a pocket's mouth";
  for (const auto& s : segments_)
  {
    const double along = (p - s.start).dot(s.direction);
    const bool behind = along >= 0 && along <= s.length && (p - s.start).dot(s.normal) < R - tolerance;
    if (why.str().empty() && (behind || distanceToSegment(p, s) < R - tolerance))
      why << "position (" << p.x() << ", " << p.y() << ") overlaps " << s.name;
  }
  for (const auto& c : circles_)
    if (why.str().empty() && (p - c.centre).norm() < R + c.radius - tolerance)
      why << "position (" << p.x() << ", " << p.y() << ") overlaps " << c.name;
  for (const auto& k : pockets_)
    if (why.str().empty() && (p - k.centre).norm() < k.radius)
      why << "position (" << p.x() << ", " << p.y() << ") is over " << k.name;
  return why.str();
}

}  // namespace physics
}  // namespace cue_sim
