#include "cue_sim/physics/execution_noise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cue_sim
{
namespace physics
{
std::string ExecutionNoise::validate() const
{
  const std::pair<const char*, double> fields[] = {
      {"speed", speed}, {"phi", phi}, {"theta", theta}, {"a", a}, {"b", b}};
  for (const auto& [name, value] : fields)
    if (!(std::isfinite(value) && value >= 0))
      return std::string("noise ") + name + " must be a finite standard deviation >= 0, got " + std::to_string(value);
  return "";
}

NoisyCue::NoisyCue(const ExecutionNoise& noise, std::uint64_t seed) : noise_(noise), random_(seed) {}

double NoisyCue::normal()
{
  if (has_spare_)
  {
    has_spare_ = false;
    return spare_;
  }
  const auto uniform = [this] { return static_cast<double>(random_() >> 11) * 0x1.0p-53 * 2 - 1; };
  double u, v, s;
  do
  {
    u = uniform();
    v = uniform();
    s = u * u + v * v;
  } while (s >= 1 || s == 0);
  const double scale = std::sqrt(-2 * std::log(s) / s);
  spare_ = v * scale;
  has_spare_ = true;
  return u * scale;
}

CueStrike<double> NoisyCue::execute(const CueStrike<double>& planned, double ball_radius)
{
  if (noise_.isNone())
    return planned;
  CueStrike<double> out = planned;
  // Always five deviates in the same order, so that one strike's noise never depends on
  // which deviations are zero.
  const double d_speed = normal(), d_phi = normal(), d_theta = normal(), d_a = normal(), d_b = normal();
  out.speed = std::clamp(planned.speed + noise_.speed * d_speed, 1e-3, CueLimits::max_speed);
  out.phi = planned.phi + noise_.phi * d_phi;
  out.theta = std::clamp(planned.theta + noise_.theta * d_theta, 0.0, CueLimits::max_elevation);
  out.a = planned.a + noise_.a / ball_radius * d_a;
  out.b = planned.b + noise_.b / ball_radius * d_b;
  // A tip pushed past the miscue limit is brought back to it along the same direction.
  const double offset = std::hypot(out.a, out.b);
  if (offset > CueLimits::max_offset)
  {
    // A few ulps inside, so that rounding never puts it back outside.
    const double shrink = CueLimits::max_offset / offset * (1 - 4 * std::numeric_limits<double>::epsilon());
    out.a *= shrink;
    out.b *= shrink;
  }
  return out;
}

}  // namespace physics
}  // namespace cue_sim
