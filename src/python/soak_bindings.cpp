// cue_sim._core.soak: a range of the soak campaign's shots, its summary as a dict.
#include "python/soak_bindings.hpp"

#include <pybind11/stl.h>

#include "cue_sim/evaluation/soak.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
py::dict summaryDict(const evaluation::SoakSummary& s)
{
  py::dict out;
  out["shots"] = s.shots;
  out["events"] = s.events;
  out["scanned"] = s.scanned;
  out["at_rest"] = s.at_rest;
  out["endless"] = s.endless;
  out["by_table"] = s.by_table;
  out["by_models"] = s.by_models;
  out["by_balls"] = s.by_balls;
  out["regime_shots"] = s.regime_shots;
  out["regime_seconds"] = s.regime_seconds;
  out["violations"] = s.violations;
  out["reports"] = s.reports;
  out["seconds"] = s.seconds;
  return out;
}

py::dict soak(std::uint64_t seed, long first, long shots, bool airborne, unsigned threads, long full_scan_every,
              const std::string& out_dir)
{
  if (shots < 1)
    throw std::invalid_argument("shots: " + std::to_string(shots) + " is not at least 1");
  if (first < 0)
    throw std::invalid_argument("first: " + std::to_string(first) + " is negative");
  if (full_scan_every < 1)
    throw std::invalid_argument("full_scan_every: " + std::to_string(full_scan_every) + " is not at least 1");
  evaluation::SoakOptions options;
  options.seed = seed;
  options.first = first;
  options.shots = shots;
  options.airborne = airborne;
  options.threads = threads;
  options.full_scan_every = full_scan_every;
  options.out_dir = out_dir;
  evaluation::SoakSummary summary;
  {
    py::gil_scoped_release free_python;
    summary = evaluation::runSoak(options);
  }
  return summaryDict(summary);
}
}  // namespace

void bindSoak(py::module_& m)
{
  m.def("soak", &soak, py::arg("seed"), py::arg("first"), py::arg("shots"), py::arg("airborne") = false,
        py::arg("threads") = 1, py::arg("full_scan_every") = 4, py::arg("out_dir") = "soak_violations",
        "Shots first .. first + shots - 1 of the soak campaign with this seed, each checked at every event "
        "(doc/accuracy.md): the summary as a dict. Violations are written as scene files into out_dir.");
}

}  // namespace python
}  // namespace cue_sim
