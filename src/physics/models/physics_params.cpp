#include "cue_sim/physics/physics_params.hpp"

#include <cmath>
#include <sstream>

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
      continue;  // a range of its own, below
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
  // Where a range is wider than the physical one, the models hold across it and the soak
  // campaign (soak) checks them there.
  static const char* const kPositive = "the models hold for any positive value; beyond these bounds none is checked";
  static const char* const kFriction = "0 is frictionless; Coulomb coefficients beyond the upper bound are not checked";
  static const char* const kRestitution = "0 is perfectly plastic, 1 perfectly elastic; above 1 would create energy";
  static const std::vector<ParamField> fields = {
      {"ball_mass", &P::ball_mass, "kg", 1e-3, 10.0, kPositive},
      {"ball_radius", &P::ball_radius, "m", 1e-3, 1.0, kPositive},
      {"gravity", &P::gravity, "m/s^2", 0.1, 30.0,
       "from a hundredth of the Earth's to three times it: the range the soak campaign checks (below 0.1 a "
       "rolling ball outlasts max_shot_time)"},
      {"mu_slide", &P::mu_slide, "-", 0.0, 100.0, kFriction},
      {"mu_roll", &P::mu_roll, "-", 0.0, 10.0, kFriction},
      {"mu_spin", &P::mu_spin, "-", 0.0, 10.0, kFriction},
      {"e_ball", &P::e_ball, "-", 0.0, 1.0, kRestitution},
      {"mu_ball_a", &P::mu_ball_a, "-", 0.0, 10.0, kFriction},
      {"mu_ball_b", &P::mu_ball_b, "-", 0.0, 10.0, kFriction},
      {"mu_ball_c", &P::mu_ball_c, "s/m", 0.0, 100.0,
       "the decay of mu_b with the slip speed: 0 makes it constant; faster decays are not checked"},
      {"e_cushion", &P::e_cushion, "-", 0.0, 1.0, kRestitution},
      {"f_cushion", &P::f_cushion, "-", 0.0, 10.0, kFriction},
      {"cushion_height", &P::cushion_height, "m", NAN, NAN, "strictly between R and 2R (validate says why)"},
      {"cue_mass", &P::cue_mass, "kg", 1e-3, 100.0, kPositive},
      {"cue_end_mass", &P::cue_end_mass, "kg", 1e-6, 100.0, kPositive},
      {"cue_tip_radius", &P::cue_tip_radius, "m", 0.0, 1.0, "0 is a point tip; the strike model holds for any"},
  };
  return fields;
}

}  // namespace physics
}  // namespace cue_sim
