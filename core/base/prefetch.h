// Asking the processor early for memory another thread wrote, or that a loop will reach only a
// few steps later: where a run waits on cache misses it cannot otherwise avoid.
#pragma once

#include <cstddef>

namespace tsk {

// Every cache line of a record, to read it.
template <typename T>
void prefetch_record(const T& record) {
  const char* bytes = reinterpret_cast<const char*>(&record);
  for (std::size_t b = 0; b < sizeof(T); b += 64) __builtin_prefetch(bytes + b);
  __builtin_prefetch(bytes + sizeof(T) - 1);
}

// Every cache line of a record, to write it.
template <typename T>
void prefetch_record_to_write(const T& record) {
  const char* bytes = reinterpret_cast<const char*>(&record);
  for (std::size_t b = 0; b < sizeof(T); b += 64) __builtin_prefetch(bytes + b, 1);
  __builtin_prefetch(bytes + sizeof(T) - 1, 1);
}

}  // namespace tsk
