// Ceres under the arrow-shaped least squares (include/cue_sim/calibration/arrow_least_squares.hpp).
// The caller's evaluation runs once a point, for every group at once, from Ceres' evaluation
// callback; each residual is a residual block of its own (so that the robust loss applies to each
// coordinate, as scipy's soft_l1 does), whose cost function copies its value and its row of the
// Jacobian from what the evaluation left.
#include "cue_sim/calibration/arrow_least_squares.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace cue_sim
{
namespace calibration
{
namespace
{
/// The caller's residuals and Jacobian at the point being evaluated, shared by every residual
/// block's cost function.
class EvaluationCache : public ceres::EvaluationCallback
{
public:
  EvaluationCache(const ArrowShape& shape, std::vector<double>& x, const ArrowEvaluation& evaluate)
    : shape_(shape), x_(x), evaluate_(evaluate)
  {
    std::size_t rows = 0, entries = 0;
    for (const auto& group : shape.groups)
    {
      block_offsets_.push_back(entries);
      rows += static_cast<std::size_t>(group.rows);
      entries += static_cast<std::size_t>(group.rows) * static_cast<std::size_t>(shape.shared + group.columns);
    }
    rows_ = rows;
    entries_ = entries;
    residuals_.resize(rows);
    jacobian_.resize(entries);
  }

  void PrepareForEvaluation(bool evaluate_jacobians, bool new_evaluation_point) override
  {
    if (!new_evaluation_point && (!evaluate_jacobians || jacobian_ready_))
      return;
    if (new_evaluation_point)
    {
      ++residual_evaluations_;
      jacobian_ready_ = false;
    }
    if (evaluate_jacobians)
      ++jacobian_evaluations_;
    ok_ = false;
    if (error_)
      return;  // an earlier evaluation threw: every step from here fails until the solver stops
    try
    {
      const bool computed = evaluate_(x_, evaluate_jacobians, residuals_, jacobian_);
      if (computed && residuals_.size() != rows_)
        throw std::length_error("the evaluation gave " + std::to_string(residuals_.size()) + " residuals for " +
                                std::to_string(rows_));
      if (computed && evaluate_jacobians && jacobian_.size() != entries_)
        throw std::length_error("the evaluation gave " + std::to_string(jacobian_.size()) + " Jacobian entries for " +
                                std::to_string(entries_));
      ok_ = computed;
      jacobian_ready_ = ok_ && evaluate_jacobians;
    }
    catch (...)
    {
      error_ = std::current_exception();
      ok_ = false;
    }
  }

  /// The cost function of residual `row` of group `group` (its `local` row).
  bool copy(int group, int local, double* residual, double** jacobians) const
  {
    if (!ok_)
      return false;
    const auto& g = shape_.groups[static_cast<std::size_t>(group)];
    *residual = residuals_[static_cast<std::size_t>(g.row + local)];
    if (jacobians == nullptr)
      return true;
    if (!jacobian_ready_)
      return false;
    const std::size_t width = static_cast<std::size_t>(shape_.shared + g.columns);
    const double* row = &jacobian_[block_offsets_[static_cast<std::size_t>(group)] + width * local];
    int block = 0;
    if (shape_.shared > 0)
    {
      if (jacobians[block] != nullptr)
        std::copy(row, row + shape_.shared, jacobians[block]);
      ++block;
    }
    if (jacobians[block] != nullptr)
      std::copy(row + shape_.shared, row + width, jacobians[block]);
    return true;
  }

  std::exception_ptr error() const { return error_; }
  int residualEvaluations() const { return residual_evaluations_; }
  int jacobianEvaluations() const { return jacobian_evaluations_; }

private:
  const ArrowShape& shape_;
  std::vector<double>& x_;  // Ceres' parameter blocks point into it: it holds the point evaluated
  const ArrowEvaluation& evaluate_;
  std::vector<std::size_t> block_offsets_;
  std::size_t rows_ = 0, entries_ = 0;
  std::vector<double> residuals_, jacobian_;
  bool ok_ = false, jacobian_ready_ = false;
  std::exception_ptr error_;
  int residual_evaluations_ = 0, jacobian_evaluations_ = 0;
};

/// One residual: its value and Jacobian row from the cache.
class CachedResidual : public ceres::CostFunction
{
public:
  CachedResidual(const EvaluationCache& cache, int group, int local, int shared, int own)
    : cache_(cache), group_(group), local_(local)
  {
    set_num_residuals(1);
    if (shared > 0)
      mutable_parameter_block_sizes()->push_back(shared);
    mutable_parameter_block_sizes()->push_back(own);
  }

  bool Evaluate(double const* const* /*parameters: the cache was evaluated at them*/, double* residuals,
                double** jacobians) const override
  {
    return cache_.copy(group_, local_, residuals, jacobians);
  }

private:
  const EvaluationCache& cache_;
  int group_, local_;
};

/// Stops the solver when the evaluations are spent or the caller's evaluation threw, and keeps the
/// last accepted point (Ceres leaves the parameter blocks at it before each callback).
class Budget : public ceres::IterationCallback
{
public:
  Budget(const EvaluationCache& cache, const std::vector<double>& x, int max_evaluations)
    : cache_(cache), x_(x), max_evaluations_(max_evaluations), accepted_(x)
  {
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& /*summary*/) override
  {
    if (cache_.error())
      return ceres::SOLVER_ABORT;
    accepted_ = x_;
    if (cache_.residualEvaluations() >= max_evaluations_)
    {
      spent_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

  bool spent() const { return spent_; }
  const std::vector<double>& accepted() const { return accepted_; }

private:
  const EvaluationCache& cache_;
  const std::vector<double>& x_;
  int max_evaluations_;
  std::vector<double> accepted_;
  bool spent_ = false;
};

/// Ceres reports through glog; what it would print (a failed evaluation, a step refused) the
/// summary's message says, so only a fatal error is printed.
void quietenCeres()
{
  static std::once_flag once;
  std::call_once(once, [] { FLAGS_minloglevel = google::GLOG_FATAL; });
}

}  // namespace

std::string whyBadShape(const ArrowShape& shape, std::size_t unknowns)
{
  if (shape.shared < 0)
    return "shared: at least 0 unknowns, got " + std::to_string(shape.shared);
  if (shape.lower.size() != unknowns || shape.upper.size() != unknowns)
    return "lower and upper: one bound per unknown (" + std::to_string(unknowns) + "), got " +
           std::to_string(shape.lower.size()) + " and " + std::to_string(shape.upper.size());
  for (std::size_t i = 0; i < unknowns; ++i)
    if (!(shape.lower[i] <= shape.upper[i]))
      return "bounds of x[" + std::to_string(i) + "]: lower " + std::to_string(shape.lower[i]) + " above upper " +
             std::to_string(shape.upper[i]);
  int column = shape.shared, row = 0, rows = 0;
  for (std::size_t g = 0; g < shape.groups.size(); ++g)
  {
    const auto& group = shape.groups[g];
    const std::string name = "groups[" + std::to_string(g) + "]";
    if (group.column != column || group.columns < 1)
      return name + ": its unknowns must follow the last group's, at x[" + std::to_string(column) +
             "], at least one; got " + std::to_string(group.columns) + " at x[" + std::to_string(group.column) + "]";
    if (group.row != row || group.rows < 0)
      return name + ": its residuals must follow the last group's, at row " + std::to_string(row) + "; got " +
             std::to_string(group.rows) + " at row " + std::to_string(group.row);
    column += group.columns;
    row += group.rows;
    rows += group.rows;
  }
  if (static_cast<std::size_t>(column) != unknowns)
    return "the groups' unknowns and the shared ones are " + std::to_string(column) + ", x has " +
           std::to_string(unknowns);
  if (rows == 0)
    return "no residuals: nothing to fit";
  return {};
}

ArrowSummary solveArrowLeastSquares(const ArrowShape& shape, std::vector<double>& x, const ArrowEvaluation& evaluate,
                                    const ArrowOptions& options)
{
  const std::string why = whyBadShape(shape, x.size());
  if (!why.empty())
    throw std::invalid_argument(why);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = std::min(std::max(x[i], shape.lower[i]), shape.upper[i]);

  quietenCeres();
  EvaluationCache cache(shape, x, evaluate);
  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = &cache;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::unique_ptr<ceres::LossFunction> loss;
  if (options.loss_scale > 0)
    loss = std::make_unique<ceres::SoftLOneLoss>(options.loss_scale);

  double* shared = shape.shared > 0 ? x.data() : nullptr;
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  bool any_own = false;
  for (std::size_t g = 0; g < shape.groups.size(); ++g)
  {
    const auto& group = shape.groups[g];
    if (group.rows == 0)
      continue;  // no residual: its unknowns are not in the problem, and stay as they are
    double* own = x.data() + group.column;
    for (int r = 0; r < group.rows; ++r)
    {
      auto* cost = new CachedResidual(cache, static_cast<int>(g), r, shape.shared, group.columns);
      if (shared != nullptr)
        problem.AddResidualBlock(cost, loss.get(), shared, own);
      else
        problem.AddResidualBlock(cost, loss.get(), own);
    }
    ordering->AddElementToGroup(own, 0);  // eliminated first: a group's own block touches no other
    any_own = true;
  }
  auto bound = [&](double* block, int first, int size) {
    for (int i = 0; i < size; ++i)
    {
      const auto k = static_cast<std::size_t>(first + i);
      if (std::isfinite(shape.lower[k]))
        problem.SetParameterLowerBound(block, i, shape.lower[k]);
      if (std::isfinite(shape.upper[k]))
        problem.SetParameterUpperBound(block, i, shape.upper[k]);
    }
  };
  if (shared != nullptr)
  {
    bound(shared, 0, shape.shared);
    ordering->AddElementToGroup(shared, 1);
  }
  for (const auto& group : shape.groups)
    if (group.rows > 0)
      bound(x.data() + group.column, group.column, group.columns);

  ceres::Solver::Options solver;
  solver.minimizer_type = ceres::TRUST_REGION;
  // Powell's dogleg, not Levenberg-Marquardt: on the 20-shot fits (doc/calibration.md, "Speed")
  // Levenberg-Marquardt crept, each step accepted and short, and spent a stage's whole budget where
  // the dogleg stopped at its tolerance in a quarter of the evaluations (the first stages of seed
  // 4's first draw: 1596 simulations of the shots against 588), and it left the slow draw with a
  // shot on other contacts and mu_slide 2.2 standard errors off (the dogleg: 1.2).
  solver.trust_region_strategy_type = ceres::DOGLEG;
  // With shared unknowns: each group's own eliminated by its Schur complement. Without (each group
  // alone, the Jacobian block-diagonal): a dense QR of each small block would do as well, and the
  // sparse normal equations of the whole are that.
  if (shared != nullptr && any_own)
  {
    solver.linear_solver_type = ceres::DENSE_SCHUR;
    solver.linear_solver_ordering = ordering;
  }
  else
  {
    solver.linear_solver_type = ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE)
                                    ? ceres::SPARSE_NORMAL_CHOLESKY
                                    : ceres::DENSE_QR;
  }
  solver.max_num_iterations = std::max(options.max_evaluations, 1);
  solver.function_tolerance = options.function_tolerance;
  solver.parameter_tolerance = options.parameter_tolerance;
  solver.gradient_tolerance = options.gradient_tolerance;
  solver.num_threads = std::max(options.threads, 1);
  solver.update_state_every_iteration = true;
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  Budget budget(cache, x, options.max_evaluations);
  solver.callbacks.push_back(&budget);

  ceres::Solver::Summary report;
  ceres::Solve(solver, &problem, &report);
  if (cache.error())
  {
    x = budget.accepted();
    std::rethrow_exception(cache.error());
  }
  ArrowSummary summary;
  summary.converged = report.termination_type == ceres::CONVERGENCE;
  summary.failed = report.termination_type == ceres::FAILURE || report.termination_type == ceres::USER_FAILURE;
  summary.message =
      budget.spent() ? "the evaluations were spent (" + std::to_string(options.max_evaluations) + ")" : report.message;
  summary.initial_cost = report.initial_cost;
  summary.final_cost = report.final_cost;
  summary.iterations = static_cast<int>(report.iterations.size());
  summary.residual_evaluations = cache.residualEvaluations();
  summary.jacobian_evaluations = cache.jacobianEvaluations();
  if (summary.failed)
    x = budget.accepted();
  return summary;
}

}  // namespace calibration
}  // namespace cue_sim
