// Runs independent profile ranges on several threads, with progress and cancellation.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

namespace tsk {

// Called with the fraction done (0..1) from the caller's thread; return false to cancel.
using ProgressFn = std::function<bool(double fraction)>;

// The number of threads a `threads` setting stands for: 0 means the hardware threads.
unsigned resolve_threads(unsigned threads);

// Calls work(begin, end) on chunks of [0, count) from up to `threads` threads (0: hardware
// threads). Exceptions from work are rethrown in the caller; a cancel throws Cancelled.
void parallel_for(std::size_t count, unsigned threads,
                  const std::function<void(std::size_t begin, std::size_t end)>& work,
                  const ProgressFn& progress = {});

// Work that goes alongside the caller's, strip after strip, on one thread of its own: the same
// thread every time, so that memory it frees comes back to it. (A new thread for every strip may
// take another of the allocator's arenas each time, and each arena keeps what was freed in it:
// reading a 40000 x 40000 DEM, 0.2 GB more at the peak.) Not on its own thread, a task runs
// when its result is asked for, on the caller's thread.
class Worker {
 public:
  explicit Worker(bool on_own_thread = true);
  ~Worker();  // finishes the tasks given
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // Runs `task` after those given before; get() on the future waits for it and rethrows what it
  // threw.
  std::future<void> run(std::function<void()> task);

 private:
  void serve();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<void()>> tasks_;
  bool stopping_ = false;
  std::thread thread_;  // not started without threads
};

}  // namespace tsk
