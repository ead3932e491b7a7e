#include "core/base/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/base/errors.h"

namespace tsk {

void tell_progress(const ProgressFn& progress, double fraction) {
  if (progress && !progress(fraction)) throw Cancelled();
}

ProgressFn progress_part(const ProgressFn& whole, double from, double to) {
  if (!whole) return {};
  return [whole, from, to](double fraction) { return whole(from + (to - from) * fraction); };
}

unsigned resolve_threads(unsigned threads) {
  return threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

void run_two_shares(bool two,
                    const std::function<void(int share, const std::atomic<bool>& stop)>& share) {
  std::atomic<bool> stop{false};
  const auto run = [&](int which) {
    try {
      share(which, stop);
    } catch (...) {
      stop = true;
      throw;
    }
  };
  std::future<void> second;
  if (two) second = std::async(std::launch::async, run, 1);
  try {
    run(0);
  } catch (...) {
    if (second.valid()) second.wait();
    throw;
  }
  if (second.valid()) second.get();
}

void parallel_for(std::size_t count, unsigned threads,
                  const std::function<void(std::size_t, std::size_t)>& work,
                  const ProgressFn& progress) {
  if (count == 0) return;
  threads = resolve_threads(threads);
  // Small chunks so the caller's thread reports progress often and cancels quickly.
  const std::size_t chunk = std::max<std::size_t>(1, std::min<std::size_t>(64, count / 256 + 1));
  const std::size_t chunks = (count + chunk - 1) / chunk;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  bool cancelled = false;

  auto worker = [&](bool reports) {
    for (;;) {
      if (stop.load(std::memory_order_relaxed)) return;
      const std::size_t k = next.fetch_add(1);
      if (k >= chunks) return;
      try {
        work(k * chunk, std::min(count, (k + 1) * chunk));
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
        return;
      }
      const std::size_t finished = done.fetch_add(1) + 1;
      if (reports && progress && !progress(static_cast<double>(finished) / chunks)) {
        cancelled = true;
        stop = true;
        return;
      }
    }
  };

  const unsigned helpers = static_cast<unsigned>(std::min<std::size_t>(threads, chunks)) - 1;
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  for (unsigned t = 0; t < helpers; ++t) pool.emplace_back(worker, false);
  worker(true);
  for (auto& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
  if (cancelled) throw Cancelled();
}

Worker::Worker(bool on_own_thread) {
  if (on_own_thread) thread_ = std::thread([this] { serve(); });
}

Worker::~Worker() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

std::future<void> Worker::run(std::function<void()> task) {
  if (!thread_.joinable()) return std::async(std::launch::deferred, std::move(task));
  std::packaged_task<void()> packaged(std::move(task));
  std::future<void> done = packaged.get_future();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    tasks_.push_back(std::move(packaged));
  }
  wake_.notify_one();
  return done;
}

void Worker::serve() {
  for (;;) {
    std::packaged_task<void()> task;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (tasks_.empty()) return;  // stopping, every task done
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    task();  // what it throws goes to its future
  }
}

TasksBehind::~TasksBehind() {
  for (std::future<void>& task : unfinished_)
    if (task.valid()) task.wait();
}

void TasksBehind::run(std::function<void()> task) {
  std::future<void> done = worker_.run(std::move(task));
  if (!done.valid() || done.wait_for(std::chrono::seconds(0)) == std::future_status::deferred) {
    done.get();  // no thread of its own: the task runs here and now
    return;
  }
  unfinished_.push_back(std::move(done));
  while (!unfinished_.empty() &&
         (unfinished_.size() > most_behind_ ||
          unfinished_.front().wait_for(std::chrono::seconds(0)) == std::future_status::ready)) {
    finish_oldest();
  }
}

void TasksBehind::finish() {
  while (!unfinished_.empty()) finish_oldest();
}

void TasksBehind::finish_oldest() {
  std::future<void> oldest = std::move(unfinished_.front());
  unfinished_.pop_front();
  oldest.get();
}

}  // namespace tsk
