// Runs one bench scene to rest once (or advanced in steps, for the stepped runs) and prints its
// events: the program that scripts/callgrind_shots.sh measures (only runScene is counted).
#include <iostream>

#include "bench_scenes.hpp"

int main(int argc, char** argv)
{
  using namespace cue_sim::bench;
  if (argc != 2)
  {
    std::cerr << "usage: bench_scene NAME\nscenes:";
    for (const auto& [name, build] : benchScenes())
      std::cerr << ' ' << name;
    for (const auto& [name, run] : steppedRuns())
      std::cerr << ' ' << name;
    std::cerr << '\n';
    return 2;
  }
  try
  {
    const std::string name = argv[1];
    const auto stepped = steppedRuns().find(name);
    const double rate = stepped == steppedRuns().end() ? 0.0 : stepped->second.second;
    const BenchScene scene = benchScene(stepped == steppedRuns().end() ? name : stepped->second.first);
    TableState<double> state = scene.state;
    std::vector<Event<double>> events;
    const bool at_rest = runScene(scene, state, rate, events);
    std::cout << name << ": " << state.balls.size() << " balls, " << events.size() << " events\n";
    return at_rest ? 0 : 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_scene: " << e.what() << '\n';
    return 2;
  }
}
