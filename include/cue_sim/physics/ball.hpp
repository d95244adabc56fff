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
  /// In the air in sustained contact: resting on, rolling or sliding round balls, a cushion's nose or
  /// a post's rim, moved by the contact equations (src/physics/supports/), piece by piece (Ball::piece)
  Supported = 8,
  /// On the cloth, moved by the contact equations with the balls in sustained contact it bears or is
  /// pushed by (a ball under a Supported one), piece by piece (Ball::piece)
  Bearing = 9,
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

/// A stretch of the motion of a ball in sustained contact (Motion::Supported or Motion::Bearing): the
/// contact equations, integrated to the engine's contact_tolerance, give the ball's state at `until`;
/// between its own time and then, the ball follows the quadratic r + v tau + a tau^2 / 2 (within the
/// tolerance of the integrated path) and spins at w + alpha tau. Zero for every other motion.
template <typename S>
struct SupportPiece
{
  Vec3<S> a = Vec3<S>::Zero();      ///< acceleration over the piece [m/s^2]
  Vec3<S> alpha = Vec3<S>::Zero();  ///< angular acceleration over the piece [rad/s^2]
  Vec3<S> v_end = Vec3<S>::Zero();  ///< the velocity the contact equations give at `until` [m/s]
  S until = S(0);                   ///< the piece's end [s]
};

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
  SupportPiece<S> piece;        ///< Supported and Bearing only: the stretch of motion the contact equations gave it

  bool inPlay() const { return motion != Motion::Pocketed && motion != Motion::OffTable; }
  bool moving() const { return translating() || motion == Motion::Spinning; }
  /// Its centre moves (a ball in the air counts, even one dropped straight down; so does a ball in
  /// sustained contact, even one at rest at a turning point).
  bool translating() const
  {
    return motion == Motion::Sliding || motion == Motion::Rolling || motion == Motion::Airborne || supported();
  }
  /// Off the cloth: in flight, in sustained contact in the air, or held at rest in the air.
  bool airborne() const { return motion == Motion::Airborne || motion == Motion::Held || motion == Motion::Supported; }
  bool held() const { return motion == Motion::Held; }
  /// Moved by the contact equations (Supported in the air, Bearing on the cloth).
  bool supported() const { return motion == Motion::Supported || motion == Motion::Bearing; }
};

}  // namespace physics
}  // namespace cue_sim
