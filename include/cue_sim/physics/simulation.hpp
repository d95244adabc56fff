// A live table: a table state and the event search kept alive between calls (the engine is the
// immutable model, the simulation the data, as MuJoCo's mjModel and mjData; Box2D's world keeps
// its broad phase likewise). Advancing in any steps gives, bit for bit, the events and states of
// one run, at the cost of one run: a step with no event in it costs a comparison. An edit (a
// strike, a ball placed, moved or removed) renews only the candidates of the balls it changes.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace physics
{
/// Thrown when a shot reaches EngineLimits::max_events; the state is left at the last event.
class EventLimitError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

template <typename S>
struct ShotResult
{
  std::vector<Event<S>> events;
  S duration = S(0);     ///< from the strike to the last event [s]
  bool at_rest = false;  ///< false if max_shot_time was reached first
};

/// The search a simulation keeps (internal: src/physics/search/event_search.hpp).
template <typename S>
class EventSearch;

template <typename S>
class Simulation
{
public:
  /// Runs `state` (valid on the engine: check Engine::whyInvalid) on `engine`, which must
  /// outlive the simulation.
  Simulation(const Engine<S>& engine, TableState<S> state);
  /// The same, sharing the engine's ownership.
  Simulation(std::shared_ptr<const Engine<S>> engine, TableState<S> state);
  /// A copy has the same state and finds the same events (its search is found afresh).
  Simulation(const Simulation& other);
  Simulation& operator=(const Simulation& other);
  Simulation(Simulation&& other) noexcept;
  Simulation& operator=(Simulation&& other) noexcept;
  ~Simulation();

  const Engine<S>& engine() const { return *engine_; }
  const TableState<S>& state() const { return state_; }
  S time() const { return state_.time; }
  /// True if no ball moves (nothing will happen however far it is advanced).
  bool atRest() const { return !moving_; }

  /// Processes every event with time <= t_end (appending them to `events` if given) and moves
  /// the state's time on to t_end (never back). Throws EventLimitError when the shot reaches
  /// limits().max_events, leaving the state at its last event, and std::invalid_argument for
  /// a NaN t_end.
  void advance(S t_end, std::vector<Event<S>>* events = nullptr)
  {
    if (t_end < next_)
    {
      if (t_end > state_.time)
        state_.time = t_end;
      return;
    }
    advanceThrough(t_end, events);
  }
  /// Advances until no ball moves, or for limits().max_shot_time.
  ShotResult<S> runToRest();
  /// Processes exactly the next event (moving the time on to it) and returns it; an invalid
  /// event, and no change to the balls, if nothing moves (or nothing happens within 1e7 s, the
  /// horizon of the search for motion that never ends), or if it comes after t_end.
  Event<S> step(S t_end = infinity<S>());

  /// Every ball at time().
  std::vector<Ball<S>> snapshot() const { return engine_->snapshot(state_); }
  /// When the search next has something to do (+inf if never): advancing to just before it
  /// changes no ball; advancing to it may change some (each once, at that time).
  S nextCheck() const { return next_; }

  // Edits, each at time(). What an edit refuses it leaves unchanged (std::invalid_argument).
  /// Empty if the strike may be applied to the ball with this id, else why not.
  std::string whyNotStrikable(int ball_id, const CueStrike<S>& strike) const;
  void strike(int ball_id, const CueStrike<S>& strike);
  /// Empty if the ball may be placed: in play on the cloth and overlapping no other ball (the
  /// ball with its id, if any, is the one it replaces), or pocketed; finite.
  std::string whyNotPlaceable(const Ball<S>& ball) const;
  /// Adds the ball, or replaces the ball with its id, as it is now (its time is set to time()
  /// and its motion state follows from its velocity and spin).
  void place(Ball<S> ball);
  /// Takes the ball with this id off the table; the last ball of state().balls takes its place
  /// in that list.
  void remove(int ball_id);
  /// Runs on another engine from now on (new coefficients or models): every candidate is found
  /// again. The state must be valid on it.
  void setEngine(std::shared_ptr<const Engine<S>> engine);
  /// Starts again from another state (valid on the engine).
  void reset(TableState<S> state);

  /// The state, leaving the simulation empty (to be destroyed or reset).
  TableState<S> release() &&;

private:
  void advanceThrough(S t_end, std::vector<Event<S>>* events);
  /// After an edit: a new shot for the event limit, and the next event and motion found again.
  void edited();
  /// After a placement or a removal: every ball held in the air falls, to be held again if its
  /// supports still hold it (Engine::letAllHeldBallsFall).
  void letHeldBallsFall();
  void refresh();

  std::shared_ptr<const Engine<S>> engine_;
  TableState<S> state_;
  std::unique_ptr<EventSearch<S>> search_;
  /// When the search next has something to do (+inf if never): advance() stops short of it
  /// without a call.
  S next_;
  bool moving_ = false;
  long events_in_shot_ = 0;  ///< since the last edit, for EngineLimits::max_events
};

/// Event searches started on the calling thread so far: one each time a Simulation is made,
/// copied, reset or moved to another engine, so one for every advance or simulateToRest. What a
/// caller counts to know how often a shot was simulated (a prediction's tests do).
long searchesStartedOnThisThread();

/// A Simulation of `state` on `engine` for one call: processes every event with time <= t_end
/// (appending them to `events` if given) and sets state.time = t_end. Throws EventLimitError
/// after limits().max_events events, leaving the state at its last event. To advance the same
/// table again and again, keep a Simulation instead: it keeps its event search.
template <typename S>
void advance(const Engine<S>& engine, TableState<S>& state, S t_end, std::vector<Event<S>>* events = nullptr);

/// A Simulation of `state` on `engine` for one call: advances until no ball moves (or for
/// max_shot_time after state.time).
template <typename S>
ShotResult<S> simulateToRest(const Engine<S>& engine, TableState<S>& state);

}  // namespace physics
}  // namespace cue_sim
