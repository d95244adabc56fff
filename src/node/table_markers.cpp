#include "node/table_markers.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "cue_sim/scene/ball_colours.hpp"

namespace cue_sim
{
namespace
{
using visualization_msgs::Marker;

/// The marker id of a ball's second number (at its lower pole) is this plus the ball's id.
constexpr int kSecondLabel = 100;

/// A circle as a polygon, clipped to the box [low, high] (Sutherland-Hodgman; both convex).
std::vector<Eigen::Vector2d> clippedCircle(const Eigen::Vector2d& centre, double radius, const Eigen::Vector2d& low,
                                           const Eigen::Vector2d& high)
{
  std::vector<Eigen::Vector2d> polygon;
  const int sides = 48;
  for (int i = 0; i < sides; ++i)
  {
    const double angle = 2 * M_PI * i / sides;
    polygon.push_back(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  for (int axis = 0; axis < 2; ++axis)
    for (const double sign : {1.0, -1.0})
    {
      const double limit = sign > 0 ? low[axis] : high[axis];
      const auto inside = [&](const Eigen::Vector2d& q) { return sign * (q[axis] - limit) >= 0; };
      std::vector<Eigen::Vector2d> kept;
      for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
        if (inside(a))
          kept.push_back(a);
        if (inside(a) != inside(b))
          kept.push_back(a + (b - a) * ((limit - a[axis]) / (b[axis] - a[axis])));
      }
      polygon = kept;
    }
  return polygon;
}

void setYaw(Marker& m, double yaw)
{
  m.pose.orientation.z = std::sin(yaw / 2);
  m.pose.orientation.w = std::cos(yaw / 2);
}
}  // namespace

std_msgs::ColorRGBA rgba(float r, float g, float b, float a)
{
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

Marker markerIn(const std::string& frame, const std::string& ns, int id, int type)
{
  Marker m;
  m.header.frame_id = frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  return m;
}

std_msgs::ColorRGBA poolColour(int id, BallSet set)
{
  const Rgb c = ballColour(id, set);
  return rgba(c.r, c.g, c.b);
}

visualization_msgs::MarkerArray tableMarkers(const physics::TableModel& table, const physics::TableState<double>& state,
                                             double R, double cushion_height, const MarkerFrames& frames)
{
  visualization_msgs::MarkerArray array;
  Marker clear;
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);

  Marker cloth = markerIn(frames.table, "cloth", 0, Marker::CUBE);
  cloth.pose.position.x = table.clothCentre().x();
  cloth.pose.position.y = table.clothCentre().y();
  cloth.pose.position.z = -0.0005;
  cloth.scale.x = table.clothLength();
  cloth.scale.y = table.clothWidth();
  cloth.scale.z = 0.001;
  cloth.color = rgba(0.05f, 0.5f, 0.22f);
  array.markers.push_back(cloth);

  const double rubber = 0.03;  // drawn thickness of a cushion behind its nose line [m]
  int id = 0;
  for (const auto& s : table.segments())
  {
    Marker m = markerIn(frames.table, "cushions", id++, Marker::CUBE);
    const Eigen::Vector2d centre = (s.start + s.end) / 2 - s.normal * rubber / 2;
    m.pose.position.x = centre.x();
    m.pose.position.y = centre.y();
    m.pose.position.z = cushion_height / 2;
    setYaw(m, std::atan2(s.direction.y(), s.direction.x()));
    m.scale.x = s.length;
    m.scale.y = rubber;
    m.scale.z = cushion_height;
    m.color = rgba(0.02f, 0.36f, 0.15f);
    array.markers.push_back(m);
  }
  id = 0;
  for (const auto& c : table.circles())
  {
    if (c.radius <= 0)
      continue;  // a cushion's end cap is a point
    Marker m = markerIn(frames.table, "jaws", id++, Marker::CYLINDER);
    m.pose.position.x = c.centre.x();
    m.pose.position.y = c.centre.y();
    m.pose.position.z = cushion_height / 2;
    m.scale.x = m.scale.y = 2 * c.radius;
    m.scale.z = cushion_height;
    m.color = rgba(0.02f, 0.36f, 0.15f);
    array.markers.push_back(m);
  }
  id = 0;
  for (const auto& p : table.pockets())
  {
    // The capture circle where it matters: clipped to the cloth and its cushions.
    Marker m = markerIn(frames.table, "pockets", id++, Marker::TRIANGLE_LIST);
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    m.color = rgba(0.0f, 0.0f, 0.0f, 0.9f);
    const Eigen::Vector2d half(table.clothLength() / 2 + rubber, table.clothWidth() / 2 + rubber);
    const std::vector<Eigen::Vector2d> outline =
        clippedCircle(p.centre, p.radius, table.clothCentre() - half, table.clothCentre() + half);
    for (std::size_t i = 1; i + 1 < outline.size(); ++i)
      for (const auto* corner : {&outline[0], &outline[i], &outline[i + 1]})
      {
        geometry_msgs::Point point;
        point.x = corner->x();
        point.y = corner->y();
        point.z = 0.0005;
        m.points.push_back(point);
      }
    if (!m.points.empty())
      array.markers.push_back(m);
  }
  const BallSet set = ballSetFor(table);
  for (const auto& b : state.balls)
  {
    const std::string frame = frames.ball_prefix + std::to_string(b.id);
    const bool striped = isStriped(b.id, set);
    Marker ball = markerIn(frame, "balls", b.id, Marker::SPHERE);
    ball.frame_locked = true;
    ball.scale.x = ball.scale.y = ball.scale.z = 2 * R;
    ball.color = striped ? poolColour(0) : poolColour(b.id, set);
    array.markers.push_back(ball);
    if (striped)
    {
      // A coloured band round the equator of a white ball: from above, a white cap in a ring.
      Marker band = markerIn(frame, "stripes", b.id, Marker::CYLINDER);
      band.frame_locked = true;
      band.scale.x = band.scale.y = 2.02 * R;
      band.scale.z = R;
      band.color = poolColour(b.id);
      array.markers.push_back(band);
    }
    // The number twice, at the poles of the ball's own frame as on a real ball: it turns with the
    // ball (tf carries the orientation), and one of the two is always on the upper half or at the
    // sides. Large, in the colour that reads on the ball; the cue ball's 0 too, to tell its frame.
    // Carom balls carry none.
    for (const int pole : {1, -1})
    {
      if (set != BallSet::Pool)
        break;
      Marker label = markerIn(frame, "labels", pole > 0 ? b.id : kSecondLabel + b.id, Marker::TEXT_VIEW_FACING);
      label.frame_locked = true;
      label.pose.position.z = pole * 1.05 * R;
      label.scale.z = 1.5 * R;
      const Rgb ink = numberColour(b.id);
      label.color = rgba(ink.r, ink.g, ink.b);
      label.text = std::to_string(b.id);
      array.markers.push_back(label);
    }
  }
  return array;
}

}  // namespace cue_sim
