// Runs independent profile ranges on several threads, with progress and cancellation.
#pragma once

#include <cstddef>
#include <functional>

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

}  // namespace tsk
