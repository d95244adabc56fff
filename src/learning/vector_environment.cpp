#include "cue_sim/learning/vector_environment.hpp"

#include <stdexcept>
#include <string>

namespace cue_sim
{
namespace learning
{
namespace
{
/// The most tables one vector environment steps: far beyond a machine's cores, and a bound on
/// what one call may cost.
constexpr int kMaxTables = 100000;
}  // namespace

VectorEnvironment::VectorEnvironment(std::shared_ptr<const physics::Engine<double>> engine, const EnvOptions& options,
                                     int count, unsigned threads)
{
  if (!(count >= 1 && count <= kMaxTables))
    throw std::invalid_argument("num_envs: must be in [1, " + std::to_string(kMaxTables) + "], got " +
                                std::to_string(count));
  const Environment first(engine, options);
  tables_.assign(static_cast<std::size_t>(count), first);
  pool_ = std::make_unique<physics::ThreadPool>(threads);
}

ObservationBuffers VectorEnvironment::rowOf(const VectorBuffers& out, std::size_t i) const
{
  const Spaces& s = spaces();
  ObservationBuffers row;
  if (out.state)
    row.state = out.state + i * s.state.size();
  if (out.pixels)
    row.pixels = out.pixels + i * s.pixelBytes();
  return row;
}

void VectorEnvironment::reset(std::optional<std::uint64_t> seed, const VectorBuffers& out)
{
  pool_->parallelFor(tables_.size(), [&](std::size_t i) {
    tables_[i].reset(seed ? std::optional<std::uint64_t>(*seed + i) : std::nullopt, rowOf(out, i));
  });
}

void VectorEnvironment::step(const double* actions, std::size_t rows, std::size_t columns, const VectorBuffers& out)
{
  if (rows != tables_.size())
    throw std::invalid_argument("actions: one row per table, " + std::to_string(tables_.size()) + " rows, got " +
                                std::to_string(rows));
  for (std::size_t i = 0; i < rows; ++i)
    if (const std::string why = tables_.front().whyActionInvalid(actions + i * columns, columns); !why.empty())
      throw std::invalid_argument("row " + std::to_string(i) + ": " + why);
  pool_->parallelFor(tables_.size(), [&](std::size_t i) {
    Environment& table = tables_[i];
    StepResult result;
    // A table whose episode ended at the last step (or never began) is reset instead.
    const bool resetting = table.done();
    if (resetting)
      table.reset(std::nullopt, rowOf(out, i));
    else
      result = table.step(actions + i * columns, columns, rowOf(out, i));
    if (out.rewards)
      out.rewards[i] = result.reward;
    if (out.terminated)
      out.terminated[i] = result.terminated;
    if (out.truncated)
      out.truncated[i] = result.truncated;
    if (out.autoreset)
      out.autoreset[i] = resetting;
    if (out.infos)
      out.infos[i] = std::move(result.info);
  });
}

}  // namespace learning
}  // namespace cue_sim
