#include "core/applications/drape.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "core/base/errors.h"

namespace tsk {
namespace {

[[noreturn]] void refuse_extent(const OrientedFrame& frame, const std::string& size) {
  throw Error("the plan-oblique drape would be " + size + ", far larger than the DEM's " +
              std::to_string(frame.dem_cols) + " x " + std::to_string(frame.dem_rows) +
              " cells: check the DEM's heights, or lower the vertical exaggeration or raise the "
              "base slope");
}

// The plan-oblique positions of each profile's visible cells, sorted (visible cells have
// non-decreasing transformed height, so their positions i + k (z - z_ref) are), and the cells'
// oriented indices.
struct VisiblePlaces {
  explicit VisiblePlaces(std::size_t profiles) : position(profiles), cell(profiles) {}
  std::vector<std::vector<double>> position;
  std::vector<std::vector<std::uint32_t>> cell;
};

// The pixel columns and rows the visible cells reach.
struct PixelExtent {
  double col_min = 1e300, col_max = -1e300, row_min = 1e300, row_max = -1e300;
  void take_in(const PixelExtent& other) {
    col_min = std::min(col_min, other.col_min), col_max = std::max(col_max, other.col_max);
    row_min = std::min(row_min, other.row_min), row_max = std::max(row_max, other.row_max);
  }
};

void place_profile(const HeightGrid& oriented, const CellFlags& flags, const OrientedFrame& frame,
                   const PlanObliqueShift& shift, std::size_t p, VisiblePlaces& places,
                   PixelExtent& extent) {
  // Held for every visible cell until the layout is done: no room to spare.
  const std::uint8_t* row = flags.row(p);
  const auto visible =
      static_cast<std::size_t>(std::count_if(row, row + frame.length, [](std::uint8_t f) {
        return (f & cell::valid) && !(f & cell::hidden);
      }));
  std::vector<double>& position = places.position[p];
  std::vector<std::uint32_t>& cell = places.cell[p];
  position.reserve(visible);
  cell.reserve(visible);
  for (std::size_t i = 0; i < frame.length; ++i) {
    const std::uint8_t f = row[i];
    if (!(f & cell::valid) || (f & cell::hidden)) continue;
    const double s = shift(static_cast<double>(i), static_cast<double>(oriented(p, i)));
    position.push_back(s);
    cell.push_back(static_cast<std::uint32_t>(p * frame.length + i));
    const PixelPoint px = frame.to_pixel(static_cast<double>(p), s);
    // A place beyond any number (heights of 1e30 shifted) is refused as an unbounded extent.
    if (!std::isfinite(px.col) || !std::isfinite(px.row)) refuse_extent(frame, "unbounded");
    extent.take_in({px.col, px.col, px.row, px.row});
  }
}

PixelExtent place_visible_cells(const HeightGrid& oriented, const CellFlags& flags,
                                const OrientedFrame& frame, const PlanObliqueShift& shift,
                                VisiblePlaces& places, const ProgressFn& progress,
                                unsigned threads) {
  PixelExtent whole;
  std::mutex whole_mutex;
  parallel_for(
      frame.profiles, threads,
      [&](std::size_t begin, std::size_t end) {
        PixelExtent part;
        for (std::size_t p = begin; p < end; ++p)
          place_profile(oriented, flags, frame, shift, p, places, part);
        const std::lock_guard<std::mutex> lock(whole_mutex);
        whole.take_in(part);
      },
      progress);
  return whole;
}

// The output lattice's row starting at pixel (col0, row), `cols` cells: each cell takes the
// nearest visible cell of its profile, into `sources`.
void fill_row_sources(const OrientedFrame& frame, std::int64_t col0, std::int64_t row,
                      std::size_t cols, const VisiblePlaces& places, std::uint32_t* sources) {
  for (std::size_t col = 0; col < cols; ++col) {
    double pf = 0, s = 0;
    frame.from_pixel({static_cast<double>(col0 + static_cast<std::int64_t>(col)) + 0.5,
                      static_cast<double>(row) + 0.5},
                     pf, s);
    pf = std::round(pf);
    if (pf < 0 || pf >= static_cast<double>(frame.profiles)) continue;
    const auto& pos = places.position[static_cast<std::size_t>(pf)];
    if (pos.empty() || s < pos.front() - 0.5 || s > pos.back() + 0.5) continue;
    const auto above = std::upper_bound(pos.begin(), pos.end(), s);
    std::size_t best = static_cast<std::size_t>(above - pos.begin());
    if (best == pos.size() || (best > 0 && s - pos[best - 1] <= pos[best] - s)) --best;
    sources[col] = places.cell[static_cast<std::size_t>(pf)][best];
  }
}

}  // namespace

PlanObliqueDrape::PlanObliqueDrape(const HeightGrid& oriented, const CellFlags& flags,
                                   const OrientedFrame& frame, const ViewParams& view, double z_ref,
                                   const ProgressFn& progress, unsigned threads)
    : frame_(frame) {
  if (static_cast<double>(frame.profiles) * static_cast<double>(frame.length) >= kNone) {
    throw Error("the DEM is too large to drape: more than 4 294 967 294 cells in view");
  }
  tell_progress(progress, 0.0);
  VisiblePlaces places(frame.profiles);
  const PixelExtent extent =
      place_visible_cells(oriented, flags, frame_, PlanObliqueShift(view, frame.d, z_ref), places,
                          progress_part(progress, 0.0, 0.5), threads);
  if (!lay_out_extent(extent.col_min, extent.col_max, extent.row_min, extent.row_max)) return;
  source_cell_.assign(checked_cell_count(rows_, cols_), kNone);
  parallel_for(
      rows_, threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t r = begin; r < end; ++r) {
          fill_row_sources(frame_, col0_, row0_ + static_cast<std::int64_t>(r), cols_, places,
                           source_cell_.data() + r * cols_);
        }
      },
      progress_part(progress, 0.5, 1.0));
}

bool PlanObliqueDrape::lay_out_extent(double col_min, double col_max, double row_min,
                                      double row_max) {
  if (col_min > col_max) {
    // Nothing visible: an empty drape, one cell without data at the DEM's corner (a raster of no
    // cells is no raster).
    rows_ = cols_ = 1;
    source_cell_.assign(1, kNone);
    return false;
  }
  constexpr double kSlack = 1e-6;  // positions a hair past a cell edge stay in that cell
  const double col0 = std::floor(col_min - 0.5 + kSlack), row0 = std::floor(row_min - 0.5 + kSlack);
  const double cols = std::ceil(col_max + 0.5 - kSlack) - col0;
  const double rows = std::ceil(row_max + 0.5 - kSlack) - row0;
  // Checked before any cast: heights of 1e30 put a cell 1e30 cells away.
  const double dem_cells =
      static_cast<double>(frame_.dem_rows) * static_cast<double>(frame_.dem_cols);
  if (!(cols >= 1 && rows >= 1 && rows * cols <= 16.0 * dem_cells + 1e6)) {
    const bool bounded = std::isfinite(rows * cols) && rows * cols >= 1;
    refuse_extent(frame_, bounded ? number_text(cols) + " x " + number_text(rows) + " cells"
                                  : std::string("unbounded"));
  }
  col0_ = static_cast<std::int64_t>(col0), row0_ = static_cast<std::int64_t>(row0);
  cols_ = static_cast<std::size_t>(cols), rows_ = static_cast<std::size_t>(rows);
  return true;
}

GeoTransform PlanObliqueDrape::geotransform(const GeoTransform& dem) const {
  GeoTransform out = dem;
  dem.apply({static_cast<double>(col0_), static_cast<double>(row0_)}, out.a[0], out.a[3]);
  return out;
}

void PlanObliqueDrape::check_on_dem_grid(const HeightGrid& source_on_dem) const {
  if (source_on_dem.rows() != frame_.dem_rows || source_on_dem.cols() != frame_.dem_cols) {
    throw Error("the raster to drape must be on the DEM's grid (" +
                std::to_string(frame_.dem_cols) + " x " + std::to_string(frame_.dem_rows) +
                " cells); resample it first");
  }
}

HeightGrid PlanObliqueDrape::from_oriented(const HeightGrid& oriented) const {
  HeightGrid out(rows_, cols_, kNoData);
  for (std::size_t k = 0; k < source_cell_.size(); ++k) {
    if (source_cell_[k] != kNone) out.data()[k] = oriented.data()[source_cell_[k]];
  }
  return out;
}

HeightGrid PlanObliqueDrape::drape(const HeightGrid& source_on_dem) const {
  check_on_dem_grid(source_on_dem);
  return from_oriented(orient(source_on_dem, frame_));
}

HeightGrid PlanObliqueDrape::drape(HeightGrid&& source_on_dem) const {
  check_on_dem_grid(source_on_dem);
  const HeightGrid oriented = orient(source_on_dem, frame_);
  source_on_dem = HeightGrid();
  return from_oriented(oriented);
}

}  // namespace tsk
