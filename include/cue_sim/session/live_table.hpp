// The live table: what table_node does with the table, without ROS. A thin composition of the
// parts that each own one thing: the clock (TableClock: stamps to physics time, pause, steps, the
// real-time factor), the balls in motion (LiveBalls: the simulation and its event search kept
// between calls, orientations, physics swaps), the edits (TableEdits: racks, a whole table, one
// ball), the game (LiveGame) and the cue's execution noise. It takes strikes, racks and edits, and
// says why it refuses one, field by field, changing nothing then. Not thread-safe: the node calls
// it under one lock, and runs heavy predictions outside it on a copy (predictionStart, then
// predictShot).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/physics/cue_aim.hpp"
#include "cue_sim/physics/execution_noise.hpp"
#include "cue_sim/session/live_balls.hpp"
#include "cue_sim/session/live_game.hpp"
#include "cue_sim/session/outcome.hpp"
#include "cue_sim/session/shot_prediction.hpp"
#include "cue_sim/session/table_clock.hpp"
#include "cue_sim/session/table_edits.hpp"

namespace cue_sim
{
namespace session
{
struct LiveTableOptions
{
  bool allow_strike_while_moving = false;
  double rack_gap = 1e-5;  ///< [m] between neighbouring balls of a standard rack, in [0, 0.01)
  /// [m] The rack the table starts with (and ~reset returns to, until the next ~rack) has each
  /// ball but the apex moved by up to this, in [0, rack_gap / 2], seeded by rack_seed: a real
  /// rack's uneven gaps, the same on every run. 0: the perfect triangle.
  double rack_jitter = 0;
  std::uint32_t rack_seed = 0;
  double real_time_factor = 1.0;  ///< physics time per stamp time, in (0, 1000]
  bool paused = false;
  physics::ExecutionNoise noise;  ///< the deviations of ~strike's noise, and of predictions that ask for it
  bool noise_enabled = false;     ///< noise on strikes
  std::uint64_t noise_seed = 0;
  PredictionLimits limits;
  /// Carry each ball's orientation along its motion (LiveBalls::orientations()); off, they stay
  /// identity and the table advances in one call a tick (bench: LiveTableBreakTicks measures the cost).
  bool orientations = true;

  /// Empty if every option is in its range, else which one is not and why.
  std::string whyInvalid() const;
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

  const physics::Engine<double>& engine() const { return balls_.engine(); }
  const physics::TableModel& table() const { return engine().table(); }
  const LiveTableOptions& options() const { return options_; }
  /// The parts, to read: the clock, the balls in motion (as of the last advanceTo), the game.
  const TableClock& clock() const { return clock_; }
  const LiveBalls& motion() const { return balls_; }
  const LiveGame& game() const { return game_; }

  // Time.
  /// Brings the table up to `now`, appending what happened to `events`. A stamp before the last
  /// one changes nothing.
  void advanceTo(Stamp now, std::vector<StampedEvent>* events = nullptr);
  /// The stamp of the table's last change, as of the last advanceTo: a ball placed, removed or
  /// struck, a rack, a game's turn, new physics taking effect, or a ball's last event (the last
  /// ball coming to rest). A strike stamped before it is refused: the balls were not as they are.
  Stamp lastChange() const { return last_change_; }
  /// The balls as they stand at `stamp` (at the last advance, if it is before), found on a copy:
  /// the table is unchanged. A cue sampled between two advances meets the balls where they are then.
  std::vector<physics::Ball<double>> ballsAt(Stamp stamp) const;
  Outcome pause(bool paused, Stamp now);
  /// Moves a paused table's physics `duration` [s] on at `now`.
  Outcome step(double duration, Stamp now);
  Outcome setRealTimeFactor(double factor, Stamp now);
  /// New coefficients and models; they take effect when the balls rest (a shot in flight ends
  /// with the physics it started with, as its prediction said).
  Outcome setPhysics(const physics::PhysicsParams<double>& params, const physics::ModelChoice& models, Stamp now);

  // Shots.
  /// A strike at `now`. `now` may be before the table's latest stamp (a robot's cue touched the
  /// ball a tf sample ago): if the balls rest and have not changed since `now` (lastChange()), the
  /// shot starts at `now`, physics time 0 there, as it would have had it come then; else refused.
  StrikeOutcome strike(const Shot& shot, Stamp now);
  /// Strikes the ball a cue in the table frame meets, as it meets it; `aimed` is the shot. `now` as
  /// for strike().
  StrikeOutcome strikeWithCue(const physics::CueStick& cue, double speed, Stamp now, Shot& aimed);
  /// The table a prediction starts from: `balls`, or if empty the live table, which must rest.
  /// Every ball is referred to time 0, as the live table is at a strike from rest.
  std::string predictionStart(const std::vector<BallInput>& balls, Stamp now, PredictionStart& start);

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

private:
  /// Every ball replaced by `state` at `now`, physics time 0 there.
  void startFrom(physics::TableState<double> state, Stamp now);
  /// A table at rest restarts at physics time 0 at `now`.
  void restartAtRest(Stamp now);
  /// Notes a change of the balls at `stamp` (lastChange()).
  void changed(Stamp stamp) { last_change_ = std::max(last_change_, stamp); }
  /// Empty if a strike may be stamped `now`, else why not (a stamp before the latest).
  std::string whyNotStrikeAt(Stamp now) const;

  LiveTableOptions options_;
  TableClock clock_;
  LiveBalls balls_;
  TableEdits edits_;
  LiveGame game_;
  physics::NoisyCue cue_;
  Stamp last_change_ = 0;
};

}  // namespace session
}  // namespace cue_sim
