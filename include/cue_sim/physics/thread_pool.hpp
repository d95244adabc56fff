// A fixed set of worker threads that runs an indexed loop on all cores: what batch prediction
// needs, and nothing more. The engine has no global state, so shots can run side by side.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cue_sim
{
namespace physics
{
class ThreadPool
{
public:
  /// `threads` threads take part in a loop, the calling thread among them (0: one per core the
  /// machine reports). Each worker calls `on_start` first, if given (to lower its priority, say).
  explicit ThreadPool(unsigned threads = 0, const std::function<void()>& on_start = nullptr);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// Threads that take part in a loop, the caller included.
  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Calls body(i) for every i in [0, count), spread over the threads; returns when all are
  /// done. An exception from body is rethrown here (the first one; the rest of the loop still
  /// runs). One loop at a time per pool.
  void parallelFor(std::size_t count, const std::function<void(std::size_t)>& body);

private:
  void work();
  void drain();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* body_ = nullptr;
  std::size_t count_ = 0, next_ = 0, finished_ = 0;
  unsigned long generation_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace physics
}  // namespace cue_sim
