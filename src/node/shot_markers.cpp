#include "node/shot_markers.hpp"

#include <Eigen/Geometry>

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

visualization_msgs::MarkerArray previewMarkers(const std::vector<session::PreviewPath>& paths, const std::string& frame,
                                               BallSet set)
{
  visualization_msgs::MarkerArray out = clearedPreview();
  for (const session::PreviewPath& path : paths)
  {
    Marker m;
    m.header.frame_id = frame;
    m.ns = "preview";
    m.id = path.id;
    m.type = Marker::LINE_STRIP;
    m.action = Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = 0.004;
    m.color = poolColour(path.id, set);
    m.color.a = 0.9f;
    m.points.reserve(path.points.size());
    for (const Eigen::Vector2d& point : path.points)
    {
      geometry_msgs::Point p;
      p.x = point.x();
      p.y = point.y();
      p.z = 0.002;  // just above the cloth
      m.points.push_back(p);
    }
    out.markers.push_back(m);
  }
  return out;
}

}  // namespace cue_sim
