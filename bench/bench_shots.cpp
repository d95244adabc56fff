// Time per shot of the fixed scenes in bench_scenes.hpp (Google Benchmark): `rosrun cue_sim
// bench`. Each reports the time per shot, the events per shot and the time per event.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "bench_scenes.hpp"
#include "cue_sim/evaluation/ball_impact_precision.hpp"
#include "cue_sim/evaluation/cushion_precision.hpp"
#include "cue_sim/evaluation/soak.hpp"
#include "cue_sim/physics/batch.hpp"
#include "cue_sim/session/live_table.hpp"

namespace
{
using namespace cue_sim::bench;

/// The node's live table through an 8-ball break, advanced in 100 Hz ticks from the strike to
/// rest, with the balls' orientations carried along (argument 1) or not (0): the cost of turning
/// the balls for tf, per break.
void LiveTableBreakTicks(benchmark::State& bench)
{
  const BenchScene scene = benchScene("eight_ball_break");
  cue_sim::session::LiveTableOptions options;
  options.orientations = bench.range(0) != 0;
  constexpr cue_sim::session::Stamp kTick = 10000000;  // 10 ms
  cue_sim::session::Shot shot;
  shot.strike.speed = 8.0;
  shot.strike.phi = 0.002;
  long ticks = 0;
  for (auto _ : bench)
  {
    bench.PauseTiming();
    cue_sim::session::LiveTable table(scene.engine, options, "eight", 0);
    bench.ResumeTiming();
    cue_sim::session::Stamp now = 0;
    table.strike(shot, now);
    while (!table.motion().atRest())
    {
      now += kTick;
      table.advanceTo(now);
      ++ticks;
    }
    benchmark::DoNotOptimize(table.motion().orientations().data());
  }
  bench.counters["ticks_per_break"] = benchmark::Counter(static_cast<double>(ticks) / bench.iterations());
}
BENCHMARK(LiveTableBreakTicks)->ArgName("orientations")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// 8-ball breaks from one rack, each with a slightly different cue (fixed seed), run by
/// simulateBatch on one thread (argument 1) or on every core (argument 0): breaks per second of
/// wall time. Unlike the fixed break replayed, no two of these shots are alike.
void BatchOfEightBallBreaks(benchmark::State& bench)
{
  const BenchScene scene = benchScene("eight_ball_break");
  const TableState<double> rack =
      rackLayout<double>("eight", scene.engine->table(), scene.engine->params().ball_radius, realRack());
  std::mt19937 random(7);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  std::vector<BatchShot<double>> shots(2000);
  for (auto& shot : shots)
  {
    shot.cue.speed = 5.0 + 0.5 * unit();  // the cue ball leaves at about 8 m/s
    shot.cue.phi = 0.01 * (unit() - 0.5);
  }
  ThreadPool pool(static_cast<unsigned>(bench.range(0)));
  std::size_t events = 0;
  for (auto _ : bench)
  {
    const auto outcomes = simulateBatch(*scene.engine, rack, shots, pool);
    events = 0;
    for (const auto& outcome : outcomes)
      events += outcome.result.events.size();
  }
  const double breaks = static_cast<double>(shots.size()) * bench.iterations();
  bench.counters["threads"] = pool.size();
  bench.counters["events_per_shot"] = static_cast<double>(events) / shots.size();
  bench.counters["breaks_per_second"] = benchmark::Counter(breaks, benchmark::Counter::kIsRate);
  bench.counters["time_per_shot_per_thread"] =
      benchmark::Counter(breaks / pool.size(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BatchOfEightBallBreaks)->ArgName("threads")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Runs the scenes in turn (or one scene, replayed), each from its own copy of its start, copied
/// into the same storage every time as a planner would reuse it, to rest in one call or advanced
/// in steps of 1/rate s (runScene); reports the time per event.
void runInTurn(benchmark::State& bench, const std::vector<BenchScene>& scenes, double rate = 0)
{
  std::vector<TableState<double>> states(scenes.size());
  std::vector<Event<double>> events;
  std::size_t event_count = 0, shots = 0;
  for (auto _ : bench)
    for (std::size_t k = 0; k < scenes.size(); ++k)
    {
      states[k] = scenes[k].state;
      events.clear();
      runScene(scenes[k], states[k], rate, events);
      event_count += events.size();
      ++shots;
    }
  bench.counters["balls"] = static_cast<double>(scenes.front().state.balls.size());
  bench.counters["scenes"] = static_cast<double>(scenes.size());
  bench.counters["events_per_shot"] = static_cast<double>(event_count) / static_cast<double>(shots);
  bench.counters["time_per_event"] =
      benchmark::Counter(static_cast<double>(event_count), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["events_per_second"] =
      benchmark::Counter(static_cast<double>(event_count), benchmark::Counter::kIsRate);
}

/// The scaling series over distinct scenes in turn (distinctScalingScenes): the time per event
/// that a planner's different shots see, with no path learnt by the branch predictor.
void ScalingDistinctScenes(benchmark::State& bench)
{
  runInTurn(bench, distinctScalingScenes(static_cast<int>(bench.range(0))));
}
BENCHMARK(ScalingDistinctScenes)
    ->ArgName("balls")
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);

/// The control: as many copies of the fixed scene as there are distinct scenes, each with its own
/// engine and memory, in turn. It costs about what the fixed scene replayed costs, so what makes
/// the distinct scenes dearer is their differing paths, not the switching between scenes.
void ScalingCopiesOfOneScene(benchmark::State& bench)
{
  const int count = static_cast<int>(bench.range(0));
  std::vector<BenchScene> copies;
  for (int k = 0; k < distinctSceneCount(count); ++k)
    copies.push_back(scaling(count, static_cast<unsigned>(count)));
  runInTurn(bench, copies);
}
BENCHMARK(ScalingCopiesOfOneScene)->ArgName("balls")->Arg(16)->Unit(benchmark::kMillisecond);

/// A benchmark of one contact model's cost per impact over `arrivals`: `resolve` takes one and
/// returns it resolved.
template <typename Arrival, typename Resolve>
void registerImpactCost(const std::string& name, std::vector<Arrival> arrivals, Resolve resolve)
{
  benchmark::RegisterBenchmark(name.c_str(), [arrivals, resolve](benchmark::State& s) {
    for (auto _ : s)
      for (const Arrival& arrival : arrivals)
        benchmark::DoNotOptimize(resolve(arrival));
    s.SetItemsProcessed(s.iterations() * static_cast<long>(arrivals.size()));
    s.counters["ns_per_impact"] = benchmark::Counter(static_cast<double>(s.iterations() * arrivals.size()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  })->Unit(benchmark::kMicrosecond);
}

/// Coefficients across the registry's ranges: those of the soak's first kRangeScenes scenes
/// (each coefficient its default half the time, else a bound or between them), and the speed
/// scales an impact meets: a shot's, a ball pressed on another's, a held ball's rounding.
constexpr long kRangeScenes = 64;
const double kRangeSpeedScales[] = {1.0, 1e-6, 1e-13};

std::vector<PhysicsParams<double>> registryRangeParams()
{
  std::vector<PhysicsParams<double>> params;
  for (long k = 0; k < kRangeScenes; ++k)
    params.push_back(cue_sim::evaluation::soakScene(1, k, false).params);
  return params;
}

/// A model's impacts over the registry's ranges, `arrivals(p)` at each coefficient set and speed
/// scale, each timed: the mean and the worst single impact (worst_us, the figure issue 53 holds
/// under a millisecond).
template <typename Arrivals, typename Resolve>
void registerImpactCostOverRanges(const std::string& name, Arrivals arrivals, Resolve resolve)
{
  benchmark::RegisterBenchmark(name.c_str(), [arrivals, resolve](benchmark::State& s) {
    static const std::vector<PhysicsParams<double>> ranges = registryRangeParams();
    double worst = 0;
    long impacts = 0;
    for (auto _ : s)
      for (const PhysicsParams<double>& p : ranges)
        for (auto arrival : arrivals(p))
          for (const double scale : kRangeSpeedScales)
          {
            const auto start = std::chrono::steady_clock::now();
            benchmark::DoNotOptimize(resolve(arrival, scale, p));
            worst = std::max(worst, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            ++impacts;
          }
    s.counters["ns_per_impact"] =
        benchmark::Counter(static_cast<double>(impacts), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    s.counters["worst_us"] = worst * 1e6;
  })->Unit(benchmark::kMillisecond);
}

Ball<double> scaled(Ball<double> b, double scale)
{
  b.v *= scale;
  b.w *= scale;
  return b;
}

/// The 8-ball break with these models, as eight_ball_break_<model>.
void registerBreak(const std::string& model, const ModelChoice& models)
{
  benchmark::RegisterBenchmark(("eight_ball_break_" + model).c_str(), [models](benchmark::State& s) {
    runInTurn(s, {eightBallBreakWith(models)});
  })->Unit(benchmark::kMicrosecond);
}

const int registered = [] {
  for (const auto& [name, build] : benchScenes())
    benchmark::RegisterBenchmark(name.c_str(), [name = name](benchmark::State& s) {
      runInTurn(s, {benchScene(name)});  // one scene, replayed
    })->Unit(benchmark::kMicrosecond);
  // Beside the 8-ball break run to rest: the same break advanced as the node's tick advances the
  // live table, at 100 Hz and 1 kHz.
  for (const auto& [name, run] : steppedRuns())
    benchmark::RegisterBenchmark(name.c_str(), [run = run](benchmark::State& s) {
      runInTurn(s, {benchScene(run.first)}, run.second);
    })->Unit(benchmark::kMicrosecond);
  // Each cushion model: its cost per impact, and the break's cost with it (the default ball-ball
  // model); then each ball-ball model with the default cushion model.
  const PhysicsParams<double> p;
  for (const std::string& model : cushionModelNames())
  {
    registerImpactCost("cushion_impact_" + model, cue_sim::evaluation::cushionArrivals(p),
                       [resolver = std::shared_ptr(makeCushionModel<double>(model)), p](Ball<double> b) {
                         resolver->resolve(b, Vec3<double>(0, -1, 0), p);
                         return b;
                       });
    registerBreak(model, ModelChoice(ModelChoice().ball_ball, model));
    registerImpactCostOverRanges(
        "cushion_impact_" + model + "_over_the_registry",
        [](const PhysicsParams<double>& q) { return cue_sim::evaluation::cushionArrivals(q); },
        [resolver = std::shared_ptr(makeCushionModel<double>(model))](const Ball<double>& arrival, double scale,
                                                                      const PhysicsParams<double>& q) {
          Ball<double> b = scaled(arrival, scale);
          resolver->resolve(b, Vec3<double>(0, -1, 0), q);
          return b;
        });
  }
  for (const std::string& model : ballBallModelNames())
  {
    registerImpactCost("ball_impact_" + model, cue_sim::evaluation::ballArrivals(p),
                       [resolver = std::shared_ptr(makeBallBallModel<double>(model)), p](auto pair) {
                         resolver->resolve(pair.first, pair.second, p);
                         return pair;
                       });
    registerBreak(model, ModelChoice(model, ModelChoice().cushion));
    registerImpactCostOverRanges(
        "ball_impact_" + model + "_over_the_registry",
        [](const PhysicsParams<double>& q) { return cue_sim::evaluation::ballArrivals(q); },
        [resolver = std::shared_ptr(makeBallBallModel<double>(model))](const auto& arrival, double scale,
                                                                       const PhysicsParams<double>& q) {
          auto pair = std::make_pair(scaled(arrival.first, scale), scaled(arrival.second, scale));
          resolver->resolve(pair.first, pair.second, q);
          return pair;
        });
  }
  return 0;
}();
}  // namespace

BENCHMARK_MAIN();
