// The event search a Simulation keeps alive between calls (internal to the physics core): what
// it knows of each ball, the queue of candidate events, and, on a crowded table, a grid of the
// balls' boxes. An event or an edit renews only the candidates of the balls it changed; every
// other candidate stands, being a function of its own balls' states alone.
#pragma once

#include <optional>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "physics/search/ball_grid.hpp"
#include "physics/search/candidates.hpp"
#include "physics/search/event_queue.hpp"

namespace cue_sim
{
namespace physics
{
/// How the search finds the balls near a ball: a grid beyond kGridFrom balls, or by force.
enum class BroadPhase
{
  Automatic,
  AllPairs,
  Grid,
};

template <typename S>
class EventSearch
{
public:
  /// Finds every ball's candidates and every pair's in `state` (valid on the engine, which
  /// must outlive the search).
  EventSearch(const Engine<S>& engine, const TableState<S>& state, BroadPhase broad_phase = BroadPhase::Automatic);
  EventSearch(const EventSearch&) = delete;
  EventSearch& operator=(const EventSearch&) = delete;

  /// When the search next has something to do: the earliest candidate, event or not (+inf if
  /// nothing is left). Nothing happens to the state before it.
  S nextTime();

  /// Processes the candidates up to and including t_end, appending the events to `events` if
  /// given. `processed` counts the shot's events: at limits().max_events it throws
  /// EventLimitError, before the event, with the search intact.
  void processThrough(TableState<S>& state, S t_end, std::vector<Event<S>>* events, long& processed);
  /// Processes the next event at or before t_end (and what comes before it that is not an
  /// event); an invalid event if there is none.
  Event<S> processNext(TableState<S>& state, S t_end, long& processed);

  /// Edits: the ball at `index` was changed (struck, moved, replaced) at state.time.
  void ballChanged(const TableState<S>& state, int index);
  /// A ball was appended to state.balls.
  void ballAdded(const TableState<S>& state);
  /// The ball at `index` left; the ball that was last, at `moved_from`, now stands at `index`
  /// (unless the one that left was last).
  void ballRemoved(const TableState<S>& state, int index, int moved_from);

private:
  class PathNeighbours;

  /// Processes the earliest candidate if it is at or before t_end; the event, if it was one.
  /// False if there is nothing at or before t_end.
  bool processOne(TableState<S>& state, S t_end, long& processed, Event<S>& event);
  /// A pair left unsolved comes up: solved now, and filed at its contact if they meet.
  void solveDeferred(const Candidate<S>& pair);
  /// A ball's box has run out: drawn over its next stretch, and the balls it now reaches looked at.
  void renewBox(const TableState<S>& state, int k);
  /// Resolves the event and finds the candidates of the balls it changed.
  Event<S> resolve(TableState<S>& state, const Candidate<S>& candidate);
  /// A group in sustained contact takes its next step (not an event), and the balls it changed get
  /// their candidates anew.
  void resolveStep(TableState<S>& state, const Candidate<S>& candidate);
  /// Finds the paths and candidates of the balls in changed_ anew, from `time`.
  void renewChanged(const TableState<S>& state, S time);

  /// Finds the ball's record (path, own event, box from `from`) and lists it in the grid.
  void findPath(const TableState<S>& state, int k, S from);
  void list(const TableState<S>& state, int k);
  /// Files the ball's own next event, and the renewal of its box if that comes first.
  void fileOwn(const TableState<S>& state, int k);
  void fileRenewal(const TableState<S>& state, int k);
  /// Files the pairs ball k may meet among the balls near it, but those `filed(o, k)` says
  /// are filed from the other ball o: one of the three below.
  template <typename Filed>
  void filePairsOf(int k, const Filed& filed);
  /// A look of its own (a box drawn further, an edit): no pair of k's is filed from elsewhere.
  struct NoneFiled
  {
    bool operator()(int, int) const { return false; }
  };
  /// The first look at every ball: a pair of translating balls is filed from the lower index.
  struct FiledByTranslatingBelow
  {
    const std::vector<Ball<S>>& balls;
    bool operator()(int o, int k) const { return o < k && balls[o].translating(); }
  };
  /// After an event: a pair of balls it changed is filed from the lower index.
  struct FiledByChangedBelow
  {
    const std::vector<char>& changed;
    bool operator()(int o, int k) const { return o < k && changed[o]; }
  };
  /// Calls visit(o) for every other ball whose box meets ball k's (through the grid: may meet it).
  template <typename Visit>
  void visitNear(int k, const Visit& visit);
  /// Makes room for every ball of the state in the search's structures (one record per ball).
  void reserveBalls(const TableState<S>& state);

  const Engine<S>& engine_;
  CandidateFinder<S> finder_;
  BallRecords<S> records_;
  EventQueue<Candidate<S>> queue_;
  std::optional<BallGrid<S>> grid_;  ///< beyond kGridFrom balls
  /// How far a ball's box reaches along its path: about two cells with a grid, so that a box
  /// on a large table lists the ball in few cells (it is drawn further when the ball gets
  /// there); all of it without.
  S travel_ = infinity<S>();
  std::vector<int> changed_;      ///< the balls the event being resolved changed
  std::vector<char> is_changed_;  ///< by index: in changed_, during one event
  std::vector<int> scratch_;      ///< neighbour lists of the event's resolution
};

}  // namespace physics
}  // namespace cue_sim
