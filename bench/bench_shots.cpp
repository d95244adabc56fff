// Time per shot for fixed scenes (Google Benchmark). `rosrun cue_sim bench`.
#include <benchmark/benchmark.h>

#include <memory>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/rack.hpp"

namespace
{
using namespace cue_sim::physics;

std::shared_ptr<const TableModel> sevenFoot()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  return table;
}

/// Runs `rack` struck by the cue ball at `speed` along phi to rest, once per iteration.
void runShot(benchmark::State& bench, const std::string& rack, double speed, double phi)
{
  const PhysicsParams<double> params;
  const Engine<double> engine(sevenFoot(), params);
  TableState<double> start = rackLayout<double>(rack, engine.table(), params.ball_radius);
  CueStrike<double> cue;
  cue.speed = speed;
  cue.phi = phi;
  engine.strike(start, 0, cue);
  std::size_t events = 0;
  for (auto _ : bench)
  {
    TableState<double> state = start;
    const ShotResult<double> result = engine.simulateToRest(state);
    events = result.events.size();
    benchmark::DoNotOptimize(state.balls.data());
  }
  bench.counters["events_per_shot"] = static_cast<double>(events);
  bench.counters["time_per_event"] = benchmark::Counter(static_cast<double>(events) * bench.iterations(),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void EightBallBreak(benchmark::State& s)
{
  runShot(s, "eight", 8.0, 0.0);
}
void NineBallBreak(benchmark::State& s)
{
  runShot(s, "nine", 8.0, 0.0);
}
void SingleBallToRest(benchmark::State& s)
{
  runShot(s, "empty", 3.0, 0.4);
}
BENCHMARK(EightBallBreak)->Unit(benchmark::kMicrosecond);
BENCHMARK(NineBallBreak)->Unit(benchmark::kMicrosecond);
BENCHMARK(SingleBallToRest)->Unit(benchmark::kMicrosecond);
}  // namespace

BENCHMARK_MAIN();
