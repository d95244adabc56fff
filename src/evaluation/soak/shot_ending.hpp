// When a campaign shot must have ended, and which shots cannot end by physics.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace evaluation
{
/// The simulated time [s] after the strike by which every ball of `struck` has stopped if its
/// coefficients stop it: twice the longest a ball could slide, roll, spin and bounce with all of the
/// table's energy (kinetic, and the height of the balls in the air) in it, at least
/// SoakLimits::max_shot_time and at most kLongestShot. A coefficient of zero adds nothing: the
/// motion it leaves goes on for ever (endlessByPhysics).
double stoppingTime(const physics::TableState<double>& struck, const physics::PhysicsParams<double>& p);

/// Why a shot that has not stopped cannot stop: a ball moves with no rolling resistance (it rolls for
/// ever once its slide ends), slides with no sliding friction or spins with no spin friction (it may
/// go on hitting the others for ever); empty if no ball's motion goes on for ever by its coefficients.
std::string endlessByPhysics(const physics::TableState<double>& state, const physics::PhysicsParams<double>& p);

/// Whether the last kStormEvents of `times` (events' times, in order) fell within kStormSpan of
/// simulated time: an event storm at one instant, which is a defect whatever the coefficients,
/// not the steady events of a shot that cannot end.
bool endsInAStorm(const std::vector<double>& times);

}  // namespace evaluation
}  // namespace cue_sim
