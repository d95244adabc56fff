// A cue's pose in any frame tf knows, brought into the table frame. tf is listened to from the
// start, so that a robot's frame is found at once; a lookup waits at most ~tf_timeout.
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <string>

#include "cue_sim/physics/cue_aim.hpp"

namespace cue_sim
{
class CueFrames
{
public:
  CueFrames(std::string table_frame, double timeout);

  /// Empty if the pose is a cue in a known frame (a unit quaternion, a finite position), which
  /// `cue` then is in the table frame; else why not (an unknown frame names it and the wait).
  std::string toTableFrame(const geometry_msgs::PoseStamped& pose, physics::CueStick& cue) const;

private:
  std::string table_frame_;
  double timeout_;  ///< [s]
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
};

}  // namespace cue_sim
