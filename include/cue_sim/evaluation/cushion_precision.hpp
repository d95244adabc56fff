// Error against run time of the cushion models: the integrated impact's (Mathavan 2010)
// tolerance against the rebound's error, measured against the same impact in long double with a
// far tighter one; and every model's cost, rounding and distance from that integrated impact.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace evaluation
{
/// Balls meeting a cushion (normal -y) at 1 m/s: incidence 5 to 90 degrees, topspin -1 to 2 and
/// side spin -2 to 2 times V/R with rolling topspin (the ranges of Mathavan 2010's figures).
std::vector<physics::Ball<double>> cushionArrivals(const physics::PhysicsParams<double>& p);

struct CushionPrecision
{
  double tolerance = 0;
  double seconds_per_impact = 0;  ///< median over repeats
  double max_velocity_error = 0;  ///< largest |v' - reference| over the arrivals, per unit of speed
  double max_spin_error = 0;      ///< largest R |w' - reference|, per unit of speed
};

/// Each tolerance on every arrival with the default coefficients; the reference is the impact in
/// long double with `reference_tolerance`.
std::vector<CushionPrecision> cushionImpactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                                     int repeats);

struct CushionModelCost
{
  std::string model;
  CushionPrecision own;            ///< at the default coefficients, against the same model in long double
  double velocity_difference = 0;  ///< largest |v' - mathavan2010's| per unit speed: the model's difference
  double spin_difference = 0;      ///< the same for R x spin
};

/// Every registered cushion model on every arrival at the default coefficients: its time per
/// impact, its error against itself in long double (rounding, and its tolerance if it has one),
/// and how far its rebound is from mathavan2010's in long double at `reference_tolerance`.
std::vector<CushionModelCost> cushionModelCosts(double reference_tolerance, int repeats);

}  // namespace evaluation
}  // namespace cue_sim
