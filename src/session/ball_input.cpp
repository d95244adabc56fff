#include "cue_sim/session/ball_input.hpp"

#include <set>
#include <sstream>

#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
namespace session
{
std::string ballFromInput(const BallInput& input, const std::string& field, const physics::TableModel& table,
                          double ball_radius, physics::Ball<double>& out)
{
  std::ostringstream why;
  if (input.id < 0 || input.id > kMaxBallId)
  {
    why << field << ".id = " << input.id << " is not in [0, " << kMaxBallId << "]";
    return why.str();
  }
  if (!physics::isFinite(input.position) || !physics::isFinite(input.velocity) ||
      !physics::isFinite(input.angular_velocity))
    return field + ": position, velocity and angular_velocity must be finite";
  physics::Ball<double> b;
  b.id = input.id;
  if (input.pocketed && input.pocket.empty())
  {
    // Out of play in no pocket: it left the table, and rests where it landed.
    b.motion = physics::Motion::OffTable;
    b.pocket = physics::kOffTable;
    b.r = input.position;
    out = b;
    return "";
  }
  if (input.pocketed)
  {
    for (std::size_t k = 0; k < table.pockets().size(); ++k)
      if (table.pockets()[k].name == input.pocket)
        b.pocket = static_cast<int>(k);
    if (b.pocket < 0)
      return field + ".pocket = '" + input.pocket + "' is not a pocket of table '" + table.name() + "'";
    b.motion = physics::Motion::Pocketed;
    b.r = input.position;
    out = b;
    return "";
  }
  // Above the cloth the ball is in the air at its height; at or below it (a request's default
  // z = 0 included) it is on the cloth, where it may leave the slate but not press into it.
  const bool in_the_air = input.position.z() > ball_radius;
  if (!in_the_air && input.velocity.z() < 0)
  {
    why << field << ".velocity.z = " << input.velocity.z()
        << " m/s drives a ball on the cloth into the slate: it must be >= 0 there (a ball in the air, position.z > "
        << ball_radius << " m, may fall)";
    return why.str();
  }
  const double speed = input.velocity.norm(), spin = input.angular_velocity.norm();
  if (speed > physics::BallLimits::max_speed)
  {
    why << field << ".velocity: speed " << speed << " m/s is not in [0, " << physics::BallLimits::max_speed << "]";
    return why.str();
  }
  if (spin > physics::BallLimits::max_spin)
  {
    why << field << ".angular_velocity: " << spin << " rad/s is not in [0, " << physics::BallLimits::max_spin << "]";
    return why.str();
  }
  b.r = physics::Vec3<double>(input.position.x(), input.position.y(), in_the_air ? input.position.z() : ball_radius);
  b.v = input.velocity;
  b.w = input.angular_velocity;
  physics::settleMotion(b, ball_radius);
  out = b;
  return "";
}

std::string stateFromInputs(const std::vector<BallInput>& inputs, const physics::TableModel& table, double ball_radius,
                            physics::TableState<double>& out)
{
  out = physics::TableState<double>();
  std::set<int> ids;
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    const std::string field = "balls[" + std::to_string(i) + "]";
    physics::Ball<double> b;
    const std::string why = ballFromInput(inputs[i], field, table, ball_radius, b);
    if (!why.empty())
      return why;
    if (!ids.insert(b.id).second)
      return field + ".id = " + std::to_string(b.id) + " appears twice";
    out.balls.push_back(b);
  }
  return "";
}

}  // namespace session
}  // namespace cue_sim
