#include "cue_sim/physics/batch.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
std::vector<ShotOutcome<S>> simulateBatch(const Engine<S>& engine, const TableState<S>& start,
                                          const std::vector<BatchShot<S>>& shots, ThreadPool& pool)
{
  std::vector<ShotOutcome<S>> outcomes(shots.size());
  pool.parallelFor(shots.size(), [&](std::size_t i) {
    ShotOutcome<S>& outcome = outcomes[i];
    outcome.state = start;
    outcome.error = engine.whyNotStrikable(start, shots[i].ball_id, shots[i].cue);
    if (!outcome.error.empty())
      return;
    engine.strike(outcome.state, shots[i].ball_id, shots[i].cue);
    try
    {
      outcome.result = simulateToRest(engine, outcome.state);
    }
    catch (const EventLimitError& e)
    {
      outcome.error = e.what();
    }
  });
  return outcomes;
}

template std::vector<ShotOutcome<double>> simulateBatch(const Engine<double>&, const TableState<double>&,
                                                        const std::vector<BatchShot<double>>&, ThreadPool&);
template std::vector<ShotOutcome<long double>> simulateBatch(const Engine<long double>&, const TableState<long double>&,
                                                             const std::vector<BatchShot<long double>>&, ThreadPool&);

}  // namespace physics
}  // namespace cue_sim
