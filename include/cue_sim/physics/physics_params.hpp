// Coefficients of the ball, cloth, cushion and cue models. SI units throughout (REP 103).
// Each is declared once, with its unit, default, range and source, in physics_params.def.
#pragma once

#include <cmath>
#include <string>

namespace cue_sim
{
namespace physics
{
template <typename S>
struct PhysicsParams
{
  // The coefficients, their defaults and ranges: physics_params.def.
#define CUE_SIM_PARAM(name, unit, default_value, min, max, description, why) S name = S(default_value);
#include "cue_sim/physics/physics_params.def"
#undef CUE_SIM_PARAM

  /// Deceleration of a sliding ball's contact-point slip is 7/2 of this [m/s^2].
  S slideDecel() const
  {
    return mu_slide * gravity;
  }
  S rollDecel() const
  {
    return mu_roll * gravity;
  }
  /// Angular deceleration of z-spin [rad/s^2].
  S spinDecel() const
  {
    return S(5) * mu_spin * gravity / (S(2) * ball_radius);
  }

  /// Empty when every coefficient is finite and in its physical range, else which one is not.
  std::string validate() const;

  template <typename T>
  PhysicsParams<T> cast() const
  {
    PhysicsParams<T> p;
#define CUE_SIM_PARAM(name, ...) p.name = T(name);
#include "cue_sim/physics/physics_params.def"
#undef CUE_SIM_PARAM
    return p;
  }
};

}  // namespace physics
}  // namespace cue_sim

#include <vector>

namespace cue_sim
{
namespace physics
{
/// One coefficient as declared in physics_params.def: its name as scene files and ROS parameters
/// spell it (config/physics.yaml), its unit, the range PhysicsParams::validate accepts, with
/// why, and what it is.
struct ParamField
{
  const char* name;
  double PhysicsParams<double>::*member;
  const char* unit;  ///< "-" for a pure number
  double min, max;   ///< the accepted range, bounds included; NaN for a range that depends on others
  const char* range_reason;
  const char* description;  ///< what it is, its usual values and their source
};

/// Every coefficient of PhysicsParams, in the order of config/physics.yaml. cushion_height has a
/// range of its own besides: strictly between R and 2R (validate says why).
const std::vector<ParamField>& physicsParamFields();

class TableModel;

/// The coefficients a table is played with before any are set: the defaults above, with the
/// ball's radius and mass from the table's description where it names its balls (a snooker
/// table's, a carom table's). Adapters start from these and then apply what a user sets, so an
/// explicit ball_radius or ball_mass wins.
PhysicsParams<double> tableDefaults(const TableModel& table);

}  // namespace physics
}  // namespace cue_sim
