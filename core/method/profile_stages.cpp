#include "core/method/profile_stages.h"

#include <cstring>
#include <iterator>
#include <limits>
#include <optional>

#include "core/method/candidates.h"
#include "core/method/slope_filter.h"
#include "core/method/thinning.h"
#include "core/method/visibility.h"

namespace tsk {
namespace {

// True when the eight heights from z on are all nodata (NaN or infinite: every exponent bit set).
static_assert(std::numeric_limits<float>::is_iec559, "eight_nodata reads IEEE 754 floats");
bool eight_nodata(const float* z) {
  constexpr std::uint32_t kExponent = 0x7f800000u;
  std::uint32_t bits[8];
  std::memcpy(bits, z, sizeof bits);
  std::uint32_t common = kExponent;
  for (std::uint32_t b : bits) common &= b;
  return common == kExponent;
}

// Cells [begin, end) of a profile: from its first to its last cell with data. The nodata margins
// of a resampled profile can be half of it, so they are skipped eight cells at a time.
CellRange data_range(const float* z, std::size_t length) {
  std::size_t begin = 0, end = length;
  while (begin + 8 <= end && eight_nodata(z + begin)) begin += 8;
  while (begin < end && !is_data(z[begin])) ++begin;
  while (end >= begin + 8 && eight_nodata(z + end - 8)) end -= 8;
  while (end > begin && !is_data(z[end - 1])) --end;
  return {begin, end};
}

// The rows of profile `row` and its neighbours from cell `first` on.
ProfileRows rows_from(const HeightGrid& z, std::size_t row, std::size_t first) {
  ProfileRows rows = profile_rows(z, row);
  for (const float** r : {&rows.left, &rows.centre, &rows.right})
    if (*r) *r += first;
  return rows;
}

// The stage counts in the order of their flags' bits.
constexpr std::size_t StageStats::*kCountOfBit[] = {&StageStats::valid,     &StageStats::hidden,
                                                    &StageStats::occluding, &StageStats::candidate,
                                                    &StageStats::filtered,  &StageStats::thinned};
static_assert(cell::valid == 1 && cell::hidden == 2 && cell::occluding == 4 &&
                  cell::candidate == 8 && cell::filtered == 16 && cell::thinned == 32,
              "kCountOfBit lists the counts bit by bit");
constexpr std::size_t kCounted = std::size(kCountOfBit);

}  // namespace

// Eight cells at a time: byte k of lanes[b] counts flag b of every eighth cell, for at most 255
// words before it is summed.
void count_profile(const std::uint8_t* f, std::size_t length, StageStats& stats) {
  constexpr std::uint64_t kLowBits = 0x0101010101010101ull;
  constexpr std::uint64_t kEvenBytes = 0x00ff00ff00ff00ffull;
  std::size_t totals[kCounted] = {};
  std::size_t i = 0;
  while (i + 8 <= length) {
    std::uint64_t lanes[kCounted] = {};
    const std::size_t words = std::min<std::size_t>((length - i) / 8, 255);
    for (std::size_t w = 0; w < words; ++w, i += 8) {
      std::uint64_t word;
      std::memcpy(&word, f + i, sizeof word);
      for (std::size_t b = 0; b < kCounted; ++b) lanes[b] += (word >> b) & kLowBits;
    }
    for (std::size_t b = 0; b < kCounted; ++b) {
      // Byte lanes to 16-bit lanes (each at most 510), then their sum in the top 16 bits.
      const std::uint64_t pairs = (lanes[b] & kEvenBytes) + ((lanes[b] >> 8) & kEvenBytes);
      totals[b] += (pairs * 0x0001000100010001ull) >> 48;
    }
  }
  for (; i < length; ++i)
    for (std::size_t b = 0; b < kCounted; ++b) totals[b] += (f[i] >> b) & 1u;
  for (std::size_t b = 0; b < kCounted; ++b) stats.*kCountOfBit[b] += totals[b];
}

void add_counts(const StageStats& counts, StageStats& stats) {
  stats.valid += counts.valid, stats.hidden += counts.hidden;
  stats.occluding += counts.occluding, stats.candidate += counts.candidate;
  stats.filtered += counts.filtered, stats.thinned += counts.thinned;
}

CellRange classify_profile(const HeightGrid& z, std::size_t row, std::size_t p, std::uint8_t* f,
                           const OrientedFrame& frame, const SilhouetteParams& params,
                           StageClock& clock) {
  const float* zp = z.row(row);
  const std::size_t length = frame.length;
  // Every stage skips the nodata before the first and after the last cell with data: up to half
  // of a resampled profile.
  const CellRange cells = data_range(zp, length);
  const std::size_t b = cells.begin, e = cells.end;
  clock.time(&StageTimings::visibility, [&] {
    std::memset(f, 0, length);
    classify_profile_visibility(zp, f, e, frame.d, params.view, b);
  });
  clock.time(&StageTimings::candidates, [&] {
    select_profile_candidates(zp + b, f + b, e - b, frame.d, params.view, params.height_tolerance);
  });
  clock.time(&StageTimings::filter, [&] {
    std::optional<ProfileScales> scales;
    if (params.local_scale) scales.emplace(ProfileScales{*params.local_scale, frame, p, b});
    filter_profile(rows_from(z, row, b), f + b, e - b, frame.d, frame.w, params.filter,
                   scales ? &*scales : nullptr);
  });
  clock.time(&StageTimings::thinning, [&] { thin_profile(f + b, e - b, params.placement); });
  return cells;
}

void ProfileChainCells::collect(const StrokeContext& context, const std::uint8_t* f, std::size_t p,
                                CellRange cells) {
  profile_candidates(f, cells.end, true, factual, cells.begin);
  profile_candidates(f, cells.end, false, formulated, cells.begin);
  factual_cells.clear();
  formulated_cells.clear();
  factual_cells.reserve(factual.cell.size());  // one allocation, sized to fit
  formulated_cells.reserve(formulated.cell.size());
  for (std::int32_t i : factual.cell)
    factual_cells.push_back(stroke_cell(context, p, static_cast<std::size_t>(i), true));
  for (std::int32_t i : formulated.cell)
    formulated_cells.push_back(stroke_cell(context, p, static_cast<std::size_t>(i), false));
}

}  // namespace tsk
