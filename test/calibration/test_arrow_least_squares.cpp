// The arrow-shaped least squares under the calibration (Ceres with each group's unknowns
// eliminated): exact data fitted back, the robust loss against outliers, bounds, the budget, and
// refusals. The model: groups of decays y = A_g exp(-k t) + c_g sharing the rate k, as shots share
// a table's coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "cue_sim/calibration/arrow_least_squares.hpp"

namespace cue_sim
{
namespace calibration
{
namespace
{
struct Decays
{
  std::vector<std::vector<double>> times, observed;  // per group
  bool shared_rate = true;                           // else each group has its own rate (x: k, A, c)

  ArrowShape shape() const
  {
    ArrowShape s;
    s.shared = shared_rate ? 1 : 0;
    int column = s.shared, row = 0;
    const int own = shared_rate ? 2 : 3;
    for (const auto& t : times)
    {
      s.groups.push_back({column, own, row, static_cast<int>(t.size())});
      column += own;
      row += static_cast<int>(t.size());
    }
    s.lower.assign(static_cast<std::size_t>(column), -INFINITY);
    s.upper.assign(static_cast<std::size_t>(column), INFINITY);
    return s;
  }

  /// Residuals (model - observed) and the groups' Jacobian blocks, analytic.
  bool operator()(const std::vector<double>& x, bool jacobian, std::vector<double>& r, std::vector<double>& j) const
  {
    r.clear();
    j.clear();
    std::size_t column = shared_rate ? 1 : 0;
    for (std::size_t g = 0; g < times.size(); ++g)
    {
      const double k = shared_rate ? x[0] : x[column];
      const double a = x[column + (shared_rate ? 0 : 1)], c = x[column + (shared_rate ? 1 : 2)];
      for (std::size_t i = 0; i < times[g].size(); ++i)
      {
        const double e = std::exp(-k * times[g][i]);
        r.push_back(a * e + c - observed[g][i]);
        if (jacobian)
        {
          j.push_back(-a * times[g][i] * e);  // d/dk (shared first, or the group's first own)
          j.push_back(e);
          j.push_back(1.0);
        }
      }
      column += shared_rate ? 2 : 3;
    }
    return true;
  }
};

Decays makeDecays(double k, const std::vector<std::pair<double, double>>& groups, double noise, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> error(0.0, noise);
  Decays d;
  for (const auto& [a, c] : groups)
  {
    d.times.emplace_back();
    d.observed.emplace_back();
    for (int i = 0; i < 40; ++i)
    {
      const double t = 0.05 * i;
      d.times.back().push_back(t);
      d.observed.back().push_back(a * std::exp(-k * t) + c + (noise > 0 ? error(random) : 0.0));
    }
  }
  return d;
}

ArrowEvaluation evaluationOf(const Decays& d)
{
  return [&d](const std::vector<double>& x, bool jacobian, std::vector<double>& r, std::vector<double>& j) {
    return d(x, jacobian, r, j);
  };
}

const std::vector<std::pair<double, double>> kGroups = {{1.0, 0.2}, {2.5, -0.4}, {0.7, 1.1}, {1.8, 0.0}};

/// A start far from kGroups' decays: the rate 0.5, each group's amplitude 1 and offset 0.
std::vector<double> sharedStart()
{
  std::vector<double> x = {0.5};
  for (std::size_t g = 0; g < kGroups.size(); ++g)
    x.insert(x.end(), {1.0, 0.0});
  return x;
}

TEST(ArrowLeastSquares, ExactDataFittedBack)
{
  const Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  std::vector<double> x = sharedStart();
  ArrowOptions options;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  const ArrowSummary summary = solveArrowLeastSquares(d.shape(), x, evaluationOf(d), options);
  EXPECT_FALSE(summary.failed) << summary.message;
  EXPECT_NEAR(x[0], 1.3, 1e-9);
  for (std::size_t g = 0; g < kGroups.size(); ++g)
  {
    EXPECT_NEAR(x[1 + 2 * g], kGroups[g].first, 1e-9) << "group " << g;
    EXPECT_NEAR(x[2 + 2 * g], kGroups[g].second, 1e-9) << "group " << g;
  }
  EXPECT_LT(summary.final_cost, 1e-18);
  EXPECT_GT(summary.initial_cost, 1.0);
  EXPECT_GE(summary.residual_evaluations, summary.iterations);
  EXPECT_GE(summary.jacobian_evaluations, 1);
}

double softL1Cost(const Decays& d, const std::vector<double>& x, double c)
{
  std::vector<double> r, j;
  d(x, false, r, j);
  double cost = 0;
  for (const double v : r)
    cost += c * c * (std::sqrt(1 + v * v / (c * c)) - 1);  // 1/2 of 2 c^2 (sqrt(1 + r^2/c^2) - 1)
  return cost;
}

TEST(ArrowLeastSquares, RobustLossHoldsOutliers)
{
  const double noise = 0.01;
  Decays d = makeDecays(1.3, kGroups, noise, 7);
  // One observation in ten thrown far, all upwards: plain squares follow them.
  for (auto& group : d.observed)
    for (std::size_t i = 3; i < group.size(); i += 10)
      group[i] += 0.5;
  std::vector<double> robust = sharedStart(), plain = sharedStart();
  ArrowOptions options;
  options.function_tolerance = 1e-12;
  options.loss_scale = noise;
  const ArrowSummary summary = solveArrowLeastSquares(d.shape(), robust, evaluationOf(d), options);
  options.loss_scale = 0;
  solveArrowLeastSquares(d.shape(), plain, evaluationOf(d), options);
  EXPECT_NEAR(robust[0], 1.3, 0.02);
  for (std::size_t g = 0; g < kGroups.size(); ++g)
    EXPECT_NEAR(robust[2 + 2 * g], kGroups[g].second, 0.02) << "group " << g;
  EXPECT_GT(std::abs(plain[2] - kGroups[0].second), 0.03);  // the outliers' 0.05 mean pulls the plain fit
  // The cost reported is the soft-L1 cost at the point returned, and the solution is a minimum:
  // a small move of the shared rate either way costs more.
  EXPECT_NEAR(summary.final_cost, softL1Cost(d, robust, noise), 1e-9 * summary.final_cost);
  for (const double step : {-1e-4, 1e-4})
  {
    auto moved = robust;
    moved[0] += step;
    EXPECT_GT(softL1Cost(d, moved, noise), summary.final_cost);
  }
}

TEST(ArrowLeastSquares, BoundsHold)
{
  const Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  ArrowShape shape = d.shape();
  shape.upper[0] = 1.0;   // the rate below its truth
  shape.lower[2] = 0.25;  // the first group's offset above its truth (0.2)
  std::vector<double> x = {0.5};
  for (std::size_t g = 0; g < kGroups.size(); ++g)
    x.insert(x.end(), {1.0, 0.3});
  const ArrowSummary summary = solveArrowLeastSquares(shape, x, evaluationOf(d), ArrowOptions());
  EXPECT_FALSE(summary.failed) << summary.message;
  EXPECT_DOUBLE_EQ(x[0], 1.0);
  EXPECT_DOUBLE_EQ(x[2], 0.25);
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    EXPECT_GE(x[i], shape.lower[i]);
    EXPECT_LE(x[i], shape.upper[i]);
  }
}

TEST(ArrowLeastSquares, GroupsWithoutSharedUnknownsAreFittedEachAlone)
{
  Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  d.shared_rate = false;
  std::vector<double> x;
  for (std::size_t g = 0; g < kGroups.size(); ++g)
    x.insert(x.end(), {0.5, 1.0, 0.0});
  ArrowOptions options;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  solveArrowLeastSquares(d.shape(), x, evaluationOf(d), options);
  for (std::size_t g = 0; g < kGroups.size(); ++g)
  {
    EXPECT_NEAR(x[3 * g], 1.3, 1e-8) << "group " << g;
    EXPECT_NEAR(x[3 * g + 1], kGroups[g].first, 1e-8) << "group " << g;
  }
}

TEST(ArrowLeastSquares, AGroupWithoutResidualsKeepsItsUnknowns)
{
  Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  d.times[1].clear();
  d.observed[1].clear();
  std::vector<double> x = sharedStart();
  solveArrowLeastSquares(d.shape(), x, evaluationOf(d), ArrowOptions());
  EXPECT_EQ(x[3], 1.0);
  EXPECT_EQ(x[4], 0.0);
  EXPECT_NEAR(x[0], 1.3, 1e-6);
}

TEST(ArrowLeastSquares, TheBudgetIsKept)
{
  const Decays d = makeDecays(1.3, kGroups, 0.01, 3);
  std::vector<double> x = {0.1};
  for (std::size_t g = 0; g < kGroups.size(); ++g)
    x.insert(x.end(), {5.0, 3.0});
  ArrowOptions options;
  options.max_evaluations = 3;
  options.function_tolerance = 1e-15;
  const ArrowSummary summary = solveArrowLeastSquares(d.shape(), x, evaluationOf(d), options);
  EXPECT_FALSE(summary.converged);
  EXPECT_LE(summary.residual_evaluations, 3);
  EXPECT_LE(summary.final_cost, summary.initial_cost);  // never a worse point than the start
}

TEST(ArrowLeastSquares, AnEvaluationThatThrowsEndsTheSolve)
{
  const Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  std::vector<double> x = sharedStart();
  int calls = 0;
  const ArrowEvaluation throwing = [&](const std::vector<double>& at, bool jacobian, std::vector<double>& r,
                                       std::vector<double>& j) {
    if (++calls == 3)
      throw std::runtime_error("the simulator is gone");
    return d(at, jacobian, r, j);
  };
  EXPECT_THROW(solveArrowLeastSquares(d.shape(), x, throwing, ArrowOptions()), std::runtime_error);
  EXPECT_EQ(calls, 3);
  for (const double v : x)
    EXPECT_TRUE(std::isfinite(v));
}

TEST(ArrowLeastSquares, BadShapesAreRefusedByName)
{
  const Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  std::vector<double> x(9, 0.0);
  ArrowShape shape = d.shape();
  EXPECT_EQ(whyBadShape(shape, 9), "");
  EXPECT_NE(whyBadShape(shape, 8).find("one bound per unknown (8)"), std::string::npos);
  shape.lower.push_back(0);
  shape.upper.push_back(1);
  EXPECT_NE(whyBadShape(shape, 10).find("x has 10"), std::string::npos);
  shape = d.shape();
  shape.groups[2].row += 1;
  EXPECT_NE(whyBadShape(shape, 9).find("groups[2]"), std::string::npos);
  shape = d.shape();
  shape.lower[4] = 1;
  shape.upper[4] = 0;
  EXPECT_NE(whyBadShape(shape, 9).find("x[4]"), std::string::npos);
  EXPECT_THROW(solveArrowLeastSquares(shape, x, evaluationOf(d), ArrowOptions()), std::invalid_argument);
  shape = d.shape();
  for (auto& group : shape.groups)
    group.rows = group.row = 0;
  EXPECT_NE(whyBadShape(shape, 9).find("no residuals"), std::string::npos);
}

TEST(ArrowLeastSquares, AWrongSizedEvaluationIsAnError)
{
  const Decays d = makeDecays(1.3, kGroups, 0.0, 1);
  std::vector<double> x(9, 0.5);
  const ArrowEvaluation short_one = [&](const std::vector<double>& at, bool jacobian, std::vector<double>& r,
                                        std::vector<double>& j) {
    d(at, jacobian, r, j);
    r.pop_back();
    return true;
  };
  EXPECT_THROW(solveArrowLeastSquares(d.shape(), x, short_one, ArrowOptions()), std::length_error);
}

}  // namespace
}  // namespace calibration
}  // namespace cue_sim
