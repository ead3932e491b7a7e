// Per-cell classification bits of the oriented grid, one byte per cell, filled stage by stage.
#pragma once

#include <cstdint>

#include "grid.h"

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

}  // namespace tsk
