#include "cue_sim/physics/thread_pool.hpp"

#include <algorithm>
#include <exception>

namespace cue_sim
{
namespace physics
{
ThreadPool::ThreadPool(unsigned threads, const std::function<void()>& on_start)
{
  if (threads == 0)
    threads = std::max(1u, std::thread::hardware_concurrency());
  for (unsigned i = 1; i < threads; ++i)  // the caller is the last of them
    workers_.emplace_back([this, on_start] {
      if (on_start)
        on_start();
      work();
    });
}

ThreadPool::~ThreadPool()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& worker : workers_)
    worker.join();
}

void ThreadPool::parallelFor(std::size_t count, const std::function<void(std::size_t)>& body)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    count_ = count;
    next_ = finished_ = 0;
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  drain();
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return finished_ == count_; });
  body_ = nullptr;
  if (error_)
    std::rethrow_exception(error_);
}

void ThreadPool::drain()
{
  // Indices are handed out one at a time under the lock: shots take microseconds to
  // milliseconds, so the lock is never the bottleneck, and no thread idles while work is left.
  std::unique_lock<std::mutex> lock(mutex_);
  while (body_ && next_ < count_)
  {
    const std::size_t i = next_++;
    const auto* body = body_;
    lock.unlock();
    std::exception_ptr error;
    try
    {
      (*body)(i);
    }
    catch (...)
    {
      error = std::current_exception();
    }
    lock.lock();
    if (error && !error_)
      error_ = error;
    if (++finished_ == count_)
      done_.notify_all();
  }
}

void ThreadPool::work()
{
  unsigned long seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;)
  {
    wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
    if (stopping_)
      return;
    seen = generation_;
    lock.unlock();
    drain();
    lock.lock();
  }
}

}  // namespace physics
}  // namespace cue_sim
