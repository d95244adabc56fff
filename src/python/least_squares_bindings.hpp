// cue_sim._core.solve_arrow: the calibration's robust least squares (Ceres, each shot's unknowns
// eliminated by their Schur complement) with the residuals and the Jacobian from a Python callable.
#pragma once

#include <pybind11/pybind11.h>

namespace cue_sim
{
namespace python
{
void bindLeastSquares(pybind11::module_& m);
}  // namespace python
}  // namespace cue_sim
