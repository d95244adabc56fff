#include "cue_sim/physics/physics_params.hpp"

#include <cmath>
#include <sstream>

namespace cue_sim
{
namespace physics
{
template <typename S>
std::string PhysicsParams<S>::validate() const
{
  struct Check
  {
    const char* name;
    S value;
    double min, max;
  };
  const Check checks[] = {
      {"ball_mass", ball_mass, 1e-3, 10.0},
      {"ball_radius", ball_radius, 1e-3, 1.0},
      {"gravity", gravity, 0.1, 100.0},
      {"mu_slide", mu_slide, 0.0, 100.0},
      {"mu_roll", mu_roll, 0.0, 10.0},
      {"mu_spin", mu_spin, 0.0, 10.0},
      {"e_ball", e_ball, 0.0, 1.0},
      {"mu_ball_a", mu_ball_a, 0.0, 10.0},
      {"mu_ball_b", mu_ball_b, 0.0, 10.0},
      {"mu_ball_c", mu_ball_c, 0.0, 100.0},
      {"e_cushion", e_cushion, 0.0, 1.0},
      {"f_cushion", f_cushion, 0.0, 10.0},
      {"cushion_height", cushion_height, 0.0, 1.0},
      {"cue_mass", cue_mass, 1e-3, 100.0},
      {"cue_end_mass", cue_end_mass, 1e-6, 100.0},
      {"cue_tip_radius", cue_tip_radius, 0.0, 1.0},
  };
  for (const auto& c : checks)
  {
    const double v = static_cast<double>(c.value);
    if (!std::isfinite(v) || v < c.min || v > c.max)
    {
      std::ostringstream why;
      why << c.name << " must be in [" << c.min << ", " << c.max << "], got " << v;
      return why.str();
    }
  }
  if (cushion_height > S(2) * ball_radius)
    return "cushion_height must not exceed the ball's diameter 2 ball_radius";
  return {};
}

template struct PhysicsParams<double>;
template struct PhysicsParams<long double>;

}  // namespace physics
}  // namespace cue_sim

namespace cue_sim
{
namespace physics
{
const std::vector<ParamField>& physicsParamFields()
{
  using P = PhysicsParams<double>;
  static const std::vector<ParamField> fields = {
      {"ball_mass", &P::ball_mass},
      {"ball_radius", &P::ball_radius},
      {"gravity", &P::gravity},
      {"mu_slide", &P::mu_slide},
      {"mu_roll", &P::mu_roll},
      {"mu_spin", &P::mu_spin},
      {"e_ball", &P::e_ball},
      {"mu_ball_a", &P::mu_ball_a},
      {"mu_ball_b", &P::mu_ball_b},
      {"mu_ball_c", &P::mu_ball_c},
      {"e_cushion", &P::e_cushion},
      {"f_cushion", &P::f_cushion},
      {"cushion_height", &P::cushion_height},
      {"cue_mass", &P::cue_mass},
      {"cue_end_mass", &P::cue_end_mass},
      {"cue_tip_radius", &P::cue_tip_radius},
  };
  return fields;
}

}  // namespace physics
}  // namespace cue_sim
