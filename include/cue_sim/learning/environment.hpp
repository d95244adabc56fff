// Learning environments on the exact table: a task (pot, break, a whole game) played one shot a
// step, with the observation a learner sees (the balls as numbers, the overhead camera's pixels,
// or both), the action in the cue's physical units, and the reward, as Gymnasium's API has them.
// No ROS and no Python: the Python module (cue_sim.envs) and the vector environment
// (vector_environment.hpp) are adapters over this. doc/learning.md describes each task.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/learning/random.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/execution_noise.hpp"

namespace cue_sim
{
namespace learning
{
/// How an environment is made: the options declared in env_options.def (each with its default,
/// range and meaning), and the execution noise's deviations. whyInvalid() checks every field and
/// names the one that is wrong, its value and its range.
struct EnvOptions
{
#define CUE_SIM_ENV_TEXT(name, default_value, choices, description) std::string name = default_value;
#define CUE_SIM_ENV_INTEGER(name, default_value, min, max, description) int name = default_value;
#define CUE_SIM_ENV_REAL(name, default_value, min, max, description) double name = default_value;
#define CUE_SIM_ENV_FLAG(name, default_value, description) bool name = default_value;
#include "cue_sim/learning/env_options.def"
#undef CUE_SIM_ENV_TEXT
#undef CUE_SIM_ENV_INTEGER
#undef CUE_SIM_ENV_REAL
#undef CUE_SIM_ENV_FLAG
  /// The deviations of the execution noise when `noise` is on: the tournaments' by default.
  physics::ExecutionNoise noise_model;
  /// Empty if usable, else which field is wrong and why.
  std::string whyInvalid() const;
};

/// One option as env_options.def declares it, with where it lives in EnvOptions: what adapters
/// (the Python module's keywords, its DEFAULT_OPTIONS) read and write options through.
struct EnvOptionField
{
  enum class Kind
  {
    kText,
    kInteger,
    kReal,
    kFlag
  };
  const char* name;
  Kind kind;
  const char* description;
  const char* choices = "";  ///< kText: the values it takes, space-separated ("" for task: taskNames())
  double min = 0, max = 0;   ///< kInteger, kReal: its range, both ends included
  std::string EnvOptions::*text = nullptr;
  int EnvOptions::*integer = nullptr;
  double EnvOptions::*real = nullptr;
  bool EnvOptions::*flag = nullptr;
};

/// Every option, in env_options.def's order.
const std::vector<EnvOptionField>& envOptionFields();

/// The names EnvOptions::task takes.
std::vector<std::string> taskNames();
/// Whether a task is a whole game under the referee (its action places the cue ball in hand, and
/// its info tells the players and the opponent's turns).
bool isGameTask(const std::string& task);

/// A box of reals, one name per component, as a learner's space needs it.
struct BoxSpec
{
  std::vector<std::string> names;
  std::vector<double> low, high;
  std::size_t size() const { return names.size(); }
};

/// What an environment takes and gives: its action and its observations' shapes.
struct Spaces
{
  BoxSpec action;
  BoxSpec state;                          ///< empty when the observation is pixels alone
  int pixel_width = 0, pixel_height = 0;  ///< 0 when the observation is the state alone
  std::size_t pixelBytes() const { return static_cast<std::size_t>(pixel_width) * pixel_height * 3; }
};

/// A game's start as an episode drew it: what a live table needs to rack the same game.
struct GameStart
{
  std::string rules;
  unsigned rack_seed = 0;  ///< game::gameRack's seed
  int breaker = 0;         ///< who breaks: 0 or 1
  int target = 0;          ///< the race, where the game keeps a score (0: the rules' own)
};

/// One turn of a game as it was played, by the agent or the opponent: what a live table must be
/// sent to play it too.
struct PlayedTurn
{
  int player = 0;
  int ball = 0;                              ///< the ball struck (the player's own cue ball)
  bool placed = false;                       ///< the cue ball was in hand and placed...
  double x = 0, y = 0;                       ///< ...with its centre here [m]
  int called_ball = -1, called_pocket = -1;  ///< the call made (-1: none)
  bool push_out = false;                     ///< 9-ball: declared
  physics::CueStrike<double> strike;         ///< as executed
};

/// What a step did besides its reward (Gymnasium's info).
struct StepInfo
{
  int shots = 0;                ///< shots played in this episode, this one included
  int pocketed = 0;             ///< object balls the shot pocketed
  bool scratch = false;         ///< the cue ball was pocketed
  int first_contact = -1;       ///< the first object ball the cue ball touched, -1 for none
  bool foul = false;            ///< the referee's ruling (tasks with a referee), or a scratch
  int events = 0;               ///< the shot's events
  double shot_time = 0;         ///< [s] from the strike to rest
  std::string reason;           ///< why the reward is what it is: the ruling, or the task's rule
  int player = 0;               ///< games: who shot (0 or 1)
  int next_player = 0;          ///< games: who is to play next
  int winner = -1;              ///< games: 0 or 1 once won, else -1
  int points = 0;               ///< games that keep a score (three-cushion): the shooter's points for the shot
  int penalty = 0;              ///< snooker: the points a foul on the shot gave the shooter's opponent
  int opponent_shots = 0;       ///< games against the planner: its turns within this step
  std::string opponent_reason;  ///< ... and the ruling on its last
  int open_shots = -1;          ///< position: open shots on the next ball after a pot (-1: not asked)
};

struct StepResult
{
  double reward = 0;
  bool terminated = false;  ///< the task's own end: success, failure, the game over
  bool truncated = false;   ///< stopped from outside: the shot cap, or the engine's event limit
  StepInfo info;
};

/// Where a step's observation goes: `state` holds Spaces::state.size() floats, `pixels`
/// Spaces::pixelBytes() bytes (height x width x RGB); either may be null when the observation
/// lacks it.
struct ObservationBuffers
{
  float* state = nullptr;
  std::uint8_t* pixels = nullptr;
};

class Task;
class PixelRenderer;
class ActionLayout;

/// One table and its task. Copyable: a copy plays on from the same point with the same random
/// stream (what a planner tries shots on).
class Environment
{
public:
  /// Throws std::invalid_argument naming the option that is wrong. The engine is shared.
  Environment(std::shared_ptr<const physics::Engine<double>> engine, const EnvOptions& options);
  ~Environment();
  Environment(const Environment& other);
  Environment& operator=(const Environment& other);
  Environment(Environment&&) noexcept;
  Environment& operator=(Environment&&) noexcept;

  const Spaces& spaces() const { return spaces_; }
  const EnvOptions& options() const { return options_; }

  /// A new episode. With a seed the random stream starts again from it; without one it goes on
  /// (Gymnasium's convention), so that episodes after the first differ.
  void reset(std::optional<std::uint64_t> seed, const ObservationBuffers& out);
  /// Plays `action` (spaces().action.size() values). Throws std::invalid_argument, changing
  /// nothing, for a wrong size, a NaN or a value outside the action's box, naming it; and
  /// std::logic_error if the episode is over (reset first).
  StepResult step(const double* action, std::size_t size, const ObservationBuffers& out);
  /// Empty if `action` (`size` values) is inside the action's box, else which component is not
  /// and why (what step() refuses with).
  std::string whyActionInvalid(const double* action, std::size_t size) const;
  /// Whether the episode has ended (terminated or truncated): step() needs a reset first.
  bool done() const { return done_; }
  /// The cue ball's strike the last step played, as executed (the action's, noise included):
  /// what a live table is sent.
  const physics::CueStrike<double>& lastStrike() const { return last_strike_; }
  /// Games: how the episode's game started, and the turns the last reset or step played (the
  /// opponent's too), in order; empty for the other tasks.
  std::optional<GameStart> gameStart() const;
  std::vector<PlayedTurn> lastTurns() const;

  /// The table now (the balls at rest between shots).
  const physics::TableState<double>& table() const;
  /// The balls as the last shot left them at rest: table(), but in a game or a break before the
  /// referee's table is made ready for the next shot (balls spotted, the cue ball returned).
  const physics::TableState<double>& restTable() const;
  const physics::Engine<double>& engine() const { return *engine_; }
  /// The table as the overhead camera sees it, RGB (height x width x 3), for render().
  std::vector<std::uint8_t> render(int width, int height) const;

private:
  void observe(const ObservationBuffers& out) const;

  std::shared_ptr<const physics::Engine<double>> engine_;
  EnvOptions options_;
  Spaces spaces_;
  std::shared_ptr<const ActionLayout> layout_;  ///< immutable: copies share it
  std::unique_ptr<Task> task_;
  Random random_;
  physics::NoisyCue cue_;  ///< the execution noise's own stream, seeded with the episode's seed
  int shots_ = 0;
  bool done_ = true;
  physics::CueStrike<double> last_strike_;
  /// The pixel observation's camera, made on first use; a copy makes its own (a camera keeps
  /// buffers, so two threads must not share one).
  mutable std::unique_ptr<PixelRenderer> pixels_;
};

}  // namespace learning
}  // namespace cue_sim
