// simulate: runs a scene file through the physics engine and prints JSON (no ROS needed).
//   rosrun cue_sim simulate scene.yaml      (or devel/lib/cue_sim/simulate scene.yaml)
#include <CLI/CLI.hpp>
#include <iostream>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/scene/scene_file.hpp"
#include "cue_sim/scene/shot_report.hpp"

int main(int argc, char** argv)
{
  CLI::App app{"Simulate a pool scene exactly and print every event and the final state as JSON."};
  std::string scene_path;
  int indent = 2;
  long max_events = cue_sim::physics::EngineLimits().max_events;
  app.add_option("scene", scene_path, "scene file (YAML; format in README.md, 'Scene files'); - for stdin")->required();
  app.add_option("--indent", indent, "JSON indentation, -1 for one line");
  app.add_option("--max-events", max_events, "give up after this many events")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

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
    if (scene.shot)
    {
      const std::string why = engine.whyNotStrikable(scene.state, scene.shot->ball, scene.shot->strike);
      if (!why.empty())
        throw cue_sim::SceneError("shot: " + why);
      engine.strike(scene.state, scene.shot->ball, scene.shot->strike);
    }
    std::vector<cue_sim::physics::Event<double>> events;
    bool at_rest;
    if (scene.duration)
    {
      engine.advance(scene.state, *scene.duration, &events);
      at_rest = !scene.state.anyMoving();
    }
    else
    {
      auto result = engine.simulateToRest(scene.state);
      events = std::move(result.events);
      at_rest = result.at_rest;
    }
    std::cout << cue_sim::shotReport(engine, scene.state, events, at_rest).dump(indent) << std::endl;
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "simulate: " << e.what() << std::endl;
    return 1;
  }
}
