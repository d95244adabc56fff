#include "cue_sim/evaluation/ball_impact_precision.hpp"

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
using BallPair = std::pair<Ball<double>, Ball<double>>;

std::vector<BallPair> ballArrivals(const PhysicsParams<double>& p)
{
  std::vector<BallPair> pairs;
  for (const double cut_deg : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0})
  {
    const double cut = cut_deg * M_PI / 180;
    const auto arrive = [&](double top, double side) {
      Ball<double> cue, object;
      cue.r = Vec3<double>(0, 0, p.ball_radius);
      cue.v = Vec3<double>(1, 0, 0);
      cue.w = Vec3<double>(0, top, side) / p.ball_radius;
      object.r = cue.r + 2 * p.ball_radius * Vec3<double>(std::cos(cut), std::sin(cut), 0);
      pairs.emplace_back(cue, object);
    };
    for (const double top : {-1.0, 0.0, 1.0, 2.0})
      arrive(top, 0.0);
    for (const double side : {-2.0, -1.0, 1.0, 2.0})
      arrive(1.0, side);
  }
  return pairs;
}

namespace
{
/// A cue ball meeting an object ball.
struct BallBallKind
{
  using Arrival = BallPair;
  static std::vector<std::string> models() { return physics::ballBallModelNames(); }
  template <typename S>
  static auto make(const std::string& model)
  {
    return physics::makeBallBallModel<S>(model);
  }
  template <typename S>
  static Arrival resolve(const physics::BallBallModel<S>& model, const Arrival& arrival, const PhysicsParams<S>& p)
  {
    Ball<S> a = widened<S>(arrival.first), b = widened<S>(arrival.second);
    model.resolve(a, b, p);
    return {narrowed(arrival.first, a), narrowed(arrival.second, b)};
  }
  template <typename S>
  static void setTolerance(PhysicsParams<S>& p, double tolerance)
  {
    p.ball_impact_tolerance = S(tolerance);
  }
  static std::pair<double, double> errors(const Arrival& out, const Arrival& reference, double R)
  {
    return {(out.first.v - reference.first.v).norm() + (out.second.v - reference.second.v).norm(),
            R * ((out.first.w - reference.first.w).norm() + (out.second.w - reference.second.w).norm())};
  }

private:
  template <typename S>
  static Ball<S> widened(const Ball<double>& b)
  {
    Ball<S> wide;
    wide.r = b.r.cast<S>();
    wide.v = b.v.cast<S>();
    wide.w = b.w.cast<S>();
    return wide;
  }
  template <typename S>
  static Ball<double> narrowed(Ball<double> b, const Ball<S>& wide)
  {
    b.v = wide.v.template cast<double>();
    b.w = wide.w.template cast<double>();
    return b;
  }
};
}  // namespace

std::vector<CushionPrecision> ballImpactPrecision(const std::vector<double>& tolerances, double reference_tolerance,
                                                  int repeats)
{
  return tolerancePrecision<BallBallKind>("mathavan2014", ballArrivals(PhysicsParams<double>()), tolerances,
                                          reference_tolerance, repeats);
}

std::vector<CushionModelCost> ballModelCosts(double reference_tolerance, int repeats)
{
  return modelCosts<BallBallKind>("mathavan2014", ballArrivals(PhysicsParams<double>()), reference_tolerance, repeats);
}

}  // namespace evaluation
}  // namespace cue_sim
