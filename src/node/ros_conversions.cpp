#include "node/ros_conversions.hpp"

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

BallState toBallStateMsg(const physics::Ball<double>& ball, const physics::TableModel& table)
{
  BallState msg;
  msg.id = ball.id;
  msg.position.x = ball.r.x();
  msg.position.y = ball.r.y();
  msg.position.z = ball.r.z();
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

}  // namespace cue_sim
