// The rviz picture of a game: whose turn it is, the groups and fouls or the scores, the last
// ruling, where the cue ball in hand may go, the called pocket, and a carom point's path.
#pragma once

#include <cue_sim/GameState.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Core>
#include <vector>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
/// DELETEALL, then for an active game: a text beside the table (the game, each player with
/// their group and fouls, or their cue ball, score and innings in a game that keeps a score; who
/// shoots, ball in hand, the last ruling), the ball-in-hand region on the cloth, the head string,
/// a ring round the called pocket (over the cushions, whose height is `cushion_height` [m]), and
/// `point_path` (the last point's cue-ball path, when not empty) as a line on the cloth; in
/// `state`'s frame.
visualization_msgs::MarkerArray gameMarkers(const GameState& state, const physics::TableModel& table,
                                            double cushion_height, const std::vector<Eigen::Vector2d>& point_path = {});

}  // namespace cue_sim
