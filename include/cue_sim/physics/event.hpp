// What happened during a shot: one record per processed event.
#pragma once

#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
/// Values match cue_sim/Event kinds documented in README.md.
enum class EventKind : int
{
  None = -1,
  SlideToRoll = 0,   ///< slip reached zero: natural roll begins
  RollToSpin = 1,    ///< rolling stopped with z-spin left
  RollToStop = 2,    ///< rolling stopped
  SpinToStop = 3,    ///< z-spin ran out
  SlideToSpin = 4,   ///< sliding ended with no translation left (a pure spin)
  SlideToStop = 5,   ///< sliding ended with nothing left
  BallBall = 10,     ///< balls `ball` and `other` collided
  BallCushion = 11,  ///< `ball` hit straight cushion `obstacle`
  BallCircle = 12,   ///< `ball` hit circular cushion `obstacle` (jaw or cushion end)
  Pocketed = 13,     ///< `ball` dropped into pocket `obstacle`
  BallSlate = 14,    ///< `ball` came down onto the slate from the air (it bounces, or stays on the cloth)
  OffTable = 15,     ///< `ball` flew over the cushions out of play; `obstacle` says where it lands (below)
};

/// Where a ball that left the table lands (Event::obstacle of an OffTable event).
enum OffTablePlace : int
{
  kLandsOnRail = 0,   ///< on the rail's top, inside the table's edge (Ball::r is where it lands)
  kLandsOffTable = 1  ///< beyond the table's edge, on the floor (Ball::r is where it crossed the edge)
};

const char* eventKindName(EventKind kind);
/// "rail" or "floor".
const char* offTablePlaceName(int place);

template <typename S>
struct Event
{
  EventKind kind = EventKind::None;
  S time = infinity<S>();  ///< [s]
  int ball = -1;           ///< id of the (first) ball
  int other = -1;          ///< id of the second ball (BallBall) or -1
  int obstacle = -1;       ///< index of the cushion, circle or pocket, or -1
  S speed = S(0);          ///< [m/s] the ball's speed right after the event (recorded by advance)
  S other_speed = S(0);    ///< [m/s] the other ball's, BallBall only

  bool valid() const { return kind != EventKind::None; }
  bool isCollision() const
  {
    return kind == EventKind::BallBall || kind == EventKind::BallCushion || kind == EventKind::BallCircle;
  }
};

}  // namespace physics
}  // namespace cue_sim
