// Table states, events and batch outcomes as NumPy arrays, and back: what cue_sim._core passes
// across. Every array is checked (shape, finite values, ids) before it becomes a state.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "cue_sim/physics/batch.hpp"
#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace python
{
/// A table state, one row a ball.
struct StateArrays
{
  pybind11::array_t<std::int32_t> ids;     ///< (N,)
  pybind11::array_t<double> positions;     ///< (N, 3) [m]
  pybind11::array_t<double> velocities;    ///< (N, 3) [m/s]
  pybind11::array_t<double> spins;         ///< (N, 3) angular velocities [rad/s]
  pybind11::array_t<std::uint8_t> motion;  ///< (N,) physics::Motion
  pybind11::array_t<std::int32_t> pocket;  ///< (N,) the pocket's index, -1 on the table
};

StateArrays toArrays(const physics::TableState<double>& state);
StateArrays toArrays(const std::vector<physics::Ball<double>>& balls);
/// The state at time 0; throws std::invalid_argument naming the array and the row at fault, or
/// the engine's reason the balls cannot stand so.
physics::TableState<double> fromArrays(const physics::Engine<double>& engine, const StateArrays& arrays);

/// Events as columns: time [s] since `strike_time`, kind, ball, other, and obstacle (the
/// cushion's, jaw's or pocket's name, empty for the others).
pybind11::dict eventArrays(const physics::TableModel& table, const std::vector<physics::Event<double>>& events,
                           double strike_time);

/// Samples as columns: positions, velocities, spins (K, N, 3), motion and pocket (K, N).
pybind11::dict sampleArrays(const std::vector<std::vector<physics::Ball<double>>>& samples);

/// A batch's outcomes as columns: the strikes as executed, each shot's final positions, pockets
/// and motion per ball, its events' count, time to rest, whether it came to rest, and why a shot
/// was not run ("" when it was).
pybind11::dict batchArrays(const std::vector<physics::BatchShot<double>>& shots,
                           const std::vector<physics::ShotOutcome<double>>& outcomes, std::size_t balls);

}  // namespace python
}  // namespace cue_sim
