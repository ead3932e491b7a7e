#include "core/method/slope_survey.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <utility>

#include "core/base/byte_stream.h"
#include "core/base/parallel.h"

namespace tsk {
namespace {

// Surveys of DEMs up to this size read every cell; larger ones read 64 windows of about a 64th of
// it each. A median from two million slopes is as good as from all of them.
constexpr std::size_t kWholeSurveyCells = std::size_t{1} << 21;
constexpr std::size_t kLattice = 8;

// The quanta a DEM's heights may step by, largest first.
constexpr double kQuanta[] = {1.0, 0.5, 0.1, 0.01};
constexpr std::uint32_t kHeightStepMagic = 0x54534b48;  // "TSKH"
constexpr std::uint32_t kSlopesMagic = 0x54534b53;      // "TSKS"

// Where a survey window of `size` cells around `centre` starts in [0, extent): on a multiple of
// kAlignCells when one keeps it inside its part of the lattice [begin, end), else centred. A DEM
// tiled in blocks of 128, 256 or 512 cells then decompresses one block's worth of cells for a
// window, not four (on the 8000 x 8000 benchmark, the survey decompressed a quarter of the DEM
// before the run could start).
std::size_t window_start(std::size_t centre, std::size_t size, std::size_t begin, std::size_t end,
                         std::size_t extent) {
  constexpr std::size_t kAlignCells = 512;
  const std::size_t centred = std::min(extent - size, centre - std::min(centre, size / 2));
  const std::size_t below = centred / kAlignCells * kAlignCells, above = below + kAlignCells;
  const bool above_nearer = above - centred < centred - below;
  for (const std::size_t start : {above_nearer ? above : below, above_nearer ? below : above}) {
    if (start >= begin && start + size <= std::min(end, extent)) return start;
  }
  return centred;
}

// The survey's lattice of windows, rows by columns: one window, the whole DEM, for a DEM of at
// most kWholeSurveyCells, else kLattice each way (fewer where the DEM has fewer cells).
std::pair<std::size_t, std::size_t> survey_lattice(std::size_t rows, std::size_t cols) {
  if (rows * cols <= kWholeSurveyCells) return {1, 1};
  return {std::min(kLattice, rows), std::min(kLattice, cols)};
}

}  // namespace

std::size_t survey_window_count(std::size_t rows, std::size_t cols) {
  const auto [lattice_rows, lattice_cols] = survey_lattice(rows, cols);
  return lattice_rows * lattice_cols;
}

// Forward differences need the next row and column: each window is a cell wider and taller than
// the cells it measures.
std::vector<DemWindow> survey_windows(std::size_t rows, std::size_t cols) {
  const auto [lattice_rows, lattice_cols] = survey_lattice(rows, cols);
  if (lattice_rows * lattice_cols == 1) return {{0, 0, rows, cols}};
  const std::size_t side = 181;  // 64 windows of 181 x 181 cells: two million cells
  const std::size_t height = std::min(rows, std::min(side, rows / lattice_rows) + 1);
  const std::size_t width = std::min(cols, std::min(side, cols / lattice_cols) + 1);
  std::vector<DemWindow> windows;
  for (std::size_t a = 0; a < lattice_rows; ++a) {
    for (std::size_t b = 0; b < lattice_cols; ++b) {
      // About the middle of its part of the lattice, kept inside the DEM.
      const std::size_t row0 =
          window_start((2 * a + 1) * rows / (2 * lattice_rows), height, a * rows / lattice_rows,
                       (a + 1) * rows / lattice_rows, rows);
      const std::size_t col0 =
          window_start((2 * b + 1) * cols / (2 * lattice_cols), width, b * cols / lattice_cols,
                       (b + 1) * cols / lattice_cols, cols);
      windows.push_back({row0, col0, height, width});
    }
  }
  return windows;
}

namespace {

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
  HeightStepPart part;
  part.add(heights, count);
  return part.step();
}

void HeightStepPart::add(const float* heights, std::size_t count) {
  for (std::size_t q = 0; q < multiples_.size(); ++q)
    if (multiples_[q] && !all_multiples(heights, count, kQuanta[q])) multiples_[q] = 0;
  // A fill value's magnitude would make every step between real heights "flat": the survey
  // then found no slope and scaled the filter by its most (0 formulated strokes).
  for (std::size_t k = 0; k < count; ++k) {
    const double magnitude = std::fabs(double{heights[k]});
    if (magnitude < kFillMagnitude) largest_ = std::max(largest_, magnitude);
  }
}

void HeightStepPart::merge(const HeightStepPart& other) {
  for (std::size_t q = 0; q < multiples_.size(); ++q) multiples_[q] &= other.multiples_[q];
  largest_ = std::max(largest_, other.largest_);
}

HeightStep HeightStepPart::step() const {
  HeightStep step;
  for (std::size_t q = 0; q < multiples_.size(); ++q) {
    if (multiples_[q]) {
      step.quantum = kQuanta[q];
      step.tolerance = kQuanta[q] / 2;
      return step;
    }
  }
  // Float heights: resampling moves a flat cell's height by a few units in the last place of a
  // float (about 1e-7 of it), so a millionth of the largest height is flat.
  step.tolerance = 1e-6 * largest_;
  return step;
}

void SlopePart::add(const float* heights, const DemWindow& w, double dx, double dy,
                    double tolerance) {
  for (std::size_t r = 0; r + 1 < w.rows; ++r) {
    const float* row = heights + r * w.cols;
    for (std::size_t c = 0; c + 1 < w.cols; ++c) {
      const float slope = cell_slope_pct(row, w.cols, c, dx, dy, tolerance);
      if (slope < -1.5f) continue;
      ++cells_;
      if (slope < 0) {
        ++flat_cells_;
      } else {
        histogram_.add(slope);
      }
    }
  }
}

void SlopePart::merge(const SlopePart& other) {
  histogram_.merge(other.histogram_);
  cells_ += other.cells_;
  flat_cells_ += other.flat_cells_;
}

SlopeSurvey SlopePart::survey(const HeightStep& heights) const {
  SlopeSurvey survey;
  survey.heights = heights;
  survey.cells = static_cast<std::size_t>(cells_);
  survey.flat_cells = static_cast<std::size_t>(flat_cells_);
  survey.median_slope_pct = histogram_.quantile(0.5);
  return survey;
}

namespace {

// Reads `windows` into `heights`, through `read` or, for those read_alongside() names, through
// `alongside` when given, on a thread of its own: the reads were a run's first 0.05 s on one
// core. Either one's failure stops the other at its next window and is rethrown.
void read_survey_windows(const std::vector<DemWindow>& windows,
                         std::vector<std::vector<float>>& heights, const WindowReader& read,
                         const WindowReader& alongside) {
  const bool two = static_cast<bool>(alongside);
  run_two_shares(two, [&](int share, const std::atomic<bool>& stop) {
    const bool second = share == 1;
    const WindowReader& reader = second ? alongside : read;
    for (std::size_t k = 0; k < windows.size() && !stop; ++k) {
      if (!reader_takes(k, two, second)) continue;
      heights[k].resize(windows[k].rows * windows[k].cols);
      reader(windows[k], heights[k].data());
    }
  });
}

}  // namespace

SlopeSurvey survey_slopes(std::size_t rows, std::size_t cols, double dx, double dy,
                          const WindowReader& read, unsigned threads,
                          const WindowReader& alongside) {
  const std::vector<DemWindow> windows = survey_windows(rows, cols);
  std::vector<std::vector<float>> heights(windows.size());
  read_survey_windows(windows, heights, read,
                      resolve_threads(threads) > 1 ? alongside : WindowReader());
  HeightStepPart step;
  for (const std::vector<float>& window : heights) step.add(window.data(), window.size());
  const HeightStep found = step.step();
  // The slopes on every core, a band of rows of a window at a time, each thread counting into a
  // part of its own: the parts' counts add up to one part's exactly, in any order.
  struct Band {
    const float* heights;
    DemWindow rows;  // the band's slope rows and the row below them
  };
  std::vector<Band> bands;
  constexpr std::size_t kBandRows = 128;
  for (std::size_t k = 0; k < windows.size(); ++k) {
    const DemWindow& w = windows[k];
    for (std::size_t r = 0; r + 1 < w.rows; r += kBandRows) {
      const std::size_t slope_rows = std::min(kBandRows, w.rows - 1 - r);
      bands.push_back(
          {heights[k].data() + r * w.cols, {w.row0 + r, w.col0, slope_rows + 1, w.cols}});
    }
  }
  SlopePart slopes;
  std::mutex merging;
  parallel_for(bands.size(), threads, [&](std::size_t begin, std::size_t end) {
    SlopePart part;
    for (std::size_t b = begin; b < end; ++b)
      part.add(bands[b].heights, bands[b].rows, dx, dy, found.tolerance);
    const std::lock_guard<std::mutex> lock(merging);
    slopes.merge(part);
  });
  return slopes.survey(found);
}

std::string SurveyBytes::of(const HeightStepPart& part) {
  ByteWriter w;
  w.put(kHeightStepMagic);
  w.put(part.multiples_);
  w.put(part.largest_);
  return w.take();
}

std::string SurveyBytes::of(const SlopePart& part) {
  ByteWriter w;
  w.put(kSlopesMagic);
  w.put(part.histogram_.counts_);
  w.put(part.cells_);
  w.put(part.flat_cells_);
  return w.take();
}

HeightStepPart SurveyBytes::height_step(const std::string& bytes) {
  ByteReader r(bytes, "a part of a survey of heights");
  r.expect(kHeightStepMagic);
  HeightStepPart part;
  r.get(part.multiples_);
  r.get(part.largest_);
  r.finish();
  for (const std::uint8_t m : part.multiples_)
    if (m > 1) throw Error("these bytes are not a part of a survey of heights: a flag unset");
  if (!(part.largest_ >= 0.0)) throw Error("a part of a survey of heights has no largest height");
  return part;
}

SlopePart SurveyBytes::slopes(const std::string& bytes) {
  ByteReader r(bytes, "a part of a survey of slopes");
  r.expect(kSlopesMagic);
  SlopePart part;
  r.get(part.histogram_.counts_);
  r.get(part.cells_);
  r.get(part.flat_cells_);
  r.finish();
  std::uint64_t total = 0;
  for (const std::uint32_t n : part.histogram_.counts_) total += n;
  part.histogram_.total_ = total;
  if (part.flat_cells_ > part.cells_ || total + part.flat_cells_ > part.cells_)
    throw Error("a part of a survey of slopes counts more slopes than cells");
  return part;
}

}  // namespace tsk
