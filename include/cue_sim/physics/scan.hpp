// The next event found afresh: every ball and every pair looked at, nothing kept between calls.
// It is the reference the kept search of a Simulation is checked against (bit for bit, by the
// tests and the soak campaign), and costs a full look at every pair per event.
#pragma once

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace physics
{
/// The earliest event after state.event_time, or an invalid event if nothing moves.
template <typename S>
Event<S> scanNextEvent(const Engine<S>& engine, const TableState<S>& state);

/// Processes exactly that event (advancing state.time to it) and returns it; an invalid event,
/// and no change, if nothing moves.
template <typename S>
Event<S> scanStep(const Engine<S>& engine, TableState<S>& state);

}  // namespace physics
}  // namespace cue_sim
