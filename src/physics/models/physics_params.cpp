#include "cue_sim/physics/physics_params.hpp"

#include <cmath>
#include <sstream>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
std::string outOfRange(const char* name, double value, const char* unit, const std::string& range, const char* reason)
{
  std::ostringstream why;
  why << name << " must be in " << range << (std::string(unit) == "-" ? "" : std::string(" ") + unit) << ", got "
      << value << " (" << reason << ")";
  return why.str();
}
}  // namespace

template <typename S>
std::string PhysicsParams<S>::validate() const
{
  const PhysicsParams<double> p = cast<double>();
  for (const ParamField& field : physicsParamFields())
  {
    const double value = p.*field.member;
    if (std::isnan(field.min))
      continue;                                       // a range of its own, below
    if (!(value >= field.min && value <= field.max))  // NaN too
    {
      std::ostringstream range;
      range << "[" << field.min << ", " << field.max << "]";
      return outOfRange(field.name, value, field.unit, range.str(), field.range_reason);
    }
  }
  // Han 2005 places the cushion's nose on the ball theta = asin(h/R - 1) above its equator.
  const double R = p.ball_radius, h = p.cushion_height;
  if (!(h > R && h < 2 * R))
  {
    std::ostringstream range;
    range << "(R, 2R) = (" << R << ", " << 2 * R << ")";
    return outOfRange("cushion_height", h, "m", range.str(),
                      "strictly between the ball's equator and its top: the nose must push the ball down onto "
                      "the cloth, which takes that push (at or below R it would lift the ball), and must push it "
                      "back from the cushion (at 2R it presses straight down, and the ball runs into the cushion "
                      "without end)");
  }
  return {};
}

template struct PhysicsParams<double>;
template struct PhysicsParams<long double>;

const std::vector<ParamField>& physicsParamFields()
{
  using P = PhysicsParams<double>;
  static const char* const kPositive = "the models hold for any positive value; beyond these bounds none is checked";
  static const char* const kFriction = "0 is frictionless; Coulomb coefficients beyond the upper bound are not checked";
  static const char* const kRestitution = "0 is perfectly plastic, 1 perfectly elastic; above 1 would create energy";
  static const std::vector<ParamField> fields = {
#define CUE_SIM_PARAM(name, unit, default_value, min, max, description, why)                                           \
  {#name, &P::name, unit, min, max, why, description},
#include "cue_sim/physics/physics_params.def"
#undef CUE_SIM_PARAM
  };
  return fields;
}

PhysicsParams<double> tableDefaults(const TableModel& table)
{
  PhysicsParams<double> params;
  if (const auto& balls = table.balls())
  {
    params.ball_radius = balls->radius;
    params.ball_mass = balls->mass;
  }
  return params;
}

}  // namespace physics
}  // namespace cue_sim
