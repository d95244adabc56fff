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
/// What the execution noise's stream is seeded with, beside the episode's seed: a stream of its
/// own, so that the noise does not depend on how many draws the table's setup took.
constexpr std::uint64_t kNoiseStream = 0x9e3779b97f4a7c15ULL;
}  // namespace

const std::vector<EnvOptionField>& envOptionFields()
{
  using Kind = EnvOptionField::Kind;
  static const std::vector<EnvOptionField> fields = [] {
    std::vector<EnvOptionField> f;
#define CUE_SIM_ENV_TEXT(name, default_value, choices, description)                                                    \
  f.push_back({#name, Kind::kText, description, choices});                                                             \
  f.back().text = &EnvOptions::name;
#define CUE_SIM_ENV_INTEGER(name, default_value, min, max, description)                                                \
  f.push_back({#name, Kind::kInteger, description, "", min, max});                                                     \
  f.back().integer = &EnvOptions::name;
#define CUE_SIM_ENV_REAL(name, default_value, min, max, description)                                                   \
  f.push_back({#name, Kind::kReal, description, "", min, max});                                                        \
  f.back().real = &EnvOptions::name;
#define CUE_SIM_ENV_FLAG(name, default_value, description)                                                             \
  f.push_back({#name, Kind::kFlag, description});                                                                      \
  f.back().flag = &EnvOptions::name;
#include "cue_sim/learning/env_options.def"
#undef CUE_SIM_ENV_TEXT
#undef CUE_SIM_ENV_INTEGER
#undef CUE_SIM_ENV_REAL
#undef CUE_SIM_ENV_FLAG
    return f;
  }();
  return fields;
}

namespace
{
/// The values a text option takes: its declared choices, or for `task` the registry's names.
std::vector<std::string> choicesOf(const EnvOptionField& field)
{
  if (*field.choices == '\0')
    return taskNames();
  std::vector<std::string> names;
  std::istringstream words(field.choices);
  for (std::string word; words >> word;)
    names.push_back(word);
  return names;
}

/// Empty if `options`' value of `field` is in its declared range or choices, else why not.
std::string whyOutOfRange(const EnvOptions& options, const EnvOptionField& field)
{
  std::ostringstream why;
  switch (field.kind)
  {
    case EnvOptionField::Kind::kText: {
      const std::string& value = options.*field.text;
      const std::vector<std::string> names = choicesOf(field);
      if (std::find(names.begin(), names.end(), value) == names.end())
      {
        why << field.name << ": '" << value << "' is not one of";
        for (std::size_t i = 0; i < names.size(); ++i)
          why << (i ? ", " : " ") << names[i];
      }
      break;
    }
    case EnvOptionField::Kind::kInteger: {
      const int value = options.*field.integer;
      if (!(value >= field.min && value <= field.max))
        why << field.name << ": must be in [" << field.min << ", " << field.max << "], got " << value;
      break;
    }
    case EnvOptionField::Kind::kReal: {
      const double value = options.*field.real;
      if (!(value >= field.min && value <= field.max))
        why << field.name << ": must be in [" << field.min << ", " << field.max << "], got " << value;
      break;
    }
    case EnvOptionField::Kind::kFlag:
      break;
  }
  return why.str();
}
}  // namespace

std::string EnvOptions::whyInvalid() const
{
  for (const EnvOptionField& field : envOptionFields())
    if (std::string why = whyOutOfRange(*this, field); !why.empty())
      return why;
  if (const std::string noisy = noise_model.validate(); !noisy.empty())
    return "noise_model: " + noisy;
  return "";
}

Environment::Environment(std::shared_ptr<const physics::Engine<double>> engine, const EnvOptions& options)
  : engine_(std::move(engine)),
    options_(options),
    cue_(options.noise ? options.noise_model : physics::ExecutionNoise::none(), kNoiseStream)
{
  if (!engine_)
    throw std::invalid_argument("engine: none given");
  if (const std::string why = options_.whyInvalid(); !why.empty())
    throw std::invalid_argument(why);
  task_ = makeTask(*engine_, options_);
  if (options_.action == "relative" && engine_->table().pockets().empty())
    throw std::invalid_argument("action: relative aims at a ball and a pocket; '" + engine_->table().name() +
                                "' has no pockets (absolute aims anywhere)");
  layout_ = std::make_shared<const ActionLayout>(options_);
  spaces_.action = layout_->box();
  if (options_.observation != "pixels")
  {
    addBallBlock(spaces_.state, task_->ballSlots());
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
    cue_ = physics::NoisyCue(options_.noise ? options_.noise_model : physics::ExecutionNoise::none(),
                             *seed ^ kNoiseStream);
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
  if (options_.noise && !options_.noise_model.isNone())
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
    writeBallBlock(engine_->table(), task_->table(), out.state, task_->ballSlots());
    task_->writeFeatures(out.state + 3 * task_->ballSlots());
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
