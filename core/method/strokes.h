// Stage 7 (SPEC 1.8, 1.9): chains to strokes with attributes, in map or plan-oblique geometry.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/geotransform.h"
#include "core/base/prefetch.h"
#include "core/method/candidates.h"
#include "core/method/chaining.h"
#include "core/method/orient.h"
#include "core/method/params.h"

namespace tsk {

enum class StrokeClass : std::uint8_t { factual, formulated };
const char* stroke_class_name(StrokeClass cls);
// 0 for factual strokes, 1 for formulated ones: where a class's own state sits in a pair.
inline std::size_t class_index(StrokeClass cls) {
  return cls == StrokeClass::factual ? 0 : 1;
}

struct StrokePoint {
  double x;
  double y;
};

inline double distance(StrokePoint a, StrokePoint b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return std::sqrt(dx * dx + dy * dy);
}

// What drawing a stroke needs of each of its points beyond its place (see drawn_strokes.h).
struct StrokeVertex {
  double dist;          // distance from the front of the view, ground units
  double z;             // height, metres
  double offset = 0.0;  // of the point from its cell's centre along the profile, cells
};

struct Stroke {
  StrokeClass cls = StrokeClass::factual;
  std::vector<StrokePoint> points;  // in the chosen geometry, in the DEM's CRS
  Chain chain;                      // the oriented cells the points stand for (exact strokes)
  // Drawn strokes: each point's weight in (0, 1], its taper times its depth cue, written as M.
  // Empty for exact strokes.
  std::vector<double> weights;
  // Drawn strokes while they are drawn: one per point, points in map geometry. Emptied once the
  // stroke is drawn.
  std::vector<StrokeVertex> vertices;
  int cells = 0;
  double length = 0.0;          // ground length in map units (map geometry)
  double mean_slope_pct = 0.0;  // mean |column slope|, percent
  double mean_row_slope_pct = 0.0;
  double mean_depth_m = 0.0;  // factual: mean hidden-zone depth in metres; formulated: NaN
  double max_depth_m = 0.0;   // factual: deepest hidden zone; formulated: NaN
  double mean_dist = 0.0;     // mean distance from the front of the view, ground units
  double mean_z = 0.0;        // mean height, metres
};

// The real-valued attributes of a stroke, in output order, for adapters that write fields
// (class and cells come first and are not listed). NaN values are written as null.
struct StrokeRealField {
  const char* name;
  double Stroke::*member;
};
const std::vector<StrokeRealField>& stroke_real_fields();

// Hands the attributes of `stroke` to `row` by field position in output order: class (text),
// cells, then stroke_real_fields(). `row` has set(int, const char*), set(int, std::int64_t) and
// set(int, double).
template <typename Row>
void set_stroke_attributes(Row& row, const Stroke& stroke) {
  row.set(0, stroke_class_name(stroke.cls));
  row.set(1, std::int64_t{stroke.cells});
  int field = 2;
  for (const StrokeRealField& f : stroke_real_fields()) row.set(field++, stroke.*(f.member));
}

// What placing stroke cells needs to know about the grid and the view. The grid may hold only a
// strip of profiles: its row 0 is profile `first_profile`.
struct StrokeContext {
  const HeightGrid& z;
  const CellFlags& flags;
  const OrientedFrame& frame;
  const ViewParams& view;
  const GeoTransform& geotransform;
  Geometry geometry = Geometry::map;
  bool subcell = false;
  bool drawn = false;  // points at sub-cell places, in map geometry, for drawn strokes
  // The c-set's bounds with its height tolerance (SilhouetteParams::height_tolerance), for sub-cell
  // breaks: worked out once, not for every cell.
  CandidateBounds bounds;
  double z_ref = 0.0;  // height that stays in place in plan-oblique geometry (the DEM minimum)
  std::size_t first_profile = 0;
};

// One cell of a stroke with what the stroke's geometry and attributes need from it.
struct StrokeCell {
  ChainCell cell;
  StrokePoint map;      // cell centre (or sub-cell peak) in map geometry
  StrokePoint point;    // in the chosen geometry
  double dist = 0.0;    // distance from the front of the view, ground units
  double offset = 0.0;  // of the point from the cell's centre along the profile, cells
  double slope_pct = 0.0, row_slope_pct = 0.0, depth_m = 0.0, z = 0.0;
};

// Position of an occluding cell along its profile, refined to the peak of the parabola through
// the transformed heights of it and its neighbours (within half a cell).
double subcell_peak(const float* z, std::size_t length, std::size_t i, double d,
                    const ViewParams& view);

// Position of a thinned (t-set) cell along its profile, refined to where the exaggerated column
// slope, interpolated linearly between cell centres, leaves the c-set's bounds at the end of its
// f-set zone (within half a cell, towards the zone's edge). `flags` is the profile's; `bounds`
// are the c-set's for the view's exaggeration `ve`.
double subcell_break(const float* z, const std::uint8_t* flags, std::size_t length, std::size_t i,
                     double d, double ve, const CandidateBounds& bounds);

// The record of cell i of profile p (a global profile index; the grid row is p - first_profile).
StrokeCell stroke_cell(const StrokeContext& ctx, std::size_t p, std::size_t i, bool factual);

// A stroke built cell by cell as its chain grows (consecutive profiles): its geometry and the
// running sums of its attributes, so that the records of its cells need not be kept.
class alignas(64) StrokeBuilder {
 public:
  // drawn: keep what drawing needs of the cell instead, the attributes left to drawn_pieces.
  void add(const StrokeCell& c, bool drawn = false);
  // Asks the processor for the place the next add() writes to (the builder's first cache line
  // in the cache already).
  void prefetch(bool drawn) const {
    if (drawn) __builtin_prefetch(drawn_.data() + drawn_.size(), 1);
  }
  // Asks the processor for the first cells added drawn, which drawn_pieces reads (the builder's
  // first cache line in the cache already).
  void prefetch_cells(bool drawn) const {
    if (!drawn || drawn_.empty()) return;
    prefetch_bytes(drawn_.data(), std::min<std::size_t>(drawn_.size() * sizeof(DrawnCell), 256));
  }
  int cells() const { return static_cast<int>(chain_.size() + drawn_.size()); }
  // The profile of the first cell (the builder must hold one).
  std::int32_t first_profile() const { return first_cell().p; }
  // The first cell (the builder must hold one): where the chain started.
  ChainCell first_cell() const { return drawn_.empty() ? chain_.front() : drawn_.front().cell; }
  // The stroke so far with its attributes, its vectors sized to fit (cells added not drawn).
  Stroke stroke(StrokeClass cls) const;
  // The stroke so far, its vectors moved out of the builder, which is left empty.
  Stroke take(StrokeClass cls);
  // Drawn strokes (cells added drawn): appends to `pieces` the stroke so far cut where it leaps, a
  // step between neighbouring points longer than `max_step` map units; each piece with its
  // vertices, its length and its attributes worked out from its own cells.
  void drawn_pieces(StrokeClass cls, double max_step, std::vector<Stroke>& pieces) const;
  // Empties the builder for the next chain, keeping its storage.
  void clear();

 private:
  // Mean of the finite values added, NaN when there were none.
  struct Mean {
    double sum = 0.0;
    int count = 0;
    void add(double v) {
      if (std::isfinite(v)) sum += v, ++count;
    }
    double value() const;
  };
  // What the attributes of cells are worked out from.
  struct Sums {
    Mean slope, row_slope, depth, dist, z;
    double max_depth = 0.0;
    void add(double slope_pct, double row_slope_pct, double depth_m, double from_front,
             double height);
  };
  // A cell added drawn, whole in one record: a chain's cells are added one profile at a time,
  // each to another of the open chains, and one record is one place in memory to miss.
  struct DrawnCell {
    ChainCell cell;
    StrokePoint point;
    StrokeVertex vertex;
    double slope_pct, row_slope_pct, depth_m;
  };
  // A stroke's attributes, without its vectors.
  static Stroke attributes(StrokeClass cls, int cells, double length, const Sums& sums);
  // The drawn piece of cells [from, to).
  Stroke drawn_piece(StrokeClass cls, std::size_t from, std::size_t to, double length) const;
  // Cells added drawn; first, in the builder's first cache line, which the linking fetches.
  std::vector<DrawnCell> drawn_;
  Chain chain_;                      // cells added not drawn
  std::vector<StrokePoint> points_;  // of the cells added not drawn
  StrokePoint last_map_{};
  double length_ = 0.0;
  Sums sums_;
};

}  // namespace tsk
