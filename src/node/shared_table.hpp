// The live table as the node's threads share it: one lock, and the time now as the node keeps
// it (with use_sim_time its own /clock, which roscpp's copy, set from /clock messages on the
// service threads, may lag behind).
#pragma once

#include <ros/time.h>

#include <atomic>
#include <mutex>
#include <optional>

#include "cue_sim/session/live_table.hpp"

namespace cue_sim
{
struct SharedTable
{
  std::mutex mutex;  ///< guards live and sim_now
  std::optional<session::LiveTable> live;
  bool sim_time = false;
  ros::Time sim_now;                      ///< with sim_time: the time last published on /clock
  std::atomic<double> clock_factor{1.0};  ///< with sim_time: /clock per wall time; 0 as fast as possible

  /// The time now; call it holding the lock.
  ros::Time now() const { return sim_time ? sim_now : ros::Time::now(); }
};

}  // namespace cue_sim
