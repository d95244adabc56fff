#include "cue_sim/evaluation/cushion_precision.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "cue_sim/physics/collision_models.hpp"

namespace cue_sim
{
namespace evaluation
{
using physics::Ball;
using physics::PhysicsParams;
using physics::Vec3;

std::vector<Ball<double>> cushionArrivals(const PhysicsParams<double>& p)
{
  std::vector<Ball<double>> balls;
  for (const double alpha_deg : {5.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0})
  {
    const double alpha = alpha_deg * M_PI / 180;
    const auto arrive = [&](double top, double side) {
      Ball<double> b;
      b.r = Vec3<double>(0, 0, p.ball_radius);
      b.v = Vec3<double>(std::cos(alpha), std::sin(alpha), 0);
      b.w = Vec3<double>(-top * std::sin(alpha), top * std::cos(alpha), side) / p.ball_radius;
      balls.push_back(b);
    };
    for (const double top : {-1.0, 0.0, 1.0, 2.0})
      arrive(top, 0.0);
    for (const double side : {-2.0, -1.0, 1.0, 2.0})
      arrive(1.0, side);
  }
  return balls;
}

namespace
{
/// The ball after `model`'s impact with a cushion of normal -y, at the tolerance `p` gives.
template <typename S>
Ball<S> rebound(const physics::CushionModel<S>& model, Ball<S> ball, const PhysicsParams<S>& p)
{
  model.resolve(ball, Vec3<S>(0, -1, 0), p);
  return ball;
}

/// Each arrival's rebound from `model` in long double, with `p`'s coefficients.
std::vector<Ball<double>> longDoubleRebounds(const std::string& model, const std::vector<Ball<double>>& arrivals,
                                             const PhysicsParams<long double>& p)
{
  const auto resolver = physics::makeCushionModel<long double>(model);
  std::vector<Ball<double>> rebounds;
  for (const Ball<double>& b : arrivals)
  {
    Ball<long double> bl;
    bl.r = b.r.cast<long double>();
    bl.v = b.v.cast<long double>();
    bl.w = b.w.cast<long double>();
    const Ball<long double> out = rebound(*resolver, bl, p);
    Ball<double> back = b;
    back.v = out.v.cast<double>();
    back.w = out.w.cast<double>();
    rebounds.push_back(back);
  }
  return rebounds;
}

/// `model` in double on every arrival against `reference`: the largest errors, and the median
/// over `repeats` of the time per impact.
CushionPrecision measure(const std::string& model, const std::vector<Ball<double>>& arrivals,
                         const std::vector<Ball<double>>& reference, const PhysicsParams<double>& p, int repeats)
{
  const auto resolver = physics::makeCushionModel<double>(model);
  CushionPrecision r;
  r.tolerance = p.cushion_impact_tolerance;
  std::vector<double> times;
  for (int repeat = 0; repeat < std::max(1, repeats); ++repeat)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < arrivals.size(); ++k)
    {
      const Ball<double> out = rebound(*resolver, arrivals[k], p);
      if (repeat == 0)
      {
        r.max_velocity_error = std::max(r.max_velocity_error, (out.v - reference[k].v).norm());
        r.max_spin_error = std::max(r.max_spin_error, p.ball_radius * (out.w - reference[k].w).norm());
      }
    }
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    times.push_back(took.count() / static_cast<double>(arrivals.size()));
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  r.seconds_per_impact = times[times.size() / 2];
  return r;
}
}  // namespace

std::vector<CushionPrecision> cushionImpactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                                     int repeats)
{
  PhysicsParams<double> p;
  PhysicsParams<long double> pl = p.cast<long double>();
  pl.cushion_impact_tolerance = reference_tolerance;
  const std::vector<Ball<double>> arrivals = cushionArrivals(p);
  const std::vector<Ball<double>> reference = longDoubleRebounds("mathavan2010", arrivals, pl);
  std::vector<CushionPrecision> results;
  for (const double tolerance : tolerances)
  {
    p.cushion_impact_tolerance = tolerance;
    results.push_back(measure("mathavan2010", arrivals, reference, p, repeats));
  }
  return results;
}

std::vector<CushionModelCost> cushionModelCosts(double reference_tolerance, int repeats)
{
  const PhysicsParams<double> p;
  const PhysicsParams<long double> pl = p.cast<long double>();
  PhysicsParams<long double> integrated = pl;
  integrated.cushion_impact_tolerance = reference_tolerance;
  const std::vector<Ball<double>> arrivals = cushionArrivals(p);
  const std::vector<Ball<double>> mathavan = longDoubleRebounds("mathavan2010", arrivals, integrated);
  std::vector<CushionModelCost> costs;
  for (const std::string& model : physics::cushionModelNames())
  {
    CushionModelCost c;
    c.model = model;
    c.own = measure(model, arrivals, longDoubleRebounds(model, arrivals, pl), p, repeats);
    const CushionPrecision against = measure(model, arrivals, mathavan, p, 1);
    c.velocity_difference = against.max_velocity_error;
    c.spin_difference = against.max_spin_error;
    costs.push_back(c);
  }
  return costs;
}

}  // namespace evaluation
}  // namespace cue_sim
