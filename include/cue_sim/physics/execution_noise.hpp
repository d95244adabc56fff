// Execution noise: a robot (or a person) never strikes exactly as planned. Each cue parameter
// gets independent Gaussian noise, as in the computational pool tournaments (Archibald,
// Altman and Shoham, "Analysis of a winning computational billiards player", IJCAI 2009,
// and the ICGA tournaments that used FastFiz): the defaults are their standard deviations.
#pragma once

#include <cstdint>
#include <random>
#include <string>

#include "cue_sim/physics/cue_strike.hpp"

namespace cue_sim
{
namespace physics
{
/// Standard deviations of the noise on each cue parameter; all zero means no noise.
struct ExecutionNoise
{
  static constexpr double kDegree = 3.14159265358979323846 / 180;
  double speed = 0.075;          ///< V0 [m/s]
  double phi = 0.125 * kDegree;  ///< heading [rad]
  double theta = 0.1 * kDegree;  ///< elevation [rad]
  double a = 0.5e-3;             ///< tip offset to the right [m] (CueStrike::a is in units of R)
  double b = 0.5e-3;             ///< tip offset up [m]

  static ExecutionNoise none() { return {0, 0, 0, 0, 0}; }
  bool isNone() const { return speed == 0 && phi == 0 && theta == 0 && a == 0 && b == 0; }
  /// Empty if every deviation is finite and >= 0, else which one is not.
  std::string validate() const;
};

/// A reproducible source of noisy strikes: the same seed gives the same sequence of strikes on
/// every machine (the normal deviates are computed here, not by the standard library, whose
/// algorithm is unspecified).
class NoisyCue
{
public:
  explicit NoisyCue(const ExecutionNoise& noise = ExecutionNoise::none(), std::uint64_t seed = 0);

  /// The strike as executed: `planned` plus noise, brought back into the cue's limits (speed
  /// in (0, max], elevation in [0, max], offset within max_offset) so that a noisy strike of
  /// a valid plan is always valid. `ball_radius` [m] converts the offsets' deviations.
  CueStrike<double> execute(const CueStrike<double>& planned, double ball_radius);

  const ExecutionNoise& noise() const { return noise_; }

private:
  /// A standard normal deviate (Marsaglia's polar method on 53-bit uniforms).
  double normal();

  ExecutionNoise noise_;
  std::mt19937_64 random_;
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace physics
}  // namespace cue_sim
