// The exact event-based simulator (Leckie and Greenspan 2005) as an immutable model: the table,
// the coefficients, the collision models and the limits. Between events every ball follows its
// closed-form trajectory; the next event is the earliest root of the transition, ball-ball,
// ball-cushion and pocket polynomials; the simulation jumps to it and resolves it.
//
// An Engine is the model only (as MuJoCo's mjModel): it holds no simulation state and runs
// nothing, so one engine serves any number of table states, from any number of threads. What
// it answers is closed form: a ball at a time, whether a state or a strike is valid, a strike
// applied. A Simulation (simulation.hpp) runs a state on it, keeping the event search alive
// between calls; simulateToRest and advance there run one for a call's length, and scan.hpp
// finds events afresh, the reference the kept search is checked against.
#pragma once

#include <memory>
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
/// The table's geometry in the engine's scalar type, with the boxes the event search culls by:
/// internal to the physics core (src/physics/engine/table_geometry.hpp), which reads it through
/// Engine::geometry().
template <typename S>
struct TableGeometry;

struct EngineLimits
{
  /// Events a shot may have before the simulation gives up: from one edit of a Simulation (a
  /// strike, a placement) to the next, or in one call of advance or simulateToRest. A
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
  const BallTableModel<S>& ballTableModel() const { return *ball_table_; }
  const CueModel<S>& cueModel() const { return *cue_; }
  /// The model for a pair with a ball in the air: the chosen one, unless it needs the cloth under
  /// both balls (BallBallModel::needsCloth), then the default ball-ball model.
  const BallBallModel<S>& ballBallModelInAir() const { return ball_ball_in_air_ ? *ball_ball_in_air_ : *ball_ball_; }

  /// A ball of the state at time t (>= the state's last event): pure, closed form.
  Ball<S> ballAt(const TableState<S>& state, std::size_t index, S t) const;
  /// Every ball at state.time.
  std::vector<Ball<S>> snapshot(const TableState<S>& state) const;
  /// The balls' mechanical energy at time t [J]: kinetic, and the height's potential of a ball in the
  /// air (mechanicalEnergy). A ball in sustained contact (Supported, Bearing) counts as at the start of
  /// its current piece, the state the contact equations gave it: between steps it follows an
  /// interpolant true to the contact tolerance, not to the energy. The energy never grows.
  S energyAt(const TableState<S>& state, S t) const;

  /// Empty if the strike may be applied to the ball with this id in this state, else why not.
  std::string whyNotStrikable(const TableState<S>& state, int ball_id, const CueStrike<S>& strike) const;
  /// Applies a strike at state.time (check whyNotStrikable first; throws std::invalid_argument):
  /// the cue model's impulse, then the slate's answer to any downward part (the ball may leave
  /// the cloth). A struck ball that bore one in the air (Motion::Bearing) lets every group in
  /// sustained contact go.
  void strike(TableState<S>& state, int ball_id, const CueStrike<S>& strike) const;
  /// Lets fall the balls held in the air (Motion::Held) on state.balls[index], and any held on
  /// them in turn, at state.time. They are held again, a few events later, if their supports
  /// still hold them. Returns their indices. strike calls it for the struck ball.
  std::vector<int> letHeldBallsFallOff(TableState<S>& state, int index) const;
  /// Lets every held ball fall at state.time, and every ball in sustained contact go back to its
  /// own closed-form motion (after an edit that may have moved or taken away their supports, or new
  /// parameters). Returns their indices.
  std::vector<int> letAllHeldBallsFall(TableState<S>& state) const;

  /// Empty if the state is valid on this table: finite numbers, unique ids, balls in play on
  /// the cloth, clear of cushions and pockets, and no two overlapping (tolerance in metres).
  std::string whyInvalid(const TableState<S>& state, double tolerance = 1e-9) const;
  /// Empty if the ball may join the state (ids and overlaps with the state's other balls at
  /// state.time included), else why not.
  std::string whyNotPlaceable(const TableState<S>& state, const Ball<S>& ball, double tolerance = 1e-9) const;

  /// The table's geometry as the event search and the contacts read it: an internal type, whose
  /// definition only the physics core sees (the core's own interface, not part of the API).
  const TableGeometry<S>& geometry() const { return *geometry_; }

private:
  std::shared_ptr<const TableModel> table_;
  PhysicsParams<S> params_;
  ModelChoice model_choice_;
  EngineLimits limits_;
  std::unique_ptr<BallBallModel<S>> ball_ball_;
  std::unique_ptr<CushionModel<S>> cushion_;
  std::unique_ptr<BallTableModel<S>> ball_table_;
  std::unique_ptr<CueModel<S>> cue_;
  std::unique_ptr<BallBallModel<S>> ball_ball_in_air_;  ///< null when ball_ball_ serves
  std::shared_ptr<const TableGeometry<S>> geometry_;
};

}  // namespace physics
}  // namespace cue_sim
