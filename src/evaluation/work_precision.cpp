#include "cue_sim/evaluation/work_precision.hpp"

#include <algorithm>
#include <chrono>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace evaluation
{
using namespace physics;

namespace
{
/// The bundled 7 ft pool table's playing area, cushion and pocket sizes [m].
TableModel sevenFoot()
{
  return TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137);
}

ShotScene strikeScene(std::string name, bool single, TableState<double> state, int ball, const CueStrike<double>& cue,
                      const TableModel& table = sevenFoot(), const ModelChoice& models = ModelChoice())
{
  ShotScene scene;
  scene.name = std::move(name);
  scene.models = models;
  scene.single_shot = single;
  scene.table = std::make_shared<const TableModel>(table);
  const Engine<double> engine(scene.table, scene.params, scene.models);
  engine.strike(state, ball, cue);
  scene.state = state;
  return scene;
}

Ball<double> resting(int id, double x, double y, double R)
{
  Ball<double> b;
  b.id = id;
  b.r = Vec3<double>(x, y, R);
  return b;
}

template <typename Clock = std::chrono::steady_clock>
double secondsSince(typename Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// A ball's centre for comparison: pocketed balls count as at their pocket's centre on the cloth
/// (z = R), so that a shot on the cloth is compared in the plane alone.
template <typename S>
Eigen::Vector3d where(const Ball<S>& b, const ShotScene& scene)
{
  if (b.motion == Motion::Pocketed && b.pocket >= 0)
  {
    const Vec2<double>& centre = scene.table->pockets()[b.pocket].centre;
    return Eigen::Vector3d(centre.x(), centre.y(), scene.params.ball_radius);
  }
  return b.r.template cast<double>();
}
}  // namespace

std::vector<ShotScene> workPrecisionScenes()
{
  const double R = PhysicsParams<double>().ball_radius;
  std::vector<ShotScene> scenes;
  {
    TableState<double> s;
    s.balls.push_back(resting(0, -0.5, 0.0, R));
    CueStrike<double> cue;
    cue.speed = 0.4;
    cue.b = -0.2;  // a little backspin: it slides, then rolls to rest
    scenes.push_back(strikeScene("single ball sliding to rest", true, s, 0, cue));
  }
  {
    TableState<double> s;
    s.balls.push_back(resting(0, -0.5, 0.0, R));
    s.balls.push_back(resting(1, 0.0, 0.03, R));
    CueStrike<double> cue;
    cue.speed = 1.5;
    cue.b = -0.25;  // arrives sliding without topspin: a stun cut
    scenes.push_back(strikeScene("stun cut shot", true, s, 0, cue));
  }
  {
    TableState<double> s;
    s.balls.push_back(resting(0, -0.55, 0.02, R));
    s.balls.push_back(resting(1, -0.25, 0.0, R));
    CueStrike<double> cue;
    cue.speed = 2.5;
    cue.b = -0.4;  // draws back into the head cushion
    scenes.push_back(strikeScene("draw shot off a cushion", true, s, 0, cue));
  }
  {
    // Flight: a cue at 45 degrees jumps the ball over one 0.2 m ahead (11 mm to spare); it comes
    // down 0.38 m on and bounces eleven times, its draw taken by the slate's friction over the
    // first four, then rolls into the foot cushion and back, and stops.
    TableState<double> s;
    s.balls.push_back(resting(0, -0.7, 0.0, R));
    s.balls.push_back(resting(1, -0.5, 0.0, R));
    CueStrike<double> cue;
    cue.speed = 2.5;
    cue.theta = M_PI / 4;
    cue.b = -0.3;
    scenes.push_back(strikeScene("jump shot with draw over a ball", true, s, 0, cue, sevenFoot(),
                                 ModelChoice("", "", "", "sequential")));
  }
  const TableModel table = sevenFoot();
  CueStrike<double> cue;
  cue.speed = 8.0;
  scenes.push_back(strikeScene("9-ball break", false, rackLayout<double>("nine", table, R), 0, cue));
  scenes.push_back(strikeScene("8-ball break", false, rackLayout<double>("eight", table, R), 0, cue));
  return scenes;
}

std::vector<ShotScene> stabilityScenes()
{
  const double R = PhysicsParams<double>().ball_radius;
  const TableModel table = sevenFoot();
  std::vector<ShotScene> scenes;
  CueStrike<double> cue;
  cue.speed = 3.0;
  cue.phi = 0.3;
  {
    TableState<double> s;
    s.balls.push_back(resting(0, -0.5, 0.0, R));
    ShotScene scene = strikeScene("stiff friction, mu_s = 50", true, s, 0, cue);
    scene.params.mu_slide = 50.0;
    scenes.push_back(scene);
  }
  {
    ShotScene scene = strikeScene("ball at 50 m/s into a rack", false, rackLayout<double>("eight", table, R), 0, cue);
    scene.state.balls[0].v = Vec3<double>(50.0, 0.0003, 0);
    scene.state.balls[0].w.setZero();
    settleMotion(scene.state.balls[0], R);
    scenes.push_back(scene);
  }
  {
    TableState<double> s;
    s.balls.push_back(resting(0, 0.2, 0.9906 / 2 - R, R));  // frozen to the top cushion
    CueStrike<double> into = cue;
    into.phi = M_PI / 2;
    scenes.push_back(strikeScene("frozen to a cushion, struck into it", true, s, 0, into));
  }
  {
    // A dead cushion: e_cushion = 0 leaves the ball no normal speed, and its follow keeps
    // pressing it into the cushion; it slides, then rolls, along the cushion and stops on it
    // (at x = 0.43 m, short of the corner pocket).
    TableState<double> s;
    s.balls.push_back(resting(0, -0.3, 0.9906 / 2 - R - 0.3, R));
    CueStrike<double> follow = cue;
    follow.speed = 1.0;
    follow.phi = 1.2;
    follow.b = 0.4;
    ShotScene scene = strikeScene("dead cushion (e = 0), follow into it", true, s, 0, follow);
    scene.params.e_cushion = 0.0;
    scenes.push_back(scene);
  }
  {
    // The carom table's corner is a right angle: the ball meets both cushions at once.
    const TableModel carom = TableModel::carom("carom", 2.84, 1.42);
    TableState<double> s;
    s.balls.push_back(resting(0, 2.84 / 2 - R - 0.6, 1.42 / 2 - R - 0.6, R));
    CueStrike<double> corner = cue;
    corner.phi = M_PI / 4;
    scenes.push_back(strikeScene("into a corner at 45 degrees", true, s, 0, corner, carom));
  }
  {
    TableState<double> s;
    s.balls.push_back(resting(0, -0.5, 0.0, R));
    for (int i = 1; i <= 8; ++i)
      s.balls.push_back(resting(i, -0.3 + 2 * R * (i - 1), 0.0, R));
    CueStrike<double> straight = cue;
    straight.phi = 0.0;
    scenes.push_back(strikeScene("Newton's cradle of 8", true, s, 0, straight));
  }
  {
    TableState<double> s;
    s.balls.push_back(resting(0, 0.1, 0.1, R));
    ShotScene scene = strikeScene("a ball at 1e-9 m/s", true, s, 0, cue);
    scene.state.balls[0].v = Vec3<double>(1e-9, 0, 0);
    scene.state.balls[0].w.setZero();
    settleMotion(scene.state.balls[0], R);
    scenes.push_back(scene);
  }
  return scenes;
}

Samples referenceRun(const ShotScene& scene, double interval, double max_time)
{
  const Engine<long double> engine(scene.table, scene.params.cast<long double>(), scene.models);
  TableState<long double> state = scene.state.cast<long double>();
  TableState<long double> probe = state;
  const ShotResult<long double> rest = simulateToRest(engine, probe);
  const double end = std::min(static_cast<double>(rest.duration), max_time);
  Samples out;
  for (long k = 0; k * interval <= end + interval; ++k)
  {
    const double t = k * interval;
    advance(engine, state, static_cast<long double>(t));
    out.times.push_back(t);
    std::vector<Eigen::Vector3d> row;
    for (std::size_t i = 0; i < state.balls.size(); ++i)
      row.push_back(where(engine.ballAt(state, i, static_cast<long double>(t)), scene));
    out.positions.push_back(row);
  }
  return out;
}

void compareSamples(const Samples& run, const Samples& reference, double& max_error, double& final_error)
{
  max_error = final_error = 0;
  const std::size_t n = std::min(run.positions.size(), reference.positions.size());
  for (std::size_t k = 0; k < n; ++k)
  {
    double worst = 0;
    for (std::size_t i = 0; i < reference.positions[k].size(); ++i)
      worst = std::max(worst, (run.positions[k][i] - reference.positions[k][i]).norm());
    max_error = std::max(max_error, worst);
    if (k + 1 == n)
      final_error = worst;
  }
}

MethodResult runEventEngine(const ShotScene& scene, const Samples& reference, int repeats)
{
  const Engine<double> engine(scene.table, scene.params, scene.models);
  MethodResult result;
  result.method = "event";
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r)
  {
    TableState<double> state = scene.state;
    const auto start = std::chrono::steady_clock::now();
    const ShotResult<double> shot = simulateToRest(engine, state);
    times.push_back(secondsSince(start));
    result.work = static_cast<long>(shot.events.size());
  }
  result.seconds = median(times);
  // Sampling is not timed: the run above already holds every event; evaluating the closed
  // forms at the sample times is what a user asking for them would add.
  TableState<double> state = scene.state;
  Samples run;
  for (double t : reference.times)
  {
    advance(engine, state, t);
    std::vector<Eigen::Vector3d> row;
    for (std::size_t i = 0; i < state.balls.size(); ++i)
      row.push_back(where(engine.ballAt(state, i, t), scene));
    run.times.push_back(t);
    run.positions.push_back(row);
  }
  compareSamples(run, reference, result.max_error, result.final_error);
  return result;
}

MethodResult runStepper(const ShotScene& scene, const Samples& reference, Integrator integrator, double parameter,
                        int repeats)
{
  StepperOptions options;
  options.integrator = integrator;
  if (integrator == Integrator::DormandPrince54)
  {
    options.tolerance = parameter;
    options.step = 1e-3;
    options.max_steps = 300000;  // each step watches every event function: a budget, not a hang
  }
  else
    options.step = parameter;
  options.max_time = reference.times.empty() ? 0.0 : reference.times.back();
  const TimeStepper stepper(scene.table, scene.params, scene.models, options);
  MethodResult result;
  result.method = integratorName(integrator);
  result.parameter = parameter;
  std::vector<double> times;
  Samples run;
  for (int r = 0; r < repeats; ++r)
  {
    Samples this_run;
    const auto start = std::chrono::steady_clock::now();
    result.stepper = stepper.run(scene.state, reference.times, [&](double t, const std::vector<Ball<double>>& balls) {
      std::vector<Eigen::Vector3d> row;
      for (const auto& b : balls)
        row.push_back(where(b, scene));
      this_run.times.push_back(t);
      this_run.positions.push_back(std::move(row));
    });
    times.push_back(secondsSince(start));
    run = std::move(this_run);
  }
  result.seconds = median(times);
  result.work = result.stepper.steps;
  compareSamples(run, reference, result.max_error, result.final_error);
  return result;
}

}  // namespace evaluation
}  // namespace cue_sim
