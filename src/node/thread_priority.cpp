#include "node/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace cue_sim
{
void lowerThisThreadsPriority()
{
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kBackgroundNice);
}

bool raiseThisThreadToRealTime()
{
  sched_param priority{};
  priority.sched_priority = kPublishingRealTimePriority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &priority) == 0;
}

}  // namespace cue_sim
