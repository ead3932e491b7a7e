#include "orient.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "parallel.h"
#include "vector_clones.h"

#if TSK_HAS_AVX2_CODE
#include <immintrin.h>
#endif

namespace tsk {
namespace {

constexpr double kPi = 3.14159265358979323846;

void check_dem(std::size_t rows, std::size_t cols, double dx, double dy) {
  if (rows == 0 || cols == 0) throw Error("the DEM has no cells");
  checked_cell_count(rows, cols);
  if (!std::isfinite(dx) || !std::isfinite(dy) || dx <= 0.0 || dy <= 0.0) {
    throw Error("cell sizes must be finite and positive, got " + number_text(dx) + " x " +
                number_text(dy));
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

OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg) {
  check_dem(rows, cols, dx, dy);
  if (!is_cardinal(azimuth_deg)) return make_resampled_frame(rows, cols, dx, dy, azimuth_deg);
  const double azimuth = normalise_azimuth(azimuth_deg);
  return cardinal_frame(rows, cols, dx, dy, static_cast<int>(std::round(azimuth / 90.0)) % 4 * 90);
}

void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented) {
  if (frame.resampled) throw Error("a resampled view needs the whole DEM (use orient)");
  const bool profiles_are_rows = frame.row_per_p != 0;
  if (cols != frame.dem_cols || first_row + count > frame.dem_rows ||
      oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("DEM block does not match the oriented frame");
  }
  if (profiles_are_rows) {
    for (std::size_t k = 0; k < count; ++k) {
      // The row is one profile, possibly reversed.
      const float* src = rows + k * cols;
      const auto p = static_cast<std::size_t>(
          (static_cast<std::int64_t>(first_row + k) - frame.row0) * frame.row_per_p);
      float* dst = oriented.row(p);
      if (frame.col_per_i > 0) {
        std::copy(src, src + cols, dst);
      } else {
        std::reverse_copy(src, src + cols, dst);
      }
    }
    return;
  }
  // Each row is cell i of every profile: a transpose. It goes a tile of columns at a time down
  // all the rows, so that the tile's profiles stay in cache from row to row; row by row, a DEM
  // far wider than high would write every profile's cache line again for each row.
  constexpr std::size_t kTile = 256;
  for (std::size_t c0 = 0; c0 < cols; c0 += kTile) {
    const std::size_t c1 = std::min(cols, c0 + kTile);
    for (std::size_t k = 0; k < count; ++k) {
      const float* src = rows + k * cols;
      const auto i = static_cast<std::size_t>(
          (static_cast<std::int64_t>(first_row + k) - frame.row0) * frame.row_per_i);
      for (std::size_t c = c0; c < c1; ++c) {
        const auto p =
            static_cast<std::size_t>((static_cast<std::int64_t>(c) - frame.col0) * frame.col_per_p);
        oriented(p, i) = src[c];
      }
    }
  }
}

DemWindow profile_window(const OrientedFrame& frame, std::size_t first, std::size_t count) {
  if (frame.resampled) throw Error("strips work for the cardinal views (azimuth 0, 90, 180, 270)");
  if (count == 0 || first + count > frame.profiles) throw Error("strip outside the grid");
  const bool by_rows = frame.row_per_p != 0;  // views from the west or east: profiles are rows
  const bool reversed = by_rows ? frame.row_per_p < 0 : frame.col_per_p < 0;
  const std::size_t extent = by_rows ? frame.dem_rows : frame.dem_cols;
  const std::size_t start = reversed ? extent - (first + count) : first;
  DemWindow w;
  w.row0 = by_rows ? start : 0;
  w.col0 = by_rows ? 0 : start;
  w.rows = by_rows ? count : frame.dem_rows;
  w.cols = by_rows ? frame.dem_cols : count;
  return w;
}

void orient_window(const OrientedFrame& frame, const HeightGrid& window, HeightGrid& out) {
  // The window seen from the same side is exactly its run of profiles, in order.
  const OrientedFrame turned = make_frame(window.rows(), window.cols(), 1, 1, frame.azimuth_deg);
  out.reshape(turned.profiles, turned.length, kUnset);
  scatter_dem_rows(turned, 0, window.rows(), window.data(), window.cols(), out);
}

namespace {

// The cells of a whole DEM, row by row.
class GridCells {
 public:
  explicit GridCells(const HeightGrid& dem) : z_(dem.data()), cols_(dem.cols()) {}
  const float* at(std::size_t r, std::size_t c) const { return z_ + (r * cols_ + c); }
#if TSK_HAS_AVX2_CODE
  // at(r, c) is base() + row_offsets(r) + c, for four rows (below 2^31) at a time.
  const float* base() const {
    return z_;
  }
  TSK_AVX2 __m256i row_offsets(__m128i rows, __m256i) const {
    return _mm256_mul_epu32(_mm256_cvtepu32_epi64(rows),
                            _mm256_set1_epi64x(static_cast<long long>(cols_)));
  }
#endif

 private:
  const float* z_;
  std::size_t cols_;
};

// The cells of a DemBand: each DEM row holds its own run of columns.
class BandCells {
 public:
  explicit BandCells(const DemBand& band) : band_(band) {}
  const float* at(std::size_t r, std::size_t c) const {
    const std::size_t k = r - band_.first_row();
    assert(k < band_.rows() && c >= band_.col_begin(k) && c < band_.col_end(k));
    return band_.heights() + (band_.row_base(k) + static_cast<std::ptrdiff_t>(c));
  }
#if TSK_HAS_AVX2_CODE
  // As GridCells': the rows' bases looked up in the 64-bit `lanes` set, 0 in the others.
  const float* base() const {
    return band_.heights();
  }
  TSK_AVX2 __m256i row_offsets(__m128i rows, __m256i lanes) const {
    const __m128i k = _mm_sub_epi32(rows, _mm_set1_epi32(static_cast<int>(band_.first_row())));
    return _mm256_mask_i32gather_epi64(
        _mm256_setzero_si256(), reinterpret_cast<const long long*>(band_.row_bases()), k, lanes, 8);
  }
#endif

 private:
  const DemBand& band_;
};

#if TSK_HAS_AVX2_CODE
// Helpers of BilinearSampler::run_avx2, each lane as its scalar operator() does it.
// The 32-bit lanes of a 64-bit lane mask.
TSK_AVX2 inline __m128i avx2_narrow(__m256d mask) {
  return _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(
      _mm256_castpd_si256(mask), _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7)));
}

// std::clamp(t, 0.0, 1.0)
TSK_AVX2 inline __m256d avx2_clamp01(__m256d t) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  t = _mm256_blendv_pd(t, one, _mm256_cmp_pd(one, t, _CMP_LT_OQ));
  return _mm256_blendv_pd(t, zero, _mm256_cmp_pd(t, zero, _CMP_LT_OQ));
}

// weight < 1e-9 ? 0.0 : weight * height
TSK_AVX2 inline __m256d avx2_term(__m256d weight, __m128 height) {
  return _mm256_blendv_pd(_mm256_mul_pd(weight, _mm256_cvtps_pd(height)), _mm256_setzero_pd(),
                          _mm256_cmp_pd(weight, _mm256_set1_pd(1e-9), _CMP_LT_OQ));
}

// The heights at base + at in the lanes of `mask`, nodata in the others (not read).
TSK_AVX2 inline __m128 avx2_heights(const float* base, __m256i at, __m128 mask) {
  return _mm256_mask_i64gather_ps(_mm_set1_ps(kNoData), base, at, mask, 4);
}
#endif

// Bilinear sampling of a DEM of rows x cols cells held as `Cells`, with what every sample needs
// worked out once.
template <typename Cells>
class BilinearSampler {
 public:
  BilinearSampler(const Cells& cells, std::size_t rows, std::size_t cols)
      : cells_(cells),
        last_col_(static_cast<double>(cols - 1)),
        last_row_(static_cast<double>(rows - 1)),
        max_c0_(cols > 1 ? cols - 2 : 0),
        max_r0_(rows > 1 ? rows - 2 : 0),
        dc_(cols > 1 ? 1 : 0),
        dr_(rows > 1 ? 1 : 0) {}

  float operator()(double col, double row) const {
    constexpr double kEdge = 1e-9;
    const double u = col - 0.5, v = row - 0.5;
    if (!(u >= -kEdge && u <= last_col_ + kEdge && v >= -kEdge && v <= last_row_ + kEdge)) {
      return kNoData;
    }
    // The lower-left source cell, kept inside so that the far edge is reachable with weight 0.
    // Truncating a non-negative number is its floor, without a call into libm.
    // (Through a signed integer: x86-64 converts doubles to signed integers in one instruction.)
    const auto c0 =
        std::min(static_cast<std::size_t>(static_cast<std::int64_t>(std::max(0.0, u))), max_c0_);
    const auto r0 =
        std::min(static_cast<std::size_t>(static_cast<std::int64_t>(std::max(0.0, v))), max_r0_);
    const double fu = dc_ ? std::clamp(u - static_cast<double>(c0), 0.0, 1.0) : 0.0;
    const double fv = dr_ ? std::clamp(v - static_cast<double>(r0), 0.0, 1.0) : 0.0;
    const float* near = cells_.at(r0, c0);
    const float* far = cells_.at(r0 + dr_, c0);
    // A weight under 1e-9 (a position on a cell centre line) leaves its cell out, nodata or not;
    // a nodata cell that counts makes the sum nodata. Without branches: this is the hot loop of
    // every non-cardinal view.
    const auto term = [](double weight, float height) {
      return weight < 1e-9 ? 0.0 : weight * static_cast<double>(height);
    };
    const double z = term((1 - fu) * (1 - fv), near[0]) + term(fu * (1 - fv), near[dc_]) +
                     term((1 - fu) * fv, far[0]) + term(fu * fv, far[dc_]);
    return std::isfinite(z) ? static_cast<float>(z) : kNoData;
  }

  // Samples the positions (col0 + dcol * i, row0 + drow * i) for i in [begin, end) into out[i],
  // as operator() samples each: four at a time where the processor has AVX2.
  void run(double col0, double row0, double dcol, double drow, std::size_t begin, std::size_t end,
           float* out) const {
    std::size_t i = begin;
    const auto sample_until = [&](std::size_t stop) {
      for (; i < stop; ++i) {
        const auto s = static_cast<double>(i);
        out[i] = (*this)(col0 + dcol * s, row0 + drow * s);
      }
    };
#if TSK_HAS_AVX2_CODE
    if (cpu_has_avx2()) {
      // Most of a profile lies well inside the DEM, where the checks and clamps change nothing.
      const auto [a, b] = interior(col0, row0, dcol, drow, begin, end);
      if (a < b) {
        i = run_avx2<false>(col0, row0, dcol, drow, i, a, out);
        sample_until(a);
        i = run_avx2<true>(col0, row0, dcol, drow, i, b, out);
        sample_until(b);
      }
      i = run_avx2<false>(col0, row0, dcol, drow, i, end, out);
    }
#endif
    sample_until(end);
  }

 private:
  // True when the sample at step s lies where every check and clamp of operator() leaves it as
  // it is: its lower-left cell at least a cell from the far sides, with both neighbours there.
  bool well_inside(double col0, double row0, double dcol, double drow, std::size_t i) const {
    const auto s = static_cast<double>(i);
    const double u = col0 + dcol * s - 0.5, v = row0 + drow * s - 0.5;
    return u >= 0.0 && u < last_col_ && v >= 0.0 && v < last_row_;
  }

  // Steps [a, b) within [begin, end) that are all well_inside(), possibly empty. A coordinate
  // start + step * s - 0.5 is monotonic in s as the floats round it, so each of the four bounds
  // holds on an interval of steps: if the first and last step of [a, b) are well inside, all
  // are. An estimate shrunk by two steps at either end is tried first, then two more.
  std::pair<std::size_t, std::size_t> interior(double col0, double row0, double dcol, double drow,
                                               std::size_t begin, std::size_t end) const {
    if (!dc_ || !dr_ || begin >= end) return {0, 0};
    double lo = static_cast<double>(begin), hi = static_cast<double>(end);
    const auto within = [&lo, &hi](double start, double step, double last) {
      if (step == 0.0) return;
      double a = (0.5 - start) / step, b = (last + 0.5 - start) / step;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a), hi = std::min(hi, b);
    };
    within(col0, dcol, last_col_);
    within(row0, drow, last_row_);
    for (double shrink : {2.0, 4.0}) {
      const double a = std::ceil(lo + shrink), b = std::floor(hi - shrink);
      if (!(a < b)) break;
      const auto first = static_cast<std::size_t>(a), last = static_cast<std::size_t>(b);
      if (well_inside(col0, row0, dcol, drow, first) && well_inside(col0, row0, dcol, drow, last))
        return {first, last + 1};
    }
    return {0, 0};
  }

#if TSK_HAS_AVX2_CODE
  // operator() on four positions at once, operation for operation in its order, so that each
  // lane gives the same float; returns where it stopped (fewer than four positions left).
  // kInterior: every position is well_inside(), so the checks and clamps are left out.
  template <bool kInterior>
  TSK_AVX2 std::size_t run_avx2(double col0, double row0, double dcol, double drow, std::size_t i,
                                std::size_t end, float* out) const {
    constexpr double kEdge = 1e-9;
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d half = _mm256_set1_pd(0.5), low = _mm256_set1_pd(-kEdge);
    const __m256d u_high = _mm256_set1_pd(last_col_ + kEdge);
    const __m256d v_high = _mm256_set1_pd(last_row_ + kEdge);
    const __m256d largest = _mm256_set1_pd(std::numeric_limits<double>::max());
    const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
    const __m128i max_c0 = _mm_set1_epi32(static_cast<int>(max_c0_));
    const __m128i max_r0 = _mm_set1_epi32(static_cast<int>(max_r0_));
    const __m128i next_row = _mm_set1_epi32(static_cast<int>(dr_));
    const __m256i next_col = _mm256_set1_epi64x(static_cast<long long>(dc_));
    const __m128 nodata = _mm_set1_ps(kNoData);
    const __m256d lanes = _mm256_setr_pd(0, 1, 2, 3);
    const float* base = cells_.base();
    for (; i + 4 <= end; i += 4) {
      const __m256d s = _mm256_add_pd(_mm256_set1_pd(static_cast<double>(i)), lanes);
      const __m256d u = _mm256_sub_pd(
          _mm256_add_pd(_mm256_set1_pd(col0), _mm256_mul_pd(_mm256_set1_pd(dcol), s)), half);
      const __m256d v = _mm256_sub_pd(
          _mm256_add_pd(_mm256_set1_pd(row0), _mm256_mul_pd(_mm256_set1_pd(drow), s)), half);
      __m256d inside = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
      if constexpr (!kInterior) {
        inside = _mm256_and_pd(
            _mm256_and_pd(_mm256_cmp_pd(u, low, _CMP_GE_OQ), _mm256_cmp_pd(u, u_high, _CMP_LE_OQ)),
            _mm256_and_pd(_mm256_cmp_pd(v, low, _CMP_GE_OQ), _mm256_cmp_pd(v, v_high, _CMP_LE_OQ)));
        if (_mm256_movemask_pd(inside) == 0) {
          _mm_storeu_ps(out + i, nodata);
          continue;
        }
      }
      const __m128i inside32 = avx2_narrow(inside);
      __m128i c0, r0;
      __m256d fu, fv;
      if constexpr (kInterior) {
        c0 = _mm256_cvttpd_epi32(u), r0 = _mm256_cvttpd_epi32(v);
        fu = _mm256_sub_pd(u, _mm256_cvtepi32_pd(c0));
        fv = _mm256_sub_pd(v, _mm256_cvtepi32_pd(r0));
      } else {
        // Truncated and capped as operator() does, and 0 in the lanes outside (whose positions
        // need not convert).
        c0 = _mm_and_si128(_mm_min_epi32(_mm256_cvttpd_epi32(_mm256_max_pd(u, zero)), max_c0),
                           inside32);
        r0 = _mm_and_si128(_mm_min_epi32(_mm256_cvttpd_epi32(_mm256_max_pd(v, zero)), max_r0),
                           inside32);
        fu = dc_ ? avx2_clamp01(_mm256_sub_pd(u, _mm256_cvtepi32_pd(c0))) : zero;
        fv = dr_ ? avx2_clamp01(_mm256_sub_pd(v, _mm256_cvtepi32_pd(r0))) : zero;
      }
      const __m256d gu = _mm256_sub_pd(one, fu), gv = _mm256_sub_pd(one, fv);
      const __m256i lanes_in = _mm256_castpd_si256(inside);
      const __m128 read = _mm_castsi128_ps(inside32);
      const __m256i col = _mm256_cvtepu32_epi64(c0);
      const __m256i near = _mm256_add_epi64(cells_.row_offsets(r0, lanes_in), col);
      const __m256i far =
          _mm256_add_epi64(cells_.row_offsets(_mm_add_epi32(r0, next_row), lanes_in), col);
      const __m256d t00 = avx2_term(_mm256_mul_pd(gu, gv), avx2_heights(base, near, read));
      const __m256d t01 = avx2_term(_mm256_mul_pd(fu, gv),
                                    avx2_heights(base, _mm256_add_epi64(near, next_col), read));
      const __m256d t10 = avx2_term(_mm256_mul_pd(gu, fv), avx2_heights(base, far, read));
      const __m256d t11 = avx2_term(_mm256_mul_pd(fu, fv),
                                    avx2_heights(base, _mm256_add_epi64(far, next_col), read));
      const __m256d z = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(t00, t01), t10), t11);
      const __m256d finite = _mm256_cmp_pd(_mm256_and_pd(z, magnitude), largest, _CMP_LE_OQ);
      const __m128i keep = avx2_narrow(_mm256_and_pd(finite, inside));
      _mm_storeu_ps(out + i, _mm_blendv_ps(nodata, _mm256_cvtpd_ps(z), _mm_castsi128_ps(keep)));
    }
    return i;
  }
#endif

  Cells cells_;
  double last_col_, last_row_;
  std::size_t max_c0_, max_r0_;
  std::size_t dc_, dr_;  // steps to the next column and row; 0 on a grid one cell wide or high
};

// The cells [first, last) of a profile of `length` cells whose pixel coordinate start + step * i
// may fall on a DEM side of `cells` cells: a range with a cell's margin in pixel coordinates
// around the cell centres' hull, which the sampler then checks exactly.
std::pair<std::size_t, std::size_t> inside_range(double start, double step, std::size_t cells,
                                                 std::size_t length) {
  const double lo = -0.5, hi = static_cast<double>(cells) + 0.5;
  const auto len = static_cast<double>(length);
  double a = -1, b = len;  // a constant coordinate inside: every cell
  if (step != 0.0) {
    a = (lo - start) / step;
    b = (hi - start) / step;
    if (a > b) std::swap(a, b);
  } else if (start < lo || start > hi) {
    return {0, 0};
  }
  const double first = std::clamp(std::floor(a), 0.0, len);
  const double last = std::clamp(std::ceil(b) + 1, 0.0, len);
  return {static_cast<std::size_t>(first), static_cast<std::size_t>(last)};
}

// Profiles [first, first + count) of a resampled frame sampled through `sample` into `out`.
template <typename Cells>
void resample_with(const BilinearSampler<Cells>& sample, const OrientedFrame& frame,
                   std::size_t first, std::size_t count, HeightGrid& out, unsigned threads) {
  if (!frame.resampled || first > frame.profiles || count > frame.profiles - first) {
    throw Error("the profiles do not match the resampled frame");
  }
  out.reshape(count, frame.length, kUnset);
  // Where each profile starts in pixel coordinates (frame.to_pixel(p, i) with the profile's part
  // worked out once, same rounding) and its cells [lo, hi) that fall on the DEM (the sampler
  // still checks); the margins of the line-of-sight grid, up to half of it, are nodata.
  struct Profile {
    double col0, row0;
    std::size_t lo, hi;
  };
  const auto profile = [&](std::size_t k) {
    const auto p = static_cast<double>(first + k);
    Profile pr{frame.px_col0 + frame.px_col_per_p * p, frame.px_row0 + frame.px_row_per_p * p, 0,
               0};
    const auto cols = inside_range(pr.col0, frame.px_col_per_i, frame.dem_cols, frame.length);
    const auto rows = inside_range(pr.row0, frame.px_row_per_i, frame.dem_rows, frame.length);
    pr.lo = std::max(cols.first, rows.first);
    pr.hi = std::min(cols.second, rows.second);
    if (pr.lo >= pr.hi) pr.lo = pr.hi = 0;
    return pr;
  };
  // Neighbouring profiles read nearly the same DEM cells, but a whole profile at a slant reads a
  // new DEM row every cell or two, more than a core's cache holds. So the profiles are sampled a
  // stretch of cells at a time, every profile in turn, while those cells' rows are in cache.
  constexpr std::size_t kStretch = 1024;
  parallel_for(count, threads, [&](std::size_t begin, std::size_t end) {
    std::vector<Profile> profiles(end - begin);
    for (std::size_t k = begin; k < end; ++k) profiles[k - begin] = profile(k);
    for (std::size_t i0 = 0; i0 < frame.length; i0 += kStretch) {
      const std::size_t i1 = std::min(frame.length, i0 + kStretch);
      for (std::size_t k = begin; k < end; ++k) {
        const Profile& pr = profiles[k - begin];
        float* row = out.row(k);
        const std::size_t a = std::clamp(pr.lo, i0, i1), b = std::clamp(pr.hi, i0, i1);
        std::fill(row + i0, row + a, kNoData);
        sample.run(pr.col0, pr.row0, frame.px_col_per_i, frame.px_row_per_i, a, b, row);
        std::fill(row + b, row + i1, kNoData);
      }
    }
  });
}

// The least and greatest x of the convex polygon `corners` within the rows y0 <= y <= y1; empty
// (lo > hi) when the polygon does not reach them.
std::pair<double, double> x_range_in_rows(const PixelPoint (&corners)[4], double y0, double y1) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto take = [&](double x) { lo = std::min(lo, x), hi = std::max(hi, x); };
  for (std::size_t k = 0; k < 4; ++k) {
    const PixelPoint a = corners[k], b = corners[(k + 1) % 4];
    if (a.row >= y0 && a.row <= y1) take(a.col);
    if (a.row == b.row) continue;
    for (const double y : {y0, y1}) {
      const double t = (y - a.row) / (b.row - a.row);
      if (t >= 0 && t <= 1) take(a.col + t * (b.col - a.col));
    }
  }
  return {lo, hi};
}

// floor(x) clamped to [0, limit], for positions that may lie far outside the DEM.
std::size_t clamped_floor(double x, std::size_t limit) {
  return static_cast<std::size_t>(std::clamp(std::floor(x), 0.0, static_cast<double>(limit)));
}

}  // namespace

float sample_bilinear(const HeightGrid& dem, PixelPoint px) {
  return BilinearSampler<GridCells>(GridCells(dem), dem.rows(), dem.cols())(px.col, px.row);
}

void resample_profiles(const HeightGrid& dem, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads) {
  if (dem.rows() != frame.dem_rows || dem.cols() != frame.dem_cols) {
    throw Error("the DEM does not match the resampled frame");
  }
  resample_with(BilinearSampler<GridCells>(GridCells(dem), dem.rows(), dem.cols()), frame, first,
                count, out, threads);
}

void DemBand::load(const OrientedFrame& frame, std::size_t first, std::size_t count,
                   const WindowReader& read) {
  if (!frame.resampled || count == 0 || first > frame.profiles || count > frame.profiles - first)
    throw Error("the profiles do not match the resampled frame");
  first_profile_ = first, profile_count_ = count;
  // The samples of the strip fill a parallelogram of pixel positions. A sample at row position y
  // reads DEM rows floor(y - 0.5) and the next, so DEM row r is read from y in [r - 0.5, r + 1.5];
  // likewise columns. A margin of one cell more on every side absorbs rounding.
  constexpr double kMargin = 1.0;
  const auto p0 = static_cast<double>(first), p1 = static_cast<double>(first + count - 1);
  const auto s1 = static_cast<double>(frame.length - 1);
  const PixelPoint corners[4] = {frame.to_pixel(p0, 0), frame.to_pixel(p1, 0),
                                 frame.to_pixel(p1, s1), frame.to_pixel(p0, s1)};
  double y_min = corners[0].row, y_max = corners[0].row;
  for (const PixelPoint& c : corners)
    y_min = std::min(y_min, c.row), y_max = std::max(y_max, c.row);
  first_row_ = clamped_floor(std::ceil(y_min - 1.5 - kMargin), frame.dem_rows);
  const std::size_t end_row = clamped_floor(y_max + 0.5 + kMargin + 1, frame.dem_rows);
  const std::size_t rows = end_row > first_row_ ? end_row - first_row_ : 0;
  col_begin_.resize(rows), col_end_.resize(rows), row_base_.resize(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    const auto r = static_cast<double>(first_row_ + k);
    const auto [x_lo, x_hi] = x_range_in_rows(corners, r - 0.5 - kMargin, r + 1.5 + kMargin);
    const std::size_t begin = clamped_floor(x_lo - 1.5 - kMargin, frame.dem_cols);
    const std::size_t end =
        x_lo <= x_hi ? clamped_floor(x_hi + 0.5 + kMargin + 1, frame.dem_cols) : 0;
    col_begin_[k] = begin;
    col_end_[k] = std::max(begin, end);
  }
  // Rows are read a few at a time, each chunk as the window spanning their runs, straight into
  // the band: a row holds the window's columns. A chunk grows while its window stays within an
  // eighth more than its widest run (a diagonal band's runs shift from row to row).
  constexpr std::size_t kMostChunkRows = 64;
  struct Chunk {
    std::size_t k0, k1, c0, c1, offset;
  };
  std::vector<Chunk> chunks;
  std::size_t cells = 0;
  for (std::size_t k0 = 0; k0 < rows;) {
    Chunk chunk{k0, k0 + 1, col_begin_[k0], col_end_[k0], cells};
    std::size_t widest = col_end_[k0] - col_begin_[k0];
    while (chunk.k1 < rows && chunk.k1 - k0 < kMostChunkRows) {
      const std::size_t k = chunk.k1;
      const std::size_t c0 = std::min(chunk.c0, col_begin_[k]);
      const std::size_t c1 = std::max(chunk.c1, col_end_[k]);
      const std::size_t run = std::max(widest, col_end_[k] - col_begin_[k]);
      if ((c1 - c0) * 8 > run * 9) break;
      chunk.c0 = c0, chunk.c1 = c1, widest = run, ++chunk.k1;
    }
    const std::size_t width = chunk.c1 - chunk.c0;
    for (std::size_t k = chunk.k0; k < chunk.k1; ++k) {
      row_base_[k] = static_cast<std::ptrdiff_t>(cells + (k - chunk.k0) * width) -
                     static_cast<std::ptrdiff_t>(chunk.c0);
    }
    cells += (chunk.k1 - chunk.k0) * width;
    chunks.push_back(chunk);
    k0 = chunk.k1;
  }
  if (cells > heights_.capacity()) {
    // A band holds about as many DEM cells as its strip covers, and the strips across the middle
    // of the DEM cover the most: room for those from the start, rather than growing band by band
    // into fresh memory (each page of it a fault), copying what is to be overwritten.
    const double cells_per_sample =
        std::abs(frame.px_col_per_i * frame.px_row_per_p - frame.px_row_per_i * frame.px_col_per_p);
    const double largest =
        std::min(cells_per_sample * static_cast<double>(count) * static_cast<double>(frame.length),
                 static_cast<double>(frame.dem_rows) * static_cast<double>(frame.dem_cols));
    heights_ = {};
    heights_.reserve(std::max(cells, static_cast<std::size_t>(1.125 * largest)));
  }
  heights_.resize(cells);
  for (const Chunk& chunk : chunks) {
    if (chunk.c0 >= chunk.c1) continue;
    read({first_row_ + chunk.k0, chunk.c0, chunk.k1 - chunk.k0, chunk.c1 - chunk.c0},
         heights_.data() + chunk.offset);
  }
}

void resample_profiles(const DemBand& band, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads) {
  // Samples outside the band's profiles would read cells it does not hold.
  if (first < band.first_profile() || first + count > band.first_profile() + band.profile_count())
    throw Error("the band does not hold these profiles");
  resample_with(BilinearSampler<BandCells>(BandCells(band), frame.dem_rows, frame.dem_cols), frame,
                first, count, out, threads);
}

void read_row_blocks(std::size_t rows, std::size_t cols, const WindowReader& read,
                     const std::function<void(std::size_t first_row, std::size_t count,
                                              const float* heights)>& use) {
  const std::size_t block_rows = std::max<std::size_t>(1, (std::size_t{1} << 22) / cols);
  std::vector<float> block(std::min(block_rows, rows) * cols);
  for (std::size_t top = 0; top < rows; top += block_rows) {
    const std::size_t count = std::min(block_rows, rows - top);
    read({top, 0, count, cols}, block.data());
    use(top, count, block.data());
  }
}

double dem_lowest_height(std::size_t rows, std::size_t cols, const WindowReader& read) {
  LowestHeight lowest;
  read_row_blocks(rows, cols, read,
                  [&lowest, cols](std::size_t, std::size_t count, const float* z) {
                    lowest.add(z, count * cols);
                  });
  return lowest.value();
}

StripLoader::StripLoader(const OrientedFrame& frame, WindowReader read, unsigned threads)
    : frame_(frame), read_(std::move(read)), threads_(threads) {}

void StripLoader::load(std::size_t first, std::size_t count, HeightGrid& strip) {
  if (frame_.resampled) {
    band_.load(frame_, first, count, read_);
    resample_profiles(band_, frame_, first, count, strip, threads_);
    return;
  }
  const DemWindow w = profile_window(frame_, first, count);
  // Seen from the west the window is the strip as it is; any other cardinal view turns it.
  const bool turned = frame_.row_per_p <= 0 || frame_.col_per_i <= 0;
  HeightGrid& target = turned ? window_ : strip;
  target.reshape(w.rows, w.cols, kUnset);
  read_(w, target.data());
  if (turned) orient_window(frame_, window_, strip);
}

HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame, unsigned threads) {
  if (dem.rows() != frame.dem_rows || dem.cols() != frame.dem_cols) {
    throw Error("the DEM does not match the oriented frame");
  }
  HeightGrid oriented(frame.profiles, frame.length, kUnset);
  if (!frame.resampled) {
    scatter_dem_rows(frame, 0, dem.rows(), dem.data(), dem.cols(), oriented);
    return oriented;
  }
  resample_profiles(dem, frame, 0, frame.profiles, oriented, threads);
  return oriented;
}

OrientedGridBuilder::OrientedGridBuilder(const OrientedFrame& frame)
    : frame_(frame),
      grid_(frame.resampled ? HeightGrid(frame.dem_rows, frame.dem_cols, kUnset)
                            : HeightGrid(frame.profiles, frame.length, kUnset)) {}

void OrientedGridBuilder::add_rows(std::size_t first_row, std::size_t count, const float* rows) {
  if (!frame_.resampled) {
    scatter_dem_rows(frame_, first_row, count, rows, frame_.dem_cols, grid_);
  } else {
    if (first_row + count > frame_.dem_rows) throw Error("DEM block does not match the frame");
    std::copy(rows, rows + count * frame_.dem_cols, grid_.row(first_row));
  }
  lowest_.add(rows, count * frame_.dem_cols);
}

HeightGrid OrientedGridBuilder::finish(unsigned threads) {
  if (!frame_.resampled) return std::move(grid_);
  return orient(grid_, frame_, threads);
}

double OrientedGridBuilder::dem_lowest_height() const {
  return lowest_.value();
}

}  // namespace tsk
