#include "cue_sim/evaluation/cushion_precision.hpp"

#include <cmath>

#include "cue_sim/physics/collision_models.hpp"
#include "evaluation/impact_measurement.hpp"

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
/// A ball meeting a cushion of normal -y.
struct CushionKind
{
  using Arrival = Ball<double>;
  static std::vector<std::string> models() { return physics::cushionModelNames(); }
  template <typename S>
  static auto make(const std::string& model)
  {
    return physics::makeCushionModel<S>(model);
  }
  template <typename S>
  static Arrival resolve(const physics::CushionModel<S>& model, const Arrival& arrival, const PhysicsParams<S>& p)
  {
    Ball<S> ball;
    ball.r = arrival.r.cast<S>();
    ball.v = arrival.v.cast<S>();
    ball.w = arrival.w.cast<S>();
    model.resolve(ball, Vec3<S>(0, -1, 0), p);
    Arrival out = arrival;
    out.v = ball.v.template cast<double>();
    out.w = ball.w.template cast<double>();
    return out;
  }
  template <typename S>
  static void setTolerance(PhysicsParams<S>& p, double tolerance)
  {
    p.cushion_impact_tolerance = S(tolerance);
  }
  static std::pair<double, double> errors(const Arrival& out, const Arrival& reference, double R)
  {
    return {(out.v - reference.v).norm(), R * (out.w - reference.w).norm()};
  }
};
}  // namespace

std::vector<CushionPrecision> cushionImpactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                                     int repeats)
{
  return tolerancePrecision<CushionKind>("mathavan2010", cushionArrivals(PhysicsParams<double>()), tolerances,
                                         reference_tolerance, repeats);
}

std::vector<CushionModelCost> cushionModelCosts(double reference_tolerance, int repeats)
{
  return modelCosts<CushionKind>("mathavan2010", cushionArrivals(PhysicsParams<double>()), reference_tolerance,
                                 repeats);
}

}  // namespace evaluation
}  // namespace cue_sim
