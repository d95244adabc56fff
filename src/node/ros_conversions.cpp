#include "node/ros_conversions.hpp"

#include <cmath>

#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
geometry_msgs::Vector3 toVector3(const physics::Vec3<double>& v)
{
  geometry_msgs::Vector3 out;
  out.x = v.x();
  out.y = v.y();
  out.z = v.z();
  return out;
}

geometry_msgs::Point toPoint(const physics::Vec3<double>& p)
{
  geometry_msgs::Point out;
  out.x = p.x();
  out.y = p.y();
  out.z = p.z();
  return out;
}

geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q)
{
  geometry_msgs::Quaternion out;
  out.x = q.x();
  out.y = q.y();
  out.z = q.z();
  out.w = q.w();
  return out;
}

BallState toBallStateMsg(const physics::Ball<double>& ball, const physics::TableModel& table)
{
  BallState msg;
  msg.id = ball.id;
  msg.position = toPoint(ball.r);
  msg.velocity = toVector3(ball.v);
  msg.angular_velocity = toVector3(ball.w);
  msg.motion = static_cast<uint8_t>(ball.motion);
  msg.pocketed = !ball.inPlay();
  if (ball.pocket >= 0)
    msg.pocket = table.pockets()[ball.pocket].name;
  return msg;
}

TableState toTableStateMsg(const std::vector<physics::Ball<double>>& balls, const physics::TableModel& table,
                           const ros::Time& stamp, const std::string& frame_id)
{
  TableState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame_id;
  for (const auto& b : balls)
  {
    msg.balls.push_back(toBallStateMsg(b, table));
    msg.moving = msg.moving || b.moving();
  }
  return msg;
}

physics::CueStrike<double> toCueStrike(const Shot& shot)
{
  physics::CueStrike<double> strike;
  strike.speed = shot.speed;
  strike.phi = shot.phi;
  strike.theta = shot.theta;
  strike.a = shot.a;
  strike.b = shot.b;
  return strike;
}

Shot toShotMsg(int ball_id, const physics::CueStrike<double>& strike)
{
  Shot shot;
  shot.ball_id = ball_id;
  shot.speed = strike.speed;
  shot.phi = strike.phi;
  shot.theta = strike.theta;
  shot.a = strike.a;
  shot.b = strike.b;
  return shot;
}

Shot shotOf(const Strike::Request& request)
{
  Shot shot;
  shot.ball_id = request.ball_id;
  shot.speed = request.speed;
  shot.phi = request.phi;
  shot.theta = request.theta;
  shot.a = request.a;
  shot.b = request.b;
  return shot;
}

Event toEventMsg(const physics::Event<double>& event, const physics::TableModel& table, const ros::Time& stamp,
                 double shot_time)
{
  Event msg;
  msg.stamp = stamp;
  msg.shot_time = shot_time;
  msg.kind = static_cast<uint8_t>(event.kind);
  msg.kind_name = physics::eventKindName(event.kind);
  msg.ball_id = event.ball;
  msg.other_ball_id = event.other;
  switch (event.kind)
  {
    case physics::EventKind::BallCushion:
      msg.obstacle = table.segments()[event.obstacle].name;
      break;
    case physics::EventKind::BallCircle:
      msg.obstacle = table.circles()[event.obstacle].name;
      break;
    case physics::EventKind::Pocketed:
      msg.obstacle = table.pockets()[event.obstacle].name;
      break;
    case physics::EventKind::OffTable:
      msg.obstacle = physics::offTablePlaceName(event.obstacle);
      break;
    default:
      break;
  }
  msg.ball_speed = event.speed;
  msg.other_speed = event.other_speed;
  return msg;
}

namespace
{
physics::Vec3<double> toVec3(double x, double y, double z)
{
  return physics::Vec3<double>(x, y, z);
}
}  // namespace

session::BallInput toBallInput(const BallState& msg)
{
  session::BallInput input;
  input.id = msg.id;
  input.position = toVec3(msg.position.x, msg.position.y, msg.position.z);
  input.velocity = toVec3(msg.velocity.x, msg.velocity.y, msg.velocity.z);
  input.angular_velocity = toVec3(msg.angular_velocity.x, msg.angular_velocity.y, msg.angular_velocity.z);
  input.pocketed = msg.pocketed;
  input.pocket = msg.pocket;
  return input;
}

std::vector<session::BallInput> toBallInputs(const std::vector<BallState>& msgs)
{
  std::vector<session::BallInput> inputs;
  inputs.reserve(msgs.size());
  for (const auto& m : msgs)
    inputs.push_back(toBallInput(m));
  return inputs;
}

session::Shot toSessionShot(const Shot& msg)
{
  return {msg.ball_id, toCueStrike(msg)};
}

Shot toShotMsg(const session::Shot& shot)
{
  return toShotMsg(shot.ball_id, shot.strike);
}

Prediction toPredictionMsg(const session::ShotPrediction& prediction, const physics::TableModel& table,
                           double sample_period, const std::string& frame_id)
{
  Prediction msg;
  msg.success = prediction.success;
  msg.message = prediction.message;
  msg.executed = toShotMsg(prediction.executed);
  msg.time_to_rest = prediction.time_to_rest;
  msg.at_rest = prediction.at_rest;
  msg.sample_period = sample_period;
  msg.final_balls.reserve(prediction.final_balls.size());
  for (const auto& b : prediction.final_balls)
    msg.final_balls.push_back(toBallStateMsg(b, table));
  msg.events.reserve(prediction.events.size());
  for (const auto& e : prediction.events)
    msg.events.push_back(toEventMsg(e, table, ros::Time(), e.time - prediction.strike_time));
  msg.samples.reserve(prediction.samples.size());
  for (const auto& sample : prediction.samples)
    msg.samples.push_back(toTableStateMsg(sample, table, ros::Time(), frame_id));
  return msg;
}

ros::Time toRosTime(session::Stamp stamp)
{
  ros::Time time;
  time.fromNSec(static_cast<std::uint64_t>(stamp));
  return time;
}

session::Stamp toStamp(const ros::Time& time)
{
  return static_cast<session::Stamp>(time.toNSec());
}

}  // namespace cue_sim
