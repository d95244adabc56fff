// cue_sim._core's learning environments: options from a dict, observations and results as NumPy
// arrays, every step with the GIL released.
#include "python/learning_bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "cue_sim/learning/environment.hpp"
#include "cue_sim/learning/vector_environment.hpp"
#include "python/fast_method.hpp"
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

/// The option of that name, or null.
const learning::EnvOptionField* optionField(const std::string& name)
{
  for (const learning::EnvOptionField& field : learning::envOptionFields())
    if (name == field.name)
      return &field;
  return nullptr;
}

/// The options a dict gives, over the defaults (env_options.def); an unknown key or a value of
/// the wrong type is refused, naming it.
EnvOptions optionsFrom(const py::dict& given)
{
  using Kind = learning::EnvOptionField::Kind;
  EnvOptions o;
  for (const auto& [key_object, value] : given)
  {
    const std::string key = py::str(key_object);
    const learning::EnvOptionField* field = optionField(key);
    if (!field)
    {
      std::string names;
      for (const learning::EnvOptionField& f : learning::envOptionFields())
        names += (names.empty() ? "" : ", ") + std::string(f.name);
      throw std::invalid_argument(key + ": not an option; the options are " + names);
    }
    // Strictly typed: a bool is not taken for a number, nor a number for a flag (NumPy's scalars
    // are taken as Python's).
    const std::string type_name = Py_TYPE(value.ptr())->tp_name;
    const bool is_bool = PyBool_Check(value.ptr()) || type_name == "numpy.bool_" || type_name == "numpy.bool";
    const bool is_integer = !is_bool && PyIndex_Check(value.ptr());
    const bool is_real =
        is_integer || (!is_bool && (PyFloat_Check(value.ptr()) || type_name.rfind("numpy.float", 0) == 0));
    const bool fits = field->kind == Kind::kText      ? py::isinstance<py::str>(value)
                      : field->kind == Kind::kInteger ? is_integer
                      : field->kind == Kind::kReal    ? is_real
                                                      : is_bool;
    try
    {
      if (!fits)
        throw py::cast_error();
      switch (field->kind)
      {
        case Kind::kText:
          o.*field->text = value.cast<std::string>();
          break;
        case Kind::kInteger:
          o.*field->integer = value.cast<int>();
          break;
        case Kind::kReal:
          o.*field->real = value.cast<double>();
          break;
        case Kind::kFlag:
          o.*field->flag = value.cast<bool>();
          break;
      }
    }
    catch (const py::cast_error&)
    {
      static const char* const kinds[] = {"a string", "an integer", "a number", "True or False"};
      throw std::invalid_argument(key + ": " + std::string(py::str(py::repr(value))) + " is of the wrong type (" +
                                  kinds[static_cast<int>(field->kind)] + ")");
    }
  }
  return o;
}

/// The options as a dict of their values in `o`.
py::dict optionValues(const EnvOptions& o)
{
  using Kind = learning::EnvOptionField::Kind;
  py::dict values;
  for (const learning::EnvOptionField& field : learning::envOptionFields())
    switch (field.kind)
    {
      case Kind::kText:
        values[field.name] = o.*field.text;
        break;
      case Kind::kInteger:
        values[field.name] = o.*field.integer;
        break;
      case Kind::kReal:
        values[field.name] = o.*field.real;
        break;
      case Kind::kFlag:
        values[field.name] = o.*field.flag;
        break;
    }
  return values;
}

/// Every option's declaration, for the module's documentation and its tests.
py::list optionDeclarations()
{
  using Kind = learning::EnvOptionField::Kind;
  static const char* const kinds[] = {"text", "integer", "real", "flag"};
  const py::dict defaults = optionValues(EnvOptions());
  py::list out;
  for (const learning::EnvOptionField& field : learning::envOptionFields())
  {
    py::dict d(py::arg("name") = field.name, py::arg("kind") = kinds[static_cast<int>(field.kind)],
               py::arg("default") = defaults[field.name], py::arg("description") = field.description);
    if (field.kind == Kind::kText)
      d["choices"] =
          *field.choices ? py::cast(std::string(field.choices)).attr("split")() : py::cast(learning::taskNames());
    if (field.kind == Kind::kInteger || field.kind == Kind::kReal)
      d["range"] = py::make_tuple(field.min, field.max);
    out.append(d);
  }
  return out;
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

/// A new C-contiguous NumPy array of `typenum` (numpy's NPY_* number) and shape `dims`, made
/// through numpy's C API: pybind11's array constructor builds shape and stride vectors on the heap
/// first, a cost worth saving on a step that takes some 10 us.
py::object newArray(int typenum, std::initializer_list<py::ssize_t> dims)
{
  auto& api = py::detail::npy_api::get();
  std::array<Py_intptr_t, 4> shape{};
  std::copy(dims.begin(), dims.end(), shape.begin());
  PyObject* descr = api.PyArray_DescrFromType_(typenum);  // the new array takes this reference
  PyObject* array = api.PyArray_NewFromDescr_(api.PyArray_Type_, descr, static_cast<int>(dims.size()), shape.data(),
                                              nullptr, nullptr, 0, nullptr);
  if (!array)
    throw py::error_already_set();
  return py::reinterpret_steal<py::object>(array);
}

template <typename T>
T* dataOf(const py::object& array)
{
  return reinterpret_cast<T*>(py::detail::array_proxy(array.ptr())->data);
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
    using Api = py::detail::npy_api;
    const auto n = static_cast<py::ssize_t>(rows);
    if (s.state.size() > 0)
    {
      const auto size = static_cast<py::ssize_t>(s.state.size());
      state = rows > 0 ? newArray(Api::NPY_FLOAT_, {n, size}) : newArray(Api::NPY_FLOAT_, {size});
      buffers.state = dataOf<float>(state);
    }
    if (s.pixel_width > 0)
    {
      const py::ssize_t h = s.pixel_height, w = s.pixel_width;
      pixels = rows > 0 ? newArray(Api::NPY_UBYTE_, {n, h, w, 3}) : newArray(Api::NPY_UBYTE_, {h, w, 3});
      buffers.pixels = dataOf<std::uint8_t>(pixels);
    }
  }
};

/// The keys of a step's info: what every task tells, then what games tell, then position's.
enum InfoKey
{
  kShots,
  kPocketed,
  kScratch,
  kFirstContact,
  kFoul,
  kEvents,
  kShotTime,
  kReason,
  kPlayer,
  kNextPlayer,
  kWinner,
  kOpponentShots,
  kOpponentReason,
  kOpenShots,
  kPoints,
  kPenalty,
  kInfoKeys
};
constexpr std::array<const char*, kInfoKeys> kInfoKeyNames{
    "shots",           "pocketed",   "scratch", "first_contact", "foul",   "events",
    "shot_time",       "reason",     "player",  "next_player",   "winner", "opponent_shots",
    "opponent_reason", "open_shots", "points",  "penalty"};

/// The keys as Python strings, made once and kept for the module's life.
const std::array<py::str, kInfoKeys>& infoKeys()
{
  static const auto* keys = [] {
    auto* k = new std::array<py::str, kInfoKeys>;
    for (std::size_t i = 0; i < k->size(); ++i)
      (*k)[i] = py::str(kInfoKeyNames[i]);
    return k;
  }();
  return *keys;
}

/// d[key] = value, taking `value`'s reference.
void putInfo(PyObject* d, int key, PyObject* value)
{
  const auto owned = py::reinterpret_steal<py::object>(value);
  if (!value || PyDict_SetItem(d, infoKeys()[static_cast<std::size_t>(key)].ptr(), value) != 0)
    throw py::error_already_set();
}

PyObject* stringObject(const std::string& s)
{
  return PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
}

/// A step's info as a dict: what every task tells, what games tell (`game`) and what position
/// tells (`position`). The dict is made at its final size (CPython's _PyDict_NewPresized, which
/// Cython's modules use too): grown key by key it would be resized twice; a cheap shot's step
/// costs some 10 us, and the info is the larger part of Python's share of it.
py::dict infoDict(const learning::StepInfo& info, bool game, bool position)
{
  auto d = py::reinterpret_steal<py::dict>(_PyDict_NewPresized(kInfoKeys));
  if (!d)
    throw py::error_already_set();
  PyObject* p = d.ptr();
  putInfo(p, kShots, PyLong_FromLong(info.shots));
  putInfo(p, kPocketed, PyLong_FromLong(info.pocketed));
  putInfo(p, kScratch, PyBool_FromLong(info.scratch));
  putInfo(p, kFirstContact, PyLong_FromLong(info.first_contact));
  putInfo(p, kFoul, PyBool_FromLong(info.foul));
  putInfo(p, kEvents, PyLong_FromLong(info.events));
  putInfo(p, kShotTime, PyFloat_FromDouble(info.shot_time));
  putInfo(p, kReason, stringObject(info.reason));
  if (game)
  {
    putInfo(p, kPlayer, PyLong_FromLong(info.player));
    putInfo(p, kNextPlayer, PyLong_FromLong(info.next_player));
    putInfo(p, kWinner, PyLong_FromLong(info.winner));
    putInfo(p, kOpponentShots, PyLong_FromLong(info.opponent_shots));
    putInfo(p, kOpponentReason, stringObject(info.opponent_reason));
    putInfo(p, kPoints, PyLong_FromLong(info.points));
    putInfo(p, kPenalty, PyLong_FromLong(info.penalty));
  }
  if (position)
    putInfo(p, kOpenShots, PyLong_FromLong(info.open_shots));
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

/// `seed` as the engine takes it for `tables` tables (table i gets seed + i): an integer (not a
/// bool) with seed + tables - 1 below 2**64; else ValueError naming the value.
std::uint64_t checkedSeed(PyObject* seed, std::uint64_t tables)
{
  if (PyBool_Check(seed) || !PyIndex_Check(seed))
    throw std::invalid_argument("seed: an integer, got " + std::string(py::repr(seed)));
  const auto index = py::reinterpret_steal<py::object>(PyNumber_Index(seed));
  if (!index)
    throw py::error_already_set();
  const unsigned long long value = PyLong_AsUnsignedLongLong(index.ptr());
  const bool overflow = value == static_cast<unsigned long long>(-1) && PyErr_Occurred();
  if (overflow)
    PyErr_Clear();
  if (overflow || value > std::numeric_limits<std::uint64_t>::max() - (tables - 1))
    throw std::invalid_argument("seed: must be in [0, 2**64 - " + std::to_string(tables) + "], got " +
                                std::string(py::str(index)));
  return value;
}

/// A seed from the operating system's entropy: what a fresh environment's first unseeded reset
/// plays from, as Gymnasium's environments do.
std::uint64_t drawnSeed()
{
  std::random_device entropy;
  return (static_cast<std::uint64_t>(entropy()) << 32) ^ entropy();
}

struct PyEnvironment
{
  std::shared_ptr<const Engine> engine;
  learning::Environment env;

  bool game_info, position_info;  ///< what the task's info tells beside every task's
  /// Whether a step and a reset let other Python threads run: not for the one-shot tasks, pot and
  /// position, whose steps cost 10 to 20 us; releasing the GIL and taking it back costs some
  /// 0.5 us on this machine (3 to 5 % of such a step, measured with scripts/env_throughput.py),
  /// more than another thread could do in the time. A break or a game step costs 80 us and more
  /// (against the planner, milliseconds), and releases it.
  bool release_gil;

  PyEnvironment(std::shared_ptr<Engine> e, const py::dict& options)
    : engine(std::move(e)),
      env(engine, optionsFrom(options)),
      game_info(learning::isGameTask(env.options().task)),
      position_info(env.options().task == "position"),
      release_gil(env.options().task != "pot" && env.options().task != "position")
  {
  }

  std::uint64_t seeded_resets = 0;  ///< resets that seeded the episodes' stream
  std::uint64_t last_seed = 0;      ///< ... and the seed of the last of them

  /// Gymnasium's reset: (the first observation, {}). `seed`: None (the stream goes on; a fresh
  /// environment's first reset draws one) or an integer in [0, 2**64); `options`: None or empty
  /// (the options are the environment's). Nothing changes when either is refused.
  py::tuple reset(PyObject* seed, PyObject* options)
  {
    std::optional<std::uint64_t> s;
    if (seed != Py_None)
      s = checkedSeed(seed, 1);
    if (options != Py_None && (!PyDict_Check(options) || PyDict_Size(options) != 0))
      throw std::invalid_argument("options: reset takes none (give them to the environment), got " +
                                  std::string(py::str(py::handle(options))));
    if (!s && seeded_resets == 0)
      s = drawnSeed();
    Observations obs(env.spaces(), 0);
    {
      ReleasedGil released(release_gil);
      env.reset(s, obs.buffers);
    }
    if (s)
    {
      ++seeded_resets;
      last_seed = *s;
    }
    return py::make_tuple(obs.value(), py::dict());
  }

  /// Gymnasium's step: (observation, reward, terminated, truncated, info).
  py::tuple step(PyObject* action)
  {
    const auto a = actionRows(py::reinterpret_borrow<py::object>(action));
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
      ReleasedGil released(release_gil);
      r = env.step(a.data(), static_cast<std::size_t>(a.shape(0)), obs.buffers);
    }
    return py::make_tuple(obs.value(), r.reward, r.terminated, r.truncated, infoDict(r.info, game_info, position_info));
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

/// Env.step(action): CPython's own method (fast_method.hpp), the call a learner makes most.
PyObject* envStep(PyObject* self, PyObject* action) noexcept
{
  try
  {
    return instanceOf<PyEnvironment>(self).step(action).release().ptr();
  }
  catch (...)
  {
    setPythonError();
    return nullptr;
  }
}

/// Env.reset(*, seed=None, options=None): CPython's own method, with Gymnasium's keywords.
PyObject* envReset(PyObject* self, PyObject* const* args, Py_ssize_t nargsf, PyObject* kwnames) noexcept
{
  try
  {
    const Py_ssize_t positional = PyVectorcall_NARGS(nargsf);
    if (positional != 0)
      throw py::type_error("reset: takes seed and options by keyword only, got " + std::to_string(positional) +
                           " positional arguments");
    PyObject* seed = Py_None;
    PyObject* options = Py_None;
    const Py_ssize_t keywords = kwnames ? PyTuple_GET_SIZE(kwnames) : 0;
    for (Py_ssize_t k = 0; k < keywords; ++k)
    {
      PyObject* name = PyTuple_GET_ITEM(kwnames, k);
      if (PyUnicode_CompareWithASCIIString(name, "seed") == 0)
        seed = args[k];
      else if (PyUnicode_CompareWithASCIIString(name, "options") == 0)
        options = args[k];
      else
        throw py::type_error("reset: no argument " + std::string(py::str(name)) + "; it takes seed and options");
    }
    return instanceOf<PyEnvironment>(self).reset(seed, options).release().ptr();
  }
  catch (...)
  {
    setPythonError();
    return nullptr;
  }
}

PyMethodDef envStepDef{
    "step", reinterpret_cast<PyCFunction>(envStep), METH_O,
    "step($self, action, /)\n--\n\nPlays one shot: (observation, reward, terminated, truncated, info). "
    "ValueError names what is wrong with an action."};
PyMethodDef envResetDef{
    "reset", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(envReset)), METH_FASTCALL | METH_KEYWORDS,
    "reset($self, /, *, seed=None, options=None)\n--\n\nA new episode: (observation, {}). The same seed "
    "gives the same episode; without one the environment's stream goes on."};

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
        opponent_shots(n), points(n), penalty(n);
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
      points.mutable_at(i) = s.points;
      penalty.mutable_at(i) = s.penalty;
      reason.append(s.reason);
    }
    return py::dict(py::arg("shots") = shots, py::arg("pocketed") = pocketed, py::arg("scratch") = scratch,
                    py::arg("first_contact") = first_contact, py::arg("foul") = foul, py::arg("events") = events,
                    py::arg("shot_time") = shot_time, py::arg("reason") = reason, py::arg("player") = player,
                    py::arg("next_player") = next_player, py::arg("winner") = winner,
                    py::arg("opponent_shots") = opponent_shots, py::arg("points") = points,
                    py::arg("penalty") = penalty);
  }
};
}  // namespace

void bindLearning(py::module_& m)
{
  m.def("task_names", &learning::taskNames);
  m.def("default_options", [] { return optionValues(EnvOptions()); });
  m.def("env_options", &optionDeclarations);
  m.def(
      "checked_seed",
      [](const py::object& seed, std::uint64_t tables) {
        if (tables == 0)
          throw std::invalid_argument("tables: at least 1");
        return checkedSeed(seed.ptr(), tables);
      },
      py::arg("seed"), py::arg("tables") = 1);
  py::class_<PyEnvironment> env(m, "Env");
  env.def(py::init<std::shared_ptr<Engine>, const py::dict&>(), py::arg("engine"), py::arg("options"))
      .def_property_readonly("spaces", [](const PyEnvironment& e) { return spacesDict(e.env.spaces()); })
      .def("render", &PyEnvironment::render, py::arg("width"), py::arg("height"))
      .def("time_steps", &PyEnvironment::timeSteps, py::arg("actions"), py::arg("seed"))
      .def_property_readonly("done", [](const PyEnvironment& e) { return e.env.done(); })
      .def_property_readonly("seeding",
                             [](const PyEnvironment& e) { return py::make_tuple(e.seeded_resets, e.last_seed); })
      .def_property_readonly("game_start",
                             [](const PyEnvironment& e) -> py::object {
                               const auto start = e.env.gameStart();
                               if (!start)
                                 return py::none();
                               return py::dict(py::arg("rules") = start->rules, py::arg("rack_seed") = start->rack_seed,
                                               py::arg("breaker") = start->breaker, py::arg("target") = start->target);
                             })
      .def_property_readonly(
          "last_turns",
          [](const PyEnvironment& e) {
            py::list turns;
            for (const learning::PlayedTurn& t : e.env.lastTurns())
              turns.append(
                  py::dict(py::arg("player") = t.player, py::arg("ball") = t.ball, py::arg("placed") = t.placed,
                           py::arg("x") = t.x, py::arg("y") = t.y, py::arg("called_ball") = t.called_ball,
                           py::arg("called_pocket") = t.called_pocket, py::arg("push_out") = t.push_out,
                           py::arg("strike") =
                               py::make_tuple(t.strike.speed, t.strike.phi, t.strike.theta, t.strike.a, t.strike.b)));
            return turns;
          })
      .def_property_readonly("last_strike",
                             [](const PyEnvironment& e) {
                               const physics::CueStrike<double>& s = e.env.lastStrike();
                               return py::make_tuple(s.speed, s.phi, s.theta, s.a, s.b);
                             })
      .def("table", [](const PyEnvironment& e) { return toArrays(e.env.table().balls); })
      .def("rest_table", [](const PyEnvironment& e) { return toArrays(e.env.restTable().balls); });
  addFastMethod(env, envStepDef);
  addFastMethod(env, envResetDef);
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
