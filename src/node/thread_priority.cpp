#include "node/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <system_error>

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

PriorityInheritingMutex::PriorityInheritingMutex()
{
  pthread_mutexattr_t attributes;
  pthread_mutexattr_init(&attributes);
  pthread_mutexattr_setprotocol(&attributes, PTHREAD_PRIO_INHERIT);
  const int error = pthread_mutex_init(&mutex_, &attributes);
  pthread_mutexattr_destroy(&attributes);
  if (error != 0)
    throw std::system_error(error, std::generic_category(), "priority-inheriting mutex");
}

PriorityInheritingMutex::~PriorityInheritingMutex()
{
  pthread_mutex_destroy(&mutex_);
}

void PriorityInheritingMutex::lock()
{
  if (const int error = pthread_mutex_lock(&mutex_); error != 0)
    throw std::system_error(error, std::generic_category(), "locking the table");
}

bool PriorityInheritingMutex::try_lock()
{
  return pthread_mutex_trylock(&mutex_) == 0;
}

void PriorityInheritingMutex::unlock()
{
  pthread_mutex_unlock(&mutex_);
}

}  // namespace cue_sim
