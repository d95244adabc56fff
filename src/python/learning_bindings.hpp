// cue_sim._core's learning environments (learning::Environment, learning::VectorEnvironment),
// registered on the module; python/cue_sim/envs is the Gymnasium-shaped API over them.
#pragma once

#include <pybind11/pybind11.h>

namespace cue_sim
{
namespace python
{
void bindLearning(pybind11::module_& m);
}  // namespace python
}  // namespace cue_sim
