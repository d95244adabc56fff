// Physics types to and from ROS messages.
#pragma once

#include <cue_sim/BallState.h>
#include <cue_sim/Event.h>
#include <cue_sim/Shot.h>
#include <cue_sim/Strike.h>
#include <cue_sim/TableState.h>
#include <geometry_msgs/Point.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
geometry_msgs::Vector3 toVector3(const physics::Vec3<double>& v);
geometry_msgs::Point toPoint(const physics::Vec3<double>& p);
geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q);
BallState toBallStateMsg(const physics::Ball<double>& ball, const physics::TableModel& table);
TableState toTableStateMsg(const std::vector<physics::Ball<double>>& balls, const physics::TableModel& table,
                           const ros::Time& stamp, const std::string& frame_id);

physics::CueStrike<double> toCueStrike(const Shot& shot);
Shot toShotMsg(int ball_id, const physics::CueStrike<double>& strike);
/// The shot a ~strike request asks for (its fields are those of cue_sim/Shot).
Shot shotOf(const Strike::Request& request);

/// `stamp` is when the event happened (zero in predictions); `shot_time` [s] since the strike.
Event toEventMsg(const physics::Event<double>& event, const physics::TableModel& table, const ros::Time& stamp,
                 double shot_time);

/// The balls of a message as a table state at time 0, or why they cannot be: an id out of
/// [0, 15], a non-finite value, a velocity off the cloth, an unknown pocket. Motion states
/// follow from velocity and spin; placement (cloth, cushions, overlaps) is the engine's to check.
std::string fromBallStateMsgs(const std::vector<BallState>& balls, const physics::TableModel& table, double ball_radius,
                              physics::TableState<double>& out);

}  // namespace cue_sim
