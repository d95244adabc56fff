// The tasks by name: each is one file in tasks/, made here; and what the tasks share.
#include <stdexcept>

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

const TaskEntry kTasks[] = {
    {"pot", &makePotTask},         {"position", &makePotTask},   {"break", &makeBreakTask},
    {"eight_ball", &makeGameTask}, {"nine_ball", &makeGameTask},
};
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
  info.reason = turn.ruling.reason;
}

std::vector<std::string> taskNames()
{
  std::vector<std::string> names;
  for (const TaskEntry& entry : kTasks)
    names.emplace_back(entry.name);
  return names;
}

bool isGameTask(const std::string& task)
{
  for (const TaskEntry& entry : kTasks)
    if (task == entry.name)
      return entry.make == &makeGameTask;
  return false;
}

std::unique_ptr<Task> makeTask(const physics::Engine<double>& engine, const EnvOptions& options)
{
  for (const TaskEntry& entry : kTasks)
    if (options.task == entry.name)
      return entry.make(engine, options);
  std::string names;
  for (const std::string& name : taskNames())
    names += (names.empty() ? "" : ", ") + name;
  throw std::invalid_argument("task: '" + options.task + "' is not a task; the tasks are " + names);
}

}  // namespace learning
}  // namespace cue_sim
