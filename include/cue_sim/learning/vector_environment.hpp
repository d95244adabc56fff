// N tables of one task stepped in one call on every core: what a learner's rollouts need. Table i
// is exactly an Environment seeded with seed + i and reset when its episode ends, bit for bit
// (Gymnasium's vector API: seeds and next-step autoreset).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "cue_sim/learning/environment.hpp"
#include "cue_sim/physics/thread_pool.hpp"

namespace cue_sim
{
namespace learning
{
/// Where a vector step writes, row i for table i: observations (Spaces' sizes per row; null if
/// the observation lacks them), and one value per table for the rest.
struct VectorBuffers
{
  float* state = nullptr;
  std::uint8_t* pixels = nullptr;
  double* rewards = nullptr;
  std::uint8_t* terminated = nullptr;
  std::uint8_t* truncated = nullptr;
  std::uint8_t* autoreset = nullptr;  ///< 1 where the table was reset instead of stepped
  StepInfo* infos = nullptr;
};

class VectorEnvironment
{
public:
  /// `count` tables; `threads` threads step them (0: one per core). Throws
  /// std::invalid_argument as Environment does, or for a count outside [1, 100000].
  VectorEnvironment(std::shared_ptr<const physics::Engine<double>> engine, const EnvOptions& options, int count,
                    unsigned threads = 0);
  int size() const { return static_cast<int>(tables_.size()); }
  const Spaces& spaces() const { return tables_.front().spaces(); }
  const Environment& table(int i) const { return tables_.at(static_cast<std::size_t>(i)); }

  /// Every table's new episode: table i from seed + i if a seed is given, else its stream goes on.
  void reset(std::optional<std::uint64_t> seed, const VectorBuffers& out);
  /// Table i plays row i of `actions` (size() rows of spaces().action.size() values), all on the
  /// pool. A table whose episode ended at the previous step is reset instead and its row is
  /// ignored: reward 0, neither terminated nor truncated, autoreset 1. Every row is checked
  /// first: one that is wrong throws std::invalid_argument naming it, and nothing is stepped.
  void step(const double* actions, std::size_t rows, std::size_t columns, const VectorBuffers& out);

private:
  ObservationBuffers rowOf(const VectorBuffers& out, std::size_t i) const;

  std::vector<Environment> tables_;
  std::unique_ptr<physics::ThreadPool> pool_;
};

}  // namespace learning
}  // namespace cue_sim
