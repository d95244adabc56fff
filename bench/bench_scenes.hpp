// The fixed scenes of the speed benchmarks (issue 5), shared by `bench` (Google Benchmark,
// wall time) and `bench_scene` (one shot, for callgrind instruction counts).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace bench
{
using namespace physics;

/// A shot ready to run to rest: the engine it runs on and the struck table.
struct BenchScene
{
  std::shared_ptr<const Engine<double>> engine;
  TableState<double> state;
};

inline std::shared_ptr<const TableModel> sevenFoot()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  return table;
}

/// Default coefficients and models (unless `models` says otherwise) on `table`.
inline std::shared_ptr<const Engine<double>> defaultEngine(std::shared_ptr<const TableModel> table,
                                                           long max_events = EngineLimits().max_events,
                                                           const ModelChoice& models = ModelChoice())
{
  EngineLimits limits;
  limits.max_events = max_events;
  return std::make_shared<const Engine<double>>(std::move(table), PhysicsParams<double>(), models, limits);
}

/// A real rack's uneven gaps: 0.2 mm nominal, each ball moved up to 0.1 mm (fixed seed).
inline RackOptions realRack()
{
  RackOptions rack;
  rack.gap = 2e-4;
  rack.jitter = 1e-4;
  rack.seed = 2026;
  return rack;
}

inline BenchScene struck(std::shared_ptr<const Engine<double>> engine, TableState<double> state, double speed,
                         double phi, double a = 0, double b = 0)
{
  CueStrike<double> cue;
  cue.speed = speed;
  cue.phi = phi;
  cue.a = a;
  cue.b = b;
  engine->strike(state, 0, cue);
  return {std::move(engine), std::move(state)};
}

/// The cue ball sent off at `speed` [m/s] along `phi`, without spin (a centre hit with a level
/// cue): how fast the cue ball meets the rack is what defines a break.
inline BenchScene sent(std::shared_ptr<const Engine<double>> engine, TableState<double> state, double speed, double phi)
{
  Ball<double>& cue_ball = state.balls[state.indexOf(0)];
  cue_ball.v = Vec3<double>(speed * std::cos(phi), speed * std::sin(phi), 0);
  settleMotion(cue_ball, engine->params().ball_radius);
  return {std::move(engine), std::move(state)};
}

/// `count` balls placed at random (from `seed`) and clear of each other, on a pool table scaled
/// so that the density stays that of 16 balls on a 7-ft table; every ball is then sent off at
/// 0.5 to 2 m/s in a random direction with random English, as after a break, and the scene runs
/// to rest. The fixed scenes `scaling_N` use seed N.
inline BenchScene scaling(int count, unsigned seed)
{
  const double scale = std::sqrt(count / 16.0);
  const auto table =
      std::make_shared<const TableModel>(TableModel::pool("scaled", 1.9812 * scale, 0.9906 * scale, 0.118, 0.137));
  auto engine = defaultEngine(table, 10'000'000);
  const double R = engine->params().ball_radius;
  std::mt19937 random(seed);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  TableState<double> state;
  const double hx = table->clothLength() / 2 - 2 * R, hy = table->clothWidth() / 2 - 2 * R;
  while (static_cast<int>(state.balls.size()) < count)
  {
    Ball<double> b;
    b.id = static_cast<int>(state.balls.size());
    b.r = Vec3<double>((2 * unit() - 1) * hx, (2 * unit() - 1) * hy, R);
    bool clear = table->whyNotPlaceable(b.r.head<2>(), R).empty();
    for (const auto& other : state.balls)
      clear = clear && (other.r - b.r).norm() > 2 * R + 1e-6;
    if (clear)
      state.balls.push_back(b);
  }
  for (auto& b : state.balls)
  {
    const double speed = 0.5 + 1.5 * unit(), heading = 2 * M_PI * unit();
    b.v = Vec3<double>(speed * std::cos(heading), speed * std::sin(heading), 0);
    b.w = Vec3<double>((unit() - 0.5) * 40, (unit() - 0.5) * 40, (unit() - 0.5) * 40);
    settleMotion(b, R);
  }
  return {engine, state};
}

/// Scaling scenes of `count` balls from other seeds, as many as it takes for one pass over them
/// to hold several thousand events (at least 4): a shot replayed again and again teaches the
/// CPU's branch predictor its path, and a planner's shots are all different.
inline int distinctSceneCount(int count)
{
  return std::max(4, 1024 / count);
}
inline std::vector<BenchScene> distinctScalingScenes(int count)
{
  std::vector<BenchScene> scenes;
  for (int k = 0; k < distinctSceneCount(count); ++k)
    scenes.push_back(scaling(count, static_cast<unsigned>(1000 * count + k)));
  return scenes;
}

/// The 8-ball break with a cushion model: `eight_ball_break` with the default, and
/// `eight_ball_break_<model>` with each, what a model costs a whole shot.
inline BenchScene eightBallBreakWith(const ModelChoice& models)
{
  auto engine = defaultEngine(sevenFoot(), EngineLimits().max_events, models);
  return sent(engine, rackLayout<double>("eight", engine->table(), engine->params().ball_radius, realRack()), 8.0, 0.0);
}

/// Every scene by name, built on demand.
inline const std::map<std::string, std::function<BenchScene()>>& benchScenes()
{
  static const std::map<std::string, std::function<BenchScene()>> scenes = {
      {"eight_ball_break", [] { return eightBallBreakWith(ModelChoice()); }},
      {"nine_ball_break",
       [] {
         auto engine = defaultEngine(sevenFoot());
         return sent(engine, rackLayout<double>("nine", engine->table(), engine->params().ball_radius, realRack()), 8.0,
                     0.0);
       }},
      {"single_ball_stun",
       [] {
         auto engine = defaultEngine(sevenFoot());
         return struck(engine, rackLayout<double>("empty", engine->table(), engine->params().ball_radius), 3.0, 0.4);
       }},
      {"single_ball_english",
       [] {
         auto engine = defaultEngine(sevenFoot());
         return struck(engine, rackLayout<double>("empty", engine->table(), engine->params().ball_radius), 3.0, 0.4,
                       0.3, -0.3);
       }},
      // The same shot with the 8-ball rack resting at the foot: the cue ball goes to the head
      // end and never reaches it.
      {"single_ball_among_15_resting",
       [] {
         auto engine = defaultEngine(sevenFoot());
         return struck(engine, rackLayout<double>("eight", engine->table(), engine->params().ball_radius, realRack()),
                       1.0, M_PI - 0.4);
       }},
      {"single_ball_alone_same_shot",
       [] {
         auto engine = defaultEngine(sevenFoot());
         return struck(engine, rackLayout<double>("empty", engine->table(), engine->params().ball_radius), 1.0,
                       M_PI - 0.4);
       }},
      // A half-ball cut: the object ball 0.6 m ahead, its centre R to the side of the line.
      {"cut_shot",
       [] {
         auto engine = defaultEngine(sevenFoot());
         TableState<double> state = rackLayout<double>("empty", engine->table(), engine->params().ball_radius);
         Ball<double> object = state.balls[0];
         object.id = 1;
         object.r += Vec3<double>(0.6, engine->params().ball_radius, 0);
         state.balls.push_back(object);
         return struck(engine, state, 2.0, 0.0);
       }},
      {"carom_three_balls",
       [] {
         auto engine = defaultEngine(std::make_shared<const TableModel>(TableModel::carom("carom", 2.84, 1.42)));
         TableState<double> state;
         for (int id = 0; id < 3; ++id)
         {
           Ball<double> b;
           b.id = id;
           b.r = Vec3<double>(-0.5 + 0.5 * id, 0.1 * id - 0.1, engine->params().ball_radius);
           state.balls.push_back(b);
         }
         return struck(engine, state, 4.0, 0.15, 0.2, 0.2);
       }},
      // Issue 33: a jump shot (sequential cue at 45 degrees, V0 3 m/s) over a ball 0.3 m ahead, its
      // flight, landing and bounces (at 4 m/s it flies off over the foot cushion); and a ball dropped from 0.2 m onto a
      // cluster of four touching balls, bouncing off them and the slate.
      {"jump_shot",
       [] {
         auto engine = defaultEngine(sevenFoot(), EngineLimits().max_events, ModelChoice("", "", "", "sequential"));
         const double R = engine->params().ball_radius;
         TableState<double> state = rackLayout<double>("empty", engine->table(), R);
         Ball<double> obstacle = state.balls[0];
         obstacle.id = 1;
         obstacle.r += Vec3<double>(0.3, 0, 0);
         state.balls.push_back(obstacle);
         CueStrike<double> cue;
         cue.speed = 3.0;
         cue.theta = M_PI / 4;
         engine->strike(state, 0, cue);
         return BenchScene{engine, state};
       }},
      {"bouncing_cluster",
       [] {
         auto engine = defaultEngine(sevenFoot());
         const double R = engine->params().ball_radius;
         TableState<double> state;
         for (int id = 1; id <= 4; ++id)
         {
           Ball<double> b;
           b.id = id;
           b.r = Vec3<double>((id % 2) * 2 * R, (id / 3) * 2 * R, R);
           state.balls.push_back(b);
         }
         Ball<double> dropped;
         dropped.r = Vec3<double>(R + 0.004, R - 0.003, R + 0.2);
         dropped.v = Vec3<double>(0.3, 0.1, 0);
         settleMotion(dropped, R);
         state.balls.push_back(dropped);
         return BenchScene{engine, state};
       }},
      {"scaling_16", [] { return scaling(16, 16); }},
      {"scaling_64", [] { return scaling(64, 64); }},
      {"scaling_256", [] { return scaling(256, 256); }},
      {"scaling_1024", [] { return scaling(1024, 1024); }},
  };
  return scenes;
}

/// The stepped runs: a scene advanced in steps of 1/rate s until it rests, as the node's tick
/// advances the live table (`<scene>_stepped_<rate>Hz`).
inline const std::map<std::string, std::pair<std::string, double>>& steppedRuns()
{
  static const std::map<std::string, std::pair<std::string, double>> runs = {
      {"eight_ball_break_stepped_100Hz", {"eight_ball_break", 100.0}},
      {"eight_ball_break_stepped_1000Hz", {"eight_ball_break", 1000.0}},
  };
  return runs;
}

/// Runs the scene's state to rest: in one call (rate 0), or advanced in steps of 1/rate s.
/// Returns whether it came to rest; its events are appended to `events`.
#if defined(__GNUC__)
__attribute__((noinline))
#endif
inline bool
runScene(const BenchScene& scene, TableState<double>& state, double rate, std::vector<Event<double>>& events)
{
  if (rate == 0)
  {
    ShotResult<double> result = simulateToRest(*scene.engine, state);
    if (events.empty())
      events.swap(result.events);
    else
      events.insert(events.end(), result.events.begin(), result.events.end());
    return result.at_rest;
  }
  Simulation<double> simulation(*scene.engine, std::move(state));
  const double start = simulation.time(), period = 1.0 / rate;
  const double end = start + scene.engine->limits().max_shot_time;
  for (long k = 1; !simulation.atRest() && simulation.time() < end; ++k)
    simulation.advance(start + static_cast<double>(k) * period, &events);
  const bool at_rest = simulation.atRest();
  state = std::move(simulation).release();
  return at_rest;
}

inline BenchScene benchScene(const std::string& name)
{
  const auto& scenes = benchScenes();
  const auto found = scenes.find(name);
  if (found == scenes.end())
    throw std::invalid_argument("unknown scene '" + name + "'");
  return found->second();
}

}  // namespace bench
}  // namespace cue_sim
