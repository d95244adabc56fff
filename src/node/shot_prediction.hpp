// What a shot does, as a cue_sim/Prediction: the engine run on a copy of a table, so that
// ~predict, ~predict_batch and ~strike share one path. Read-only on the engine: predictions
// may run on several threads at once.
#pragma once

#include <cue_sim/Prediction.h>
#include <cue_sim/Shot.h>

#include <cstdint>
#include <string>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/execution_noise.hpp"

namespace cue_sim
{
/// At most this many samples per predicted shot.
constexpr int kMaxSamples = 10000;

/// Empty if `period` [s] is 0 (no samples) or in [0.001, 10], else why not.
std::string whyBadSamplePeriod(double period);

struct PredictionOptions
{
  double sample_period = 0;                        ///< [s]; 0: no samples
  const physics::ExecutionNoise* noise = nullptr;  ///< null: the shot as asked
  std::uint64_t seed = 0;                          ///< of the noise
  std::string frame_id;                            ///< of the samples' headers
};

/// Strikes `start` (every ball referred to time 0, as the live table is at a strike from rest)
/// and runs it to rest. A refused shot gives success false and the reason, by field.
Prediction predictShot(const physics::Engine<double>& engine, const physics::TableState<double>& start,
                       const Shot& shot, const PredictionOptions& options);

}  // namespace cue_sim
