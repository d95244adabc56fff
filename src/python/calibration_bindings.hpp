// cue_sim._core's track prediction (calibration::predictTracks), registered on the module;
// python/cue_sim/calibrate is the fit over it.
#pragma once

#include <pybind11/pybind11.h>

namespace cue_sim
{
namespace python
{
void bindCalibration(pybind11::module_& m);
}  // namespace python
}  // namespace cue_sim
