// The simulated camera's cost per frame at 1280x800 on one core (the floor: 30 Hz, so
// 33 ms a frame): a racked table at rest, and the break 40 ms after the strike, when all 16
// balls move and smear (the exposure's instants included), with and without sensor noise.
#include <benchmark/benchmark.h>

#include "bench_scenes.hpp"
#include "cue_sim/camera/exposure.hpp"
#include "cue_sim/camera/table_camera.hpp"
#include "cue_sim/session/live_table.hpp"

namespace
{
using cue_sim::session::Stamp;
using namespace cue_sim::bench;

constexpr Stamp kMillisecond = 1000000;
constexpr double kExposure = 0.004;  ///< [s] the node's default

/// Argument 0: ms after the break's strike (0: not struck, the rack at rest); 1: noise (levels).
void CameraFrame1280x800(benchmark::State& bench)
{
  const BenchScene scene = benchScene("eight_ball_break");
  cue_sim::session::LiveTable table(scene.engine, {}, "eight", 0);
  const Stamp after = bench.range(0) * kMillisecond;
  if (after > 0)
  {
    cue_sim::session::Shot shot;
    shot.strike.speed = 8.0;
    shot.strike.phi = 0.002;
    table.strike(shot, 0);
    table.advanceTo(after);
  }
  const auto& params = scene.engine->params();
  cue_sim::camera::CameraOptions options;
  options.noise_stddev = static_cast<double>(bench.range(1));
  const cue_sim::camera::Pose pose =
      cue_sim::camera::overheadPose(scene.engine->table().clothCentre(), cue_sim::camera::kOverheadHeight);
  cue_sim::camera::TableCamera camera(scene.engine->table(), params.ball_radius, params.cushion_height,
                                      cue_sim::camera::Intrinsics{}.scaled(1280, 800), pose, options);
  std::size_t instants = 0;
  for (auto _ : bench)
  {
    const cue_sim::camera::Exposure exposure =
        cue_sim::camera::exposureOf(table.motion(), table.clock(), after, kExposure);
    instants = exposure.instants.size();
    const cue_sim::camera::Frame frame = camera.render(exposure);
    benchmark::DoNotOptimize(frame.image.data);
  }
  bench.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(bench.iterations()), benchmark::Counter::kIsRate);
  bench.counters["instants"] = static_cast<double>(instants);
}
BENCHMARK(CameraFrame1280x800)
    ->ArgNames({"ms_after_break", "noise"})
    ->Args({0, 0})
    ->Args({40, 0})
    ->Args({40, 3})
    ->Unit(benchmark::kMillisecond);

}  // namespace
