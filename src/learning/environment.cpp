#include "cue_sim/learning/environment.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "learning/actions.hpp"
#include "learning/pixel_renderer.hpp"
#include "learning/state_observation.hpp"
#include "learning/tasks/task.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
/// The largest pixel observation a step renders [px a side]: beyond it a picture costs more than
/// the shot, and a learner downsamples anyway.
constexpr int kMaxPixelSide = 1024;
/// What the execution noise's stream is seeded with, beside the episode's seed: a stream of its
/// own, so that the noise does not depend on how many draws the table's setup took.
constexpr std::uint64_t kNoiseStream = 0x9e3779b97f4a7c15ULL;
/// The longest run of shots an episode may be given: a whole game is capped at 150 shots.
constexpr int kMaxShotsCap = 1000;

bool oneOf(const std::string& value, std::initializer_list<const char*> names)
{
  return std::any_of(names.begin(), names.end(), [&](const char* name) { return value == name; });
}
}  // namespace

std::string EnvOptions::whyInvalid() const
{
  std::ostringstream why;
  const std::vector<std::string> tasks = taskNames();
  if (std::find(tasks.begin(), tasks.end(), task) == tasks.end())
  {
    why << "task: '" << task << "' is not a task; the tasks are";
    for (std::size_t i = 0; i < tasks.size(); ++i)
      why << (i ? ", " : " ") << tasks[i];
  }
  else if (!(balls >= 1 && balls <= 15))
    why << "balls: must be in [1, 15], got " << balls;
  else if (!oneOf(target, {"any", "lowest"}))
    why << "target: must be any or lowest, got '" << target << "'";
  else if (!(max_shots >= 0 && max_shots <= kMaxShotsCap))
    why << "max_shots: must be in [0, " << kMaxShotsCap << "] (0: the task's own), got " << max_shots;
  else if (!oneOf(rack, {"eight", "nine"}))
    why << "rack: must be eight or nine, got '" << rack << "'";
  else if (!oneOf(action, {"absolute", "relative"}))
    why << "action: must be absolute or relative, got '" << action << "'";
  else if (!oneOf(opponent, {"planner", "self"}))
    why << "opponent: must be planner or self, got '" << opponent << "'";
  else if (!(opponent_skill >= 0 && opponent_skill <= 1))
    why << "opponent_skill: must be in [0, 1], got " << opponent_skill;
  else if (!(shaping >= 0 && shaping <= 1))
    why << "shaping: must be in [0, 1], got " << shaping;
  else if (!oneOf(observation, {"state", "pixels", "both"}))
    why << "observation: must be state, pixels or both, got '" << observation << "'";
  else if (observation != "state" &&
           !(pixel_width >= 8 && pixel_width <= kMaxPixelSide && pixel_height >= 8 && pixel_height <= kMaxPixelSide))
    why << "pixel_width, pixel_height: each must be in [8, " << kMaxPixelSide << "] px, got " << pixel_width << " x "
        << pixel_height;
  else if (const std::string noisy = noise.validate(); !noisy.empty())
    why << "noise: " << noisy;
  return why.str();
}

Environment::Environment(std::shared_ptr<const physics::Engine<double>> engine, const EnvOptions& options)
  : engine_(std::move(engine)), options_(options), cue_(options.noise, kNoiseStream)
{
  if (!engine_)
    throw std::invalid_argument("engine: none given");
  if (const std::string why = options_.whyInvalid(); !why.empty())
    throw std::invalid_argument(why);
  task_ = makeTask(*engine_, options_);
  layout_ = std::make_shared<const ActionLayout>(options_);
  spaces_.action = layout_->box();
  if (options_.observation != "pixels")
  {
    addBallBlock(spaces_.state);
    task_->addFeatures(spaces_.state);
  }
  if (options_.observation != "state")
  {
    spaces_.pixel_width = options_.pixel_width;
    spaces_.pixel_height = options_.pixel_height;
  }
}

Environment::~Environment() = default;
Environment::Environment(Environment&&) noexcept = default;
Environment& Environment::operator=(Environment&&) noexcept = default;

Environment::Environment(const Environment& other)
  : engine_(other.engine_),
    options_(other.options_),
    spaces_(other.spaces_),
    layout_(other.layout_),
    task_(other.task_->clone()),
    random_(other.random_),
    cue_(other.cue_),
    shots_(other.shots_),
    done_(other.done_),
    last_strike_(other.last_strike_)
{
}

Environment& Environment::operator=(const Environment& other)
{
  if (this != &other)
    *this = Environment(other);
  return *this;
}

const physics::TableState<double>& Environment::table() const
{
  return task_->table();
}

const physics::TableState<double>& Environment::restTable() const
{
  return task_->restTable();
}

std::string Environment::whyActionInvalid(const double* action, std::size_t size) const
{
  return layout_->whyInvalid(action, size);
}

std::optional<GameStart> Environment::gameStart() const
{
  return task_->gameStart();
}

std::vector<PlayedTurn> Environment::lastTurns() const
{
  return task_->lastTurns();
}

void Environment::reset(std::optional<std::uint64_t> seed, const ObservationBuffers& out)
{
  if (seed)
  {
    random_.seed(*seed);
    cue_ = physics::NoisyCue(options_.noise, *seed ^ kNoiseStream);
  }
  task_->reset(random_);
  shots_ = 0;
  done_ = false;
  observe(out);
}

StepResult Environment::step(const double* action, std::size_t size, const ObservationBuffers& out)
{
  if (done_)
    throw std::logic_error("step: the episode is over (terminated or truncated); call reset first");
  const ActionLayout& layout = *layout_;
  if (const std::string why = whyActionInvalid(action, size); !why.empty())
    throw std::invalid_argument(why);
  double u = 0, v = 0;
  if (layout.placement(action, u, v))
    task_->placeCueBall(u, v);
  AimContext aim;
  aim.table = &task_->table();
  aim.model = &engine_->table();
  aim.ball_radius = engine_->params().ball_radius;
  if (layout.relative())
    aim.choices = task_->aimChoices();  // only a relative action chooses among them
  ShotPlan plan = layout.plan(action, aim);
  if (!options_.noise.isNone())
    plan.strike = cue_.execute(plan.strike, engine_->params().ball_radius);
  last_strike_ = plan.strike;
  StepResult result = task_->shoot(plan, random_);
  result.info.shots = ++shots_;
  // A game caps its shots itself (both sides'); other tasks count the agent's.
  if (!result.terminated && !isGameTask(options_.task) && options_.max_shots > 0 && shots_ >= options_.max_shots)
    result.truncated = true;
  done_ = result.terminated || result.truncated;
  observe(out);
  return result;
}

void Environment::observe(const ObservationBuffers& out) const
{
  if (out.state && !spaces_.state.names.empty())
  {
    writeBallBlock(engine_->table(), task_->table(), out.state);
    task_->writeFeatures(out.state + 3 * kBallSlots);
  }
  if (out.pixels && spaces_.pixel_width > 0)
  {
    if (!pixels_)
      pixels_ = std::make_unique<PixelRenderer>(*engine_, spaces_.pixel_width, spaces_.pixel_height);
    pixels_->render(task_->table(), out.pixels);
  }
}

std::vector<std::uint8_t> Environment::render(int width, int height) const
{
  if (!(width >= 8 && width <= 4096 && height >= 8 && height <= 4096))
    throw std::invalid_argument("render: width and height must be in [8, 4096] px");
  PixelRenderer renderer(*engine_, width, height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  renderer.render(task_->table(), rgb.data());
  return rgb;
}

}  // namespace learning
}  // namespace cue_sim
