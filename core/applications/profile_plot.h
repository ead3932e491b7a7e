// Application (SPEC 3, thesis figure 4.6): the profile plot, cross-sections orthogonal to the line
// of sight drawn in plan-oblique geometry with their hidden parts removed - the ridgeline sketch.
#pragma once

#include <cstddef>
#include <vector>

#include "core/base/flags.h"
#include "core/method/params.h"
#include "core/method/strokes.h"

namespace tsk {

struct ProfileLine {
  std::size_t cross_section = 0;  // oriented cell index i: distance from the front in cells
  double distance = 0.0;          // ground distance from the front of the view
  std::vector<StrokePoint> points;
};

// Every `every_n`-th cross-section (i = 0, n, 2n, ...), split wherever a cell is hidden or
// nodata; pieces of fewer than two points are dropped. Needs the visibility flags.
std::vector<ProfileLine> profile_plot(const HeightGrid& oriented, const CellFlags& flags,
                                      const OrientedFrame& frame, const ViewParams& view,
                                      const GeoTransform& geotransform, std::size_t every_n,
                                      double z_ref);

}  // namespace tsk
