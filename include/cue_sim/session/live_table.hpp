// The live table: what table_node does with the table, without ROS. It keeps the balls and
// their event search between calls (a physics::Simulation), maps the caller's clock to physics
// time (real-time factor, pause, step), takes strikes, racks and edits, and says why it refuses
// one, field by field, changing nothing then. Not thread-safe: the node calls it under one
// lock, and runs heavy predictions outside it on a copy (predictionStart, then predictShot).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/cue_aim.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/execution_noise.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/session/ball_input.hpp"
#include "cue_sim/session/ball_orientations.hpp"
#include "cue_sim/session/physics_clock.hpp"
#include "cue_sim/session/shot_prediction.hpp"

namespace cue_sim
{
namespace session
{
struct LiveTableOptions
{
  bool allow_strike_while_moving = false;
  double rack_gap = 1e-5;         ///< [m] between neighbouring balls of a standard rack, in [0, 0.01)
  double real_time_factor = 1.0;  ///< physics time per stamp time, in (0, 1000]
  bool paused = false;
  physics::ExecutionNoise noise;  ///< the deviations of ~strike's noise, and of predictions that ask for it
  bool noise_enabled = false;     ///< noise on strikes
  std::uint64_t noise_seed = 0;
  PredictionLimits limits;
  /// Carry each ball's orientation along its motion (orientations()); off, they stay identity
  /// and the table advances in one call a tick (bench: LiveTableBreakTicks measures the cost).
  bool orientations = true;

  /// Empty if every option is in its range, else which one is not and why.
  std::string whyInvalid() const;
};

/// Largest accepted LiveTableOptions::real_time_factor.
constexpr double kMaxRealTimeFactor = 1000.0;
/// Longest ~step [s].
constexpr double kMaxStep = 60.0;

struct Outcome
{
  bool success = false;
  std::string message;  ///< why not, when success is false

  static Outcome done(const std::string& message) { return {true, message}; }
  static Outcome refused(const std::string& why) { return {false, why}; }
};

struct StrikeOutcome : Outcome
{
  Shot executed;  ///< the shot plus execution noise, if enabled
  Stamp stamp = 0;
  double time_to_rest = 0;
  std::size_t num_events = 0;
  physics::Vec3<double> ball_velocity = physics::Vec3<double>::Zero();  ///< right after the strike
  physics::Vec3<double> ball_angular_velocity = physics::Vec3<double>::Zero();
  physics::CueStick cue;  ///< the cue as it struck, its tip 5 mm short of the ball (to draw it)
  bool refereed = false;  ///< a game is on: `ruling` is the referee's on this shot
  game::Ruling ruling;    ///< read off the shot's events at the strike; it takes effect when the balls rest
};

/// A game to start on the live table.
struct GameRequest
{
  std::string rules;  ///< game::rulesNames()
  std::array<std::string, 2> players{"player 1", "player 2"};
  int breaker = 0;         ///< who shoots first: 0 or 1
  std::uint32_t seed = 0;  ///< of the rack's jitter (game::gameRack)
  std::vector<BallInput>
      balls;  ///< empty: rack and break; else the position to play on from, at rest, the break played
};

/// What the shooter declares before a game shot.
struct GameCall
{
  int ball = -1;          ///< the object ball called, -1 for none
  std::string pocket;     ///< the pocket called, by name (TableModel::pockets()), empty for none
  bool push_out = false;  ///< 9-ball: the shot is a push-out (only the shot after a legal break)
};

struct RackRequest
{
  std::string layout;                      ///< "eight", "nine", "empty" or "custom"
  std::vector<int> ids;                    ///< custom: one per ball
  std::vector<Eigen::Vector2d> positions;  ///< custom: [m] in the table frame
  double jitter = 0;       ///< [m] standard layouts: each ball but the apex moved by up to this, in [0, rack_gap / 2]
  std::uint32_t seed = 0;  ///< of the jitter
};

/// An event of the live table with the stamp it happened at.
struct StampedEvent
{
  physics::Event<double> event;
  Stamp stamp = 0;
};

/// A prediction's starting point: the engine it runs on and the table it starts from.
struct PredictionStart
{
  std::shared_ptr<const physics::Engine<double>> engine;
  physics::TableState<double> table;
  std::optional<game::GamePlay> game;  ///< the game on the live table, when the prediction starts from it
  bool push_out = false;               ///< the next game shot is declared a push-out
};

/// How the referee would rule on `prediction`, a shot from `start`: true and the ruling if
/// `start` has a game the shot may be played in (the cue ball struck, the game not over).
bool predictedRuling(const PredictionStart& start, const ShotPrediction& prediction, game::Ruling& ruling);

class LiveTable
{
public:
  /// Racks `rack` at `now`. Throws std::invalid_argument saying which option or why the rack
  /// does not fit.
  LiveTable(std::shared_ptr<const physics::Engine<double>> engine, const LiveTableOptions& options,
            const std::string& rack, Stamp now);

  const physics::Engine<double>& engine() const { return *engine_; }
  const physics::TableModel& table() const { return engine_->table(); }
  const LiveTableOptions& options() const { return options_; }

  // Time.
  /// Brings the table up to `now`, appending what happened to `events`. A stamp before the last
  /// one changes nothing.
  void advanceTo(Stamp now, std::vector<StampedEvent>* events = nullptr);
  /// Every ball as of the last advanceTo.
  const std::vector<physics::Ball<double>>& balls() const { return balls_; }
  /// How each ball of balls() is turned (its own frame to the table frame), carried along its
  /// exact motion from when it was placed (physics::rotationAlong).
  const std::vector<Eigen::Quaterniond>& orientations() const { return orientations_now_; }
  bool atRest() const { return live_.atRest(); }
  /// The physics time [s] a stamp maps to (pauses, steps and real-time factors included).
  double physicsTime(Stamp stamp) const { return clock_.at(stamp); }
  /// The stamp of the last advanceTo.
  Stamp lastStamp() const { return last_stamp_; }
  bool paused() const { return paused_; }
  /// Changes when the balls are placed anew (rack, reset, state edits) or the physics changes:
  /// what is drawn of the table may have to be drawn again.
  long layoutVersion() const { return layout_version_; }
  /// Counts the strikes that reached the table: a shot drawn in advance (a preview) is stale once
  /// this or layoutVersion() changes.
  long strikeCount() const { return strike_count_; }

  Outcome pause(bool paused, Stamp now);
  /// Moves a paused table's physics `duration` [s] on at `now`.
  Outcome step(double duration, Stamp now);
  Outcome setRealTimeFactor(double factor, Stamp now);
  /// New coefficients and models; they take effect when the balls rest (a shot in flight ends
  /// with the physics it started with, as its prediction said).
  Outcome setPhysics(const physics::PhysicsParams<double>& params, const physics::ModelChoice& models, Stamp now);

  // Shots.
  StrikeOutcome strike(const Shot& shot, Stamp now);
  /// Strikes the ball a cue in the table frame meets, as it meets it; `aimed` is the shot.
  StrikeOutcome strikeWithCue(const physics::CueStick& cue, double speed, Stamp now, Shot& aimed);
  /// The table a prediction starts from: `balls`, or if empty the live table, which must rest.
  /// Every ball is referred to time 0, as the live table is at a strike from rest.
  std::string predictionStart(const std::vector<BallInput>& balls, Stamp now, PredictionStart& start);
  /// Execution noise for predictions that ask for it.
  const physics::ExecutionNoise& noise() const { return options_.noise; }

  // What is on the table.
  Outcome rack(const RackRequest& request, Stamp now);
  /// Back to the last rack.
  Outcome reset(Stamp now);
  /// Replaces every ball on the table by `balls`.
  Outcome setState(const std::vector<BallInput>& balls, Stamp now);
  /// Places one ball (adding it, or moving the ball with its id), leaving the others.
  Outcome placeBall(const BallInput& ball, Stamp now);
  Outcome removeBall(int id, Stamp now);

  // Games. While a game is on, strikes are refereed: only the cue ball, from rest; the ruling
  // is read off the shot's events at the strike and applied when the balls rest (balls
  // spotted, a new rack, the cue ball in hand). The table is edited only through the game
  // (~rack, ~reset, ~set_state, ~place_ball and ~remove_ball are refused until endGame).
  Outcome startGame(const GameRequest& request, Stamp now);
  /// Back to free play; the balls stay where they are (a shot in play rolls on, unrefereed).
  Outcome endGame(Stamp now);
  /// Moves the cue ball in hand to p, at rest.
  Outcome placeCueBall(const Eigen::Vector2d& p, Stamp now);
  /// Declares the next shot's call; it holds until that shot.
  Outcome callShot(const GameCall& call, Stamp now);
  /// The game on the table, or null in free play.
  const game::GamePlay* game() const { return game_ ? &*game_ : nullptr; }
  /// A game shot was struck and its balls are still moving: its ruling is `pendingTurn()`'s.
  const std::optional<game::Turn>& pendingTurn() const { return pending_turn_; }
  /// The last game shot whose balls came to rest.
  const std::optional<game::Turn>& lastTurn() const { return last_turn_; }
  /// Whether the next game shot is declared a push-out.
  bool pushOutCalled() const { return push_out_called_; }
  /// Changes whenever the game's state does (a start, a call, a cue ball placed, a strike, a
  /// shot come to rest, the end): what is published of it may have to go out again.
  long gameVersion() const { return game_version_; }

private:
  /// Empty if the live table may be edited outside a game, else why not.
  std::string whyNotFreeEdit() const;
  /// Why a game shot cannot be struck (empty if it can).
  std::string whyNotGameShot(const Shot& shot) const;
  /// A game shot's balls have come to rest: take the turn and put the game's table on the live
  /// table.
  void finishGameShot(Stamp now);
  std::string whyNotRack(const RackRequest& request, physics::TableState<double>& rack) const;
  void startFrom(physics::TableState<double> state, Stamp now);
  void restartAtRest(Stamp now);
  void applyPendingPhysics();
  /// live_.advance(time, &happened), turning the balls on the way.
  void advanceTurning(double time, std::vector<physics::Event<double>>& happened);

  std::shared_ptr<const physics::Engine<double>> engine_;
  std::shared_ptr<const physics::Engine<double>> pending_engine_;  ///< waiting for the balls to rest
  LiveTableOptions options_;
  physics::Simulation<double> live_;
  PhysicsClock clock_;
  physics::NoisyCue cue_;
  physics::TableState<double> last_rack_;
  std::vector<physics::Ball<double>> balls_;
  BallOrientations orientations_;
  std::vector<Eigen::Quaterniond> orientations_now_;  ///< of balls_
  bool balls_at_rest_ = false;                        ///< balls_ are at rest and nothing has moved since
  bool paused_ = false;
  Stamp last_stamp_ = 0;
  long layout_version_ = 0;
  long strike_count_ = 0;
  std::optional<game::GamePlay> game_;
  std::optional<game::Turn> pending_turn_, last_turn_;
  bool push_out_called_ = false;
  long game_version_ = 0;
};

}  // namespace session
}  // namespace cue_sim
