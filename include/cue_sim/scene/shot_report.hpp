// The JSON the `simulate` program prints: every event and the final state of every ball.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
nlohmann::json shotReport(const physics::Engine<double>& engine, const physics::TableState<double>& final_state,
                          const std::vector<physics::Event<double>>& events, bool at_rest);

}  // namespace cue_sim
