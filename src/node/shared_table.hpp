// The live table as the node's threads share it: one lock, and the time now as the node keeps
// it (with use_sim_time its own /clock, which roscpp's copy, set from /clock messages on the
// service threads, may lag behind).
#pragma once

#include <ros/time.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>

#include "cue_sim/session/live_table.hpp"
#include "node/thread_priority.hpp"

namespace cue_sim
{
struct SharedTable
{
  /// Guards live, sim_now and last_published. Priority-inheriting: the publishing thread never
  /// waits behind the machine's other work for a background thread that holds it.
  PriorityInheritingMutex mutex;
  std::optional<session::LiveTable> live;
  bool sim_time = false;
  ros::Time sim_now;                      ///< with sim_time: the time last published on /clock
  std::atomic<double> clock_factor{1.0};  ///< with sim_time: /clock per wall time; 0 as fast as possible
  ros::Time last_published;               ///< the stamp of the last tf and ~state

  /// The clock now; call it holding the lock.
  ros::Time clock() const { return sim_time ? sim_now : ros::Time::now(); }
  /// The stamp of a request now (call it holding the lock): after the last stamp published, so
  /// that what it changes is in the next tf and ~state, whose stamp is later still, and never in
  /// one that went out before it with the same stamp.
  ros::Time now() const { return std::max(clock(), last_published + ros::Duration(0, 1)); }
};

}  // namespace cue_sim
