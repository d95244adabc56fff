// Resolving an event once the search has found it: a transition, an impact of the touching group
// of balls, a pressed cluster joined, a ball held on a wall, a ball pocketed (see README,
// "Simultaneous impacts" and "Sustained contact"). Internal to the physics core.
#pragma once

#include <vector>

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace physics
{
/// Finds the balls that may be within a distance of a point at the current event. Without one,
/// every ball in play is looked at.
template <typename S>
class Neighbours
{
public:
  virtual ~Neighbours() = default;
  /// Indices, ascending, of every ball in play that may be within `distance` of `point`.
  virtual void near(const Vec2<S>& point, S distance, std::vector<int>& out) const = 0;
};

/// What an event needs beyond the state: where the balls it names are, who changed, who is near.
template <typename S>
struct EventContext
{
  int index = -1;                       ///< of event.ball in state.balls
  int other_index = -1;                 ///< of event.other, for a ball-ball event
  std::vector<int>* changed = nullptr;  ///< receives the indices of the balls it changed
  const Neighbours<S>* neighbours = nullptr;
  std::vector<int>* scratch = nullptr;  ///< reused for neighbour lists, if given
};

/// Resolves the event (found by the search, at event.time) in the state.
template <typename S>
void resolveEvent(const Engine<S>& engine, TableState<S>& state, const Event<S>& event, const EventContext<S>& context);

/// The next step of the group in sustained contact of ball context.index, whose piece ends at `time`
/// (src/physics/contacts/support_groups.cpp): not an event, but it changes the group's balls.
template <typename S>
void resolveSupportStep(const Engine<S>& engine, TableState<S>& state, S time, const EventContext<S>& context);

}  // namespace physics
}  // namespace cue_sim
