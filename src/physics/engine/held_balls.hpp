// Balls held at rest in the air (Motion::Held) on supports that do not move: a ball that moves
// under one lets it fall, to be held again if its supports still hold it (doc/physics.md,
// "Resting on a rounded support"). Internal to the physics core: the engine lets them fall at a
// strike, the event resolution (src/physics/contacts/) when a ball moves under one.
#pragma once

#include <vector>

#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace physics
{
/// A held ball within this [m] of touching a ball that moves falls: a support's gap, a few contact
/// tolerances (supportTouch) at most, with room to spare.
constexpr double kHeldReach = 4e-6;

/// Lets every held ball among `candidates` (indices into `state.balls`) that touches
/// state.balls[mover], as it is at `time`, fall: in the air at rest, from `time`. Appends their
/// indices to `fallen`.
template <typename S>
void letHeldBallsFall(TableState<S>& state, int mover, S time, const PhysicsParams<S>& params,
                      const std::vector<int>& candidates, std::vector<int>& fallen);

/// Every ball moved by the contact equations (Motion::Supported, Motion::Bearing) back to its own
/// closed-form motion at `time` (after an edit, which may have moved or taken away what they touch;
/// their groups form again at their next contacts). Appends their indices to `released`.
template <typename S>
void releaseSupportedBalls(TableState<S>& state, S time, const PhysicsParams<S>& params, std::vector<int>& released);

}  // namespace physics
}  // namespace cue_sim
