// Maps for looking at what the method did (thesis figures 5.4, 5.10 and section 6.2), on the
// DEM's own grid so they overlay it: the per-cell classification and the row slope.
#pragma once

#include <cstdint>

#include "core/base/flags.h"
#include "core/method/orient.h"

namespace tsk {

// One class per cell, the most specific stage it reached.
enum class CellClass : std::uint8_t {
  nodata = 0,
  visible = 1,  // valid, none of the below
  hidden = 2,
  occluding = 3,  // Factual Silhouette cell
  candidate = 4,  // c-set (visible or hidden)
  filtered = 5,   // f-set
  thinned = 6,    // t-set
};
constexpr int kCellClassCount = 7;
const char* cell_class_name(CellClass c);
CellClass cell_class(std::uint8_t flags);

// The classification of every DEM cell: exact for cardinal views; for resampled views each DEM
// cell takes the class of the oriented cell nearest to its centre.
Grid<std::uint8_t> classification_map(const CellFlags& flags, const OrientedFrame& frame);

// |row slope| in percent (slope across the line of sight) on the DEM grid, NaN at nodata.
HeightGrid row_slope_map(const HeightGrid& oriented, const OrientedFrame& frame);

}  // namespace tsk
