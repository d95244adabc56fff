// pot: a few object balls and the cue ball anywhere on the cloth; pot one (any, or the lowest on
// the table, hit first) without scratching. One shot, or a run of shots while each scores.
#include <stdexcept>

#include "cue_sim/game/referee.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "learning/tasks/task.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
/// Tries at drawing a free place for one ball before the episode's table is drawn again.
constexpr int kPlacementTries = 1000;

class PotTask : public Task
{
public:
  PotTask(const physics::Engine<double>& engine, const EnvOptions& options)
    : engine_(engine), most_balls_(options.balls), lowest_(options.target == "lowest"), run_(options.max_shots > 1)
  {
    if (engine.table().pockets().empty())
      throw std::invalid_argument("task: pot needs a table with pockets; '" + engine.table().name() + "' has none");
  }
  std::unique_ptr<Task> clone() const override { return std::make_unique<PotTask>(*this); }

  void reset(Random& random) override
  {
    const int count = random.integer(1, most_balls_);
    while (!placeAll(random, count))
    {
    }
  }
  const physics::TableState<double>& table() const override { return table_; }
  std::vector<int> aimChoices() const override
  {
    const std::vector<int> on_table = game::objectBallsOnTable(table_);
    if (lowest_ && !on_table.empty())
      return {on_table.front()};
    return on_table;
  }

  StepResult shoot(const ShotPlan& plan, Random&) override
  {
    StepResult result;
    const int lowest = aimChoices().empty() ? -1 : aimChoices().front();
    engine_.strike(table_, 0, plan.strike);
    std::vector<physics::Event<double>> events;
    try
    {
      const physics::ShotResult<double> shot = physics::simulateToRest(engine_, table_);
      events = shot.events;
      result.info.shot_time = shot.duration;
    }
    catch (const physics::EventLimitError& e)
    {
      result.truncated = true;
      result.info.reason = std::string("the shot was stopped: ") + e.what();
      return result;
    }
    const game::ShotFacts facts = game::readShot(events, &engine_.table());
    result.info.events = static_cast<int>(events.size());
    result.info.pocketed = static_cast<int>(facts.pocketed.size());
    result.info.scratch = facts.scratch;
    result.info.foul = facts.scratch;
    result.info.first_contact = facts.first_contact;
    const bool cleared = game::objectBallsOnTable(table_).empty();
    if (facts.scratch)
    {
      result.reward = -1;
      result.info.reason = "scratch: the cue ball was pocketed";
    }
    else if (lowest_)
    {
      const bool potted = std::find(facts.pocketed.begin(), facts.pocketed.end(), lowest) != facts.pocketed.end();
      if (facts.first_contact != lowest)
        result.info.reason = "the cue ball did not hit ball " + std::to_string(lowest) + " first";
      else if (!potted)
        result.info.reason = "ball " + std::to_string(lowest) + " was not pocketed";
      else
      {
        result.reward = 1;
        result.info.reason = "ball " + std::to_string(lowest) + " pocketed";
      }
    }
    else
    {
      result.reward = static_cast<double>(facts.pocketed.size());
      result.info.reason =
          facts.pocketed.empty() ? "no ball pocketed" : std::to_string(facts.pocketed.size()) + " ball(s) pocketed";
    }
    // A single shot is the whole episode; a run goes on while each shot scores and balls are left.
    result.terminated = !run_ || !(result.reward > 0) || cleared;
    return result;
  }

  void addFeatures(BoxSpec& box) const override
  {
    if (!lowest_)
      return;
    for (int id = 1; id < 16; ++id)
    {
      box.names.push_back("target" + std::to_string(id));
      box.low.push_back(0);
      box.high.push_back(1);
    }
  }
  void writeFeatures(float* out) const override
  {
    if (!lowest_)
      return;
    std::fill(out, out + 15, 0.0f);
    const std::vector<int> choices = aimChoices();
    if (!choices.empty() && choices.front() < 16)
      out[choices.front() - 1] = 1.0f;
  }

private:
  /// The cue ball and balls 1 to count, each uniformly where a ball in hand may go (clear of the
  /// cushions, the pockets' mouths and the other balls); false if one found no place.
  bool placeAll(Random& random, int count)
  {
    const double R = engine_.params().ball_radius;
    Eigen::Vector2d low, high;
    game::inHandRegion(engine_.table(), R, game::BallInHand::Anywhere, low, high);
    table_ = physics::TableState<double>();
    for (int id = 0; id <= count; ++id)
    {
      bool placed = false;
      for (int tries = 0; tries < kPlacementTries && !placed; ++tries)
      {
        const Eigen::Vector2d p(random.uniform(low.x(), high.x()), random.uniform(low.y(), high.y()));
        if (!game::whyNotInHand(engine_.table(), R, table_, p, game::BallInHand::Anywhere).empty())
          continue;
        physics::Ball<double> ball;
        ball.id = id;
        ball.r = Eigen::Vector3d(p.x(), p.y(), R);
        table_.balls.push_back(ball);
        placed = true;
      }
      if (!placed)
        return false;
    }
    return true;
  }

  const physics::Engine<double>& engine_;
  int most_balls_;
  bool lowest_;
  bool run_;  ///< max_shots > 1: shots go on while they score
  physics::TableState<double> table_;
};
}  // namespace

std::unique_ptr<Task> makePotTask(const physics::Engine<double>& engine, const EnvOptions& options)
{
  return std::make_unique<PotTask>(engine, options);
}

}  // namespace learning
}  // namespace cue_sim
