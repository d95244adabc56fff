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
    default:
      break;
  }
  msg.ball_speed = event.speed;
  msg.other_speed = event.other_speed;
  return msg;
}

namespace
{
bool finite(const geometry_msgs::Point& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
bool finite(const geometry_msgs::Vector3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace

std::string fromBallStateMsgs(const std::vector<BallState>& balls, const physics::TableModel& table, double ball_radius,
                              physics::TableState<double>& out)
{
  out = physics::TableState<double>();
  for (std::size_t i = 0; i < balls.size(); ++i)
  {
    const BallState& m = balls[i];
    const std::string field = "balls[" + std::to_string(i) + "]";
    if (m.id < 0 || m.id > 15)
      return field + ".id = " + std::to_string(m.id) + " is not in [0, 15]";
    if (!finite(m.position) || !finite(m.velocity) || !finite(m.angular_velocity))
      return field + ": position, velocity and angular_velocity must be finite";
    physics::Ball<double> b;
    b.id = m.id;
    if (m.pocketed)
    {
      for (std::size_t k = 0; k < table.pockets().size(); ++k)
        if (table.pockets()[k].name == m.pocket)
          b.pocket = static_cast<int>(k);
      if (b.pocket < 0)
        return field + ".pocket = '" + m.pocket + "' is not a pocket of table '" + table.name() + "'";
      b.motion = physics::Motion::Pocketed;
      b.r = physics::Vec3<double>(m.position.x, m.position.y, m.position.z);
      out.balls.push_back(b);
      continue;
    }
    if (m.velocity.z != 0)
      return field + ".velocity.z must be 0 (balls stay on the cloth), got " + std::to_string(m.velocity.z);
    b.r = physics::Vec3<double>(m.position.x, m.position.y, ball_radius);  // z: on the cloth
    b.v = physics::Vec3<double>(m.velocity.x, m.velocity.y, 0);
    b.w = physics::Vec3<double>(m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z);
    physics::settleMotion(b, ball_radius);
    out.balls.push_back(b);
  }
  return "";
}

}  // namespace cue_sim
