#include "core/method/resample.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "core/base/errors.h"
#include "core/base/parallel.h"
#include "core/base/vector_clones.h"

#if TSK_HAS_AVX2_CODE
// GCC 12 warns that its own AVX-512 intrinsics read an unset value (its bug 105593, mended in
// GCC 13: the "undefined" first operand they start from); nowhere else.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#else
#include <immintrin.h>
#endif
#endif

namespace tsk {
namespace {

// The cells of a whole DEM, row by row.
class GridCells {
 public:
  explicit GridCells(const HeightGrid& dem)
      : z_(dem.data()), cols_(dem.cols()), count_(dem.size()) {}
  const float* at(std::size_t r, std::size_t c) const { return z_ + (r * cols_ + c); }
#if TSK_HAS_AVX2_CODE
  // Rows a fixed stride apart: cells further along a line can be fetched ahead.
  static constexpr bool kFetchAhead = true;
  std::int64_t row_stride() const {
    return static_cast<std::int64_t>(cols_);
  }
  std::int64_t cell_count() const {
    return static_cast<std::int64_t>(count_);
  }
  // at(r, c) is base() + row_offsets(r) + c, for four rows (below 2^31) at a time.
  const float* base() const {
    return z_;
  }
  TSK_AVX2 __m256i row_offsets(__m128i rows, __m256i) const {
    return _mm256_mul_epu32(_mm256_cvtepu32_epi64(rows),
                            _mm256_set1_epi64x(static_cast<long long>(cols_)));
  }
  TSK_AVX512 __m512i row_offsets(__m256i rows) const {
    return _mm512_mul_epu32(_mm512_cvtepu32_epi64(rows),
                            _mm512_set1_epi64(static_cast<long long>(cols_)));
  }
#endif

 private:
  const float* z_;
  std::size_t cols_, count_;
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
  static constexpr bool kFetchAhead = false;  // each row has a base of its own
  // As GridCells': the rows' bases looked up in the 64-bit `lanes` set, 0 in the others.
  const float* base() const {
    return band_.heights();
  }
  TSK_AVX2 __m256i row_offsets(__m128i rows, __m256i lanes) const {
    const __m128i k = _mm_sub_epi32(rows, _mm_set1_epi32(static_cast<int>(band_.first_row())));
    return _mm256_mask_i32gather_epi64(
        _mm256_setzero_si256(), reinterpret_cast<const long long*>(band_.row_bases()), k, lanes, 8);
  }
  // Eight rows, every one in the band.
  TSK_AVX512 __m512i row_offsets(__m256i rows) const {
    const __m256i k =
        _mm256_sub_epi32(rows, _mm256_set1_epi32(static_cast<int>(band_.first_row())));
    return _mm512_i32gather_epi64(k, band_.row_bases(), 8);
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

// Asks for the cells at base + cell + ahead, for each of the lanes' cells where that lies within
// `count` cells: a ray across the rows meets a fresh cache line at every sample, and fetched
// ahead the wait is hidden (16 samples ahead: a panorama's processor time about 10 % less).
template <std::size_t kLanes>
inline void fetch_cells_ahead(const float* base, const std::int64_t (&cells)[kLanes],
                              std::int64_t ahead, std::int64_t count) {
  for (const std::int64_t cell : cells) {
    const std::int64_t later = cell + ahead;
    if (later >= 0 && later < count)
      _mm_prefetch(reinterpret_cast<const char*>(base + later), _MM_HINT_T0);
  }
}

TSK_AVX2 inline void avx2_fetch_ahead(const float* base, __m256i at, std::int64_t ahead,
                                      std::int64_t count) {
  alignas(32) std::int64_t lane[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lane), at);
  fetch_cells_ahead(base, lane, ahead, count);
}

// The heights at base + at and the next column, each lane's two in one 64-bit read. Four plain
// loads, not a gather: on the development machine's processor (AMD EPYC) gathers bound the
// sampling loop, and these loads took a panorama from 0.93 s to 0.83 s.
TSK_AVX2 inline void avx2_height_pairs(const float* base, __m256i at, __m128& left, __m128& right) {
  alignas(32) std::int64_t index[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(index), at);
  std::int64_t pair[4];
  for (int k = 0; k < 4; ++k) std::memcpy(&pair[k], base + index[k], sizeof pair[k]);
  const __m256i pairs = _mm256_setr_epi64x(pair[0], pair[1], pair[2], pair[3]);
  const __m256i split =
      _mm256_permutevar8x32_epi32(pairs, _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7));
  left = _mm_castsi128_ps(_mm256_castsi256_si128(split));
  right = _mm_castsi128_ps(_mm256_extracti128_si256(split, 1));
}

// The helpers of BilinearSampler::run_avx512, eight lanes at a time as run_avx2's four.
// weight < 1e-9 ? 0.0 : weight * height
TSK_AVX512 inline __m512d avx512_term(__m512d weight, __m512d height) {
  const __mmask8 counts = _mm512_cmp_pd_mask(weight, _mm512_set1_pd(1e-9), _CMP_NLT_UQ);
  return _mm512_maskz_mul_pd(counts, weight, height);
}

// As avx2_height_pairs, with the eight pairs gathered at once (the loads are not what bounds
// this loop on AVX-512 processors, its shuffles were), widened to doubles.
TSK_AVX512 inline void avx512_height_pairs(const float* base, __m512i at, __m512d& left,
                                           __m512d& right) {
  const __m512i split = _mm512_permutexvar_epi32(
      _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15),
      _mm512_i64gather_epi64(at, base, 4));
  left = _mm512_cvtps_pd(_mm256_castsi256_ps(_mm512_castsi512_si256(split)));
  right = _mm512_cvtps_pd(_mm256_castsi256_ps(_mm512_extracti64x4_epi64(split, 1)));
}

TSK_AVX512 inline void avx512_fetch_ahead(const float* base, __m512i at, std::int64_t ahead,
                                          std::int64_t count) {
  alignas(64) std::int64_t lane[8];
  _mm512_store_si512(lane, at);
  fetch_cells_ahead(base, lane, ahead, count);
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
    // A sample this close outside the outermost cell centres takes the edge cell: a view a hair
    // off a cardinal azimuth must not lose the DEM's edge rows (1e-9 lost them at 90.000001).
    constexpr double kEdge = 1e-5;
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
        if (cpu_has_avx512()) i = run_avx512(col0, row0, dcol, drow, i, b, out);
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
  // What fetching ahead needs: the offset of the cells `samples` samples on from a sample's, and
  // how many cells there are (both 0 for cells not fetched ahead).
  std::pair<std::int64_t, std::int64_t> fetch_ahead(double dcol, double drow,
                                                    double samples) const {
    if constexpr (Cells::kFetchAhead) {
      return {static_cast<std::int64_t>(std::llround(samples * drow)) * cells_.row_stride() +
                  static_cast<std::int64_t>(std::llround(samples * dcol)),
              static_cast<std::int64_t>(cells_.cell_count())};
    }
    return {0, 0};
  }

  // operator() on four positions at once, operation for operation in its order, so that each
  // lane gives the same float; returns where it stopped (fewer than four positions left).
  // kInterior: every position is well_inside(), so the checks and clamps are left out.
  template <bool kInterior>
  TSK_AVX2 std::size_t run_avx2(double col0, double row0, double dcol, double drow, std::size_t i,
                                std::size_t end, float* out) const {
    constexpr double kEdge = 1e-5;
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
    [[maybe_unused]] const auto [ahead, cell_count] = fetch_ahead(dcol, drow, 16.0);
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
      __m128 h00, h01, h10, h11;
      if constexpr (kInterior) {  // every lane reads, and the next column is there
        if constexpr (Cells::kFetchAhead) avx2_fetch_ahead(base, near, ahead, cell_count);
        avx2_height_pairs(base, near, h00, h01);
        avx2_height_pairs(base, far, h10, h11);
      } else {
        h00 = avx2_heights(base, near, read);
        h01 = avx2_heights(base, _mm256_add_epi64(near, next_col), read);
        h10 = avx2_heights(base, far, read);
        h11 = avx2_heights(base, _mm256_add_epi64(far, next_col), read);
      }
      const __m256d t00 = avx2_term(_mm256_mul_pd(gu, gv), h00);
      const __m256d t01 = avx2_term(_mm256_mul_pd(fu, gv), h01);
      const __m256d t10 = avx2_term(_mm256_mul_pd(gu, fv), h10);
      const __m256d t11 = avx2_term(_mm256_mul_pd(fu, fv), h11);
      const __m256d z = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(t00, t01), t10), t11);
      const __m256d finite = _mm256_cmp_pd(_mm256_and_pd(z, magnitude), largest, _CMP_LE_OQ);
      const __m128i keep = avx2_narrow(_mm256_and_pd(finite, inside));
      _mm_storeu_ps(out + i, _mm_blendv_ps(nodata, _mm256_cvtpd_ps(z), _mm_castsi128_ps(keep)));
    }
    return i;
  }

  // run_avx2<true> on eight positions at once, each lane's operations those of operator() in its
  // order (the build fuses no multiply-adds); returns where it stopped (fewer than eight left).
  TSK_AVX512 std::size_t run_avx512(double col0, double row0, double dcol, double drow,
                                    std::size_t i, std::size_t end, float* out) const {
    const __m512d one = _mm512_set1_pd(1.0), half = _mm512_set1_pd(0.5);
    const __m512d largest = _mm512_set1_pd(std::numeric_limits<double>::max());
    const __m512d lanes = _mm512_setr_pd(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i next_row = _mm256_set1_epi32(1);
    const __m256 nodata = _mm256_set1_ps(kNoData);
    const float* base = cells_.base();
    // Further ahead than run_avx2 fetches, as a step here is about twice as quick: of 16 to 96
    // samples ahead, 48 was the quickest sampling lines across an 8000 x 8000 grid.
    [[maybe_unused]] const auto [ahead, cell_count] = fetch_ahead(dcol, drow, 48.0);
    for (; i + 8 <= end; i += 8) {
      const __m512d s = _mm512_add_pd(_mm512_set1_pd(static_cast<double>(i)), lanes);
      const __m512d u = _mm512_sub_pd(
          _mm512_add_pd(_mm512_set1_pd(col0), _mm512_mul_pd(_mm512_set1_pd(dcol), s)), half);
      const __m512d v = _mm512_sub_pd(
          _mm512_add_pd(_mm512_set1_pd(row0), _mm512_mul_pd(_mm512_set1_pd(drow), s)), half);
      const __m256i c0 = _mm512_cvttpd_epi32(u), r0 = _mm512_cvttpd_epi32(v);
      const __m512d fu = _mm512_sub_pd(u, _mm512_cvtepi32_pd(c0));
      const __m512d fv = _mm512_sub_pd(v, _mm512_cvtepi32_pd(r0));
      const __m512d gu = _mm512_sub_pd(one, fu), gv = _mm512_sub_pd(one, fv);
      const __m512i col = _mm512_cvtepu32_epi64(c0);
      const __m512i near = _mm512_add_epi64(cells_.row_offsets(r0), col);
      const __m512i far = _mm512_add_epi64(cells_.row_offsets(_mm256_add_epi32(r0, next_row)), col);
      if constexpr (Cells::kFetchAhead) avx512_fetch_ahead(base, near, ahead, cell_count);
      __m512d h00, h01, h10, h11;
      avx512_height_pairs(base, near, h00, h01);
      avx512_height_pairs(base, far, h10, h11);
      const __m512d t00 = avx512_term(_mm512_mul_pd(gu, gv), h00);
      const __m512d t01 = avx512_term(_mm512_mul_pd(fu, gv), h01);
      const __m512d t10 = avx512_term(_mm512_mul_pd(gu, fv), h10);
      const __m512d t11 = avx512_term(_mm512_mul_pd(fu, fv), h11);
      const __m512d z = _mm512_add_pd(_mm512_add_pd(_mm512_add_pd(t00, t01), t10), t11);
      const __mmask8 finite = _mm512_cmp_pd_mask(_mm512_abs_pd(z), largest, _CMP_LE_OQ);
      _mm256_storeu_ps(out + i, _mm256_mask_blend_ps(finite, nodata, _mm512_cvtpd_ps(z)));
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

}  // namespace

float sample_bilinear(const HeightGrid& dem, PixelPoint px) {
  return BilinearSampler<GridCells>(GridCells(dem), dem.rows(), dem.cols())(px.col, px.row);
}

void sample_line(const HeightGrid& dem, PixelPoint start, PixelPoint step, std::size_t count,
                 float* out) {
  BilinearSampler<GridCells>(GridCells(dem), dem.rows(), dem.cols())
      .run(start.col, start.row, step.col, step.row, 0, count, out);
}

void resample_profiles(const HeightGrid& dem, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads) {
  if (dem.rows() != frame.dem_rows || dem.cols() != frame.dem_cols) {
    throw Error("the DEM does not match the resampled frame");
  }
  resample_with(BilinearSampler<GridCells>(GridCells(dem), dem.rows(), dem.cols()), frame, first,
                count, out, threads);
}

void resample_profiles(const DemBand& band, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads) {
  // Samples outside the band's profiles would read cells it does not hold.
  if (first < band.first_profile() || first + count > band.first_profile() + band.profile_count())
    throw Error("the band does not hold these profiles");
  resample_with(BilinearSampler<BandCells>(BandCells(band), frame.dem_rows, frame.dem_cols), frame,
                first, count, out, threads);
}

}  // namespace tsk
