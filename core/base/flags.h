// Per-cell classification bits of the oriented grid, one byte per cell, filled stage by stage.
#pragma once

#include <cstdint>
#include <cstring>

#include "core/base/grid.h"

namespace tsk {

namespace cell {
constexpr std::uint8_t valid = 1;      // has a height
constexpr std::uint8_t hidden = 2;     // strictly below something nearer on its profile
constexpr std::uint8_t occluding = 4;  // visible, next valid cell hidden: a Factual Silhouette
constexpr std::uint8_t candidate = 8;  // c-set: back-facing, brought into view by the base slope
constexpr std::uint8_t filtered = 16;  // f-set: c-set, visible, accepted by the slope filter
constexpr std::uint8_t thinned = 32;   // t-set: what thinning keeps of the f-set
}  // namespace cell

using CellFlags = Grid<std::uint8_t>;

// The first cell from `i` on whose flags have `bit`, or `end`: for bits that few cells have, so
// the cells are read eight at a time.
inline std::size_t next_cell_with(const std::uint8_t* f, std::size_t i, std::size_t end,
                                  std::uint8_t bit) {
  const std::uint64_t in_any_byte = 0x0101010101010101ull * bit;
  for (std::uint64_t word; i + 8 <= end; i += 8) {
    std::memcpy(&word, f + i, sizeof word);
    if (word & in_any_byte) break;
  }
  while (i < end && !(f[i] & bit)) ++i;
  return i;
}

// Writes into `out` the indices, less `base`, of the cells in [from, to) whose flags masked by
// `mask` equal `value`, and returns how many. Each index is written and kept by a running count,
// with no branch on the flags: for sets too dense to skip and too scattered for the processor to
// guess.
template <typename Index>
std::size_t sift_cells(const std::uint8_t* f, std::size_t from, std::size_t to, std::uint8_t mask,
                       std::uint8_t value, std::size_t base, Index* out) {
  std::size_t count = 0;
  for (std::size_t i = from; i < to; ++i) {
    out[count] = static_cast<Index>(i - base);
    count += (f[i] & mask) == value;
  }
  return count;
}

}  // namespace tsk
