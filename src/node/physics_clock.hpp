// How ROS time maps to the table's physics time: physics = anchor + rate x (stamp - anchor
// stamp). A strike from rest restarts it at 0; pausing sets the rate to 0, a real-time factor
// sets it, and a step moves the anchor on. While the rate is 1 and nothing re-anchored it since
// the restart, physics time is exactly (stamp - restart stamp) in seconds, so that a pose
// stamped t is the trajectory's pose at exactly t - t_strike.
#pragma once

#include <ros/time.h>

#include <algorithm>

namespace cue_sim
{
class PhysicsClock
{
public:
  /// Physics time 0 at `stamp`, at the current rate.
  void restart(const ros::Time& stamp)
  {
    anchor_stamp_ = stamp;
    anchor_physics_ = 0;
  }

  /// Physics time [s] at a ROS time (never before the anchor).
  double at(const ros::Time& stamp) const
  {
    if (rate_ == 0 || stamp <= anchor_stamp_)
      return anchor_physics_;
    const double elapsed = (stamp - anchor_stamp_).toSec();
    return rate_ == 1 ? anchor_physics_ + elapsed : anchor_physics_ + rate_ * elapsed;
  }

  /// The ROS time of a physics time: when an event is stamped. Events found by a step while
  /// paused happen at `now`.
  ros::Time stampOf(double physics, const ros::Time& now) const
  {
    if (rate_ == 0)
      return now;
    const ros::Time stamp = anchor_stamp_ + ros::Duration((physics - anchor_physics_) / rate_);
    return std::min(stamp, now);
  }

  /// Physics advances at `rate` x ROS time from `stamp` on (0: paused).
  void setRate(const ros::Time& stamp, double rate)
  {
    anchor_physics_ = at(stamp);
    anchor_stamp_ = stamp;
    rate_ = rate;
  }
  double rate() const { return rate_; }

  /// Physics time jumps `duration` [s] ahead at `stamp`.
  void step(const ros::Time& stamp, double duration)
  {
    anchor_physics_ = at(stamp) + duration;
    anchor_stamp_ = stamp;
  }

private:
  ros::Time anchor_stamp_;
  double anchor_physics_ = 0;
  double rate_ = 1;
};

}  // namespace cue_sim
