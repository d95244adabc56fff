// cue_sim._core's learning environments: options from a dict, observations and results as NumPy
// arrays, every step with the GIL released.
#include "python/learning_bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cue_sim/learning/environment.hpp"
#include "cue_sim/learning/vector_environment.hpp"
#include "python/state_arrays.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
using learning::EnvOptions;
using Engine = physics::Engine<double>;

/// The options a dict gives, over the defaults; an unknown key or a value of the wrong type is
/// refused, naming it.
EnvOptions optionsFrom(const py::dict& given)
{
  EnvOptions o;
  for (const auto& [key_object, value] : given)
  {
    const std::string key = py::str(key_object);
    try
    {
      if (key == "task")
        o.task = value.cast<std::string>();
      else if (key == "balls")
        o.balls = value.cast<int>();
      else if (key == "target")
        o.target = value.cast<std::string>();
      else if (key == "max_shots")
        o.max_shots = value.cast<int>();
      else if (key == "rack")
        o.rack = value.cast<std::string>();
      else if (key == "action")
        o.action = value.cast<std::string>();
      else if (key == "spin")
        o.spin = value.cast<bool>();
      else if (key == "opponent")
        o.opponent = value.cast<std::string>();
      else if (key == "opponent_skill")
        o.opponent_skill = value.cast<double>();
      else if (key == "opponent_noise")
        o.opponent_noise = value.cast<bool>();
      else if (key == "shaping")
        o.shaping = value.cast<double>();
      else if (key == "noise")
      {
        if (!value.cast<bool>())
          o.noise = physics::ExecutionNoise::none();
      }
      else if (key == "observation")
        o.observation = value.cast<std::string>();
      else if (key == "pixel_width")
        o.pixel_width = value.cast<int>();
      else if (key == "pixel_height")
        o.pixel_height = value.cast<int>();
      else
        throw std::invalid_argument(
            key +
            ": not an option; the options are task, balls, target, max_shots, rack, "
            "action, spin, opponent, opponent_skill, opponent_noise, shaping, noise, observation, "
            "pixel_width, pixel_height");
    }
    catch (const py::cast_error&)
    {
      throw std::invalid_argument(key + ": " + std::string(py::str(py::repr(value))) + " is of the wrong type");
    }
  }
  return o;
}

py::dict boxDict(const learning::BoxSpec& box)
{
  return py::dict(py::arg("names") = box.names, py::arg("low") = box.low, py::arg("high") = box.high);
}

py::dict spacesDict(const learning::Spaces& s)
{
  return py::dict(py::arg("action") = boxDict(s.action), py::arg("state") = boxDict(s.state),
                  py::arg("pixel_width") = s.pixel_width, py::arg("pixel_height") = s.pixel_height);
}

/// Observation arrays for `rows` tables (rows 0: one table, no leading axis), or None where the
/// observation lacks them.
struct Observations
{
  py::object state = py::none(), pixels = py::none();
  learning::ObservationBuffers buffers;

  /// The observation as the space has it: the state, the pixels, or both in a dict.
  py::object value() const
  {
    if (!state.is_none() && !pixels.is_none())
      return py::dict(py::arg("state") = state, py::arg("pixels") = pixels);
    return state.is_none() ? pixels : state;
  }

  Observations(const learning::Spaces& s, std::size_t rows)
  {
    const auto lead = [rows](std::vector<py::ssize_t> shape) {
      if (rows > 0)
        shape.insert(shape.begin(), static_cast<py::ssize_t>(rows));
      return shape;
    };
    if (s.state.size() > 0)
    {
      const auto size = static_cast<py::ssize_t>(s.state.size());
      py::array_t<float> a =
          rows > 0 ? py::array_t<float>({static_cast<py::ssize_t>(rows), size}) : py::array_t<float>(size);
      buffers.state = a.mutable_data();
      state = a;
    }
    if (s.pixel_width > 0)
    {
      py::array_t<std::uint8_t> a(lead({s.pixel_height, s.pixel_width, 3}));
      buffers.pixels = a.mutable_data();
      pixels = a;
    }
  }
};

/// A step's info as a dict: what every task tells, what games tell (`game`) and what position
/// tells (`position`). Its keys are made once: a step of a cheap shot costs some 12 us, so the
/// dict's making is a part of Python's share worth keeping small.
py::dict infoDict(const learning::StepInfo& info, bool game, bool position)
{
  static const auto* keys =
      new std::array<py::str, 14>{py::str("shots"),           py::str("pocketed"),  py::str("scratch"),
                                  py::str("first_contact"),   py::str("foul"),      py::str("events"),
                                  py::str("shot_time"),       py::str("reason"),    py::str("player"),
                                  py::str("next_player"),     py::str("winner"),    py::str("opponent_shots"),
                                  py::str("opponent_reason"), py::str("open_shots")};
  const auto& k = *keys;
  py::dict d;
  d[k[0]] = info.shots;
  d[k[1]] = info.pocketed;
  d[k[2]] = info.scratch;
  d[k[3]] = info.first_contact;
  d[k[4]] = info.foul;
  d[k[5]] = info.events;
  d[k[6]] = info.shot_time;
  d[k[7]] = info.reason;
  if (game)
  {
    d[k[8]] = info.player;
    d[k[9]] = info.next_player;
    d[k[10]] = info.winner;
    d[k[11]] = info.opponent_shots;
    d[k[12]] = info.opponent_reason;
  }
  if (position)
    d[k[13]] = info.open_shots;
  return d;
}

/// A (rows, columns) C-contiguous float64 view of `actions` (one table: a vector is one row).
py::array_t<double, py::array::c_style | py::array::forcecast> actionRows(const py::object& actions)
{
  using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;
  // A learner's float64 array, the common case, is taken as it is, without numpy's conversion.
  if (py::isinstance<py::array_t<double, py::array::c_style>>(actions) &&
      (py::reinterpret_borrow<py::array>(actions).flags() & py::array::c_style))
    return py::reinterpret_borrow<Rows>(actions);
  return Rows::ensure(actions);
}

struct PyEnvironment
{
  std::shared_ptr<const Engine> engine;
  learning::Environment env;

  PyEnvironment(std::shared_ptr<Engine> e, const py::dict& options)
    : engine(std::move(e)), env(engine, optionsFrom(options))
  {
  }

  /// The first observation of a new episode.
  py::object reset(std::optional<std::uint64_t> seed)
  {
    Observations obs(env.spaces(), 0);
    {
      py::gil_scoped_release release;
      env.reset(seed, obs.buffers);
    }
    return obs.value();
  }

  /// Gymnasium's step: (observation, reward, terminated, truncated, info).
  py::tuple step(const py::object& action)
  {
    const auto a = actionRows(action);
    if (!a || a.ndim() != 1)
    {
      std::string names;
      for (const std::string& name : env.spaces().action.names)
        names += (names.empty() ? "" : ", ") + name;
      throw std::invalid_argument("action: a vector of " + std::to_string(env.spaces().action.size()) + " values (" +
                                  names + "), got shape of " + std::to_string(a ? a.ndim() : -1) + " dimensions");
    }
    Observations obs(env.spaces(), 0);
    learning::StepResult r;
    {
      py::gil_scoped_release release;
      r = env.step(a.data(), static_cast<std::size_t>(a.shape(0)), obs.buffers);
    }
    const std::string& task = env.options().task;
    return py::make_tuple(obs.value(), r.reward, r.terminated, r.truncated,
                          infoDict(r.info, task == "eight_ball" || task == "nine_ball", task == "position"));
  }

  /// The same episodes as reset(seed) and step() over the rows of `actions` (reset when one ends)
  /// give, in C++ alone: the seconds they take, for scripts/env_throughput.py to set Python's
  /// cost beside.
  double timeSteps(const py::object& actions, std::uint64_t seed)
  {
    const auto a = actionRows(actions);
    if (!a || a.ndim() != 2)
      throw std::invalid_argument("actions: a 2-D array, one action a row");
    std::vector<float> state(env.spaces().state.size());
    std::vector<std::uint8_t> pixels(env.spaces().pixelBytes());
    const learning::ObservationBuffers out{state.empty() ? nullptr : state.data(),
                                           pixels.empty() ? nullptr : pixels.data()};
    py::gil_scoped_release release;
    const auto begin = std::chrono::steady_clock::now();
    env.reset(seed, out);
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
    {
      env.step(a.data(i, 0), static_cast<std::size_t>(a.shape(1)), out);
      if (env.done())
        env.reset(std::nullopt, out);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  }

  py::array_t<std::uint8_t> render(int width, int height) const
  {
    std::vector<std::uint8_t> rgb = env.render(width, height);
    py::array_t<std::uint8_t> out({height, width, 3});
    std::copy(rgb.begin(), rgb.end(), out.mutable_data());
    return out;
  }
};

struct PyVectorEnvironment
{
  std::shared_ptr<const Engine> engine;
  learning::VectorEnvironment envs;

  PyVectorEnvironment(std::shared_ptr<Engine> e, const py::dict& options, int count, unsigned threads)
    : engine(std::move(e)), envs(engine, optionsFrom(options), count, threads)
  {
  }

  py::object reset(std::optional<std::uint64_t> seed)
  {
    Observations obs(envs.spaces(), static_cast<std::size_t>(envs.size()));
    learning::VectorBuffers out;
    out.state = obs.buffers.state;
    out.pixels = obs.buffers.pixels;
    {
      py::gil_scoped_release release;
      envs.reset(seed, out);
    }
    return obs.value();
  }

  py::tuple step(const py::object& actions)
  {
    const auto a = actionRows(actions);
    if (!a || a.ndim() != 2)
      throw std::invalid_argument("actions: an array of shape (" + std::to_string(envs.size()) + ", " +
                                  std::to_string(envs.spaces().action.size()) + "), got " +
                                  std::to_string(a ? a.ndim() : -1) + " dimensions");
    const auto n = static_cast<std::size_t>(envs.size());
    Observations obs(envs.spaces(), n);
    py::array_t<double> rewards(static_cast<py::ssize_t>(n));
    py::array_t<bool> terminated(static_cast<py::ssize_t>(n)), truncated(static_cast<py::ssize_t>(n)),
        autoreset(static_cast<py::ssize_t>(n));
    std::vector<learning::StepInfo> infos(n);
    learning::VectorBuffers out;
    out.state = obs.buffers.state;
    out.pixels = obs.buffers.pixels;
    out.rewards = rewards.mutable_data();
    out.terminated = reinterpret_cast<std::uint8_t*>(terminated.mutable_data());
    out.truncated = reinterpret_cast<std::uint8_t*>(truncated.mutable_data());
    out.autoreset = reinterpret_cast<std::uint8_t*>(autoreset.mutable_data());
    out.infos = infos.data();
    {
      py::gil_scoped_release release;
      envs.step(a.data(), static_cast<std::size_t>(a.shape(0)), static_cast<std::size_t>(a.shape(1)), out);
    }
    py::dict info = infoArrays(infos);
    info["autoreset"] = autoreset;
    return py::make_tuple(obs.value(), rewards, terminated, truncated, info);
  }

  static py::dict infoArrays(const std::vector<learning::StepInfo>& infos)
  {
    const auto n = static_cast<py::ssize_t>(infos.size());
    py::array_t<int> shots(n), pocketed(n), first_contact(n), events(n), player(n), next_player(n), winner(n),
        opponent_shots(n);
    py::array_t<bool> scratch(n), foul(n);
    py::array_t<double> shot_time(n);
    py::list reason;
    for (py::ssize_t i = 0; i < n; ++i)
    {
      const learning::StepInfo& s = infos[static_cast<std::size_t>(i)];
      shots.mutable_at(i) = s.shots;
      pocketed.mutable_at(i) = s.pocketed;
      first_contact.mutable_at(i) = s.first_contact;
      events.mutable_at(i) = s.events;
      scratch.mutable_at(i) = s.scratch;
      foul.mutable_at(i) = s.foul;
      shot_time.mutable_at(i) = s.shot_time;
      player.mutable_at(i) = s.player;
      next_player.mutable_at(i) = s.next_player;
      winner.mutable_at(i) = s.winner;
      opponent_shots.mutable_at(i) = s.opponent_shots;
      reason.append(s.reason);
    }
    return py::dict(py::arg("shots") = shots, py::arg("pocketed") = pocketed, py::arg("scratch") = scratch,
                    py::arg("first_contact") = first_contact, py::arg("foul") = foul, py::arg("events") = events,
                    py::arg("shot_time") = shot_time, py::arg("reason") = reason, py::arg("player") = player,
                    py::arg("next_player") = next_player, py::arg("winner") = winner,
                    py::arg("opponent_shots") = opponent_shots);
  }
};
}  // namespace

void bindLearning(py::module_& m)
{
  m.def("task_names", &learning::taskNames);
  m.def("default_options", [] {
    const EnvOptions o;
    return py::dict(py::arg("balls") = o.balls, py::arg("target") = o.target, py::arg("max_shots") = o.max_shots,
                    py::arg("rack") = o.rack, py::arg("action") = o.action, py::arg("spin") = o.spin,
                    py::arg("opponent") = o.opponent, py::arg("opponent_skill") = o.opponent_skill,
                    py::arg("opponent_noise") = o.opponent_noise, py::arg("shaping") = o.shaping,
                    py::arg("noise") = !o.noise.isNone(), py::arg("observation") = o.observation,
                    py::arg("pixel_width") = o.pixel_width, py::arg("pixel_height") = o.pixel_height);
  });
  py::class_<PyEnvironment>(m, "Env")
      .def(py::init<std::shared_ptr<Engine>, const py::dict&>(), py::arg("engine"), py::arg("options"))
      .def_property_readonly("spaces", [](const PyEnvironment& e) { return spacesDict(e.env.spaces()); })
      .def("reset", &PyEnvironment::reset, py::arg("seed") = py::none())
      .def("step", &PyEnvironment::step, py::arg("action"))
      .def("render", &PyEnvironment::render, py::arg("width"), py::arg("height"))
      .def("time_steps", &PyEnvironment::timeSteps, py::arg("actions"), py::arg("seed"))
      .def_property_readonly("done", [](const PyEnvironment& e) { return e.env.done(); })
      .def_property_readonly("game_start",
                             [](const PyEnvironment& e) -> py::object {
                               const auto start = e.env.gameStart();
                               if (!start)
                                 return py::none();
                               return py::dict(py::arg("rules") = start->rules, py::arg("rack_seed") = start->rack_seed,
                                               py::arg("breaker") = start->breaker);
                             })
      .def_property_readonly(
          "last_turns",
          [](const PyEnvironment& e) {
            py::list turns;
            for (const learning::PlayedTurn& t : e.env.lastTurns())
              turns.append(py::dict(py::arg("player") = t.player, py::arg("placed") = t.placed, py::arg("x") = t.x,
                                    py::arg("y") = t.y, py::arg("called_ball") = t.called_ball,
                                    py::arg("called_pocket") = t.called_pocket, py::arg("push_out") = t.push_out,
                                    py::arg("strike") = py::make_tuple(t.strike.speed, t.strike.phi, t.strike.theta,
                                                                       t.strike.a, t.strike.b)));
            return turns;
          })
      .def_property_readonly("last_strike",
                             [](const PyEnvironment& e) {
                               const physics::CueStrike<double>& s = e.env.lastStrike();
                               return py::make_tuple(s.speed, s.phi, s.theta, s.a, s.b);
                             })
      .def("table", [](const PyEnvironment& e) { return toArrays(e.env.table().balls); })
      .def("rest_table", [](const PyEnvironment& e) { return toArrays(e.env.restTable().balls); });
  py::class_<PyVectorEnvironment>(m, "VectorEnv")
      .def(py::init<std::shared_ptr<Engine>, const py::dict&, int, unsigned>(), py::arg("engine"), py::arg("options"),
           py::arg("num_envs"), py::arg("threads") = 0)
      .def_property_readonly("spaces", [](const PyVectorEnvironment& e) { return spacesDict(e.envs.spaces()); })
      .def_property_readonly("num_envs", [](const PyVectorEnvironment& e) { return e.envs.size(); })
      .def("reset", &PyVectorEnvironment::reset, py::arg("seed") = py::none())
      .def("step", &PyVectorEnvironment::step, py::arg("actions"));
}

}  // namespace python
}  // namespace cue_sim
