// The rviz picture of a game: whose turn it is, the groups and fouls, the last ruling, where the
// cue ball in hand may go, and the called pocket.
#pragma once

#include <cue_sim/GameState.h>
#include <visualization_msgs/MarkerArray.h>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
/// DELETEALL, then for an active game: a text beside the table (the game, each player with
/// their group and fouls, who shoots, ball in hand, the last ruling), the ball-in-hand region
/// on the cloth, the head string, and a ring round the called pocket (over the cushions, whose
/// height is `cushion_height` [m]); in `state`'s frame.
visualization_msgs::MarkerArray gameMarkers(const GameState& state, const physics::TableModel& table,
                                            double cushion_height);

}  // namespace cue_sim
