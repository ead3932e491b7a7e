#include "core/method/slope_survey.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace tsk {
namespace {

// Surveys of DEMs up to this size read every cell; larger ones read 64 windows of about a 64th of
// it each. A median from two million slopes is as good as from all of them.
constexpr std::size_t kWholeSurveyCells = std::size_t{1} << 21;
constexpr std::size_t kLattice = 8;

// The windows a survey reads, each a cell wider and taller than the cells it measures (forward
// differences need the next row and column).
std::vector<DemWindow> survey_windows(std::size_t rows, std::size_t cols) {
  if (rows * cols <= kWholeSurveyCells) return {{0, 0, rows, cols}};
  const std::size_t side = 181;  // 64 windows of 181 x 181 cells: two million cells
  const std::size_t lattice_rows = std::min(kLattice, rows),
                    lattice_cols = std::min(kLattice, cols);
  const std::size_t height = std::min(rows, std::min(side, rows / lattice_rows) + 1);
  const std::size_t width = std::min(cols, std::min(side, cols / lattice_cols) + 1);
  std::vector<DemWindow> windows;
  for (std::size_t a = 0; a < lattice_rows; ++a) {
    for (std::size_t b = 0; b < lattice_cols; ++b) {
      // Centred in its part of the lattice, kept inside the DEM.
      const std::size_t centre_row = (2 * a + 1) * rows / (2 * lattice_rows);
      const std::size_t centre_col = (2 * b + 1) * cols / (2 * lattice_cols);
      const std::size_t row0 =
          std::min(rows - height, centre_row - std::min(centre_row, height / 2));
      const std::size_t col0 = std::min(cols - width, centre_col - std::min(centre_col, width / 2));
      windows.push_back({row0, col0, height, width});
    }
  }
  return windows;
}

// True when every finite height is within a thousandth of a quantum of a multiple of `quantum`.
bool all_multiples(const float* heights, std::size_t count, double quantum) {
  for (std::size_t k = 0; k < count; ++k) {
    const double units = static_cast<double>(heights[k]) / quantum;
    if (std::isfinite(units) && std::fabs(units - std::round(units)) > 1e-3) return false;
  }
  return true;
}

}  // namespace

void SlopeHistogram::add(float slope_pct) {
  // The bin is the float's exponent and the top three bits of its mantissa: an eighth of an octave.
  std::uint32_t bits;
  std::memcpy(&bits, &slope_pct, sizeof bits);
  const std::int64_t first = std::int64_t{127 + kLowestOctave} * kPerOctave;
  const std::int64_t bin = static_cast<std::int64_t>(bits >> 20) - first;
  ++counts_[static_cast<std::size_t>(std::clamp<std::int64_t>(bin, 0, kBins - 1))];
  ++total_;
}

void SlopeHistogram::merge(const SlopeHistogram& other) {
  for (int b = 0; b < kBins; ++b) counts_[b] += other.counts_[b];
  total_ += other.total_;
}

double SlopeHistogram::quantile(double q) const {
  if (total_ == 0) return std::numeric_limits<double>::quiet_NaN();
  const double wanted = q * static_cast<double>(total_);
  double below = 0;
  for (int b = 0; b < kBins; ++b) {
    const double in_bin = counts_[b];
    if (below + in_bin >= wanted && in_bin > 0) {
      const int octave = kLowestOctave + b / kPerOctave, eighth = b % kPerOctave;
      const double low = std::ldexp(1.0 + eighth / 8.0, octave);
      const double high = std::ldexp(1.0 + (eighth + 1) / 8.0, octave);
      return low + (high - low) * (wanted - below) / in_bin;
    }
    below += in_bin;
  }
  return std::ldexp(2.0, kLowestOctave + kOctaves - 1);
}

HeightStep height_step(const float* heights, std::size_t count) {
  HeightStep step;
  for (double quantum : {1.0, 0.5, 0.1, 0.01}) {
    if (all_multiples(heights, count, quantum)) {
      step.quantum = quantum;
      step.tolerance = quantum / 2;
      return step;
    }
  }
  // Float heights: resampling moves a flat cell's height by a few units in the last place of a
  // float (about 1e-7 of it), so a millionth of the largest height is flat.
  double largest = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (std::isfinite(heights[k])) largest = std::max(largest, std::fabs(double{heights[k]}));
  }
  step.tolerance = 1e-6 * largest;
  return step;
}

SlopeSurvey survey_slopes(std::size_t rows, std::size_t cols, double dx, double dy,
                          const WindowReader& read) {
  const std::vector<DemWindow> windows = survey_windows(rows, cols);
  std::vector<float> heights;
  std::vector<std::size_t> starts;
  for (const DemWindow& w : windows) {
    starts.push_back(heights.size());
    heights.resize(heights.size() + w.rows * w.cols);
    read(w, heights.data() + starts.back());
  }
  SlopeSurvey survey;
  survey.heights = height_step(heights.data(), heights.size());
  SlopeHistogram histogram;
  for (std::size_t k = 0; k < windows.size(); ++k) {
    const DemWindow& w = windows[k];
    for (std::size_t r = 0; r + 1 < w.rows; ++r) {
      const float* row = heights.data() + starts[k] + r * w.cols;
      for (std::size_t c = 0; c + 1 < w.cols; ++c) {
        const float slope = cell_slope_pct(row, w.cols, c, dx, dy, survey.heights.tolerance);
        if (slope < -1.5f) continue;
        ++survey.cells;
        if (slope < 0) {
          ++survey.flat_cells;
        } else {
          histogram.add(slope);
        }
      }
    }
  }
  survey.median_slope_pct = histogram.quantile(0.5);
  return survey;
}

}  // namespace tsk
