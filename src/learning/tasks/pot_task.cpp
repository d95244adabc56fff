// pot: a few object balls and the cue ball anywhere on the cloth; pot one (any, or the lowest on
// the table, hit first) without scratching. One shot, or a run of shots while each scores.
//
// position: pot the lowest ball and leave the cue ball a shot at the next one, the one-shot
// look-ahead of position play (Smith, "PickPocket: a computer billiards shark", Artificial
// Intelligence 171, 2007; Landry and Dussault, "AI optimization of a billiard player", J. Intell.
// Robot. Syst. 50, 2007): a pot scores 1, and up to 1 more as the next ball then has open shots
// (ghost-ball cuts the core's planner would play, with clear paths: game::openShots).
#include <algorithm>
#include <stdexcept>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/game/referee.hpp"
#include "cue_sim/game/self_play.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "learning/tasks/placement.hpp"
#include "learning/tasks/task.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
/// Open shots on the next ball that earn position's whole point: a choice of three pockets, as a
/// player who plays position wants (one open pocket is a shot; three are an easy one).
constexpr int kOpenShotsForFullPosition = 3;

class PotTask : public Task
{
public:
  PotTask(const physics::Engine<double>& engine, const EnvOptions& options)
    : engine_(engine),
      position_(options.task == "position"),
      least_balls_(position_ ? 2 : 1),
      most_balls_(std::max(least_balls_, options.balls)),
      lowest_(position_ || options.target == "lowest"),
      run_(options.max_shots > 1)
  {
    requirePockets(engine, options.task);
  }
  std::unique_ptr<Task> clone() const override { return std::make_unique<PotTask>(*this); }

  void reset(Random& random) override
  {
    table_ = scatteredBalls(engine_, random.integer(least_balls_, most_balls_), random);
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
        if (position_)
          addPositionBonus(cleared, result);
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
  /// Position play's second point: up to 1 more as the next ball has open shots from where the cue
  /// ball lies (1/kOpenShotsForFullPosition for each, into different pockets), or 1 if the table
  /// is cleared and nothing is left to play position for.
  void addPositionBonus(bool cleared, StepResult& result) const
  {
    int open = 0;
    if (!cleared)
    {
      game::GamePlay next(engine_, "nine_ball");  // rotation: the lowest ball is the one to hit
      if (next.setPosition(table_, false).empty())
        open = game::openShots(next);
    }
    result.info.open_shots = open;
    const double bonus =
        cleared ? 1.0 : static_cast<double>(std::min(open, kOpenShotsForFullPosition)) / kOpenShotsForFullPosition;
    result.reward += bonus;
    result.info.reason +=
        cleared ? ", the table cleared" : ", leaving " + std::to_string(open) + " open shot(s) on the next ball";
  }

  const physics::Engine<double>& engine_;
  bool position_;  ///< the position task: the lowest ball, and a point for leaving a shot
  int least_balls_;
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
