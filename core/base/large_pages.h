// Memory for large grids: a DEM-sized buffer is touched page by page as it is first written, and
// on Linux each 4 KiB page is a fault into the kernel. Large blocks are aligned to 2 MiB and
// marked for transparent huge pages, which cuts those faults 512-fold; small ones are ordinary.
#pragma once

#include <cstddef>
#include <new>
#include <utility>

namespace tsk {

// Allocates `bytes`, asking the kernel for huge pages when the block is large (see above).
void* allocate_large(std::size_t bytes);
void free_large(void* block) noexcept;

template <typename T>
struct LargePageAllocator {
  using value_type = T;
  LargePageAllocator() = default;
  template <typename U>
  LargePageAllocator(const LargePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    return static_cast<T*>(allocate_large(n * sizeof(T)));
  }
  void deallocate(T* block, std::size_t) noexcept { free_large(block); }

  // Default-initialises: a vector of n numbers is left as the memory was, for grids that are
  // written in full next (by parallel workers, so pages are first touched where they are used).
  template <typename U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <typename U>
  bool operator==(const LargePageAllocator<U>&) const noexcept {
    return true;
  }
  template <typename U>
  bool operator!=(const LargePageAllocator<U>&) const noexcept {
    return false;
  }
};

}  // namespace tsk
