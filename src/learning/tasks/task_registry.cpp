// The tasks by name: each is one file in tasks/, made here; and what the tasks share.
#include <algorithm>
#include <stdexcept>

#include "cue_sim/game/referee.hpp"
#include "learning/tasks/task.hpp"

namespace cue_sim
{
namespace learning
{
std::unique_ptr<Task> makePotTask(const physics::Engine<double>& engine, const EnvOptions& options);
std::unique_ptr<Task> makeBreakTask(const physics::Engine<double>& engine, const EnvOptions& options);
std::unique_ptr<Task> makeGameTask(const physics::Engine<double>& engine, const EnvOptions& options);

namespace
{
struct TaskEntry
{
  const char* name;
  std::unique_ptr<Task> (*make)(const physics::Engine<double>&, const EnvOptions&);
};

/// The tasks on a table of balls; beside them, one game task per ruleset (game::rulesNames()).
const TaskEntry kTableTasks[] = {
    {"pot", &makePotTask},
    {"position", &makePotTask},
    {"break", &makeBreakTask},
};

bool isRuleset(const std::string& name)
{
  const std::vector<std::string> rules = game::rulesNames();
  return std::find(rules.begin(), rules.end(), name) != rules.end();
}
}  // namespace

void requirePockets(const physics::Engine<double>& engine, const std::string& task)
{
  if (engine.table().pockets().empty())
    throw std::invalid_argument("task: " + task + " needs a table with pockets; '" + engine.table().name() +
                                "' has none");
}

void describeTurn(const game::Turn& turn, StepInfo& info)
{
  info.events = static_cast<int>(turn.events.size());
  info.shot_time = turn.events.empty() ? 0 : turn.events.back().time - turn.events.front().time;
  info.pocketed = static_cast<int>(turn.facts.pocketed.size());
  info.scratch = turn.facts.scratch;
  info.first_contact = turn.facts.first_contact;
  info.foul = turn.ruling.foul;
  info.points = turn.ruling.points;
  info.penalty = turn.ruling.penalty;
  info.reason = turn.ruling.reason;
}

std::vector<std::string> taskNames()
{
  std::vector<std::string> names;
  for (const TaskEntry& entry : kTableTasks)
    names.emplace_back(entry.name);
  for (const std::string& rules : game::rulesNames())
    names.push_back(rules);
  return names;
}

bool isGameTask(const std::string& task)
{
  return isRuleset(task);
}

std::unique_ptr<Task> makeTask(const physics::Engine<double>& engine, const EnvOptions& options)
{
  for (const TaskEntry& entry : kTableTasks)
    if (options.task == entry.name)
      return entry.make(engine, options);
  if (isRuleset(options.task))
    return makeGameTask(engine, options);
  std::string names;
  for (const std::string& name : taskNames())
    names += (names.empty() ? "" : ", ") + name;
  throw std::invalid_argument("task: '" + options.task + "' is not a task; the tasks are " + names);
}

}  // namespace learning
}  // namespace cue_sim
