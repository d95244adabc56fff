// Physics types to and from ROS messages.
#pragma once

#include <cue_sim/BallState.h>
#include <cue_sim/TableState.h>
#include <geometry_msgs/Vector3.h>

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
geometry_msgs::Vector3 toVector3(const physics::Vec3<double>& v);
BallState toBallStateMsg(const physics::Ball<double>& ball, const physics::TableModel& table);
TableState toTableStateMsg(const std::vector<physics::Ball<double>>& balls, const physics::TableModel& table,
                           const ros::Time& stamp, const std::string& frame_id);

}  // namespace cue_sim
