#include "cue_sim/evaluation/contact_precision.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace evaluation
{
namespace
{
using physics::Ball;
using physics::PhysicsParams;
using physics::TableState;
using physics::Vec3;

/// The 7-ft table the tests use, and its nose line (the cushion at +y).
std::shared_ptr<const physics::TableModel> sevenFoot()
{
  return std::make_shared<const physics::TableModel>(physics::TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
}
constexpr double kNoseY = 0.9906 / 2;

template <typename S>
Ball<S> placed(int id, double x, double y, double z, const Vec3<double>& v = Vec3<double>::Zero(),
               const Vec3<double>& w = Vec3<double>::Zero())
{
  const PhysicsParams<S> p;
  Ball<S> b;
  b.id = id;
  b.r = Vec3<S>(S(x), S(y), S(z));
  b.v = v.cast<S>();
  b.w = w.cast<S>();
  physics::settleMotion(b, p.ball_radius);
  return b;
}

/// Scene k of contactPrecisionScenes(), in S.
template <typename S>
TableState<S> contactScene(int k)
{
  const PhysicsParams<double> p;
  const double R = p.ball_radius, h = p.cushion_height;
  TableState<S> s;
  switch (k)
  {
    case 0:  // 0.1 rad off a still ball's top
      s.balls.push_back(placed<S>(0, 0, 0, R));
      s.balls.push_back(placed<S>(1, -2 * R * std::sin(0.1), 0, R + 2 * R * std::cos(0.1)));
      break;
    case 1:  // 0.1 rad off a nose's edge, on the cloth's side
      s.balls.push_back(placed<S>(0, 0.2, kNoseY - R * std::sin(0.1), h + R * std::cos(0.1)));
      break;
    case 2:  // at rest 0.35 rad back on a ball rolling at 0.5 m/s
    {
      const Vec3<double> v(0.5, 0, 0);
      s.balls.push_back(placed<S>(0, -0.3, 0, R, v, Vec3<double>(0, v.x() / R, 0)));
      s.balls.push_back(placed<S>(1, -0.3 - 2 * R * std::sin(0.35), 0, R + 2 * R * std::cos(0.35), v));
      break;
    }
    default:  // a pyramid of four: three touching on the cloth, one on them
    {
      const double side = 2 * R, circum = side / std::sqrt(3.0);
      for (int i = 0; i < 3; ++i)
      {
        const double a = 2 * M_PI * i / 3;
        s.balls.push_back(placed<S>(i, circum * std::cos(a), circum * std::sin(a), R));
      }
      s.balls.push_back(placed<S>(3, 0, 0, R + std::sqrt(4 * R * R - circum * circum)));
      break;
    }
  }
  return s;
}
constexpr int kScenes = 4;

/// Scene k run for `duration` at `tolerance`: every ball at the end.
template <typename S>
std::vector<Ball<double>> runScene(int k, double tolerance, double duration)
{
  PhysicsParams<S> p;
  p.contact_tolerance = S(tolerance);
  const physics::Engine<S> engine(sevenFoot(), p);
  physics::Simulation<S> simulation(engine, contactScene<S>(k));
  simulation.advance(S(duration));
  std::vector<Ball<double>> out;
  for (std::size_t i = 0; i < simulation.state().balls.size(); ++i)
  {
    const Ball<S> b = engine.ballAt(simulation.state(), i, S(duration));
    Ball<double> d;
    d.id = b.id;
    d.r = b.r.template cast<double>();
    d.v = b.v.template cast<double>();
    out.push_back(d);
  }
  return out;
}
}  // namespace

std::vector<std::string> contactPrecisionScenes()
{
  return {"a ball 0.1 rad off a still ball's top", "a ball 0.1 rad off a cushion nose's edge",
          "a ball 0.35 rad back on a ball rolling at 0.5 m/s", "a pyramid of four on a pool cloth"};
}

std::vector<ContactPrecision> contactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                               double duration, int repeats)
{
  std::vector<std::vector<Ball<double>>> reference;
  for (int k = 0; k < kScenes; ++k)
    reference.push_back(runScene<long double>(k, reference_tolerance, duration));
  std::vector<ContactPrecision> out;
  for (const double tolerance : tolerances)
  {
    ContactPrecision r;
    r.tolerance = tolerance;
    for (int k = 0; k < kScenes; ++k)
    {
      std::vector<double> seconds;
      std::vector<Ball<double>> balls;
      for (int rep = 0; rep < std::max(1, repeats); ++rep)
      {
        const auto started = std::chrono::steady_clock::now();
        balls = runScene<double>(k, tolerance, duration);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
      }
      std::nth_element(seconds.begin(), seconds.begin() + seconds.size() / 2, seconds.end());
      r.seconds_per_run += seconds[seconds.size() / 2];
      double scene_error = 0;
      for (std::size_t i = 0; i < balls.size(); ++i)
      {
        scene_error = std::max(scene_error, (balls[i].r - reference[k][i].r).norm());
        r.max_velocity_error = std::max(r.max_velocity_error, (balls[i].v - reference[k][i].v).norm());
      }
      r.position_error.push_back(scene_error);
      r.max_position_error = std::max(r.max_position_error, scene_error);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace evaluation
}  // namespace cue_sim
