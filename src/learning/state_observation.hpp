// The state observation's ball block: one slot per ball id (the cue ball first, then 1 to 15, or
// to 21 in snooker),
// each its centre normalised by the cloth (the cloth spans -1 to 1 along each axis) and whether
// it is on the table. A ball off the table (pocketed, or not in this episode) reads 0, 0, 0.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/learning/environment.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace learning
{
/// Ball ids an observation has a slot for: the cue ball and fifteen object balls (a task with more
/// balls, snooker's 22, has a slot for each: Task::ballSlots()).
constexpr int kBallSlots = 16;
/// The bound of a normalised coordinate: a ball's centre stays within the cushions' noses, which
/// lie inside the cloth, except in a pocket's mouth, where it may pass the cloth's edge by less
/// than two ball radii before it drops (under 0.15 of the half-width of the smallest table).
constexpr double kPositionBound = 1.25;

/// Appends the ball block's names and bounds to `box`, for ids 0 to slots - 1.
void addBallBlock(BoxSpec& box, int slots = kBallSlots);
/// Writes the ball block (slots x 3 floats) for `state` on `table`.
void writeBallBlock(const physics::TableModel& table, const physics::TableState<double>& state, float* out,
                    int slots = kBallSlots);

}  // namespace learning
}  // namespace cue_sim
