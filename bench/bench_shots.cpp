// Time per shot of the fixed scenes in bench_scenes.hpp (Google Benchmark): `rosrun cue_sim
// bench`. Each reports the time per shot, the events per shot and the time per event.
#include <benchmark/benchmark.h>

#include "bench_scenes.hpp"

namespace
{
using namespace cue_sim::bench;

void runScene(benchmark::State& bench, const std::string& name)
{
  const BenchScene scene = benchScene(name);
  std::size_t events = 0;
  for (auto _ : bench)
  {
    TableState<double> state = scene.state;
    const ShotResult<double> result = scene.engine->simulateToRest(state);
    events = result.events.size();
    benchmark::DoNotOptimize(state.balls.data());
  }
  bench.counters["balls"] = static_cast<double>(scene.state.balls.size());
  bench.counters["events_per_shot"] = static_cast<double>(events);
  bench.counters["time_per_event"] = benchmark::Counter(static_cast<double>(events) * bench.iterations(),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["events_per_second"] =
      benchmark::Counter(static_cast<double>(events) * bench.iterations(), benchmark::Counter::kIsRate);
}

const int registered = [] {
  for (const auto& [name, build] : benchScenes())
    benchmark::RegisterBenchmark(name.c_str(), [name = name](benchmark::State& s) {
      runScene(s, name);
    })->Unit(benchmark::kMicrosecond);
  return 0;
}();
}  // namespace

BENCHMARK_MAIN();
