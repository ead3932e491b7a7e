// The heights a preview's page is laid out over when the DEM turned to the view is too large to
// hold (too_large_to_turn_whole): the DEM averaged block by block until it can be held, and no
// larger than a page can show, read window by window and turned to the view. The run itself
// still reads the DEM strip by strip at its own cells.
#pragma once

#include <cstddef>

#include "core/base/geotransform.h"
#include "core/base/grid.h"
#include "core/base/parallel.h"
#include "core/method/frame.h"
#include "io/read/dem_reader.h"

namespace tsk::io {

// The most cells a page's averaged heights take: 4096 x 4096, 64 MB, finer than 0.3 mm a cell on
// an A0 page.
constexpr double kPageCells = 16.0 * 1024 * 1024;

// The cells a side a DEM of `grid` seen from `azimuth_deg` is averaged by for its page: 1 when
// it can be turned whole, else the least factor whose averaged DEM can, within `most_cells`.
std::size_t page_averaging(const DemGrid& grid, double azimuth_deg, double most_cells = kPageCells);

struct PageHeights {
  HeightGrid oriented;        // the averaged DEM turned to the view
  OrientedFrame frame;        // its frame
  GeoTransform geotransform;  // the averaged DEM's
  std::size_t averaged = 1;   // the cells a side of the DEM averaged into one
  // The DEM's own lowest and highest heights (0 when it has none), which averaging narrows.
  double lowest = 0.0, highest = 0.0;
};

// The DEM of `file` averaged `factor` cells a side (read_averaged: on two threads when the file
// has a reader alongside) and turned to the view facing `azimuth_deg`, telling `progress` as it
// reads. Throws Error as the file's reads do, Cancelled when `progress` says stop.
PageHeights read_page_heights(const DemFile& file, double azimuth_deg, std::size_t factor,
                              const ProgressFn& progress = {});

}  // namespace tsk::io
