// A recorded game as files `simulate` replays: one scene per shot (the balls before it, the
// strike as executed, the game as it found the shot), and the rulings in a JSON summary.
#pragma once

#include <string>

#include "cue_sim/game/self_play.hpp"
#include "cue_sim/scene/scene_file.hpp"

namespace cue_sim
{
/// The scene of shot `k` of `record`, played on `table_name` with `engine`'s coefficients and
/// models: `simulate` on it gives that shot's events and ruling again.
Scene shotScene(const game::GameRecord& record, std::size_t k, const std::string& table_name,
                const physics::Engine<double>& engine);

/// Writes `record` to `dir`: shot_000.yaml, shot_001.yaml, ... and game.json (every ruling and
/// the end). Returns the number of files written. Throws std::runtime_error if it cannot write.
int writeGameRecord(const game::GameRecord& record, const std::string& dir, const std::string& table_name,
                    const physics::Engine<double>& engine);

}  // namespace cue_sim
