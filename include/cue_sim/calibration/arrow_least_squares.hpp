// Robust nonlinear least squares for problems shaped like an arrow: a few unknowns shared by every
// group of residuals (a table's coefficients) and, per group, unknowns of its own (a shot's strike
// and where its balls stood). Solved by Ceres (Agarwal, Mierle et al., http://ceres-solver.org):
// a trust region (Powell's dogleg) whose Gauss-Newton steps eliminate each group's own unknowns by
// their Schur complement (DENSE_SCHUR), so that a step costs a small dense solve per group and one
// of the shared size, where an iterative solver over the whole Jacobian needed hundreds of products (a
// shot's own block is rank-deficient and badly conditioned: doc/calibration.md). The residuals and
// the Jacobian come from the caller, all groups at once (a fit's simulations run as one batch on
// every core). No ROS and no Python.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace cue_sim
{
namespace calibration
{
/// A group of residuals and the unknowns of its own.
struct ResidualGroup
{
  int column = 0;   ///< the first of its own unknowns in x (after the shared ones)
  int columns = 0;  ///< how many it has
  int row = 0;      ///< its first residual
  int rows = 0;     ///< how many residuals it has (0: the group and its unknowns are left as they are)
};

/// The problem's shape: x = [shared, each group's own], residuals = each group's in turn.
struct ArrowShape
{
  int shared = 0;  ///< the leading unknowns every group depends on (0: none)
  std::vector<ResidualGroup> groups;
  std::vector<double> lower, upper;  ///< bounds of every component of x (+-inf: none)
};

/// What the caller computes at x: every residual, and if `jacobian` is true each group's block of
/// the Jacobian, rows x (shared + columns) row-major, the groups' blocks one after another (the
/// shared columns first). Returns false where the residuals cannot be computed (the solver then
/// takes a shorter step).
using ArrowEvaluation = std::function<bool(const std::vector<double>& x, bool jacobian, std::vector<double>& residuals,
                                           std::vector<double>& jacobian_blocks)>;

struct ArrowOptions
{
  /// The robust loss: soft L1, rho(r^2) = 2 c^2 (sqrt(1 + r^2 / c^2) - 1) per residual, as
  /// scipy.optimize.least_squares' loss="soft_l1" with f_scale c; 0 for plain squares.
  double loss_scale = 0;
  /// The solve stops at the end of the iteration in which the residuals have been evaluated at
  /// this many points (a step is one; one that leaves the bounds is projected back and searched
  /// along, a few more).
  int max_evaluations = 100;
  double function_tolerance = 1e-6;   ///< stop when a step changes the cost by less than this share of it
  double parameter_tolerance = 1e-8;  ///< ... or x by less than this share of its norm
  double gradient_tolerance = 1e-10;  ///< ... or the projected gradient's largest component is below this
  int threads = 1;                    ///< for the linear algebra
};

struct ArrowSummary
{
  bool converged = false;  ///< by one of the tolerances (else: out of evaluations, or failed)
  bool failed = false;     ///< the solver could not go on (the message says why)
  std::string message;
  double initial_cost = 0, final_cost = 0;  ///< 1/2 sum rho(r^2)
  int iterations = 0, residual_evaluations = 0, jacobian_evaluations = 0;
};

/// Empty if `shape` is consistent with x's size and has at least one residual, else what is wrong.
std::string whyBadShape(const ArrowShape& shape, std::size_t unknowns);

/// Minimises 1/2 sum rho(r_i(x)^2) over x within the bounds, from x (which takes the result: the
/// best point the solver accepted). `evaluate` is called from this thread only. An exception it
/// throws ends the solve and is thrown again from here, x left at the last accepted point.
ArrowSummary solveArrowLeastSquares(const ArrowShape& shape, std::vector<double>& x, const ArrowEvaluation& evaluate,
                                    const ArrowOptions& options);

}  // namespace calibration
}  // namespace cue_sim
