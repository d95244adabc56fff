// cue_sim._core.predict_tracks: many shots' balls at the instants observed, on every core with
// the GIL released.
#include "python/calibration_bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "cue_sim/calibration/track_prediction.hpp"
#include "python/state_arrays.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
using Engine = physics::Engine<double>;

/// A strike as (ball, speed, phi, theta, a, b), or None.
std::optional<calibration::TrackStrike> strikeFrom(const py::handle& row, std::size_t shot)
{
  if (row.is_none())
    return std::nullopt;
  const auto values = row.cast<std::vector<double>>();
  if (values.size() != 6)
    throw std::invalid_argument("strikes[" + std::to_string(shot) + "]: None or (ball, speed, phi, theta, a, b), got " +
                                std::to_string(values.size()) + " values");
  return calibration::TrackStrike{static_cast<int>(values[0]), {values[1], values[2], values[3], values[4], values[5]}};
}

/// One dict a shot: positions (K, N, 2), on_table (K, N), contacts, error.
py::list predictTracks(const Engine& engine, const std::vector<StateArrays>& starts, const py::list& strikes,
                       const std::vector<std::vector<double>>& times, unsigned threads)
{
  if (strikes.size() != starts.size() || times.size() != starts.size())
    throw std::invalid_argument("starts, strikes and times: one of each a shot, got " + std::to_string(starts.size()) +
                                ", " + std::to_string(strikes.size()) + " and " + std::to_string(times.size()));
  std::vector<calibration::TrackRequest> requests(starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i)
  {
    try
    {
      requests[i].start = fromArrays(engine, starts[i]);
    }
    catch (const std::invalid_argument& e)
    {
      throw std::invalid_argument("starts[" + std::to_string(i) + "]: " + e.what());
    }
    requests[i].strike = strikeFrom(strikes[i], i);
    requests[i].times = times[i];
  }
  std::vector<calibration::TrackPrediction> predictions;
  {
    py::gil_scoped_release release;
    physics::ThreadPool pool(threads);
    predictions = calibration::predictTracks(engine, requests, pool);
  }
  py::list out;
  for (std::size_t i = 0; i < predictions.size(); ++i)
  {
    const calibration::TrackPrediction& p = predictions[i];
    const auto k = static_cast<py::ssize_t>(requests[i].times.size());
    const auto n = static_cast<py::ssize_t>(requests[i].start.balls.size());
    py::array_t<double> positions({k, n, py::ssize_t(2)});
    py::array_t<bool> on_table({k, n});
    if (p.error.empty())
    {
      std::copy(p.positions.begin(), p.positions.end(), positions.mutable_data());
      std::copy(p.on_table.begin(), p.on_table.end(), on_table.mutable_data());
    }
    out.append(py::dict(py::arg("positions") = positions, py::arg("on_table") = on_table,
                        py::arg("ball_ball") = p.contacts.ball_ball, py::arg("cushion") = p.contacts.cushion,
                        py::arg("pocketed") = p.contacts.pocketed, py::arg("error") = p.error));
  }
  return out;
}
}  // namespace

void bindCalibration(py::module_& m)
{
  m.def("predict_tracks", &predictTracks, py::arg("engine"), py::arg("starts"), py::arg("strikes"), py::arg("times"),
        py::arg("threads") = 0,
        "Each shot's balls at its times: starts (StateArrays, balls maybe moving), strikes (None or (ball, "
        "speed, phi, theta, a, b), applied first), times (ascending, from the start's) -> one dict a shot.");
}

}  // namespace python
}  // namespace cue_sim
