#include "core/method/frame.h"

#include <cmath>
#include <string>

#include "core/base/errors.h"
#include "core/base/grid.h"

namespace tsk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// No terrain has cells finer than a picometre or coarser than a billion kilometres. Beyond, the
// products and squares of cell sizes leave the doubles' range: with cells of 1e-300 a panorama's
// observer at the DEM's centre was "outside the DEM".
constexpr double kLeastCell = 1e-12, kMostCell = 1e12;

void check_dem(std::size_t rows, std::size_t cols, double dx, double dy) {
  if (rows == 0 || cols == 0) throw Error("the DEM has no cells");
  checked_cell_count(rows, cols);
  const std::string cells = number_text(dx) + " x " + number_text(dy);
  if (!std::isfinite(dx) || !std::isfinite(dy) || dx <= 0.0 || dy <= 0.0)
    throw Error("cell sizes must be finite and positive, got " + cells);
  if (dx < kLeastCell || dy < kLeastCell || dx > kMostCell || dy > kMostCell) {
    throw Error("cells of " + cells + " are beyond any terrain's (from " + number_text(kLeastCell) +
                " to " + number_text(kMostCell) +
                " map units): the georeferencing or the cell size given is wrong");
  }
}

double normalise_azimuth(double azimuth_deg) {
  if (!std::isfinite(azimuth_deg)) throw Error("the azimuth must be a finite number of degrees");
  double a = std::fmod(azimuth_deg, 360.0);
  if (a < 0) a += 360.0;
  return a >= 360.0 ? 0.0 : a;
}

// Sets the affine pixel map from the integer one.
void set_affine_from_integer_map(OrientedFrame& f) {
  f.px_col0 = static_cast<double>(f.col0) + 0.5;
  f.px_row0 = static_cast<double>(f.row0) + 0.5;
  f.px_col_per_p = static_cast<double>(f.col_per_p);
  f.px_col_per_i = static_cast<double>(f.col_per_i);
  f.px_row_per_p = static_cast<double>(f.row_per_p);
  f.px_row_per_i = static_cast<double>(f.row_per_i);
}

OrientedFrame cardinal_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                             int azimuth) {
  const auto last_row = static_cast<std::int64_t>(rows) - 1;
  const auto last_col = static_cast<std::int64_t>(cols) - 1;
  OrientedFrame f;
  f.azimuth_deg = azimuth;
  f.dem_rows = rows, f.dem_cols = cols;
  f.dem_dx = dx, f.dem_dy = dy;
  switch (azimuth) {
    case 90:  // viewed from the west: profile = row (north first), cell = column (west first)
      f.profiles = rows, f.length = cols, f.d = dx, f.w = dy;
      f.row_per_p = 1, f.col_per_i = 1;
      break;
    case 270:  // viewed from the east: profile = row (south first), cell = column (east first)
      f.profiles = rows, f.length = cols, f.d = dx, f.w = dy;
      f.row0 = last_row, f.row_per_p = -1, f.col0 = last_col, f.col_per_i = -1;
      break;
    case 0:  // viewed from the south: profile = column (west first), cell = row (south first)
      f.profiles = cols, f.length = rows, f.d = dy, f.w = dx;
      f.row0 = last_row, f.row_per_i = -1, f.col_per_p = 1;
      break;
    default:  // 180, viewed from the north: profile = column (east first), cell = row (north first)
      f.profiles = cols, f.length = rows, f.d = dy, f.w = dx;
      f.row_per_i = 1, f.col0 = last_col, f.col_per_p = -1;
      break;
  }
  set_affine_from_integer_map(f);
  return f;
}

}  // namespace

OrientedFrame make_resampled_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                                   double azimuth_deg) {
  check_dem(rows, cols, dx, dy);
  const double azimuth = normalise_azimuth(azimuth_deg);
  const double theta = azimuth * kPi / 180.0;
  // Ground unit vectors (east, north): forward along the line of sight, right across it.
  const double f_e = std::sin(theta), f_n = std::cos(theta);
  const double r_e = std::cos(theta), r_n = -std::sin(theta);
  // The DEM's corners relative to its north-west corner, projected on both axes.
  const double width = static_cast<double>(cols) * dx, height = static_cast<double>(rows) * dy;
  const double corners[4][2] = {{0, 0}, {width, 0}, {0, -height}, {width, -height}};
  double f_min = 1e300, f_max = -1e300, r_min = 1e300, r_max = -1e300;
  for (const auto& c : corners) {
    const double along = c[0] * f_e + c[1] * f_n;
    const double across = c[0] * r_e + c[1] * r_n;
    f_min = std::min(f_min, along), f_max = std::max(f_max, along);
    r_min = std::min(r_min, across), r_max = std::max(r_max, across);
  }
  const double spacing = std::min(dx, dy);
  const double profiles = std::max(1.0, std::ceil((r_max - r_min) / spacing - 1e-9));
  const double length = std::max(1.0, std::ceil((f_max - f_min) / spacing - 1e-9));
  // A square-celled DEM turned by 45 degrees needs twice its cells; very elongated DEMs or very
  // unequal cell sizes (spacing is the smaller one) need far more: refuse rather than exhaust
  // memory.
  const double dem_cells = static_cast<double>(rows) * static_cast<double>(cols);
  const double limit = std::max(8.0 * dem_cells, static_cast<double>(1 << 20));
  if (profiles * length > limit || profiles > static_cast<double>(kMaxGridSide) ||
      length > static_cast<double>(kMaxGridSide)) {
    throw Error("seen at azimuth " + number_text(azimuth) + " this DEM would need " +
                number_text(profiles * length) + " resampled cells, more than " +
                number_text(limit) +
                " (it is very elongated or its cells are far from square); "
                "resample it to near-square cells (gdalwarp -tr), crop it, or use a cardinal "
                "azimuth (0, 90, 180, 270)");
  }
  OrientedFrame f;
  f.azimuth_deg = azimuth;
  f.resampled = true;
  f.dem_rows = rows, f.dem_cols = cols;
  f.dem_dx = dx, f.dem_dy = dy;
  f.profiles = static_cast<std::size_t>(profiles);
  f.length = static_cast<std::size_t>(length);
  checked_cell_count(f.profiles, f.length);
  f.d = f.w = spacing;
  // Centre of oriented cell (p, i): (r_min + (p + 0.5) s) right + (f_min + (i + 0.5) s) forward.
  const double across0 = r_min + 0.5 * spacing, along0 = f_min + 0.5 * spacing;
  f.px_col0 = (across0 * r_e + along0 * f_e) / dx;
  f.px_row0 = -(across0 * r_n + along0 * f_n) / dy;
  f.px_col_per_p = spacing * r_e / dx;
  f.px_row_per_p = -spacing * r_n / dy;
  f.px_col_per_i = spacing * f_e / dx;
  f.px_row_per_i = -spacing * f_n / dy;
  return f;
}

bool is_cardinal(double azimuth_deg) {
  const double azimuth = normalise_azimuth(azimuth_deg);
  return std::fabs(azimuth - 90.0 * std::round(azimuth / 90.0)) <= 1e-9;
}

OrientedFrame make_frame(const DemGrid& grid, double azimuth_deg) {
  return make_frame(grid.rows, grid.cols, grid.dx, grid.dy, azimuth_deg);
}

OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg) {
  check_dem(rows, cols, dx, dy);
  if (!is_cardinal(azimuth_deg)) return make_resampled_frame(rows, cols, dx, dy, azimuth_deg);
  const double azimuth = normalise_azimuth(azimuth_deg);
  return cardinal_frame(rows, cols, dx, dy, static_cast<int>(std::round(azimuth / 90.0)) % 4 * 90);
}

}  // namespace tsk
