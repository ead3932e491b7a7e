// Application (SPEC 3, thesis section 8.2): drape any raster on the DEM's grid (a slope map, a
// hillshade, an image band) into plan-oblique space with hidden areas removed, so that the
// plan-oblique silhouettes overlay it exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/orient.h"
#include "core/method/params.h"
#include "core/method/plan_oblique.h"
#include "core/method/strokes.h"

namespace tsk {

class PlanObliqueDrape {
 public:
  // Needs the visibility flags of `oriented`; z_ref is the height that stays in place. Both
  // passes, over the profiles and then the output rows, run on `threads` threads (0: the hardware
  // threads). `progress` hears of the work done (0 to 1) from the caller's thread after each chunk
  // of either; Cancelled is thrown when it returns false.
  PlanObliqueDrape(const HeightGrid& oriented, const CellFlags& flags, const OrientedFrame& frame,
                   const ViewParams& view, double z_ref, const ProgressFn& progress = {},
                   unsigned threads = 0);

  // The output lattice: north-up, the DEM's cell size, covering every visible cell's
  // plan-oblique position; output cell (r, c) is DEM pixel cell (row0 + r, col0 + c). With no
  // visible cell, one cell without data at the DEM's corner.
  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  GeoTransform geotransform(const GeoTransform& dem) const;

  // One band of values on the DEM's grid, draped: each output cell takes the value of the
  // visible cell of its profile nearest in plan-oblique position (the nearer one on a tie);
  // NaN where no visible terrain lands.
  HeightGrid drape(const HeightGrid& source_on_dem) const;
  // The same, letting go of the band's memory once it is turned to the view.
  HeightGrid drape(HeightGrid&& source_on_dem) const;

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;  // an output cell no visible cell reaches

  // Sets the lattice covering pixel columns col_min..col_max and rows row_min..row_max; returns
  // false, the lattice one empty cell, when col_min > col_max (nothing visible). Throws Error when
  // it would be far larger than the DEM.
  bool lay_out_extent(double col_min, double col_max, double row_min, double row_max);
  void check_on_dem_grid(const HeightGrid& source_on_dem) const;
  HeightGrid from_oriented(const HeightGrid& oriented) const;

  OrientedFrame frame_;  // a copy: the DEM may go once the drape is laid out
  std::int64_t row0_ = 0, col0_ = 0;
  std::size_t rows_ = 0, cols_ = 0;
  // Per output cell: the oriented cell index (4 bytes: a DEM turned whole has fewer cells), kNone
  // for none.
  std::vector<std::uint32_t> source_cell_;
};

}  // namespace tsk
