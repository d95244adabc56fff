#include "python/state_arrays.hpp"

#include <cmath>
#include <stdexcept>

#include "cue_sim/session/ball_input.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
/// `a` as a C-contiguous (rows, columns) view, or why not, naming `field`.
template <typename T>
py::detail::unchecked_reference<T, 2> rowsOf(const py::array_t<T>& a, const char* field, py::ssize_t rows,
                                             py::ssize_t columns)
{
  if (a.ndim() != 2 || a.shape(0) != rows || a.shape(1) != columns)
    throw std::invalid_argument(std::string(field) + " must have shape (" + std::to_string(rows) + ", " +
                                std::to_string(columns) + ")");
  return a.template unchecked<2>();
}

template <typename T>
py::detail::unchecked_reference<T, 1> columnOf(const py::array_t<T>& a, const char* field, py::ssize_t rows)
{
  if (a.ndim() != 1 || a.shape(0) != rows)
    throw std::invalid_argument(std::string(field) + " must have shape (" + std::to_string(rows) + ",)");
  return a.template unchecked<1>();
}

physics::Vec3<double> row(const py::detail::unchecked_reference<double, 2>& a, py::ssize_t i, const char* field)
{
  const physics::Vec3<double> v(a(i, 0), a(i, 1), a(i, 2));
  if (!v.allFinite())
    throw std::invalid_argument(std::string(field) + "[" + std::to_string(i) + "] must be finite");
  return v;
}

const char* obstacleName(const physics::TableModel& table, const physics::Event<double>& e)
{
  using physics::EventKind;
  const auto index = static_cast<std::size_t>(e.obstacle);
  if (e.kind == EventKind::BallCushion && index < table.segments().size())
    return table.segments()[index].name.c_str();
  if (e.kind == EventKind::BallCircle && index < table.circles().size())
    return table.circles()[index].name.c_str();
  if (e.kind == EventKind::Pocketed && index < table.pockets().size())
    return table.pockets()[index].name.c_str();
  if (e.kind == EventKind::OffTable)
    return physics::offTablePlaceName(e.obstacle);
  return "";
}
}  // namespace

StateArrays toArrays(const physics::TableState<double>& state)
{
  return toArrays(state.balls);
}

StateArrays toArrays(const std::vector<physics::Ball<double>>& balls)
{
  const auto n = static_cast<py::ssize_t>(balls.size());
  StateArrays out;
  out.ids = py::array_t<std::int32_t>(n);
  out.positions = py::array_t<double>({n, py::ssize_t(3)});
  out.velocities = py::array_t<double>({n, py::ssize_t(3)});
  out.spins = py::array_t<double>({n, py::ssize_t(3)});
  out.motion = py::array_t<std::uint8_t>(n);
  out.pocket = py::array_t<std::int32_t>(n);
  auto ids = out.ids.mutable_unchecked<1>();
  auto r = out.positions.mutable_unchecked<2>();
  auto v = out.velocities.mutable_unchecked<2>();
  auto w = out.spins.mutable_unchecked<2>();
  auto motion = out.motion.mutable_unchecked<1>();
  auto pocket = out.pocket.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i)
  {
    const auto& b = balls[static_cast<std::size_t>(i)];
    ids(i) = b.id;
    for (int k = 0; k < 3; ++k)
    {
      r(i, k) = b.r[k];
      v(i, k) = b.v[k];
      w(i, k) = b.w[k];
    }
    motion(i) = static_cast<std::uint8_t>(b.motion);
    pocket(i) = b.pocket;
  }
  return out;
}

physics::TableState<double> fromArrays(const physics::Engine<double>& engine, const StateArrays& arrays)
{
  const py::ssize_t n = arrays.ids.ndim() == 1 ? arrays.ids.shape(0) : -1;
  if (n < 0)
    throw std::invalid_argument("ids must be a one-dimensional array");
  const auto ids = columnOf(arrays.ids, "ids", n);
  const auto r = rowsOf(arrays.positions, "positions", n, 3);
  const auto v = rowsOf(arrays.velocities, "velocities", n, 3);
  const auto w = rowsOf(arrays.spins, "spins", n, 3);
  const auto pocket = columnOf(arrays.pocket, "pocket", n);
  // As a request to the node gives them, checked the same way (session::stateFromInputs).
  std::vector<session::BallInput> inputs;
  for (py::ssize_t i = 0; i < n; ++i)
  {
    session::BallInput b;
    b.id = ids(i);
    b.position = row(r, i, "positions");
    b.velocity = row(v, i, "velocities");
    b.angular_velocity = row(w, i, "spins");
    const int p = pocket(i);
    if (p < physics::kOffTable || p >= static_cast<int>(engine.table().pockets().size()))
      throw std::invalid_argument("pocket[" + std::to_string(i) +
                                  "] must be -1 (on the table), -2 (off the table) or a pocket's index, got " +
                                  std::to_string(p));
    b.pocketed = p >= 0 || p == physics::kOffTable;
    if (p >= 0)  // in a pocket; off the table, in none (an empty name)
      b.pocket = engine.table().pockets()[static_cast<std::size_t>(p)].name;
    inputs.push_back(b);
  }
  physics::TableState<double> state;
  std::string why = session::stateFromInputs(inputs, engine.table(), engine.params().ball_radius, state);
  if (why.empty())
    why = engine.whyInvalid(state);
  if (!why.empty())
    throw std::invalid_argument("state: " + why);
  return state;
}

py::dict eventArrays(const physics::TableModel& table, const std::vector<physics::Event<double>>& events,
                     double strike_time)
{
  const auto n = static_cast<py::ssize_t>(events.size());
  py::array_t<double> time(n);
  py::array_t<std::int32_t> kind(n), ball(n), other(n);
  py::list obstacle;
  auto t = time.mutable_unchecked<1>();
  auto k = kind.mutable_unchecked<1>();
  auto b = ball.mutable_unchecked<1>();
  auto o = other.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i)
  {
    const auto& e = events[static_cast<std::size_t>(i)];
    t(i) = e.time - strike_time;
    k(i) = static_cast<std::int32_t>(e.kind);
    b(i) = e.ball;
    o(i) = e.other;
    obstacle.append(obstacleName(table, e));
  }
  py::dict out;
  out["time"] = time;
  out["kind"] = kind;
  out["ball"] = ball;
  out["other"] = other;
  out["obstacle"] = obstacle;
  return out;
}

py::dict sampleArrays(const std::vector<std::vector<physics::Ball<double>>>& samples)
{
  const auto k = static_cast<py::ssize_t>(samples.size());
  const auto n = static_cast<py::ssize_t>(samples.empty() ? 0 : samples.front().size());
  py::array_t<double> r({k, n, py::ssize_t(3)}), v({k, n, py::ssize_t(3)}), w({k, n, py::ssize_t(3)});
  py::array_t<std::uint8_t> motion({k, n});
  py::array_t<std::int32_t> pocket({k, n});
  auto rr = r.mutable_unchecked<3>();
  auto vv = v.mutable_unchecked<3>();
  auto ww = w.mutable_unchecked<3>();
  auto mo = motion.mutable_unchecked<2>();
  auto po = pocket.mutable_unchecked<2>();
  for (py::ssize_t s = 0; s < k; ++s)
    for (py::ssize_t i = 0; i < n; ++i)
    {
      const auto& b = samples[static_cast<std::size_t>(s)][static_cast<std::size_t>(i)];
      for (int c = 0; c < 3; ++c)
      {
        rr(s, i, c) = b.r[c];
        vv(s, i, c) = b.v[c];
        ww(s, i, c) = b.w[c];
      }
      mo(s, i) = static_cast<std::uint8_t>(b.motion);
      po(s, i) = b.pocket;
    }
  py::dict out;
  out["positions"] = r;
  out["velocities"] = v;
  out["spins"] = w;
  out["motion"] = motion;
  out["pocket"] = pocket;
  return out;
}

py::dict batchArrays(const std::vector<physics::BatchShot<double>>& shots,
                     const std::vector<physics::ShotOutcome<double>>& outcomes, std::size_t balls)
{
  const auto n = static_cast<py::ssize_t>(outcomes.size());
  const auto m = static_cast<py::ssize_t>(balls);
  py::array_t<double> executed({n, py::ssize_t(6)}), positions({n, m, py::ssize_t(3)}), time_to_rest(n);
  py::array_t<std::int32_t> pocket({n, m}), events(n);
  py::array_t<std::uint8_t> motion({n, m});
  py::array_t<bool> at_rest(n);
  py::list error;
  auto x = executed.mutable_unchecked<2>();
  auto r = positions.mutable_unchecked<3>();
  auto p = pocket.mutable_unchecked<2>();
  auto mo = motion.mutable_unchecked<2>();
  auto ev = events.mutable_unchecked<1>();
  auto tr = time_to_rest.mutable_unchecked<1>();
  auto ar = at_rest.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i)
  {
    const auto& shot = shots[static_cast<std::size_t>(i)];
    const auto& outcome = outcomes[static_cast<std::size_t>(i)];
    const double row[6] = {double(shot.ball_id), shot.cue.speed, shot.cue.phi, shot.cue.theta, shot.cue.a, shot.cue.b};
    for (int k = 0; k < 6; ++k)
      x(i, k) = row[k];
    for (py::ssize_t j = 0; j < m; ++j)
    {
      const auto& b = outcome.state.balls[static_cast<std::size_t>(j)];
      for (int k = 0; k < 3; ++k)
        r(i, j, k) = b.r[k];
      p(i, j) = b.pocket;
      mo(i, j) = static_cast<std::uint8_t>(b.motion);
    }
    ev(i) = static_cast<std::int32_t>(outcome.result.events.size());
    tr(i) = outcome.result.duration;
    ar(i) = outcome.result.at_rest;
    error.append(outcome.error);
  }
  py::dict out;
  out["executed"] = executed;
  out["positions"] = positions;
  out["pocket"] = pocket;
  out["motion"] = motion;
  out["events"] = events;
  out["time_to_rest"] = time_to_rest;
  out["at_rest"] = at_rest;
  out["error"] = error;
  return out;
}

}  // namespace python
}  // namespace cue_sim
