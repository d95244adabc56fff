// The game as ROS messages: a ruling (cue_sim/Ruling) and the game on the live table
// (cue_sim/GameState).
#pragma once

#include <cue_sim/GameState.h>
#include <cue_sim/Ruling.h>

#include <string>

#include "cue_sim/session/live_table.hpp"

namespace cue_sim
{
/// `refereed` false gives the empty ruling of free play.
Ruling toRulingMsg(const game::Ruling& ruling, bool refereed);

/// The live table's game (active false in free play), stamped `stamp` in `frame`.
GameState toGameStateMsg(const session::LiveTable& table, const ros::Time& stamp, const std::string& frame);

}  // namespace cue_sim
