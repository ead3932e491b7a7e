#include "core/drawn/drawing_scale.h"

#include <algorithm>
#include <cmath>

#include "core/drawn/drawn_strokes.h"

namespace tsk {
namespace {

// `mm` on paper at 1:scale, in cells of `cell` map units.
double cells_on_paper(double mm, double scale, double cell) {
  return mm / 1000.0 * scale / cell;
}

}  // namespace

double own_scale(const GeoTransform& geotransform) {
  const auto& a = geotransform.a;
  return kOwnScalePerCell * std::min(std::hypot(a[1], a[4]), std::hypot(a[2], a[5]));
}

std::size_t scale_averaging(double scale, const DemGrid& grid, const GeoTransform& geotransform) {
  if (!(scale > 0.0) || !std::isfinite(scale)) return 1;
  const double own = own_scale(geotransform);
  if (!(own > 0.0) || !std::isfinite(own)) return 1;
  const double wanted = std::floor(scale / own);
  const std::size_t most = std::min(grid.rows, grid.cols) / kLeastAveragedSide;
  const double factor = std::min(wanted, static_cast<double>(most));
  return factor >= 2.0 ? static_cast<std::size_t>(factor) : 1;
}

void fit_to_scale(DrawingSetup& setup) {
  DrawnParams& d = setup.drawn;
  const double cell = std::max(setup.cell, 1e-300);
  const double scale = d.scale > 0.0 ? d.scale : kOwnScalePerCell * cell;
  setup.relief_full = scale / kFullReliefPerScale;
  setup.relief_vanishing = 0.0;
  if (!(d.scale > 0.0)) return;
  setup.relief_vanishing = kVanishingShare * setup.relief_full;
  const auto raise = [&](double& cells, double mm, double most) {
    cells = std::max(cells, std::min(most, cells_on_paper(mm, scale, cell)));
  };
  raise(d.join_gap_cells, kJoinGapMm, kMostScaleGapCells);
  raise(d.smooth_cells, kSmoothMm, kMostScaleSmoothCells);
  raise(d.tolerance_cells, kToleranceMm, kMostScaleToleranceCells);
  const double least = std::ceil(cells_on_paper(kLeastStrokeMm, scale, cell));
  setup.min_cells = std::max(setup.min_cells, static_cast<int>(std::min(least, 1e6)));
}

double stroke_relief(const Stroke& stroke) {
  if (stroke.cls == StrokeClass::factual)
    return std::isfinite(stroke.max_depth_m) ? stroke.max_depth_m : 0.0;
  const double relief = std::fabs(stroke.mean_slope_pct) / 100.0 * stroke.length;
  return std::isfinite(relief) ? relief : 0.0;
}

double relief_weight(double relief, double full) {
  if (!(full > 0.0)) return 1.0;
  const double least = kLeastReliefShare * full;
  if (!(relief > least)) return kLeastReliefWeight;
  const double rise = std::min(1.0, std::log(relief / least) / std::log(1.0 / kLeastReliefShare));
  return kLeastReliefWeight + (1.0 - kLeastReliefWeight) * rise;
}

}  // namespace tsk
