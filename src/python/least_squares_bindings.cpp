// cue_sim._core.solve_arrow over calibration::solveArrowLeastSquares. The callable is Python (it
// runs the shots' simulations, which release the GIL themselves), so the solve holds the GIL.
#include "python/least_squares_bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "cue_sim/calibration/arrow_least_squares.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
using Vector = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The arrays a Python evaluation returned, copied into the solver's.
void copyInto(const py::handle& values, std::vector<double>& out, const char* what)
{
  const auto array = values.cast<Vector>();
  if (array.ndim() != 1)
    throw std::invalid_argument(std::string("evaluate: ") + what + " must be one-dimensional, got " +
                                std::to_string(array.ndim()) + " dimensions");
  out.assign(array.data(), array.data() + array.size());
}

/// evaluate(x, jacobian) -> None (cannot be computed there) or (residuals, jacobian blocks or None).
calibration::ArrowEvaluation evaluationOf(const py::function& evaluate)
{
  return [evaluate](const std::vector<double>& x, bool jacobian, std::vector<double>& residuals,
                    std::vector<double>& blocks) {
    const py::object result = evaluate(Vector(static_cast<py::ssize_t>(x.size()), x.data()), jacobian);
    if (result.is_none())
      return false;
    const auto pair = result.cast<py::tuple>();
    if (pair.size() != 2)
      throw std::invalid_argument("evaluate: None or (residuals, jacobian blocks), got a tuple of " +
                                  std::to_string(pair.size()));
    copyInto(pair[0], residuals, "residuals");
    if (jacobian)
    {
      if (pair[1].is_none())
        throw std::invalid_argument("evaluate: the Jacobian's blocks were asked for, got None");
      copyInto(pair[1], blocks, "jacobian blocks");
    }
    return true;
  };
}

py::dict solveArrow(const py::function& evaluate, const Vector& x0, const std::vector<double>& lower,
                    const std::vector<double>& upper, int shared, const std::vector<std::vector<int>>& groups,
                    double loss_scale, int max_evaluations, double function_tolerance, double parameter_tolerance,
                    double gradient_tolerance, int threads)
{
  calibration::ArrowShape shape;
  shape.shared = shared;
  shape.lower = lower;
  shape.upper = upper;
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    if (groups[g].size() != 4)
      throw std::invalid_argument("groups[" + std::to_string(g) + "]: (column, columns, row, rows), got " +
                                  std::to_string(groups[g].size()) + " values");
    shape.groups.push_back({groups[g][0], groups[g][1], groups[g][2], groups[g][3]});
  }
  std::vector<double> x(x0.data(), x0.data() + x0.size());
  const std::string why = calibration::whyBadShape(shape, x.size());
  if (!why.empty())
    throw std::invalid_argument(why);
  if (!(loss_scale >= 0) || max_evaluations < 1)
    throw std::invalid_argument("loss_scale: at least 0, got " + std::to_string(loss_scale) +
                                "; max_evaluations: at least 1, got " + std::to_string(max_evaluations));
  calibration::ArrowOptions options;
  options.loss_scale = loss_scale;
  options.max_evaluations = max_evaluations;
  options.function_tolerance = function_tolerance;
  options.parameter_tolerance = parameter_tolerance;
  options.gradient_tolerance = gradient_tolerance;
  options.threads = threads;
  const auto summary = calibration::solveArrowLeastSquares(shape, x, evaluationOf(evaluate), options);
  py::dict out;
  out["x"] = Vector(static_cast<py::ssize_t>(x.size()), x.data());
  out["converged"] = summary.converged;
  out["failed"] = summary.failed;
  out["message"] = summary.message;
  out["initial_cost"] = summary.initial_cost;
  out["cost"] = summary.final_cost;
  out["iterations"] = summary.iterations;
  out["residual_evaluations"] = summary.residual_evaluations;
  out["jacobian_evaluations"] = summary.jacobian_evaluations;
  return out;
}

}  // namespace

void bindLeastSquares(py::module_& m)
{
  m.def("solve_arrow", &solveArrow, py::arg("evaluate"), py::arg("x0"), py::arg("lower"), py::arg("upper"),
        py::arg("shared"), py::arg("groups"), py::arg("loss_scale") = 0.0, py::arg("max_evaluations") = 100,
        py::arg("function_tolerance") = 1e-6, py::arg("parameter_tolerance") = 1e-8,
        py::arg("gradient_tolerance") = 1e-10, py::arg("threads") = 1,
        "Robust least squares shaped like an arrow (calibration::solveArrowLeastSquares, Ceres): x = [shared, "
        "each group's own], groups (column, columns, row, rows) in order; evaluate(x, jacobian) returns None "
        "where it cannot be computed, else (residuals, each group's Jacobian block rows x (shared + columns) "
        "row-major, one after another, or None when not asked). Returns x, cost, converged, failed, message and "
        "the counts.");
}

}  // namespace python
}  // namespace cue_sim
