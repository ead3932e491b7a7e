#include "io/read/page_heights.h"

#include <algorithm>
#include <limits>

#include "core/base/memory_budget.h"
#include "core/method/averaged_dem.h"
#include "core/method/orient.h"

namespace tsk::io {

std::size_t page_averaging(const DemGrid& grid, double azimuth_deg, double most_cells) {
  if (!too_large_to_turn_whole(make_frame(grid, azimuth_deg))) return 1;
  const std::size_t largest = std::max<std::size_t>(1, std::max(grid.rows, grid.cols));
  for (std::size_t factor = 2; factor < largest; ++factor) {
    const OrientedFrame frame = make_frame(averaged_grid(grid, factor), azimuth_deg);
    const double cells = static_cast<double>(frame.profiles) * static_cast<double>(frame.length);
    if (cells <= most_cells && !too_large_to_turn_whole(frame)) return factor;
  }
  return largest;
}

PageHeights read_page_heights(const DemFile& file, double azimuth_deg, std::size_t factor) {
  // The DEM's own range, seen as its windows are read for averaging.
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  DemSource source = file.source();
  source.read = [&lowest, &highest, read = source.read](const DemWindow& w, float* z) {
    read(w, z);
    for (std::size_t k = 0; k < w.rows * w.cols; ++k) {
      if (!is_data(z[k])) continue;
      lowest = std::min(lowest, static_cast<double>(z[k]));
      highest = std::max(highest, static_cast<double>(z[k]));
    }
  };
  const DemSource averaged = averaged_dem(source, factor);
  // Read whole in one window: the averaging reads its source a block row at a time.
  HeightGrid heights(averaged.grid.rows, averaged.grid.cols, Unset{});
  averaged.read({0, 0, averaged.grid.rows, averaged.grid.cols}, heights.data());
  PageHeights page;
  page.frame = make_frame(averaged.grid, azimuth_deg);
  page.oriented = orient(heights, page.frame);
  page.geotransform = averaged.geotransform;
  page.averaged = factor;
  if (lowest <= highest) page.lowest = lowest, page.highest = highest;
  return page;
}

}  // namespace tsk::io
