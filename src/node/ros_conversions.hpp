// Physics types to and from ROS messages.
#pragma once

#include <cue_sim/BallState.h>
#include <cue_sim/Event.h>
#include <cue_sim/Prediction.h>
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
#include "cue_sim/session/ball_input.hpp"
#include "cue_sim/session/physics_clock.hpp"
#include "cue_sim/session/shot_prediction.hpp"

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

/// A ball of a request as the live table takes it (checked there, field by field).
session::BallInput toBallInput(const BallState& msg);
std::vector<session::BallInput> toBallInputs(const std::vector<BallState>& msgs);

session::Shot toSessionShot(const Shot& msg);
Shot toShotMsg(const session::Shot& shot);

/// A prediction as a message: events stamped zero with shot times from the strike, samples in
/// `frame_id`.
Prediction toPredictionMsg(const session::ShotPrediction& prediction, const physics::TableModel& table,
                           double sample_period, const std::string& frame_id);

ros::Time toRosTime(session::Stamp stamp);
session::Stamp toStamp(const ros::Time& time);

}  // namespace cue_sim
