// The live table's clock: the physics time a stamp of the caller's clock (ROS time, in ns) maps to,
// as pauses, steps and the real-time factor leave it (PhysicsClock), and the latest stamp seen.
// It owns the pause and the factor; the live table brings its balls up to the clock before each
// change of it, so that the balls move at the old rate until the change.
#pragma once

#include <string>

#include "cue_sim/session/physics_clock.hpp"

namespace cue_sim
{
namespace session
{
/// Largest accepted real-time factor.
constexpr double kMaxRealTimeFactor = 1000.0;
/// Longest step [s] of a paused table.
constexpr double kMaxStep = 60.0;

class TableClock
{
public:
  /// Physics time runs at `real_time_factor` (in (0, kMaxRealTimeFactor]) from `now`, or not at
  /// all while paused.
  TableClock(double real_time_factor, bool paused, Stamp now);

  /// The physics time [s] at a stamp.
  double at(Stamp stamp) const { return clock_.at(stamp); }
  /// The stamp of a physics time (an event's), at the latest `now`.
  Stamp stampOf(double physics, Stamp now) const { return clock_.stampOf(physics, now); }
  /// Physics time 0 at `now`: a strike from rest, a new rack, a game shot's next table.
  void restart(Stamp now) { clock_.restart(now); }

  /// Notes that the table was brought up to `now`; a stamp before the latest changes nothing.
  void saw(Stamp now);
  /// The latest stamp the table was brought up to.
  Stamp lastStamp() const { return last_stamp_; }

  bool paused() const { return paused_; }
  double realTimeFactor() const { return factor_; }
  void pause(bool paused, Stamp now);
  /// Empty if a paused table may step `duration` [s] now, else why not.
  std::string whyNotStep(double duration) const;
  /// Physics time jumps `duration` on at `now` (whyNotStep first).
  void step(double duration, Stamp now) { clock_.step(now, duration); }
  /// Empty if `factor` is a real-time factor the clock takes, else why not.
  static std::string whyBadFactor(double factor);
  /// Physics time runs at `factor` from `now` on (once the pause ends, if paused).
  void setRealTimeFactor(double factor, Stamp now);

private:
  PhysicsClock clock_;
  bool paused_;
  double factor_;
  Stamp last_stamp_ = 0;
};

}  // namespace session
}  // namespace cue_sim
