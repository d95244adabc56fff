// cue_sim._core: the engine for Python, arrays in and out (pybind11, NumPy). The user-facing API,
// with its type hints and docstrings, is python/cue_sim/api.py; this file only converts. Errors
// a user can make raise ValueError naming the field (pybind11 maps std::invalid_argument so).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "cue_sim/physics/batch.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/execution_noise.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/scene/ball_colours.hpp"
#include "cue_sim/session/shot_prediction.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"
#include "python/calibration_bindings.hpp"
#include "python/game_bindings.hpp"
#include "python/learning_bindings.hpp"
#include "python/least_squares_bindings.hpp"
#include "python/soak_bindings.hpp"
#include "python/state_arrays.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
using physics::Engine;
using physics::PhysicsParams;

/// Coefficients by name over `base` (the table's defaults): unknown names and values out of range are refused,
/// naming them.
PhysicsParams<double> paramsFrom(const std::map<std::string, double>& given, const PhysicsParams<double>& base)
{
  PhysicsParams<double> params = base;
  for (const auto& [name, value] : given)
  {
    bool known = false;
    for (const auto& field : physics::physicsParamFields())
      if (name == field.name)
      {
        params.*field.member = value;
        known = true;
      }
    if (!known)
    {
      std::string names;
      for (const auto& field : physics::physicsParamFields())
        names += (names.empty() ? "" : ", ") + std::string(field.name);
      throw std::invalid_argument("unknown physics parameter '" + name + "'; the parameters are " + names);
    }
  }
  if (const std::string why = params.validate(); !why.empty())
    throw std::invalid_argument(why);
  return params;
}

/// The engine a Python Engine holds: the table by name or URDF path, coefficients and models.
std::shared_ptr<const Engine<double>> makeEngine(const std::string& table, const std::map<std::string, double>& params,
                                                 const std::string& ball_ball, const std::string& cushion,
                                                 const std::string& ball_table, const std::string& cue)
{
  std::shared_ptr<const physics::TableModel> model;
  try
  {
    model = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(table)));
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("table '" + table + "': " + e.what());
  }
  const physics::ModelChoice models(ball_ball, cushion, ball_table, cue);  // empty: the default
  return std::make_shared<const Engine<double>>(model, paramsFrom(params, physics::tableDefaults(*model)), models);
}

/// A ball set by name (physics::kBallSetNames), else carom's or pool's by the flag.
BallSet ballSetOf(bool carom, const std::string& name)
{
  BallSet set = carom ? BallSet::Carom : BallSet::Pool;
  if (!name.empty() && !ballSetNamed(name, set))
    throw std::invalid_argument("ball_set must be " + physics::ballSetNameList() + "; got '" + name + "'");
  return set;
}

py::dict paramFields()
{
  py::dict fields;
  for (const auto& f : physics::physicsParamFields())
    fields[f.name] = py::dict(py::arg("default") = PhysicsParams<double>().*f.member, py::arg("unit") = f.unit,
                              py::arg("min") = f.min, py::arg("max") = f.max, py::arg("description") = f.description);
  return fields;
}

StateArrays rack(const Engine<double>& engine, const std::string& layout, double gap, double jitter, unsigned seed)
{
  const std::vector<std::string> names = physics::rackNames();
  if (std::find(names.begin(), names.end(), layout) == names.end())
    throw std::invalid_argument("layout must be one of " + physics::rackNamesText() + "; got '" + layout + "'");
  physics::RackOptions options;
  options.gap = gap;
  options.jitter = jitter;
  options.seed = seed;
  return toArrays(physics::rackLayout<double>(layout, engine.table(), engine.params().ball_radius, options));
}

physics::CueStrike<double> strikeOf(double speed, double phi, double theta, double a, double b)
{
  return {speed, phi, theta, a, b};
}

/// The balls at shot times 0, T, 2T, ... up to `end` [s] after the strike, along the shot's own
/// trajectories (as the node samples a prediction).
std::vector<std::vector<physics::Ball<double>>> samplesTo(const Engine<double>& engine,
                                                          const physics::TableState<double>& struck, double period,
                                                          double end)
{
  std::vector<std::vector<physics::Ball<double>>> samples;
  if (period <= 0)
    return samples;
  physics::Simulation<double> sampled(engine, struck);
  const auto count = static_cast<std::size_t>(std::floor(end / period)) + 1;
  for (std::size_t k = 0; k < count; ++k)
  {
    sampled.advance(struck.time + static_cast<double>(k) * period);
    samples.push_back(sampled.snapshot());
  }
  return samples;
}

/// One shot from `start` to rest: exactly the node's ~predict (session::predictShot).
session::ShotPrediction toRest(const Engine<double>& engine, const physics::TableState<double>& start,
                               const session::Shot& shot, double sample_period)
{
  session::ShotPrediction prediction;
  {
    py::gil_scoped_release release;
    prediction = session::predictShot(engine, start, shot, session::PredictionOptions{sample_period, nullptr, 0});
  }
  if (!prediction.success)
  {
    if (prediction.message.rfind("shot: ", 0) == 0)
      throw std::invalid_argument(prediction.message);
    throw std::runtime_error(prediction.message);
  }
  return prediction;
}

/// One shot from `start` for `until` [s] after the strike, sampled as toRest samples.
session::ShotPrediction forDuration(const Engine<double>& engine, physics::TableState<double> state,
                                    const session::Shot& shot, double sample_period, double until)
{
  if (const std::string why = engine.whyNotStrikable(state, shot.ball_id, shot.strike); !why.empty())
    throw std::invalid_argument("shot: " + why);
  if (!(until >= 0))
    throw std::invalid_argument("until must be at least 0 s");
  session::ShotPrediction prediction;
  py::gil_scoped_release release;
  engine.strike(state, shot.ball_id, shot.strike);
  prediction.samples = samplesTo(engine, state, sample_period, until);
  prediction.strike_time = state.time;
  advance(engine, state, state.time + until, &prediction.events);
  prediction.at_rest = !state.anyMoving();
  prediction.time_to_rest = prediction.events.empty() ? 0 : prediction.events.back().time - prediction.strike_time;
  prediction.final_balls = engine.snapshot(state);
  prediction.success = true;
  return prediction;
}

/// One shot from `start`: to rest, or for `until` [s] after the strike if it is finite; sampled
/// every `sample_period` [s] if it is not 0.
py::dict simulate(const Engine<double>& engine, const StateArrays& start, int ball, double speed, double phi,
                  double theta, double a, double b, double until, double sample_period)
{
  if (const std::string why = session::whyBadSamplePeriod(sample_period); !why.empty())
    throw std::invalid_argument(why);
  const physics::TableState<double> state = fromArrays(engine, start);
  const session::Shot shot{ball, strikeOf(speed, phi, theta, a, b)};
  const session::ShotPrediction p = std::isfinite(until) ? forDuration(engine, state, shot, sample_period, until)
                                                         : toRest(engine, state, shot, sample_period);
  if (p.samples.size() > session::PredictionLimits().max_samples_per_shot)
    throw std::invalid_argument("sample_period: " + std::to_string(p.samples.size()) + " samples, at most " +
                                std::to_string(session::PredictionLimits().max_samples_per_shot) + " a shot");
  py::dict out;
  out["events"] = eventArrays(engine.table(), p.events, p.strike_time);
  out["state"] = toArrays(p.final_balls);
  out["samples"] = sampleArrays(p.samples);
  out["time_to_rest"] = p.time_to_rest;
  out["at_rest"] = p.at_rest;
  return out;
}

/// Shots given as rows of (ball, speed, phi, theta, a, b), with optional execution noise, run on
/// `threads` threads (0: every core) with the GIL released.
py::dict batch(const Engine<double>& engine, const StateArrays& start, py::array_t<double> shots, bool noise,
               std::uint64_t seed, unsigned threads)
{
  const auto rows = shots.unchecked<2>();
  if (rows.shape(1) != 6)
    throw std::invalid_argument("shots must be an (N, 6) array of ball, speed, phi, theta, a, b; got " +
                                std::to_string(rows.shape(1)) + " columns");
  const physics::TableState<double> state = fromArrays(engine, start);
  std::vector<physics::BatchShot<double>> planned(static_cast<std::size_t>(rows.shape(0)));
  // Shot i's noise comes from seed + i alone (as the node's ~predict_batch): a batch split into
  // chunks anywhere gives the same shots.
  for (py::ssize_t i = 0; i < rows.shape(0); ++i)
  {
    physics::NoisyCue cue(noise ? physics::ExecutionNoise() : physics::ExecutionNoise::none(),
                          seed + static_cast<std::uint64_t>(i));
    planned[static_cast<std::size_t>(i)].ball_id = static_cast<int>(rows(i, 0));
    planned[static_cast<std::size_t>(i)].cue =
        cue.execute(strikeOf(rows(i, 1), rows(i, 2), rows(i, 3), rows(i, 4), rows(i, 5)), engine.params().ball_radius);
  }
  std::vector<physics::ShotOutcome<double>> outcomes;
  {
    py::gil_scoped_release release;
    physics::ThreadPool pool(threads);
    outcomes = physics::simulateBatch(engine, state, planned, pool);
  }
  return batchArrays(planned, outcomes, state.balls.size());
}

/// The engine's own time [s] for the same batch as batch() runs (the same strikes, the same
/// pool), without any array in or out: what scripts/python_overhead.py compares batch() with.
double engineSeconds(const Engine<double>& engine, const StateArrays& start, py::array_t<double> shots,
                     unsigned threads)
{
  const auto rows = shots.unchecked<2>();
  const physics::TableState<double> state = fromArrays(engine, start);
  std::vector<physics::BatchShot<double>> planned(static_cast<std::size_t>(rows.shape(0)));
  for (py::ssize_t i = 0; i < rows.shape(0); ++i)
  {
    planned[static_cast<std::size_t>(i)].ball_id = static_cast<int>(rows(i, 0));
    planned[static_cast<std::size_t>(i)].cue = strikeOf(rows(i, 1), rows(i, 2), rows(i, 3), rows(i, 4), rows(i, 5));
  }
  py::gil_scoped_release release;
  physics::ThreadPool pool(threads);
  const auto begin = std::chrono::steady_clock::now();
  const auto outcomes = physics::simulateBatch(engine, state, planned, pool);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}
}  // namespace
}  // namespace python
}  // namespace cue_sim

PYBIND11_MODULE(_core, m)
{
  using namespace cue_sim;
  using namespace cue_sim::python;
  using physics::Engine;
  m.doc() = "cue_sim's engine, arrays in and out; use the cue_sim package, not this module";
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if (p)
        std::rethrow_exception(p);
    }
    catch (const std::invalid_argument& e)
    {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("table_names", &tableNames);
  m.def("ball_ball_models", &physics::ballBallModelNames);
  m.def("cushion_models", &physics::cushionModelNames);
  m.def("ball_table_models", &physics::ballTableModelNames);
  m.def("cue_models", &physics::cueModelNames);
  m.def("param_fields", &paramFields);
  m.def("rack_names", &physics::rackNames);
  m.def(
      "ball_colour",
      [](int id, bool carom, const std::string& set) {
        const Rgb c = ballColour(id, ballSetOf(carom, set));
        return std::make_tuple(c.r, c.g, c.b);
      },
      py::arg("id"), py::arg("carom") = false, py::arg("ball_set") = "");
  m.def(
      "is_striped", [](int id, bool carom, const std::string& set) { return isStriped(id, ballSetOf(carom, set)); },
      py::arg("id"), py::arg("carom") = false, py::arg("ball_set") = "");
  m.def(
      "is_numbered", [](int id, bool carom, const std::string& set) { return isNumbered(id, ballSetOf(carom, set)); },
      py::arg("id"), py::arg("carom") = false, py::arg("ball_set") = "");
  m.def("number_colour", [](int id) {
    const Rgb c = numberColour(id);
    return std::make_tuple(c.r, c.g, c.b);
  });
  py::class_<StateArrays>(m, "StateArrays")
      .def(py::init<>())
      .def_readwrite("ids", &StateArrays::ids)
      .def_readwrite("positions", &StateArrays::positions)
      .def_readwrite("velocities", &StateArrays::velocities)
      .def_readwrite("spins", &StateArrays::spins)
      .def_readwrite("motion", &StateArrays::motion)
      .def_readwrite("pocket", &StateArrays::pocket);
  py::class_<Engine<double>, std::shared_ptr<Engine<double>>>(m, "Engine")
      .def(py::init([](const std::string& table, const std::map<std::string, double>& params,
                       const std::string& ball_ball, const std::string& cushion, const std::string& ball_table,
                       const std::string& cue) {
             return std::const_pointer_cast<Engine<double>>(
                 makeEngine(table, params, ball_ball, cushion, ball_table, cue));
           }),
           py::arg("table"), py::arg("params"), py::arg("ball_ball_model"), py::arg("cushion_model"),
           py::arg("ball_table_model") = "", py::arg("cue_model") = "")
      .def_property_readonly("table_name", [](const Engine<double>& e) { return e.table().name(); })
      .def_property_readonly("ball_set", [](const Engine<double>& e) { return ballSetName(ballSetFor(e.table())); })
      .def_property_readonly("ball_ball_model", [](const Engine<double>& e) { return e.models().ball_ball; })
      .def_property_readonly("cushion_model", [](const Engine<double>& e) { return e.models().cushion; })
      .def_property_readonly("ball_table_model", [](const Engine<double>& e) { return e.models().ball_table; })
      .def_property_readonly("cue_model", [](const Engine<double>& e) { return e.models().cue; })
      .def_property_readonly("params",
                             [](const Engine<double>& e) {
                               std::map<std::string, double> out;
                               for (const auto& f : physics::physicsParamFields())
                                 out[f.name] = e.params().*f.member;
                               return out;
                             })
      .def_property_readonly("pockets",
                             [](const Engine<double>& e) {
                               std::vector<std::tuple<std::string, double, double, double>> out;
                               for (const auto& p : e.table().pockets())
                                 out.emplace_back(p.name, p.centre.x(), p.centre.y(), p.radius);
                               return out;
                             })
      .def_property_readonly("cloth",
                             [](const Engine<double>& e) {
                               const auto& t = e.table();
                               return std::make_tuple(t.clothCentre().x(), t.clothCentre().y(), t.clothLength(),
                                                      t.clothWidth());
                             })
      .def_property_readonly("cushions",
                             [](const Engine<double>& e) {
                               std::vector<std::tuple<std::string, double, double, double, double>> out;
                               for (const auto& c : e.table().segments())
                                 out.emplace_back(c.name, c.start.x(), c.start.y(), c.end.x(), c.end.y());
                               return out;
                             })
      .def_property_readonly("jaws",
                             [](const Engine<double>& e) {
                               std::vector<std::tuple<std::string, double, double, double>> out;
                               for (const auto& c : e.table().circles())
                                 out.emplace_back(c.name, c.centre.x(), c.centre.y(), c.radius);
                               return out;
                             })
      .def(
          "with_params",
          [](const Engine<double>& e, const std::map<std::string, double>& params) {
            // The same table model, shared, not read again: what a fit that changes coefficients
            // at every evaluation needs (a URDF read costs milliseconds).
            return std::make_shared<Engine<double>>(e.tableShared(), paramsFrom(params, e.params()), e.models(),
                                                    e.limits());
          },
          py::arg("params"), "This engine with the given coefficients changed (validated), the table shared.")
      .def("check", [](const Engine<double>& e, const StateArrays& s) { fromArrays(e, s); })
      .def("rack", &rack)
      .def("simulate", &simulate)
      .def("batch", &batch)
      .def("engine_seconds", &engineSeconds);
  bindGames(m);
  bindLearning(m);
  bindCalibration(m);
  bindLeastSquares(m);
  bindSoak(m);
}
