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

namespace {

// The lowest and highest heights with data that a reader has read.
struct HeightsSeen {
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
};

// `read`, noting in `seen` the range of what it reads; empty when `read` is.
WindowReader noting_range(WindowReader read, HeightsSeen& seen) {
  if (!read) return read;
  return [&seen, read = std::move(read)](const DemWindow& w, float* z) {
    read(w, z);
    for (std::size_t k = 0; k < w.rows * w.cols; ++k) {
      if (!is_data(z[k])) continue;
      seen.lowest = std::min(seen.lowest, static_cast<double>(z[k]));
      seen.highest = std::max(seen.highest, static_cast<double>(z[k]));
    }
  };
}

}  // namespace

PageHeights read_page_heights(const DemFile& file, double azimuth_deg, std::size_t factor,
                              const ProgressFn& progress) {
  // The DEM's own range, seen by each of its readers (on threads of their own) as they read.
  HeightsSeen first, second;
  DemSource source = file.source();
  source.read = noting_range(std::move(source.read), first);
  source.read_alongside = noting_range(std::move(source.read_alongside), second);
  const HeightGrid heights = read_averaged(source, factor, progress);
  PageHeights page;
  page.frame = make_frame(averaged_grid(source.grid, factor), azimuth_deg);
  page.oriented = orient(heights, page.frame);
  page.geotransform = averaged_geotransform(source.geotransform, factor);
  page.averaged = factor;
  const double lowest = std::min(first.lowest, second.lowest);
  const double highest = std::max(first.highest, second.highest);
  if (lowest <= highest) page.lowest = lowest, page.highest = highest;
  return page;
}

}  // namespace tsk::io
