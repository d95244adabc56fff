// Measuring a contact model on a set of arrivals: its run time per impact and its errors
// against a reference, once for every kind of impact. Private to the evaluation.
//
// A Kind says what an arrival is and how a model of its kind resolves one:
//   using Arrival;                                   // in double
//   static std::vector<std::string> models();        // every registered model of the kind
//   template <typename S> static auto make(name);    // the model in S
//   template <typename S> static Arrival resolve(model, arrival, p);  // in S, back in double
//   static void setTolerance(PhysicsParams<S>&, double);
//   static std::pair<double, double> errors(out, reference, R);       // velocity, R x spin
#pragma once

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "cue_sim/evaluation/cushion_precision.hpp"

namespace cue_sim
{
namespace evaluation
{
/// Each arrival resolved by `model` in S, with `p`'s coefficients.
template <typename Kind, typename S>
std::vector<typename Kind::Arrival> resolvedAll(const std::string& model,
                                                const std::vector<typename Kind::Arrival>& arrivals,
                                                const physics::PhysicsParams<S>& p)
{
  const auto resolver = Kind::template make<S>(model);
  std::vector<typename Kind::Arrival> out;
  for (const auto& arrival : arrivals)
    out.push_back(Kind::resolve(*resolver, arrival, p));
  return out;
}

/// `model` in double on every arrival against `reference`: the largest errors (first repeat),
/// and the median over `repeats` of the time per impact.
template <typename Kind>
CushionPrecision measureModel(const std::string& model, const std::vector<typename Kind::Arrival>& arrivals,
                              const std::vector<typename Kind::Arrival>& reference,
                              const physics::PhysicsParams<double>& p, double tolerance, int repeats)
{
  const auto resolver = Kind::template make<double>(model);
  CushionPrecision r;
  r.tolerance = tolerance;
  std::vector<double> times;
  for (int repeat = 0; repeat < std::max(1, repeats); ++repeat)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < arrivals.size(); ++k)
    {
      const auto out = Kind::resolve(*resolver, arrivals[k], p);
      if (repeat == 0)
      {
        const auto [velocity, spin] = Kind::errors(out, reference[k], p.ball_radius);
        r.max_velocity_error = std::max(r.max_velocity_error, velocity);
        r.max_spin_error = std::max(r.max_spin_error, spin);
      }
    }
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    times.push_back(took.count() / static_cast<double>(arrivals.size()));
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  r.seconds_per_impact = times[times.size() / 2];
  return r;
}

/// The integrated model `integrated` at each tolerance, against itself in long double at
/// `reference_tolerance`.
template <typename Kind>
std::vector<CushionPrecision> tolerancePrecision(const std::string& integrated,
                                                 const std::vector<typename Kind::Arrival>& arrivals,
                                                 const std::vector<double>& tolerances, double reference_tolerance,
                                                 int repeats)
{
  physics::PhysicsParams<double> p;
  physics::PhysicsParams<long double> pl = p.cast<long double>();
  Kind::setTolerance(pl, reference_tolerance);
  const auto reference = resolvedAll<Kind>(integrated, arrivals, pl);
  std::vector<CushionPrecision> results;
  for (const double tolerance : tolerances)
  {
    Kind::setTolerance(p, tolerance);
    results.push_back(measureModel<Kind>(integrated, arrivals, reference, p, tolerance, repeats));
  }
  return results;
}

/// Every model of the kind at the default coefficients: its cost, its error against itself in
/// long double, and its distance from `integrated` in long double at `reference_tolerance`.
template <typename Kind>
std::vector<CushionModelCost> modelCosts(const std::string& integrated,
                                         const std::vector<typename Kind::Arrival>& arrivals,
                                         double reference_tolerance, int repeats)
{
  const physics::PhysicsParams<double> p;
  const physics::PhysicsParams<long double> pl = p.cast<long double>();
  physics::PhysicsParams<long double> tight = pl;
  Kind::setTolerance(tight, reference_tolerance);
  const auto reference = resolvedAll<Kind>(integrated, arrivals, tight);
  std::vector<CushionModelCost> costs;
  for (const std::string& model : Kind::models())
  {
    CushionModelCost c;
    c.model = model;
    c.own = measureModel<Kind>(model, arrivals, resolvedAll<Kind>(model, arrivals, pl), p, 0, repeats);
    const CushionPrecision against = measureModel<Kind>(model, arrivals, reference, p, 0, 1);
    c.velocity_difference = against.max_velocity_error;
    c.spin_difference = against.max_spin_error;
    costs.push_back(c);
  }
  return costs;
}

}  // namespace evaluation
}  // namespace cue_sim
