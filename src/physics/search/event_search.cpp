#include "physics/search/event_search.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cue_sim/physics/simulation.hpp"
#include "physics/contacts/event_resolution.hpp"
#include "physics/search/contact_times.hpp"

namespace cue_sim
{
namespace physics
{
/// During an event, the balls near a point are those whose boxes reach it: looked for in the
/// cells around it if there is a grid, else among all balls, by comparisons alone.
template <typename S>
class EventSearch<S>::PathNeighbours : public Neighbours<S>
{
public:
  PathNeighbours(const EventSearch& search, const TableState<S>& state) : search_(search), state_(state) {}

  void near(const Vec2<S>& point, S distance, std::vector<int>& out) const override
  {
    out.clear();
    const Vec2<S> reach = Vec2<S>::Constant(distance + S(kBoxMargin));
    const Vec2<S> low = point - reach, high = point + reach;
    if (search_.grid_)
    {
      for (int o : search_.grid_->inBox(low, high))
        if (state_.balls[o].inPlay())
          out.push_back(o);
      std::sort(out.begin(), out.end());
      return;
    }
    const BallRecord<S>* const records = search_.records_.data();
    const Ball<S>* const balls = state_.balls.data();
    const int n = static_cast<int>(state_.balls.size());
    for (int o = 0; o < n; ++o)
      if (balls[o].inPlay() && !(records[o].low.array() > high.array()).any() &&
          !(low.array() > records[o].high.array()).any())
        out.push_back(o);
  }

private:
  const EventSearch& search_;
  const TableState<S>& state_;
};

namespace
{
thread_local long searches_started = 0;
}  // namespace

long searchesStartedOnThisThread()
{
  return searches_started;
}

template <typename S>
EventSearch<S>::EventSearch(const Engine<S>& engine, const TableState<S>& state, BroadPhase broad_phase)
  : engine_(engine), finder_(engine), queue_(state.balls.size())
{
  ++searches_started;
  const int n = static_cast<int>(state.balls.size());
  // A few balls are simply all looked at; beyond that a grid keeps each look local.
  if (broad_phase == BroadPhase::Grid || (broad_phase == BroadPhase::Automatic && state.balls.size() > kGridFrom))
  {
    grid_.emplace(engine.geometry().cloth_low, engine.geometry().cloth_high, state.balls.size(),
                  engine.params().ball_radius);
    travel_ = S(2) * grid_->cell();
  }
  reserveBalls(state);
  for (int i = 0; i < n; ++i)
  {
    const Ball<S>& b = state.balls[i];
    if (b.motion == Motion::Stationary)
    {
      finder_.restingPath(b, i, records_[i]);  // the common case of a rack, kept out of a call
      if (grid_)
        list(state, i);
    }
    else
      findPath(state, i, std::max(b.time, state.event_time));
  }
  for (int i = 0; i < n; ++i)
    if (state.balls[i].moving())
      fileOwn(state, i);
  // Pairs need a translating ball: each is found from it (from the lower index if both are).
  for (int i = 0; i < n; ++i)
    if (state.balls[i].translating())
      filePairsOf(i, FiledByTranslatingBelow{state.balls});
}

template <typename S>
S EventSearch<S>::nextTime()
{
  const Candidate<S>* top = queue_.top();
  return top ? top->time : infinity<S>();
}

template <typename S>
void EventSearch<S>::processThrough(TableState<S>& state, S t_end, std::vector<Event<S>>* events, long& processed)
{
  Event<S> event;
  while (processOne(state, t_end, processed, event))
    if (events && event.valid())
      events->push_back(event);
}

template <typename S>
Event<S> EventSearch<S>::processNext(TableState<S>& state, S t_end, long& processed)
{
  Event<S> event;
  while (processOne(state, t_end, processed, event) && !event.valid())
  {
  }
  return event;
}

template <typename S>
bool EventSearch<S>::processOne(TableState<S>& state, S t_end, long& processed, Event<S>& event)
{
  event = Event<S>();
  const Candidate<S>* top = queue_.top();
  if (!top || top->time > t_end)
    return false;
  const Candidate<S> next = *top;
  if (next.rank == Candidate<S>::Unsolved)
  {
    queue_.pop();
    solveDeferred(next);
    return true;
  }
  if (next.rank == Candidate<S>::Renewal)
  {
    queue_.pop();
    renewBox(state, next.ball);
    return true;
  }
  if (processed >= engine_.limits().max_events)
  {
    std::ostringstream why;
    why << "event limit reached: more than " << engine_.limits().max_events
        << " events and steps of sustained contact before t = " << static_cast<double>(next.time)
        << " s (EngineLimits::max_events)";
    throw EventLimitError(why.str());
  }
  queue_.pop();
  ++processed;
  if (next.rank == Candidate<S>::Step)
  {
    resolveStep(state, next);  // a group's next step: it changes balls, but is no event
    return true;
  }
  event = resolve(state, next);
  return true;
}

template <typename S>
void EventSearch<S>::solveDeferred(const Candidate<S>& pair)
{
  // Neither ball has changed since the pair was found, so solving it now gives what solving it
  // then would have: it is filed at its contact, if they meet before either's next event.
  Candidate<S> solved = pair;
  if (finder_.solvePair(PairMotion<S>::of(records_, pair.ball, pair.other), solved))
    queue_.file(solved.ball, solved);
}

template <typename S>
void EventSearch<S>::renewBox(const TableState<S>& state, int k)
{
  // Only what is still ahead: the new box starts where the old window ends (nothing is tested
  // against a time before it any more).
  finder_.drawBox(state.balls[k], records_[k], records_[k].window, travel_);
  list(state, k);
  fileRenewal(state, k);
  filePairsOf(k, NoneFiled{});
}

template <typename S>
Event<S> EventSearch<S>::resolve(TableState<S>& state, const Candidate<S>& candidate)
{
  Event<S> event = finder_.eventOf(state, candidate);
  changed_.clear();
  const PathNeighbours neighbours(*this, state);
  EventContext<S> context;
  context.index = candidate.ball;
  context.other_index = candidate.other;
  context.changed = &changed_;
  context.neighbours = &neighbours;
  context.scratch = &scratch_;
  resolveEvent(engine_, state, event, context);
  event.speed = state.balls[candidate.ball].v.norm();
  if (candidate.other >= 0)
    event.other_speed = state.balls[candidate.other].v.norm();
  renewChanged(state, event.time);
  return event;
}

template <typename S>
void EventSearch<S>::resolveStep(TableState<S>& state, const Candidate<S>& candidate)
{
  changed_.clear();
  const PathNeighbours neighbours(*this, state);
  EventContext<S> context;
  context.index = candidate.ball;
  context.changed = &changed_;
  context.neighbours = &neighbours;
  context.scratch = &scratch_;
  resolveSupportStep(engine_, state, candidate.time, context);
  renewChanged(state, candidate.time);
}

template <typename S>
void EventSearch<S>::renewChanged(const TableState<S>& state, S time)
{
  // Only the balls the event changed get new candidates; every other candidate stands.
  std::sort(changed_.begin(), changed_.end());
  changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
  for (int k : changed_)
  {
    queue_.changed(k);
    is_changed_[k] = 1;
    findPath(state, k, time);
  }
  for (int k : changed_)
  {
    fileOwn(state, k);
    if (state.balls[k].inPlay())
      filePairsOf(k, FiledByChangedBelow{is_changed_});
  }
  for (int k : changed_)
    is_changed_[k] = 0;
}

template <typename S>
void EventSearch<S>::ballChanged(const TableState<S>& state, int index)
{
  queue_.changed(index);
  findPath(state, index, state.time);
  fileOwn(state, index);
  if (state.balls[index].inPlay())
    filePairsOf(index, NoneFiled{});
}

template <typename S>
void EventSearch<S>::ballAdded(const TableState<S>& state)
{
  reserveBalls(state);
  ballChanged(state, static_cast<int>(state.balls.size()) - 1);
}

template <typename S>
void EventSearch<S>::ballRemoved(const TableState<S>& state, int index, int moved_from)
{
  // The slot the last ball left keeps its versions (its candidates are void) for a ball placed
  // later; the ball that took the place of the one removed is a changed ball.
  queue_.changed(moved_from);
  if (grid_)
    grid_->remove(moved_from);
  records_.pop_back();
  if (index < static_cast<int>(state.balls.size()))
    ballChanged(state, index);
}

template <typename S>
void EventSearch<S>::findPath(const TableState<S>& state, int k, S from)
{
  finder_.computePath(state.balls[k], k, records_[k], from, travel_);
  list(state, k);
}

template <typename S>
void EventSearch<S>::list(const TableState<S>& state, int k)
{
  if (!grid_)
    return;
  if (state.balls[k].inPlay())
    grid_->place(k, records_[k].low, records_[k].high);
  else
    grid_->remove(k);
}

template <typename S>
void EventSearch<S>::fileOwn(const TableState<S>& state, int k)
{
  if (std::isfinite(static_cast<double>(records_[k].first.time)))
    queue_.file(k, records_[k].first);
  fileRenewal(state, k);
}

template <typename S>
void EventSearch<S>::fileRenewal(const TableState<S>& state, int k)
{
  if (state.balls[k].translating() && records_[k].window < records_[k].first.time)
  {
    Candidate<S> renewal;
    renewal.time = records_[k].window;
    renewal.rank = Candidate<S>::Renewal;
    renewal.ball = k;
    queue_.file(k, renewal);
  }
}

template <typename S>
template <typename Visit>
void EventSearch<S>::visitNear(int k, const Visit& visit)
{
  const BallRecord<S>& record = records_[k];
  if (grid_)
  {
    for (int o : grid_->near(k, record.low, record.high))
      visit(o);
    return;
  }
  const S x0 = record.low.x(), y0 = record.low.y(), x1 = record.high.x(), y1 = record.high.y();
  // Read once: visiting files candidates, which the compiler cannot tell from changing the records.
  const BallRecord<S>* const records = records_.data();
  const int n = static_cast<int>(records_.size());
  for (int o = 0; o < n; ++o)
  {
    const Vec2<S>& low = records[o].low;
    const Vec2<S>& high = records[o].high;
    if (o != k && !(low.x() > x1 || x0 > high.x() || low.y() > y1 || y0 > high.y()))  // NaN never culls
      visit(o);
  }
}

template <typename S>
template <typename Filed>
void EventSearch<S>::filePairsOf(int k, const Filed& filed)
{
  // A pair is left unsolved, at a time before which they cannot meet, if that is later than a
  // contact of k's found earlier in this look (`soonest`): that contact will most likely change
  // k first, and the pair is then never solved. Else it is solved now, since a pair left
  // unsolved that does come up costs a round of the queue, more than most solves.
  S soonest = infinity<S>();
  Candidate<S> pair;
  PairMotion<S> motion;
  visitNear(k, [&](int o) {
    if (filed(o, k) || !finder_.pairMayMeet(k, o, records_, pair, motion))
      return;
    if (soonest < infinity<S>())
    {
      const S tau = earliestMeeting<S>(motion.c0, motion.c1, motion.c2, S(2) * engine_.params().ball_radius);
      if (tau > motion.limit)
        return;  // they cannot meet before either ball's next event
      pair.time = motion.base + tau;
      if (pair.time > soonest)
      {
        queue_.file(k, pair);
        return;
      }
    }
    if (finder_.solvePair(motion, pair))
    {
      queue_.file(k, pair);
      soonest = std::min(soonest, pair.time);
    }
  });
}

template <typename S>
void EventSearch<S>::reserveBalls(const TableState<S>& state)
{
  const std::size_t n = state.balls.size();
  records_.resize(n);
  queue_.reserveBalls(n);
  if (grid_)
    grid_->reserveBalls(n);
  is_changed_.resize(std::max(is_changed_.size(), n), 0);
}

template class EventSearch<double>;
template class EventSearch<long double>;

}  // namespace physics
}  // namespace cue_sim
