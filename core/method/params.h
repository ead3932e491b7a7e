// Every parameter of the method (SPEC sections 1, 1.5, 1.6, 1.7, 1.8, 1.9) with its default.
#pragma once

#include <memory>
#include <string>

namespace tsk {

struct ViewParams {
  double azimuth_deg = 90.0;     // bearing the viewer faces, clockwise from grid north
  double ve = 2.5;               // vertical exaggeration, > 0
  double base_slope_pct = 40.0;  // base slope B added along the line of sight, percent, > 0

  double base_slope() const { return base_slope_pct / 100.0; }
  void validate() const;
};

struct FilterParams {
  double row_cut_pct = 20.0;   // row slope cut-off (Macgregor's critical 20 %)
  double col_cut_pct = 12.0;   // column slope cut-off
  double ctrl_col_pct = 8.75;  // column component of the control point
  bool diagonals = true;       // false: the removal region is the rectangle of the cut-offs

  // Row component of the control point: on the perpendicular through the origin.
  double ctrl_row_pct() const { return col_cut_pct / row_cut_pct * ctrl_col_pct; }
  void validate() const;
};

// The filter's cut-offs: `fixed` takes FilterParams as they are (SPEC 1.5, the thesis's filter);
// `adaptive` scales them to the DEM's own slopes and tests slopes with a tolerance of its height
// quantum (docs/ADAPTIVE_FILTER.md). adapt_filter() turns an adaptive choice into fixed cut-offs
// for one run; the stages only ever see fixed ones.
enum class FilterMode { fixed, adaptive };
// Whether the scale is the whole DEM's or each neighbourhood's of `window` cells.
enum class Adaptivity { whole, local };

struct AdaptiveParams {
  FilterMode mode = FilterMode::fixed;  // the core keeps SPEC's filter; the front ends default to
                                        // adaptive
  Adaptivity adapt = Adaptivity::whole;
  int window = 100;  // local adaptivity: side of the neighbourhood, DEM cells
  void validate() const;
};

// Which cells of an f-set zone the thinning keeps (SPEC 1.6).
enum class Placement { far, near_and_far };

struct ChainParams {
  int window = 3;     // formulated chaining: largest |j - i| between neighbouring profiles
  int min_cells = 3;  // generalisation: strokes shorter than this are dropped (g-set)
  void validate() const;
};

enum class Geometry { map, oblique };

// How the chains become strokes: `exact` is SPEC 1.7-1.9 to the bit (one point per cell, chains
// shorter than min_cells dropped); `drawn` places points at sub-cell positions, joins strokes that
// visually continue each other before the min_cells generalisation, smooths them within a
// tolerance of the exact chain and gives each vertex a weight for taper and depth
// (docs/DRAWN_STROKES.md).
enum class StrokeMode { exact, drawn };

struct DrawnParams {
  StrokeMode mode = StrokeMode::exact;  // the core keeps SPEC's strokes; the front ends draw
  double smooth_cells = 1.5;            // Gaussian sigma along the stroke, cells (0: none)
  double tolerance_cells = 1.0;         // farthest a drawn point lies from its cell's centre
  double join_gap_cells = 2.5;          // farthest apart two stroke ends that join may be
  double join_angle_deg = 35.0;         // largest turn between the joined ends' directions
  double taper = 0.25;                  // share of a stroke's length tapered at each end
  double depth_cue = 0.5;               // weight lost from the front of the view to its back
  double extend_cells = 0.0;            // over-extension of each end along its tangent
  // Drawn for a map at 1:scale: the smallest stroke, the smoothing, its tolerance and the join
  // gap are at least what that scale needs on paper, and strokes outlining too little relief for
  // it vanish. 0: no scale; the relief weights follow the DEM's own scale (drawing_scale.h).
  double scale = 0.0;
  bool drawn() const { return mode == StrokeMode::drawn; }
  void validate() const;
};

class SlopeScaleMap;

struct SilhouetteParams {
  ViewParams view;
  FilterParams filter;
  AdaptiveParams adaptive;
  // Set by adapt_filter for one run. height_tolerance: slopes whose height step is within it count
  // as flat in the c-set's tests (0: SPEC's strict tests). local_scale: each cell's slopes are
  // divided by its neighbourhood's scale before the filter (null: no local adaptivity).
  double height_tolerance = 0.0;
  std::shared_ptr<const SlopeScaleMap> local_scale;
  ChainParams chain;
  DrawnParams strokes;
  Placement placement = Placement::far;
  Geometry geometry = Geometry::map;
  bool subcell = false;  // place occluding points where the transformed profile peaks
  unsigned threads = 0;  // 0: one per hardware thread
  void validate() const;
};

Geometry parse_geometry(const std::string& name);
Placement parse_placement(const std::string& name);
FilterMode parse_filter_mode(const std::string& name);
Adaptivity parse_adaptivity(const std::string& name);
StrokeMode parse_stroke_mode(const std::string& name);

}  // namespace tsk
