// How the caller's clock (ROS time, in nanoseconds) maps to the table's physics time: physics =
// anchor + rate x (stamp - anchor stamp). A strike from rest restarts it at 0; pausing sets the
// rate to 0, a real-time factor sets it, and a step moves the anchor on. While the rate is 1 and
// nothing re-anchored it since the restart, physics time is exactly (stamp - restart stamp) in
// seconds as ROS computes it (whole seconds plus 1e-9 x nanoseconds), so that a pose stamped t
// is the trajectory's pose at exactly t - t_strike.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cue_sim
{
namespace session
{
using Stamp = std::int64_t;  ///< [ns]

/// Seconds of a duration in nanoseconds, rounded as ros::Duration::toSec rounds them.
inline double toSeconds(Stamp ns)
{
  const std::int64_t sec = ns >= 0 ? ns / 1000000000 : -((-ns + 999999999) / 1000000000);
  const std::int64_t nsec = ns - sec * 1000000000;
  return static_cast<double>(sec) + 1e-9 * static_cast<double>(nsec);
}

class PhysicsClock
{
public:
  /// Physics time 0 at `stamp`, at the current rate.
  void restart(Stamp stamp)
  {
    anchor_stamp_ = stamp;
    anchor_physics_ = 0;
  }

  /// Physics time [s] at a stamp (never before the anchor).
  double at(Stamp stamp) const
  {
    if (rate_ == 0 || stamp <= anchor_stamp_)
      return anchor_physics_;
    const double elapsed = toSeconds(stamp - anchor_stamp_);
    return rate_ == 1 ? anchor_physics_ + elapsed : anchor_physics_ + rate_ * elapsed;
  }

  /// The stamp of a physics time: when an event is stamped. Events found by a step while
  /// paused happen at `now`.
  Stamp stampOf(double physics, Stamp now) const
  {
    if (rate_ == 0)
      return now;
    const double after = (physics - anchor_physics_) / rate_;
    const Stamp stamp = anchor_stamp_ + static_cast<Stamp>(std::llround(after * 1e9));
    return std::min(stamp, now);
  }

  /// Physics advances at `rate` x the stamps from `stamp` on (0: paused).
  void setRate(Stamp stamp, double rate)
  {
    anchor_physics_ = at(stamp);
    anchor_stamp_ = stamp;
    rate_ = rate;
  }
  double rate() const { return rate_; }

  /// Physics time jumps `duration` [s] ahead at `stamp`.
  void step(Stamp stamp, double duration)
  {
    anchor_physics_ = at(stamp) + duration;
    anchor_stamp_ = stamp;
  }

private:
  Stamp anchor_stamp_ = 0;
  double anchor_physics_ = 0;
  double rate_ = 1;
};

}  // namespace session
}  // namespace cue_sim
