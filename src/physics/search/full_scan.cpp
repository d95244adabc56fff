#include <algorithm>
#include <cmath>

#include "cue_sim/physics/scan.hpp"
#include "physics/contacts/event_resolution.hpp"
#include "physics/search/candidates.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// The earliest candidate of every ball and pair, found afresh; false if nothing moves.
template <typename S>
bool scanEarliest(const Engine<S>& engine, const TableState<S>& state, Candidate<S>& best)
{
  const CandidateFinder<S> finder(engine);
  const int n = static_cast<int>(state.balls.size());
  BallRecords<S> records(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    finder.computePath(state.balls[i], i, records[i], state.balls[i].time, infinity<S>());
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
  return found;
}

/// Takes every step of a group in sustained contact that comes before the next event (they change
/// balls but are no events); returns the event's candidate, false if nothing moves.
template <typename S>
bool stepToEvent(const Engine<S>& engine, TableState<S>& state, Candidate<S>& next)
{
  // As many steps as a shot may have events and steps (EngineLimits::max_events): a bound the kept
  // search throws at.
  for (long steps = 0; steps <= engine.limits().max_events && scanEarliest(engine, state, next); ++steps)
  {
    if (next.rank != Candidate<S>::Step)
      return true;
    EventContext<S> context;
    context.index = next.ball;
    resolveSupportStep(engine, state, next.time, context);
  }
  return false;
}
}  // namespace

template <typename S>
Event<S> scanNextEvent(const Engine<S>& engine, const TableState<S>& state)
{
  Candidate<S> next;
  if (!scanEarliest(engine, state, next))
    return Event<S>();
  if (next.rank != Candidate<S>::Step)
    return CandidateFinder<S>(engine).eventOf(state, next);
  // Steps come first: taken on a copy, which the event is then found in.
  TableState<S> ahead = state;
  return stepToEvent(engine, ahead, next) ? CandidateFinder<S>(engine).eventOf(ahead, next) : Event<S>();
}

template <typename S>
Event<S> scanStep(const Engine<S>& engine, TableState<S>& state)
{
  Candidate<S> next;
  Event<S> event;
  if (stepToEvent(engine, state, next))
    event = CandidateFinder<S>(engine).eventOf(state, next);
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
