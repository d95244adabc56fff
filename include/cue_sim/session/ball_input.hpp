// Balls as a request gives them (~set_state, ~place_ball, ~predict's starting table): checked
// field by field before they become a table state.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace session
{
/// Ball ids a live table takes: 0 is the cue ball, 1-15 the object balls.
constexpr int kMaxBallId = 15;

struct BallInput
{
  int id = 0;
  /// [m]; a ball in play with z above the ball's radius is in the air there, else on the cloth
  physics::Vec3<double> position = physics::Vec3<double>::Zero();
  physics::Vec3<double> velocity = physics::Vec3<double>::Zero();          ///< [m/s]; z >= 0 on the cloth
  physics::Vec3<double> angular_velocity = physics::Vec3<double>::Zero();  ///< [rad/s]
  bool pocketed = false;
  std::string pocket;  ///< the pocket's name, when pocketed
};

/// The ball as a physics ball at time 0, on the cloth or in the air (its motion state follows from
/// its height, velocity and spin), or why it cannot be: `field` names it in the reason
/// ("balls[3]"). Checks the id, finite values, speeds (physics::BallLimits), a velocity into the
/// slate and the pocket's name;
/// where it is on the table is the engine's to check.
std::string ballFromInput(const BallInput& input, const std::string& field, const physics::TableModel& table,
                          double ball_radius, physics::Ball<double>& out);

/// Every ball of a request, each id once.
std::string stateFromInputs(const std::vector<BallInput>& inputs, const physics::TableModel& table, double ball_radius,
                            physics::TableState<double>& out);

}  // namespace session
}  // namespace cue_sim
