// The DEM's own slopes, surveyed on its own grid rather than the view's, for the adaptive slope
// filter (docs/ADAPTIVE_FILTER.md): how steep its terrain is, and the step of its heights. What a
// survey finds does not depend on the azimuth, so the filter does not move as the view turns.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/grid.h"
#include "core/method/dem_windows.h"

namespace tsk {

// Counts of slopes (percent) in bins an eighth of an octave wide, from 2^-12 % to 2^12 %; slopes
// beyond fall in the end bins.
class SlopeHistogram {
 public:
  static constexpr int kPerOctave = 8, kLowestOctave = -12, kOctaves = 24;
  static constexpr int kBins = kPerOctave * kOctaves;

  void add(float slope_pct);
  void merge(const SlopeHistogram& other);
  std::uint64_t total() const { return total_; }
  // The slope below which a share q of the counted slopes lie, interpolated within its bin;
  // NaN when nothing was counted.
  double quantile(double q) const;

 private:
  friend struct SurveyBytes;
  std::array<std::uint32_t, kBins> counts_{};
  std::uint64_t total_ = 0;
};

// What the adaptive filter needs to know about a DEM's heights.
struct HeightStep {
  double quantum = 0.0;    // 1, 0.5, 0.1 or 0.01 when every height is a multiple of it, else 0
  double tolerance = 0.0;  // half the quantum, or a relative epsilon of the largest height
};

struct SlopeSurvey {
  double median_slope_pct = 0.0;  // of the cells that are not flat; NaN when every cell is
  HeightStep heights;
  std::size_t cells = 0;  // cells whose slope was measured, flat or not
  std::size_t flat_cells = 0;
};

// The slope of cell (r, c) of `z` (cols wide) in percent from its forward differences east and
// south, or a negative number when it is flat (both steps within `tolerance`) or next to nodata
// (NaN, or a fill value: steps to one are no terrain's).
inline float cell_slope_pct(const float* z, std::size_t cols, std::size_t c, double dx, double dy,
                            double tolerance) {
  const double here = z[c], east_z = z[c + 1], south_z = z[c + cols];
  if (!(std::fabs(here) < kFillMagnitude && std::fabs(east_z) < kFillMagnitude &&
        std::fabs(south_z) < kFillMagnitude))
    return -2.0f;
  const double east = east_z - here, south = south_z - here;
  if (std::fabs(east) <= tolerance && std::fabs(south) <= tolerance) return -1.0f;
  // Not std::hypot, a call into libm that took 1.7 % of a panorama's processor time. Its
  // last bit may differ, which the float and then the histogram's eighths of an octave hide.
  const double gx = east / dx, gy = south / dy;
  return static_cast<float>(100.0 * std::sqrt(gx * gx + gy * gy));
}

// The step of a DEM's heights from a sample of them (NaN for nodata).
HeightStep height_step(const float* heights, std::size_t count);

// The windows a survey reads: the whole DEM when it has at most about two million cells, else 64
// windows spread evenly over it, on multiples of 512 cells where they fit (a tiled DEM's blocks).
// Each is a cell wider and taller than the cells it measures.
std::vector<DemWindow> survey_windows(std::size_t rows, std::size_t cols);

// How many windows survey_windows(rows, cols) gives, without listing them.
std::size_t survey_window_count(std::size_t rows, std::size_t cols);

// Whether survey window `k` is read through a second reader of the DEM, when there is one: every
// other pair of windows. The DEM's range (io's sampled_range) reads the even windows the same
// way, so that each reader finds in its own cache the blocks it read for the range.
inline bool read_alongside(std::size_t k) {
  return (k / 2) % 2 == 1;
}

// Whether reader `second` (the second reader, or the first) reads window `k`: with two readers,
// those read_alongside() gives it; with one, every window.
inline bool reader_takes(std::size_t k, bool two_readers, bool second) {
  return !two_readers || read_alongside(k) == second;
}

// Surveys a DEM of rows x cols cells of dx x dy ground units read through `read` (its
// survey_windows, read on the calling thread, and, given `alongside` and more than one thread,
// those read_alongside() names through it on a thread of its own), measuring the slopes on
// `threads` threads (0: every core).
SlopeSurvey survey_slopes(std::size_t rows, std::size_t cols, double dx, double dy,
                          const WindowReader& read, unsigned threads = 0,
                          const WindowReader& alongside = {});

// A survey in parts, for a cluster whose machines each read some of the windows: the parts summed
// give survey_slopes' survey exactly. First the heights' step, which the slopes need.
class HeightStepPart {
 public:
  void add(const float* heights, std::size_t count);
  void merge(const HeightStepPart& other);
  HeightStep step() const;

 private:
  friend struct SurveyBytes;
  std::array<std::uint8_t, 4> multiples_{1, 1, 1, 1};  // of each quantum, 1 to 0.01
  double largest_ = 0.0;  // of the magnitudes of the heights that are not fill values
};

// The slopes of some windows, measured with the DEM's flat-cell tolerance.
class SlopePart {
 public:
  // `heights` holds window `w` (w.rows x w.cols).
  void add(const float* heights, const DemWindow& w, double dx, double dy, double tolerance);
  void merge(const SlopePart& other);
  SlopeSurvey survey(const HeightStep& heights) const;

 private:
  friend struct SurveyBytes;
  SlopeHistogram histogram_;
  std::uint64_t cells_ = 0, flat_cells_ = 0;
};

// The parts as bytes and back, for a machine to hand them to another. Throws Error on bytes that
// are not one.
struct SurveyBytes {
  static std::string of(const HeightStepPart& part);
  static std::string of(const SlopePart& part);
  static HeightStepPart height_step(const std::string& bytes);
  static SlopePart slopes(const std::string& bytes);
};

}  // namespace tsk
