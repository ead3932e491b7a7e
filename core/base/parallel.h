// Runs independent profile ranges on several threads, with progress and cancellation.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace tsk {

// Called with the fraction done (0..1) from the caller's thread; return false to cancel.
using ProgressFn = std::function<bool(double fraction)>;

// Tells `progress` (when there is one) that `fraction` of the work is done; throws Cancelled when
// it says stop.
void tell_progress(const ProgressFn& progress, double fraction);

// Progress of a part of the work, from `from` to `to` of the whole: 0..1 of the part reported to
// `whole` as from..to. Empty when `whole` is.
ProgressFn progress_part(const ProgressFn& whole, double from, double to);

// The number of threads a `threads` setting stands for: 0 means the hardware threads.
unsigned resolve_threads(unsigned threads);

// Calls work(begin, end) on chunks of [0, count) from up to `threads` threads (0: hardware
// threads). Exceptions from work are rethrown in the caller; a cancel throws Cancelled.
void parallel_for(std::size_t count, unsigned threads,
                  const std::function<void(std::size_t begin, std::size_t end)>& work,
                  const ProgressFn& progress = {});

// Two shares of one job at once: share(0, stop) on the caller's thread and, when `two`,
// share(1, stop) on a thread of its own (parallel_for may run both on the caller's). `stop` is
// set when either share throws, for the other to end at its next step; once both have ended, the
// caller's exception is rethrown, else the other's.
void run_two_shares(bool two,
                    const std::function<void(int share, const std::atomic<bool>& stop)>& share);

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

// Tasks run in order on a Worker of their own (or, without one, at once on the caller's thread),
// with at most `most_behind` of them unfinished: the caller waits when they fall further behind,
// and what a task threw is rethrown to the caller as soon as it is seen. Used from one thread at a
// time.
class TasksBehind {
 public:
  TasksBehind(std::size_t most_behind, bool on_own_thread)
      : most_behind_(most_behind), worker_(on_own_thread) {}
  // Waits for the tasks given (their failures are dropped: the run is ending anyway).
  ~TasksBehind();

  void run(std::function<void()> task);
  // Waits for every task given; rethrows the first failure.
  void finish();

 private:
  // Waits for the oldest task still listed and forgets it; rethrows its failure.
  void finish_oldest();
  std::size_t most_behind_;
  std::deque<std::future<void>> unfinished_;
  Worker worker_;  // declared last: stopped first, its tasks done
};

// The storage of batches handed from one thread to another, kept to be filled again: a batch
// allocated anew each time is memory the allocator gives back to the system, and the system
// zeroes again when it is asked for more (a drawn run's batches of pieces, 1.6 MB each, made a
// third of its page faults). A Batch is a container, or a record of them, with clear(). Any
// thread may take or give back.
template <typename Batch>
class BatchStorage {
 public:
  // An empty batch, with the storage of one given back if there is one.
  Batch take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.empty()) return {};
    Batch batch = std::move(spare_.back());
    spare_.pop_back();
    return batch;
  }
  // Keeps the storage of a batch whose items are done with.
  void give_back(Batch&& batch) {
    batch.clear();
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.size() < kMostKept) spare_.push_back(std::move(batch));
  }

 private:
  static constexpr std::size_t kMostKept = 2;  // a producer takes one back as a consumer gives one
  std::mutex mutex_;
  std::vector<Batch> spare_;
};

// Items handed to `take`, in order, a batch at a time, on a thread of its own when `alongside`:
// so that the caller's next work goes on while the last batch is taken (strokes written while the
// next profiles are linked). Used from one thread at a time; what `take` throws is rethrown by a
// later flush() or finish(). Destroyed unfinished (a run cancelled or failed), the batches not yet
// taken are dropped.
template <typename Item>
class HandOff {
 public:
  HandOff(std::function<void(Item&&)> take, bool alongside)
      : take_(std::move(take)), batches_(kBatchesBehind, alongside) {}
  ~HandOff() { abandoned_ = true; }
  HandOff(const HandOff&) = delete;
  HandOff& operator=(const HandOff&) = delete;

  void add(Item&& item) { batch_.push_back(std::move(item)); }
  // Hands on the items added since the last flush; waits when a few batches are still untaken.
  void flush() {
    if (batch_.empty()) return;
    auto taken = std::make_shared<std::vector<Item>>(std::move(batch_));
    batch_ = storage_.take();
    batch_.reserve(taken->size());  // batches run alike: one allocation, not a doubling series
    batches_.run([this, taken] {
      for (Item& item : *taken) {
        if (abandoned_) return;
        take_(std::move(item));
      }
      storage_.give_back(std::move(*taken));
    });
  }
  // Hands on what is left and waits until every item is taken.
  void finish() {
    flush();
    batches_.finish();
  }

 private:
  static constexpr std::size_t kBatchesBehind = 2;
  std::function<void(Item&&)> take_;
  std::vector<Item> batch_;
  BatchStorage<std::vector<Item>> storage_;
  std::atomic<bool> abandoned_{false};
  TasksBehind batches_;  // declared last: its tasks done before the rest goes
};

// Runs the batches [0, size), [size, 2 size), ... of `count` items through two steps in order:
// collect(first, batch) fills a Batch (in parallel, as it likes), then link(batch) takes it, on a
// thread of its own when `overlap`, while the next batch is collected; after(done) follows each
// link with the number of items done. What link throws is rethrown; if collect throws, the
// linking in flight finishes first.
template <typename Batch, typename Collect, typename Link, typename After>
void pipeline_batches(std::size_t count, std::size_t size, bool overlap, Collect&& collect,
                      Link&& link, After&& after) {
  Batch linking, collecting;
  // One linking thread for the whole run: the memory its links allocate, freed on other
  // threads, goes back to its allocator arena, which a new thread per batch would not keep (on
  // the 8000^2 benchmark's drawn strokes, the arenas grew and shrank batch after batch).
  // Declared after the batches: if collect throws, the linking in flight finishes before they go.
  Worker linker(overlap);
  collect(std::size_t{0}, linking);
  for (std::size_t first = 0; first < count; first += size) {
    const std::size_t next = first + size;
    std::future<void> linked = linker.run([&link, &linking] { link(linking); });
    if (next < count) collect(next, collecting);
    linked.get();
    std::swap(linking, collecting);
    after(std::min(next, count));
  }
}

}  // namespace tsk
