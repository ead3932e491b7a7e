#include "core/method/params.h"

#include <cmath>

#include "core/base/errors.h"
#include "core/method/choice_names.h"

namespace tsk {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw Error(message);
}

// Rejects NaN and infinities along with values outside [lo, hi].
void require_range(double value, double lo, double hi, const std::string& what) {
  require(std::isfinite(value) && value >= lo && value <= hi,
          what + " must be between " + number_text(lo) + " and " + number_text(hi) + ", got " +
              number_text(value));
}

}  // namespace

void ViewParams::validate() const {
  require_range(azimuth_deg, -360.0, 360.0, "azimuth (degrees)");
  require(std::isfinite(ve) && ve > 0.0 && ve <= 1000.0,
          "vertical exaggeration must be > 0 and at most 1000, got " + number_text(ve));
  require(std::isfinite(base_slope_pct) && base_slope_pct > 0.0 && base_slope_pct <= 10000.0,
          "base slope must be > 0 % and at most 10000 %, got " + number_text(base_slope_pct));
}

void FilterParams::validate() const {
  require(std::isfinite(row_cut_pct) && row_cut_pct > 0.0 && row_cut_pct <= 10000.0,
          "row slope cut-off must be > 0 % and at most 10000 %");
  require(std::isfinite(col_cut_pct) && col_cut_pct > 0.0 && col_cut_pct <= 10000.0,
          "column slope cut-off must be > 0 % and at most 10000 %");
  require(std::isfinite(ctrl_col_pct) && ctrl_col_pct > 0.0 && ctrl_col_pct < col_cut_pct,
          "control point column slope must be > 0 and below the column cut-off (" +
              number_text(col_cut_pct) + " %), got " + number_text(ctrl_col_pct));
}

void AdaptiveParams::validate() const {
  require(window >= 8 && window <= 100000,
          "the local adaptivity window must be between 8 and 100000 cells, got " +
              std::to_string(window));
}

void ChainParams::validate() const {
  require(window >= 0 && window <= 1000, "chaining window must be between 0 and 1000 cells");
  require(min_cells >= 2 && min_cells <= 1000000,
          "minimum stroke cells must be at least 2 (a one-cell chain is noise)");
}

void DrawnParams::validate() const {
  require_range(smooth_cells, 0.0, 20.0, "smoothing (cells)");
  require_range(tolerance_cells, 0.0, 2.0, "smoothing tolerance (cells)");
  require_range(join_gap_cells, 0.0, 20.0, "join gap (cells)");
  require_range(join_angle_deg, 0.0, 90.0, "join angle (degrees)");
  require_range(taper, 0.0, 0.5, "taper (share of the stroke length at each end)");
  require_range(depth_cue, 0.0, 0.95, "depth cue (weight lost from front to back)");
  require_range(extend_cells, 0.0, 10.0, "over-extension (cells)");
  require(scale == 0.0 || (scale >= 100.0 && scale <= 1e9),
          "the scale drawn for (1:N) must be 0 (none) or from 100 to 1 000 000 000");
}

void SilhouetteParams::validate() const {
  view.validate();
  filter.validate();
  adaptive.validate();
  chain.validate();
  strokes.validate();
  require(std::isfinite(height_tolerance) && height_tolerance >= 0.0,
          "the height tolerance must be a finite number >= 0");
  require(threads <= 1024, "thread count must be at most 1024");
}

Geometry parse_geometry(const std::string& name) {
  return parse_choice(kGeometryNames, name, "geometry");
}

Placement parse_placement(const std::string& name) {
  return parse_choice(kPlacementNames, name, "placement");
}

FilterMode parse_filter_mode(const std::string& name) {
  return parse_choice(kFilterModeNames, name, "filter");
}

Adaptivity parse_adaptivity(const std::string& name) {
  return parse_choice(kAdaptivityNames, name, "adaptivity");
}

StrokeMode parse_stroke_mode(const std::string& name) {
  return parse_choice(kStrokeModeNames, name, "strokes");
}

}  // namespace tsk
