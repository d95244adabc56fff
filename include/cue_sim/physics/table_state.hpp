// The mutable part of a simulation: the balls and the clock. Copy it to predict a shot; the
// table model it runs on is shared and immutable.
#pragma once

#include <vector>

#include "cue_sim/physics/ball.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
struct TableState
{
  /// The time [s] the state has been advanced to. Balls keep their own reference times
  /// (Ball::time <= time); Engine::ballAt() gives a ball at any time.
  S time = S(0);
  /// Time [s] of the last processed event. Predictions start from here, not from `time`, so a
  /// shot's events do not depend on how often it was advanced.
  S event_time = S(0);
  /// How many events have happened at the instant of event_time (events each within about a
  /// picosecond of the one before count as one instant): a long run of them is an inelastic
  /// collapse, which the engine ends (EngineLimits::collapse_events). An edit sets it to 0.
  long events_this_instant = 0;
  std::vector<Ball<S>> balls;

  /// Index of the ball with this id, or -1.
  int indexOf(int id) const
  {
    for (std::size_t i = 0; i < balls.size(); ++i)
      if (balls[i].id == id)
        return static_cast<int>(i);
    return -1;
  }
  bool anyMoving() const
  {
    for (const auto& b : balls)
      if (b.moving())
        return true;
    return false;
  }

  template <typename T>
  TableState<T> cast() const
  {
    TableState<T> out;
    out.time = T(time);
    out.event_time = T(event_time);
    out.events_this_instant = events_this_instant;
    for (const auto& b : balls)
    {
      Ball<T> c;
      c.id = b.id;
      c.motion = b.motion;
      c.time = T(b.time);
      c.r = b.r.template cast<T>();
      c.v = b.v.template cast<T>();
      c.w = b.w.template cast<T>();
      c.pocket = b.pocket;
      c.piece.a = b.piece.a.template cast<T>();
      c.piece.alpha = b.piece.alpha.template cast<T>();
      c.piece.v_end = b.piece.v_end.template cast<T>();
      c.piece.until = T(b.piece.until);
      out.balls.push_back(c);
    }
    return out;
  }
};

/// Every ball referred to time 0, and the state's clock with them: a table at rest as a strike
/// from rest finds it. The live table, predictions and games all strike from here, so that the
/// same shot from the same balls rounds the same way wherever it is played.
template <typename S>
TableState<S> atTimeZero(TableState<S> state)
{
  state.time = state.event_time = S(0);
  state.events_this_instant = 0;
  for (auto& b : state.balls)
  {
    if (b.supported())
      b.piece.until -= b.time;  // a piece keeps its length
    b.time = S(0);
  }
  return state;
}

}  // namespace physics
}  // namespace cue_sim
