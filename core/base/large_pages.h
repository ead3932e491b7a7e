// Memory for large grids: a DEM-sized buffer is touched page by page as it is first written, and
// on Linux each 4 KiB page is a fault into the kernel. Large blocks are aligned to 2 MiB, so that
// a system giving transparent huge pages to every process can back them so; small ones are
// ordinary. They are not marked for huge pages (MADV_HUGEPAGE): where the system gives huge
// pages only to marked memory, it also compacts memory to find them as the block is first
// touched, and with a full page cache that stall cost more than the faults it saves (a 256 MB
// block: 0.16 s of faults unmarked; marked, 0.02 s with huge pages free, 0.95 s without).
#pragma once

#include <cstddef>

#include "core/base/scratch_vector.h"

namespace tsk {

// Allocates `bytes`, aligned for huge pages when the block is large (see above).
void* allocate_large(std::size_t bytes);
void free_large(void* block) noexcept;

// Memory from allocate_large().
struct LargePages {
  static void* take(std::size_t bytes) { return allocate_large(bytes); }
  static void give_back(void* block) noexcept { free_large(block); }
};

// Default-initialises: a vector of n numbers is left as the memory was, for grids that are written
// in full next (by parallel workers, so pages are first touched where they are used).
template <typename T>
using LargePageAllocator = DefaultInitAllocator<T, LargePages>;

}  // namespace tsk
