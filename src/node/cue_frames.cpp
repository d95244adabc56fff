#include "node/cue_frames.hpp"

#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>

namespace cue_sim
{
CueFrames::CueFrames(std::string table_frame, double timeout)
  : table_frame_(std::move(table_frame)), timeout_(timeout), listener_(buffer_)
{
}

std::string CueFrames::toTableFrame(const geometry_msgs::PoseStamped& pose, physics::CueStick& cue) const
{
  const auto& q = pose.pose.orientation;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(std::abs(norm - 1) < 1e-3))
    return "cue.pose.orientation must be a unit quaternion (its norm is " + std::to_string(norm) + ")";
  const auto& p = pose.pose.position;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return "cue.pose.position must be finite";
  if (pose.header.frame_id.empty())
    return "cue.header.frame_id is empty: give the frame of the cue pose";
  geometry_msgs::PoseStamped in_table = pose;
  if (pose.header.frame_id != table_frame_)
  {
    try
    {
      const geometry_msgs::TransformStamped t =
          buffer_.lookupTransform(table_frame_, pose.header.frame_id, ros::Time(0), ros::Duration(timeout_));
      tf2::doTransform(pose, in_table, t);
    }
    catch (const tf2::TransformException& e)
    {
      return "cannot transform the cue pose from '" + pose.header.frame_id + "' to '" + table_frame_ +
             "' (waited ~tf_timeout = " + std::to_string(timeout_) + " s): " + e.what();
    }
  }
  const auto& r = in_table.pose.orientation;
  cue.tip = physics::Vec3<double>(in_table.pose.position.x, in_table.pose.position.y, in_table.pose.position.z);
  cue.axis = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized() * physics::Vec3<double>::UnitX();
  return "";
}

}  // namespace cue_sim
