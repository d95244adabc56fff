// Runs one bench scene to rest once and prints its events: the program that
// scripts/callgrind_shots.sh measures (only Engine::simulateToRest is counted).
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
    std::cerr << '\n';
    return 2;
  }
  try
  {
    BenchScene scene = benchScene(argv[1]);
    const ShotResult<double> result = scene.engine->simulateToRest(scene.state);
    std::cout << argv[1] << ": " << scene.state.balls.size() << " balls, " << result.events.size() << " events\n";
    return result.at_rest ? 0 : 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_scene: " << e.what() << '\n';
    return 2;
  }
}
