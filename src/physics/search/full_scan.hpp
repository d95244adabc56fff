// The next event found afresh: every ball and every pair looked at, nothing kept (internal to the
// physics core). It is the reference the kept search of a Simulation is checked against.
#pragma once

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace physics
{
/// The earliest event of the state, or an invalid event if nothing moves.
template <typename S>
Event<S> scanNextEvent(const Engine<S>& engine, const TableState<S>& state);

}  // namespace physics
}  // namespace cue_sim
