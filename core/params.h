// Every parameter of the method (SPEC sections 1, 1.5, 1.6, 1.7, 1.8, 1.9) with its default.
#pragma once

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

// Which cells of an f-set zone the thinning keeps (SPEC 1.6).
enum class Placement { far, near_and_far };

struct ChainParams {
  int window = 3;     // formulated chaining: largest |j - i| between neighbouring profiles
  int min_cells = 3;  // generalisation: strokes shorter than this are dropped (g-set)
  void validate() const;
};

enum class Geometry { map, oblique };

struct SilhouetteParams {
  ViewParams view;
  FilterParams filter;
  ChainParams chain;
  Placement placement = Placement::far;
  Geometry geometry = Geometry::map;
  bool subcell = false;  // place occluding points where the transformed profile peaks
  unsigned threads = 0;  // 0: one per hardware thread
  void validate() const;
};

Geometry parse_geometry(const std::string& name);
Placement parse_placement(const std::string& name);

}  // namespace tsk
