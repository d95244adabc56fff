// A task: what an episode starts from, what a shot earns, and when the episode ends. Each task is
// one file in this folder, named in task_registry.cpp; Environment adds the action, the noise and
// the observation around it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/learning/environment.hpp"
#include "cue_sim/learning/random.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/table_state.hpp"
#include "learning/actions.hpp"
#include "learning/state_observation.hpp"

namespace cue_sim
{
namespace learning
{
class Task
{
public:
  virtual ~Task() = default;
  virtual std::unique_ptr<Task> clone() const = 0;

  /// A new episode's table, drawn from `random`.
  virtual void reset(Random& random) = 0;
  /// The table the next shot is played on.
  virtual const physics::TableState<double>& table() const = 0;
  /// The balls as the last shot left them at rest (a game then spots balls and returns a
  /// pocketed cue ball for the next shot, which table() shows); table() before any shot.
  virtual const physics::TableState<double>& restTable() const { return table(); }
  /// The object balls a relative action chooses among (ids, ascending).
  virtual std::vector<int> aimChoices() const = 0;
  /// With the cue ball in hand, places it at (u, v) of the region it may go in (fractions of
  /// the region's length and width; the nearest free place if that one is taken). Otherwise,
  /// and in tasks without ball in hand, nothing.
  virtual void placeCueBall(double /*u*/, double /*v*/) {}
  /// Plays the plan, its strike as executed (noise already on it; `random` draws whatever else
  /// the task needs, an opponent's noise say): the shot to rest, its reward, and whether the
  /// episode ended. The step's `shots` count is the environment's.
  virtual StepResult shoot(const ShotPlan& plan, Random& random) = 0;

  /// Games: how the episode's game started, and the turns the last reset or step played.
  virtual std::optional<GameStart> gameStart() const { return std::nullopt; }
  virtual std::vector<PlayedTurn> lastTurns() const { return {}; }

  /// The ball ids the observation has a slot for (state_observation.hpp): kBallSlots, or more
  /// where the task's balls need them (snooker's 22).
  virtual int ballSlots() const { return kBallSlots; }
  /// The task's own features after the ball block: their names and bounds (appended to `box`)...
  virtual void addFeatures(BoxSpec& box) const = 0;
  /// ...and their values now.
  virtual void writeFeatures(float* out) const = 0;
};

/// Throws std::invalid_argument unless `engine`'s table has pockets (every task pots balls).
void requirePockets(const physics::Engine<double>& engine, const std::string& task);

/// What a refereed turn did, in a step's info: events, the shot's time, balls pocketed, the first
/// contact, the foul and the ruling's reason.
void describeTurn(const game::Turn& turn, StepInfo& info);

/// The task `options.task` names on `engine` (throws std::invalid_argument for an unknown name or a
/// table it cannot be played on).
std::unique_ptr<Task> makeTask(const physics::Engine<double>& engine, const EnvOptions& options);

}  // namespace learning
}  // namespace cue_sim
