// cue_sim._core.predict_tracks: many shots' balls at the instants observed, on every core with
// the GIL released.
#include "python/calibration_bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "cue_sim/calibration/shot_film.hpp"
#include "cue_sim/calibration/track_prediction.hpp"
#include "cue_sim/camera/calibration_file.hpp"
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
                       const std::vector<std::vector<double>>& times, unsigned threads,
                       const std::vector<double>& exposures)
{
  if (strikes.size() != starts.size() || times.size() != starts.size())
    throw std::invalid_argument("starts, strikes and times: one of each a shot, got " + std::to_string(starts.size()) +
                                ", " + std::to_string(strikes.size()) + " and " + std::to_string(times.size()));
  if (!exposures.empty() && exposures.size() != starts.size())
    throw std::invalid_argument("exposures: one a shot or none, got " + std::to_string(exposures.size()) + " for " +
                                std::to_string(starts.size()) + " shots");
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
    requests[i].exposure = exposures.empty() ? 0.0 : exposures[i];
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
/// The film's camera: the calibration file's lens (read out at width x height if given), at `pose`
/// (4 x 4, the optical frame in the table frame; the default overhead pose if None).
calibration::FilmSettings filmSettings(const Engine& engine, const std::string& calibration, int width, int height,
                                       const py::object& pose, double exposure, double noise, std::uint64_t seed)
{
  calibration::FilmSettings settings;
  settings.intrinsics =
      camera::intrinsicsFromFile(calibration.empty() ? camera::defaultCalibrationPath() : calibration);
  if (width > 0 || height > 0)
    settings.intrinsics = settings.intrinsics.scaled(width, height);
  if (pose.is_none())
    settings.pose = camera::overheadPose(engine.table().clothCentre(), camera::kOverheadHeight);
  else
  {
    const auto m = pose.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
    if (m.ndim() != 2 || m.shape(0) != 4 || m.shape(1) != 4)
      throw std::invalid_argument("pose: a 4 x 4 matrix");
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        settings.pose.matrix()(r, c) = m.at(r, c);
  }
  settings.exposure = exposure;
  settings.options.noise_stddev = noise;
  settings.options.noise_seed = seed;
  return settings;
}

/// A frame as (image: H x W x 3 BGR uint8, truth: (id, u, v, radius, visible) per ball).
py::tuple frameOf(calibration::ShotFilm& film, double time)
{
  camera::Frame frame;
  {
    py::gil_scoped_release release;
    frame = film.frame(time);
  }
  py::array_t<std::uint8_t> image({py::ssize_t(frame.image.rows), py::ssize_t(frame.image.cols), py::ssize_t(3)});
  for (int r = 0; r < frame.image.rows; ++r)
    std::copy(frame.image.ptr<std::uint8_t>(r), frame.image.ptr<std::uint8_t>(r) + 3 * frame.image.cols,
              image.mutable_data(r, 0, 0));
  py::list truth;
  for (const camera::BallPixel& b : frame.balls)
    truth.append(py::make_tuple(b.id, b.pixel.x(), b.pixel.y(), b.radius, b.visible));
  return py::make_tuple(image, truth);
}

/// The film's lens as OpenCV takes it: (camera matrix 3 x 3, distortion (5,), pose 4 x 4).
py::tuple lensOf(const calibration::ShotFilm& film)
{
  const camera::Intrinsics& k = film.settings().intrinsics;
  py::array_t<double> matrix({3, 3});
  auto mm = matrix.mutable_unchecked<2>();
  const double values[3][3] = {{k.fx, 0, k.cx}, {0, k.fy, k.cy}, {0, 0, 1}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      mm(r, c) = values[r][c];
  py::array_t<double> distortion(5);
  std::copy(k.distortion.begin(), k.distortion.end(), distortion.mutable_data());
  py::array_t<double> pose({4, 4});
  auto pm = pose.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      pm(r, c) = film.settings().pose.matrix()(r, c);
  return py::make_tuple(matrix, distortion, pose);
}
}  // namespace

void bindCalibration(py::module_& m)
{
  py::class_<calibration::ShotFilm>(m, "ShotFilm",
                                    "A shot as the simulated camera films it (cue_sim.calibrate.film): begin(start, "
                                    "strike), then frame(t) forward in time.")
      .def(py::init([](const Engine& engine, const std::string& calibration, int width, int height,
                       const py::object& pose, double exposure, double noise, std::uint64_t seed) {
             return std::make_unique<calibration::ShotFilm>(
                 engine, filmSettings(engine, calibration, width, height, pose, exposure, noise, seed));
           }),
           py::arg("engine"), py::arg("calibration") = "", py::arg("width") = 0, py::arg("height") = 0,
           py::arg("pose") = py::none(), py::arg("exposure") = 0.004, py::arg("noise") = 0.0, py::arg("seed") = 0,
           py::keep_alive<1, 2>())
      .def(
          "begin",
          [](calibration::ShotFilm& film, const Engine& engine, const StateArrays& start, const py::object& strike) {
            film.begin(fromArrays(engine, start), strikeFrom(strike, 0));
          },
          py::arg("engine"), py::arg("start"), py::arg("strike"))
      .def("frame", &frameOf, py::arg("time"))
      .def_property_readonly("lens", &lensOf);
  m.def("predict_tracks", &predictTracks, py::arg("engine"), py::arg("starts"), py::arg("strikes"), py::arg("times"),
        py::arg("threads") = 0, py::arg("exposures") = std::vector<double>(),
        "Each shot's balls at its times: starts (StateArrays, balls maybe moving), strikes (None or (ball, "
        "speed, phi, theta, a, b), applied first), times (ascending, from the start's), exposures (one a shot "
        "[s], each position the average over it; none: instants) -> one dict a shot.");
}

}  // namespace python
}  // namespace cue_sim
