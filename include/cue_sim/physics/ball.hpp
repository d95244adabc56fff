// One ball's kinematic state. Each ball carries the time its state refers to, so an event
// touches only the balls it involves; every other ball keeps its closed-form trajectory.
#pragma once

#include <cstdint>
#include <string>

#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
/// Values match cue_sim/BallState.msg.
enum class Motion : std::uint8_t
{
  Stationary = 0,
  Spinning = 1,  ///< only z-spin is left
  Sliding = 2,   ///< the contact point slips on the cloth
  Rolling = 3,   ///< no slip: w_xy = (z x v) / R
  Pocketed = 4,  ///< out of play
  Airborne = 5,  ///< off the cloth: in flight under gravity (src/physics/models/flight.hpp)
  OffTable = 6,  ///< out of play: it flew over a cushion onto the rail or the floor (r: where it landed)
  Held = 7,      ///< at rest in the air, held by its supports (balls at rest, noses, rims) until one moves
};

const char* motionName(Motion motion);

/// The fastest a ball may be given (a placement, a scene file, a request): far beyond what a cue
/// or a collision gives (the hardest break sends the cue ball off at about 13 m/s, with at most
/// about 500 rad/s of spin from a 12 m/s cue at the largest tip offset), and small enough that
/// every term of a trajectory over EngineLimits::max_shot_time stays far inside double's range.
struct BallLimits
{
  static constexpr double max_speed = 100.0;  ///< |v| [m/s]
  static constexpr double max_spin = 1e5;     ///< |w| [rad/s]
};

/// Ball::pocket of a ball that left the table (Motion::OffTable): in no pocket, and not on the table.
constexpr int kOffTable = -2;

template <typename S>
struct Ball
{
  int id = 0;  ///< 0 is the cue ball; 1-15 the object balls.
  Motion motion = Motion::Stationary;
  S time = S(0);                ///< time [s] that r, v, w refer to
  Vec3<S> r = Vec3<S>::Zero();  ///< centre in the table frame [m]; z = R on the cloth
  Vec3<S> v = Vec3<S>::Zero();  ///< velocity [m/s]; z = 0 on the cloth
  Vec3<S> w = Vec3<S>::Zero();  ///< angular velocity [rad/s]
  int pocket = -1;              ///< index into TableModel::pockets when pocketed; kOffTable off the table

  bool inPlay() const { return motion != Motion::Pocketed && motion != Motion::OffTable; }
  bool moving() const { return translating() || motion == Motion::Spinning; }
  /// Its centre moves (a ball in the air counts, even one dropped straight down).
  bool translating() const
  {
    return motion == Motion::Sliding || motion == Motion::Rolling || motion == Motion::Airborne;
  }
  /// Off the cloth: in flight, or held at rest in the air.
  bool airborne() const { return motion == Motion::Airborne || motion == Motion::Held; }
  bool held() const { return motion == Motion::Held; }
};

}  // namespace physics
}  // namespace cue_sim
