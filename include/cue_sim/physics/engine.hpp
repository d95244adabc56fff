// The exact event-based simulator (Leckie and Greenspan 2005): between events every ball
// follows its closed-form trajectory; the next event is the earliest root of the transition,
// ball-ball, ball-cushion and pocket polynomials; the engine jumps to it and resolves it.
//
// An Engine is immutable after construction and holds no simulation state, so one engine can
// run any number of TableStates, from any number of threads.
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
struct EngineLimits
{
  /// Events one call may process before it gives up (a real 8-ball break has a few hundred;
  /// FastFiz stops at 5000).
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
};

/// Thrown when a call reaches EngineLimits::max_events; the state is left at the last event.
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
  Engine(std::shared_ptr<const TableModel> table, const PhysicsParams<S>& params, const ModelChoice& models = {},
         const EngineLimits& limits = {});

  const TableModel& table() const { return *table_; }
  const PhysicsParams<S>& params() const { return params_; }
  const ModelChoice& models() const { return model_choice_; }
  const EngineLimits& limits() const { return limits_; }

  /// Processes every event with time <= t_end (appending them to `events` if given) and sets
  /// state.time = t_end. Throws EventLimitError after limits().max_events events.
  void advance(TableState<S>& state, S t_end, std::vector<Event<S>>* events = nullptr) const;

  /// Processes exactly the next event (advancing state.time to it) and returns it; an invalid
  /// event, and no change, if nothing moves.
  Event<S> step(TableState<S>& state) const;

  /// Advances until no ball moves (or max_shot_time after state.time).
  ShotResult<S> simulateToRest(TableState<S>& state) const;

  /// The earliest event after state.event_time, or an invalid event if nothing moves.
  Event<S> nextEvent(const TableState<S>& state) const;

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

private:
  struct Obstacles;
  /// Event finding (engine_events.cpp): a candidate event of one ball or pair, and what the
  /// search knows of each ball (path, own next event, box), computed once per change of the ball.
  struct Candidate;
  struct Paths;
  /// The ball's path, its own next event, and its box until `window` (absolute).
  void computePath(const Ball<S>& ball, std::size_t index, Paths& paths, S window) const;
  void restingPath(const Ball<S>& ball, std::size_t index, Paths& paths) const;
  /// The box the ball's centre stays in from `from` until `window` (absolute times).
  void drawBox(const Ball<S>& ball, std::size_t index, Paths& paths, S from, S window) const;
  void computeOwnEvent(const Ball<S>& ball, std::size_t index, Paths& paths) const;
  /// A pair's contact is found in two steps, so that a pair whose balls change before they
  /// could meet need not be solved: whether they may meet before either's box window ends, and
  /// their relative motion if so; then the contact itself (false if not before either ball's
  /// next event).
  struct PairMotion;
  static PairMotion pairMotion(const Paths& paths, int i, int j);
  bool pairMayMeet(int a, int b, const Paths& paths, Candidate& pair, PairMotion& motion) const;
  bool solvePair(const PairMotion& motion, Candidate& pair) const;
  /// Both steps at once.
  bool pairCandidate(int a, int b, const Paths& paths, Candidate& out) const;
  Event<S> eventOf(const TableState<S>& state, const Candidate& candidate) const;

  /// Finds the balls that may be within a distance of a point at the current event: all of
  /// them by default; in advance(), those whose path boxes reach the point.
  class Neighbours
  {
  public:
    virtual ~Neighbours() = default;
    /// Indices, ascending, of every ball in play that may be within `distance` of `point`.
    virtual void near(const Vec2<S>& point, S distance, std::vector<int>& out) const = 0;
  };
  /// What an event needs beyond the state: where the balls it names are, who changed, who is near.
  struct EventContext
  {
    int index = -1;                       ///< of event.ball in state.balls
    int other_index = -1;                 ///< of event.other, for a ball-ball event
    std::vector<int>* changed = nullptr;  ///< receives the indices of the balls it changed
    const Neighbours* neighbours = nullptr;
    std::vector<int>* scratch = nullptr;  ///< reused for neighbour lists, if given
  };
  /// Resolves the event.
  void processEvent(TableState<S>& state, const Event<S>& event, const EventContext& context) const;
  /// The balls in play that may be within `distance` of `point`, ascending.
  void nearBalls(const TableState<S>& state, const EventContext& context, const Vec2<S>& point, S distance,
                 std::vector<int>& out) const;
  void pocketBall(TableState<S>& state, Ball<S>& ball, int pocket) const;
  bool inSustainedContact(const Ball<S>& a, const Ball<S>& b) const;
  /// True if the ball cannot be within `distance` of `point` (xy) at `time`: a cheap bound.
  bool cannotReach(const Ball<S>& ball, const Vec3<S>& point, S distance, S time) const;
  /// Gives the pair, and every ball pressed against them in sustained contact, the mean of
  /// their velocities and spins (EngineLimits::sustained_contact_speed).
  void joinPressedCluster(TableState<S>& state, S time, int first, int second, const EventContext& context) const;
  /// A sliding ball left on a wall with (almost) no normal speed while its slip drives it back
  /// in stays on the wall: the normal speed is removed and the slip's part into the wall is
  /// turned into spin by the cloth friction the wall balances.
  void holdAgainstWall(Ball<S>& ball, const Vec3<S>& normal) const;
  /// Unit normals (into play) of the cushions and jaws the ball touches.
  std::vector<Vec3<S>> touchingWalls(const Ball<S>& ball) const;
  /// Resolves a ball-ball impact together with every ball touching the pair, and the cushions
  /// those balls touch: one impact. Returns whether the pair's velocities changed.
  bool resolveImpactGroup(TableState<S>& state, S time, int first, int second, const EventContext& context) const;

  std::shared_ptr<const TableModel> table_;
  PhysicsParams<S> params_;
  ModelChoice model_choice_;
  EngineLimits limits_;
  std::unique_ptr<BallBallModel<S>> ball_ball_;
  std::unique_ptr<CushionModel<S>> cushion_;
  std::shared_ptr<const Obstacles> obstacles_;  ///< the table's geometry in scalar type S
};

}  // namespace physics
}  // namespace cue_sim
