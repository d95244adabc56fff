// break: a game's rack (8-, 9- or 10-ball) as games rack it (jittered, seeded by the episode), the cue ball
// on the break spot; the referee rules on the break. One shot.
#include <stdexcept>

#include "cue_sim/game/game_play.hpp"
#include "learning/tasks/task.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
/// The ruleset whose games start from `rack`: the break is refereed as its game's break.
std::string rulesRacking(const std::string& rack)
{
  for (const std::string& name : game::rulesNames())
    if (game::makeRules(name)->rack() == rack)
      return name;
  throw std::invalid_argument("rack: no game starts from '" + rack + "'");
}

class BreakTask : public Task
{
public:
  BreakTask(const physics::Engine<double>& engine, const EnvOptions& options)
    : engine_(engine), rules_(rulesRacking(options.rack))
  {
    requirePockets(engine, "break");
    game_ = std::make_unique<game::GamePlay>(engine_, rules_);
  }
  BreakTask(const BreakTask& other)
    : Task(other),
      engine_(other.engine_),
      rules_(other.rules_),
      game_(std::make_unique<game::GamePlay>(*other.game_)),
      at_rest_(other.at_rest_),
      shot_(other.shot_)
  {
  }
  std::unique_ptr<Task> clone() const override { return std::make_unique<BreakTask>(*this); }

  void reset(Random& random) override
  {
    game_ = std::make_unique<game::GamePlay>(engine_, rules_, std::array<std::string, 2>{"player 1", "player 2"},
                                             game::gameRack(static_cast<unsigned>(random.bits())));
    shot_ = false;
  }
  const physics::TableState<double>& table() const override { return game_->table(); }
  const physics::TableState<double>& restTable() const override { return shot_ ? at_rest_ : game_->table(); }
  std::vector<int> aimChoices() const override { return game_->legalFirst(); }

  StepResult shoot(const ShotPlan& plan, Random&) override
  {
    StepResult result;
    const game::Turn turn = game_->shoot(plan.strike, false, &at_rest_);
    shot_ = true;
    describeTurn(turn, result.info);
    const bool legal = !turn.ruling.foul && !turn.ruling.rerack;
    result.reward = legal ? static_cast<double>(turn.facts.pocketed.size()) : -1.0;
    result.terminated = true;
    return result;
  }

  void addFeatures(BoxSpec&) const override {}
  void writeFeatures(float*) const override {}

private:
  const physics::Engine<double>& engine_;
  std::string rules_;
  std::unique_ptr<game::GamePlay> game_;
  physics::TableState<double> at_rest_;  ///< the balls as the break left them
  bool shot_ = false;
};
}  // namespace

std::unique_ptr<Task> makeBreakTask(const physics::Engine<double>& engine, const EnvOptions& options)
{
  return std::make_unique<BreakTask>(engine, options);
}

}  // namespace learning
}  // namespace cue_sim
