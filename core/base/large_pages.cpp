#include "core/base/large_pages.h"

#include <cstdlib>

namespace tsk {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Below this a block gains little from huge pages and would waste up to 2 MiB in alignment.
constexpr std::size_t kLargeBlock = std::size_t{8} << 20;

}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes < kLargeBlock) {
    if (void* block = std::malloc(bytes == 0 ? 1 : bytes)) return block;
    throw std::bad_alloc();
  }
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* block = std::aligned_alloc(kHugePage, rounded);
  if (!block) throw std::bad_alloc();
  return block;
}

void free_large(void* block) noexcept {
  std::free(block);
}

}  // namespace tsk
