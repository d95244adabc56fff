#include <algorithm>
#include <cmath>

#include "cue_sim/physics/scan.hpp"
#include "physics/contacts/event_resolution.hpp"
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

template <typename S>
Event<S> scanStep(const Engine<S>& engine, TableState<S>& state)
{
  const Event<S> event = scanNextEvent(engine, state);
  if (event.valid())
  {
    EventContext<S> context;
    context.index = state.indexOf(event.ball);
    context.other_index = event.other >= 0 ? state.indexOf(event.other) : -1;
    resolveEvent(engine, state, event, context);
    state.time = std::max(state.time, event.time);
  }
  return event;
}

template Event<double> scanNextEvent(const Engine<double>&, const TableState<double>&);
template Event<long double> scanNextEvent(const Engine<long double>&, const TableState<long double>&);
template Event<double> scanStep(const Engine<double>&, TableState<double>&);
template Event<long double> scanStep(const Engine<long double>&, TableState<long double>&);

}  // namespace physics
}  // namespace cue_sim
