// cue_sim._core's games (game::GamePlay), registered on the module.
#pragma once

#include <pybind11/pybind11.h>

namespace cue_sim
{
namespace python
{
void bindGames(pybind11::module_& m);
}  // namespace python
}  // namespace cue_sim
