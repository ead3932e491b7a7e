// Asking the processor early for memory another thread wrote, or that a loop will reach only a
// few steps later: where a run waits on cache misses it cannot otherwise avoid.
#pragma once

#include <cstddef>

namespace tsk {

// Every cache line of `size` bytes from `at` (size > 0), to read them, or to write them when
// kToWrite is 1.
template <int kToWrite = 0>
void prefetch_bytes(const void* at, std::size_t size) {
  const char* bytes = static_cast<const char*>(at);
  for (std::size_t b = 0; b < size; b += 64) __builtin_prefetch(bytes + b, kToWrite);
  __builtin_prefetch(bytes + size - 1, kToWrite);
}

// Every cache line of a record, to read it.
template <typename T>
void prefetch_record(const T& record) {
  prefetch_bytes(&record, sizeof(T));
}

// Every cache line of a record, to write it.
template <typename T>
void prefetch_record_to_write(const T& record) {
  prefetch_bytes<1>(&record, sizeof(T));
}

}  // namespace tsk
