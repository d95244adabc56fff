// table_node's thread priorities: background threads (predictions, the camera) run below the
// publishing thread, and the publishing thread above everything where the system allows it, so
// that tf keeps its rate whatever else runs.
#pragma once

#include <pthread.h>

namespace cue_sim
{
/// Nice value of the node's background threads: below the publishing thread (0).
constexpr int kBackgroundNice = 10;

/// Lowers the calling thread's priority to kBackgroundNice (Linux gives each thread a nice value
/// of its own; raising it needs no privilege).
void lowerThisThreadsPriority();

/// The publishing thread's SCHED_FIFO priority where granted: low among real-time threads (1-99),
/// above every normal one.
constexpr int kPublishingRealTimePriority = 10;

/// Puts the calling thread at kPublishingRealTimePriority (SCHED_FIFO) if the system grants it
/// (root, CAP_SYS_NICE, or an rtprio limit); false, and unchanged, if not. Only for a thread that
/// sleeps every period: a real-time thread that never sleeps starves the rest of its core.
bool raiseThisThreadToRealTime();

/// A mutex with priority inheritance (PTHREAD_PRIO_INHERIT): a thread holding it runs at the
/// priority of the highest thread waiting for it. The node's table lock is one: a background
/// thread (nice 10) holding it while the publishing thread (SCHED_FIFO) waits would otherwise wait
/// for a core behind every normal thread of the machine, and tf with it (priority inversion:
/// pauses of 25-48 ms in node_load.test beside two CPU hogs, against 10 ms between ticks). Where
/// the publishing thread has no real-time priority it is a plain mutex. Lockable, for
/// std::lock_guard.
class PriorityInheritingMutex
{
public:
  PriorityInheritingMutex();
  ~PriorityInheritingMutex();
  PriorityInheritingMutex(const PriorityInheritingMutex&) = delete;
  PriorityInheritingMutex& operator=(const PriorityInheritingMutex&) = delete;

  void lock();
  bool try_lock();
  void unlock();

private:
  pthread_mutex_t mutex_;
};

}  // namespace cue_sim
