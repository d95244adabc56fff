// Error against run time of the integrated ball-ball impact (Mathavan 2014): its tolerance
// against the rebound's error, measured against the same impact in long double with a far
// tighter one; and every ball-ball model's cost and distance from that integrated impact.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cue_sim/evaluation/cushion_precision.hpp"

namespace cue_sim
{
namespace evaluation
{
/// A cue ball at 1 m/s meeting an object ball at rest: cut 0 to 75 degrees, topspin -1 to 2 and
/// side spin -2 to 2 times V/R with rolling topspin.
std::vector<std::pair<physics::Ball<double>, physics::Ball<double>>> ballArrivals(
    const physics::PhysicsParams<double>& p);

/// Each tolerance on every arrival with the default coefficients; the reference is the impact in
/// long double with `reference_tolerance`. Errors are |dv| of both balls (and R |dw|) summed,
/// per unit of the cue ball's speed.
std::vector<CushionPrecision> ballImpactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                                  int repeats);

/// Every registered ball-ball model on every arrival at the default coefficients: its time per
/// impact, its error against itself in long double, and how far its result is from
/// mathavan2014's in long double at `reference_tolerance`.
std::vector<CushionModelCost> ballModelCosts(double reference_tolerance, int repeats);

}  // namespace evaluation
}  // namespace cue_sim
