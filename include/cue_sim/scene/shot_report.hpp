// The JSON the `simulate` program prints: every event and the final state of every ball.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "cue_sim/game/game_state.hpp"
#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
nlohmann::json shotReport(const physics::Engine<double>& engine, const physics::TableState<double>& final_state,
                          const std::vector<physics::Event<double>>& events, bool at_rest);

/// A referee's ruling: foul, rule, reason, ball_in_hand ("anywhere", "behind_head_string" or
/// ""), next_player, continues, respot (ids), rerack, game_over, winner (-1 for none), groups.
nlohmann::json rulingJson(const game::Ruling& ruling);
/// A game's state, keyed as a scene's game block (the called pocket by its link name on `table`).
nlohmann::json gameStateJson(const game::GameState& state, const physics::TableModel& table);

}  // namespace cue_sim
