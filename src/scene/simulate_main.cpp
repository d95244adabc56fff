// simulate: runs a scene file through the physics engine and prints JSON (no ROS needed).
//   rosrun cue_sim simulate scene.yaml      (or devel/lib/cue_sim/simulate scene.yaml)
// Exit codes: 0 the scene ran; 1 the scene is refused (the message names the key and the value);
// 2 the command line is wrong; 3 the engine gave up (--max-events reached).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <optional>

#include "cue_sim/game/referee.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/scene/scene_file.hpp"
#include "cue_sim/scene/shot_report.hpp"

namespace
{
constexpr int kExitOk = 0;
constexpr int kExitRefused = 1;
constexpr int kExitCommandLine = 2;
constexpr int kExitGaveUp = 3;
}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Simulate a pool scene exactly and print every event and the final state as JSON."};
  std::string scene_path;
  int indent = 2;
  long max_events = cue_sim::physics::EngineLimits().max_events;
  std::optional<double> duration;
  app.add_option("scene", scene_path, "scene file (YAML; format in README.md, 'Scene files'); - for stdin")->required();
  app.add_option("--indent", indent, "JSON indentation, -1 for one line")->check(CLI::Range(-1, 16));
  app.add_option("--max-events", max_events, "give up after this many events")->check(CLI::PositiveNumber);
  app.add_option("--duration", duration,
                 "advance this many seconds [s] instead of running to rest (instead of the scene's duration)")
      ->check(CLI::Range(0.0, 1e6));
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    app.exit(e);  // prints the help, or what is wrong with the command line
    return e.get_exit_code() == 0 ? kExitOk : kExitCommandLine;
  }

  try
  {
    cue_sim::Scene scene;
    if (scene_path == "-")
    {
      std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
      scene = cue_sim::loadScene(text);
    }
    else
      scene = cue_sim::loadSceneFile(scene_path);
    cue_sim::physics::EngineLimits limits;
    limits.max_events = max_events;
    const cue_sim::physics::Engine<double> engine(scene.table, scene.params, scene.models, limits);
    const std::string invalid = engine.whyInvalid(scene.state);
    if (!invalid.empty())
      throw cue_sim::SceneError("balls: " + invalid);
    if (scene.game && (!scene.shot || duration))
      throw cue_sim::SceneError("game: a game's scene needs a shot, ruled on at rest (no --duration)");
    const int cue_ball = scene.game ? cue_sim::game::makeRules(scene.game->rules)->cueBall(scene.game->turn) : 0;
    const std::vector<int> on_table = cue_sim::game::objectBallsOnTable(scene.state, cue_ball);
    if (scene.game && scene.game->called_ball >= 0 &&
        std::find(on_table.begin(), on_table.end(), scene.game->called_ball) == on_table.end())
      throw cue_sim::SceneError("game.called_ball: ball " + std::to_string(scene.game->called_ball) +
                                " is not on the table");
    cue_sim::physics::Simulation<double> simulation(engine, scene.state);
    if (scene.shot)
    {
      const std::string why = simulation.whyNotStrikable(scene.shot->ball, scene.shot->strike);
      if (!why.empty())
        throw cue_sim::SceneError("shot: " + why);
      simulation.strike(scene.shot->ball, scene.shot->strike);
    }
    std::vector<cue_sim::physics::Event<double>> events;
    if (duration || scene.duration)
      simulation.advance(simulation.time() + duration.value_or(scene.duration.value_or(0)), &events);
    else
      events = simulation.runToRest().events;
    scene.state = simulation.state();
    const bool at_rest = simulation.atRest();
    nlohmann::json report = cue_sim::shotReport(engine, scene.state, events, at_rest);
    if (scene.game)
    {
      // The referee rules on the shot, and the state the game goes on from follows the ruling.
      const cue_sim::game::Ruling ruling = cue_sim::game::judgeShot(
          *cue_sim::game::makeRules(scene.game->rules), *scene.game, on_table,
          {cue_sim::game::readShot(events, scene.table.get(), scene.shot->ball), scene.shot->push_out});
      report["ruling"] = cue_sim::rulingJson(ruling);
      report["game"] = cue_sim::gameStateJson(cue_sim::game::afterRuling(*scene.game, ruling), *scene.table);
    }
    std::cout << report.dump(indent) << std::endl;
    return kExitOk;
  }
  catch (const cue_sim::physics::EventLimitError& e)
  {
    std::cerr << "simulate: " << e.what() << std::endl;
    return kExitGaveUp;
  }
  catch (const std::exception& e)
  {
    std::cerr << "simulate: " << e.what() << std::endl;
    return kExitRefused;
  }
}
