// Error against run time of sustained contact in the air (issue 53): the contact equations'
// `contact_tolerance` against the error of balls resting on, rolling and sliding round their
// supports, measured against the same runs in long double at the registry's tightest tolerance.
#pragma once

#include <string>
#include <vector>

namespace cue_sim
{
namespace evaluation
{
/// The scenes it runs, for the report's caption: a ball rolling off a still ball, a ball rolling
/// off a cushion's nose, a ball carried on a rolling ball, a pyramid of four spreading.
std::vector<std::string> contactPrecisionScenes();

struct ContactPrecision
{
  double tolerance = 0;                ///< contact_tolerance [m]
  double seconds_per_run = 0;          ///< the scenes' runs, median over repeats, summed
  double max_position_error = 0;       ///< largest |r - reference| over the scenes' balls at the end [m]
  double max_velocity_error = 0;       ///< largest |v - reference| [m/s]
  std::vector<double> position_error;  ///< each scene's largest |r - reference| [m]
};

/// Each tolerance on every scene, each run for `duration` [s] of the table's time in double; the
/// reference is each scene in long double at `reference_tolerance`.
std::vector<ContactPrecision> contactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                               double duration, int repeats);

}  // namespace evaluation
}  // namespace cue_sim
