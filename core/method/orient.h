// Stage 1 (SPEC 1.1): turn the DEM into the oriented grid g[p][i] seen by the viewer.
// Profiles p run left to right as the viewer sees them, cells i front to back. A cardinal view is
// an exact flip of the DEM (here); any other resamples it (resample.h). The frame (frame.h) maps
// oriented cells to DEM pixels, and dem_windows.h reads DEMs window by window into it.
#pragma once

#include <cstddef>

#include "core/base/grid.h"
#include "core/method/dem_windows.h"
#include "core/method/frame.h"
#include "core/method/resample.h"

namespace tsk {

// Copies DEM rows [first_row, first_row + count) into their places in the oriented grid, so an
// adapter can read a raster block by block without holding the DEM twice. Cardinal frames only.
void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented);

// The whole DEM turned (cardinal) or resampled (any other azimuth: bilinear, nodata where a
// source cell with weight is nodata or outside the DEM).
HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame, unsigned threads = 0);

// The DEM window (rows or columns, by view) that holds oriented profiles [first, first + count)
// of a cardinal frame, for readers that load a DEM strip by strip.
DemWindow profile_window(const OrientedFrame& frame, std::size_t first, std::size_t count);

// Profiles [first, first + count) turned from their window (read as rows x cols, row 0 north)
// into `out`, reusing its memory when it has their shape.
void orient_window(const OrientedFrame& frame, const HeightGrid& window, HeightGrid& out);

}  // namespace tsk
