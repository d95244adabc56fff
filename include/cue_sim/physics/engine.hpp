// The exact event-based simulator (Leckie and Greenspan 2005) as an immutable model: the table,
// the coefficients, the collision models and the limits. Between events every ball follows its
// closed-form trajectory; the next event is the earliest root of the transition, ball-ball,
// ball-cushion and pocket polynomials; the simulation jumps to it and resolves it.
//
// An Engine holds no simulation state, so one engine can run any number of table states, from
// any number of threads. A Simulation (simulation.hpp) keeps a state and its event search alive
// between calls; the calls here that advance a state run one for the call's length.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/event.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace physics
{
/// The table's geometry in the engine's scalar type, as the event search reads it, and the
/// parts of the core that read it (internal: src/physics/).
template <typename S>
struct TableGeometry;
template <typename S>
class CandidateFinder;
template <typename S>
class EventResolver;
template <typename S>
class EventSearch;

struct EngineLimits
{
  /// Events a shot may have before the simulation gives up: from one edit of a Simulation (a
  /// strike, a placement) to the next, or in one call of Engine::advance or simulateToRest. A
  /// real 8-ball break has a few hundred; FastFiz stops at 5000.
  long max_events = 20000;
  /// Longest shot [s] simulateToRest() runs (a table without rolling resistance never stops).
  double max_shot_time = 600.0;
  /// Two balls that meet closing slower than this [m/s] while their decelerations press them
  /// together are in sustained contact, which an impulse model cannot resolve (it answers with
  /// endless micro-bounces, inelastic collapse). They are joined instead, with every ball the
  /// join leaves closing on them slower than this: all take the mean of their velocities and
  /// spins. That conserves momentum, cannot add energy, and gives all the same acceleration,
  /// so they neither part nor overlap until something hits them. Likewise a sliding ball that
  /// a cushion or jaw leaves with a normal speed below this while its slip drives it back in
  /// is held on the wall: the normal speed goes, and the slip into the wall becomes spin.
  double sustained_contact_speed = 1e-4;
  /// Events at one instant before the touching balls there are taken to have collapsed: balls
  /// wedged between others and the cushions can take impact after impact at the same instant,
  /// or each a few ulps of time after the last, each changing them by rounding (an inelastic
  /// collapse: McNamara and Young 1994). Events within about a picosecond of one another count
  /// as one instant. Beyond
  /// this many, a ball-ball or wall event joins every ball touching its balls into one body (the
  /// mean of their velocities and spins, held by the walls they touch); beyond twice as many,
  /// that body stops. Both keep momentum but what the walls take and cannot add energy. A break
  /// has at most a few dozen events at one instant.
  long collapse_events = 256;
};

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

template <typename S>
class Engine
{
public:
  /// Throws std::invalid_argument for a coefficient out of its range or an unknown model.
  Engine(std::shared_ptr<const TableModel> table, const PhysicsParams<S>& params, const ModelChoice& models = {},
         const EngineLimits& limits = {});
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
  ~Engine();

  const TableModel& table() const { return *table_; }
  /// The table, to share with another engine on it.
  const std::shared_ptr<const TableModel>& tableShared() const { return table_; }
  const PhysicsParams<S>& params() const { return params_; }
  const ModelChoice& models() const { return model_choice_; }
  const EngineLimits& limits() const { return limits_; }
  const BallBallModel<S>& ballBallModel() const { return *ball_ball_; }
  const CushionModel<S>& cushionModel() const { return *cushion_; }

  /// Processes every event with time <= t_end (appending them to `events` if given) and sets
  /// state.time = t_end. Throws EventLimitError after limits().max_events events. To advance
  /// the same table again and again, keep a Simulation instead: it keeps its event search.
  void advance(TableState<S>& state, S t_end, std::vector<Event<S>>* events = nullptr) const;

  /// Advances until no ball moves (or max_shot_time after state.time).
  ShotResult<S> simulateToRest(TableState<S>& state) const;

  /// The earliest event after state.event_time, or an invalid event if nothing moves: every ball
  /// and pair looked at afresh (the reference the kept search of a Simulation is checked against).
  Event<S> nextEvent(const TableState<S>& state) const;
  /// Processes exactly that event (advancing state.time to it) and returns it; an invalid
  /// event, and no change, if nothing moves.
  Event<S> step(TableState<S>& state) const;

  /// A ball of the state at time t (>= the state's last event): pure, closed form.
  Ball<S> ballAt(const TableState<S>& state, std::size_t index, S t) const;
  /// Every ball at state.time.
  std::vector<Ball<S>> snapshot(const TableState<S>& state) const;

  /// Empty if the strike may be applied to the ball with this id in this state, else why not.
  std::string whyNotStrikable(const TableState<S>& state, int ball_id, const CueStrike<S>& strike) const;
  /// Applies a strike at state.time (check whyNotStrikable first; throws std::invalid_argument).
  void strike(TableState<S>& state, int ball_id, const CueStrike<S>& strike) const;

  /// Empty if the state is valid on this table: finite numbers, unique ids, balls in play on
  /// the cloth, clear of cushions and pockets, and no two overlapping (tolerance in metres).
  std::string whyInvalid(const TableState<S>& state, double tolerance = 1e-9) const;
  /// Empty if the ball may join the state (ids and overlaps with the state's other balls at
  /// state.time included), else why not.
  std::string whyNotPlaceable(const TableState<S>& state, const Ball<S>& ball, double tolerance = 1e-9) const;

private:
  friend class CandidateFinder<S>;
  friend class EventResolver<S>;
  friend class EventSearch<S>;
  const TableGeometry<S>& geometry() const { return *geometry_; }

  std::shared_ptr<const TableModel> table_;
  PhysicsParams<S> params_;
  ModelChoice model_choice_;
  EngineLimits limits_;
  std::unique_ptr<BallBallModel<S>> ball_ball_;
  std::unique_ptr<CushionModel<S>> cushion_;
  std::shared_ptr<const TableGeometry<S>> geometry_;
};

}  // namespace physics
}  // namespace cue_sim
