#include "node/shot_markers.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cue_sim/physics/simulation.hpp"
#include "node/ros_conversions.hpp"
#include "node/table_markers.hpp"

namespace cue_sim
{
using visualization_msgs::Marker;

Marker cueStickMarker(const physics::CueStick& cue, const std::string& frame, const ros::Time& stamp, double lifetime)
{
  Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = "cue";
  m.id = 0;
  m.type = Marker::CYLINDER;
  m.action = Marker::ADD;
  const Eigen::Vector3d u = cue.axis.normalized();
  const Eigen::Vector3d middle = cue.tip - u * (cue.length / 2);
  // A cylinder's axis is its z axis: turn z onto the stroke.
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), u);
  m.pose.position = toPoint(middle);
  m.pose.orientation = toQuaternion(q);
  m.scale.x = m.scale.y = 2 * cue.shaft_radius;
  m.scale.z = cue.length;
  m.color.r = 0.85f;
  m.color.g = 0.7f;
  m.color.b = 0.45f;
  m.color.a = 1.0f;
  m.lifetime = ros::Duration(lifetime);
  return m;
}

visualization_msgs::MarkerArray clearedPreview()
{
  visualization_msgs::MarkerArray out;
  Marker clear;
  clear.action = Marker::DELETEALL;
  out.markers.push_back(clear);
  return out;
}

visualization_msgs::MarkerArray previewMarkers(const physics::Engine<double>& engine,
                                               const physics::TableState<double>& start, int ball_id,
                                               const physics::CueStrike<double>& strike, const std::string& frame)
{
  visualization_msgs::MarkerArray out = clearedPreview();

  physics::TableState<double> state = start;
  engine.strike(state, ball_id, strike);
  physics::TableState<double> to_rest = state;
  const physics::ShotResult<double> result = simulateToRest(engine, to_rest);
  // Points at the sampling period and at every event, so that each bounce is a corner.
  const double period = std::max(0.02, result.duration / 2000);
  std::vector<double> times;
  for (double t = state.time; t < state.time + result.duration; t += period)
    times.push_back(t);
  for (const auto& e : result.events)
    times.push_back(e.time);
  times.push_back(state.time + result.duration);
  std::sort(times.begin(), times.end());

  std::vector<Marker> paths(state.balls.size());
  for (std::size_t i = 0; i < state.balls.size(); ++i)
  {
    Marker& m = paths[i];
    m.header.frame_id = frame;
    m.ns = "preview";
    m.id = state.balls[i].id;
    m.type = Marker::LINE_STRIP;
    m.action = Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = 0.004;
    m.color = poolColour(state.balls[i].id);
    m.color.a = 0.9f;
  }
  physics::Simulation<double> simulation(engine, state);
  for (double t : times)
  {
    simulation.advance(t);
    const auto balls = simulation.snapshot();
    for (std::size_t i = 0; i < balls.size(); ++i)
      if (balls[i].inPlay())
      {
        geometry_msgs::Point p;
        p.x = balls[i].r.x();
        p.y = balls[i].r.y();
        p.z = 0.002;  // just above the cloth
        paths[i].points.push_back(p);
      }
  }
  for (auto& m : paths)
  {
    // Only the balls that move have a path worth drawing.
    const auto moved = std::any_of(m.points.begin(), m.points.end(), [&](const geometry_msgs::Point& p) {
      return p.x != m.points.front().x || p.y != m.points.front().y;
    });
    if (moved)
      out.markers.push_back(m);
  }
  return out;
}

}  // namespace cue_sim
