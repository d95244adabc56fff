#include "physics/search/full_scan.hpp"

#include <cmath>

#include "physics/search/candidates.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
Event<S> scanNextEvent(const Engine<S>& engine, const TableState<S>& state)
{
  const CandidateFinder<S> finder(engine);
  const int n = static_cast<int>(state.balls.size());
  BallRecords<S> records(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    finder.computePath(state.balls[i], i, records[i], state.balls[i].time, infinity<S>());
  Candidate<S> best;
  bool found = false;
  const auto keep = [&](const Candidate<S>& c) {
    if (!found || c.before(best))
    {
      best = c;
      found = true;
    }
  };
  for (int i = 0; i < n; ++i)
    if (std::isfinite(static_cast<double>(records[i].first.time)))
      keep(records[i].first);
  Candidate<S> pair;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (finder.pairCandidate(i, j, records, pair))
        keep(pair);
  return found ? finder.eventOf(state, best) : Event<S>();
}

template Event<double> scanNextEvent(const Engine<double>&, const TableState<double>&);
template Event<long double> scanNextEvent(const Engine<long double>&, const TableState<long double>&);

}  // namespace physics
}  // namespace cue_sim
