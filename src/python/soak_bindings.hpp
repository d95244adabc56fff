// cue_sim._core.soak: a range of the soak campaign's shots (runSoak) on this process's threads, its
// summary as a dict; cue_sim.soak shards a campaign over a Dask cluster with it.
#pragma once

#include <pybind11/pybind11.h>

namespace cue_sim
{
namespace python
{
void bindSoak(pybind11::module_& m);
}  // namespace python
}  // namespace cue_sim
