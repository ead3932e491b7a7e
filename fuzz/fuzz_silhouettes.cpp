// libFuzzer target: the whole core pipeline on hostile grids and parameters.
// Input bytes: a header choosing size, azimuth, view, filter and chaining parameters (some
// deliberately out of range), then heights drawn from a palette of extreme values.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/panorama/panorama.h"
#include "core/terrain_sketch.h"

namespace {

struct Reader {
  const std::uint8_t* data;
  std::size_t size;
  std::uint8_t byte() {
    if (size == 0) return 0;
    --size;
    return *data++;
  }
  double unit() { return byte() / 255.0; }
  float height() {
    static const float special[] = {std::numeric_limits<float>::quiet_NaN(),
                                    std::numeric_limits<float>::infinity(),
                                    -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::max(),
                                    -std::numeric_limits<float>::max(),
                                    std::numeric_limits<float>::denorm_min(),
                                    0.f,
                                    -0.f};
    const std::uint8_t b = byte();
    if (b >= 248) return special[b - 248];
    return static_cast<float>(b) * (byte() % 4 == 0 ? 100.f : 1.f);
  }
};

// The panorama over the same DEM (north-up, dx by dy cells) from an observer anywhere near it,
// with a field of view, range, eye height, refraction and samples per cell from the input, some
// out of range.
void fuzz_panorama(const tsk::HeightGrid& dem, double dx, double dy, Reader& in) {
  tsk::PanoramaParams p;
  const double width = dx * static_cast<double>(dem.cols());
  const double height = dy * static_cast<double>(dem.rows());
  p.view.observer_x = (1.2 * in.unit() - 0.1) * width;
  p.view.observer_y = (1.2 * in.unit() - 0.1) * height;
  p.view.observer_height = in.byte() % 32 == 0 ? -1.0 : 500 * in.unit();
  p.view.max_distance = in.byte() % 4 == 0 ? 0.0 : 2 * width * in.unit();
  p.view.azimuth_from = 720 * in.unit() - 360;
  p.view.azimuth_to = in.byte() % 8 == 0 ? p.view.azimuth_from : 720 * in.unit() - 360;
  p.view.refraction = 1.1 * in.unit();
  p.view.samples_per_cell = in.byte() % 16 == 0 ? 0 : 1 + in.byte() % 3;  // 0: refused
  p.chain.window = static_cast<int>(in.byte() % 6);
  p.chain.min_cells = 2 + in.byte() % 4;
  p.record_visibility = in.byte() & 1;
  p.cut_leaps = in.byte() & 1;
  p.threads = 1 + in.byte() % 2;
  tsk::GeoTransform gt;
  gt.a = {0.0, dx, 0.0, height, 0.0, -dy};
  try {
    const tsk::PanoramaResult r = tsk::sketch_panorama(dem, gt, p);
    if (r.stats.filtered > r.stats.candidate || r.stats.thinned > r.stats.filtered)
      __builtin_trap();
    for (const tsk::PanoramaStroke& s : r.strokes) {
      if (s.view.size() != s.map.points.size() ||
          s.map.cells < p.chain.min_cells * p.view.samples_per_cell ||
          !(s.azimuth_min <= s.azimuth_max))
        __builtin_trap();
      for (const tsk::StrokePoint& pt : s.view)
        if (!std::isfinite(pt.x) || !std::isfinite(pt.y)) __builtin_trap();
    }
    if (p.record_visibility) {
      const tsk::Grid<std::uint8_t> seen = tsk::visibility_raster(r, dem.rows(), dem.cols(), gt, 1);
      if (seen.size() != dem.size()) __builtin_trap();
    }
    const std::vector<tsk::NamedPoint> peaks = {{"a", in.unit() * width, in.unit() * height},
                                                {"b", in.unit() * width, in.unit() * height}};
    const std::vector<tsk::PeakLeader> leaders =
        tsk::lead_peaks(r, tsk::see_peaks(dem, gt, r.rays, peaks));
    for (const tsk::PeakLeader& l : leaders)
      if (!std::isfinite(l.label.y) || l.label.y < l.top.y) __builtin_trap();
  } catch (const tsk::Error&) {
    // Refused with a message: an observer off the DEM, an empty field, a bad parameter.
  }
}

// The plan-oblique drape of the DEM onto itself: heights of 1e38 put cells beyond any raster,
// which must be refused, never cast; what is laid out is one cell at least, and bounded.
void fuzz_drape(const tsk::HeightGrid& dem, const tsk::OrientedFrame& frame,
                const tsk::ViewParams& view) {
  try {
    const tsk::HeightGrid oriented = tsk::orient(dem, frame);
    tsk::CellFlags flags;
    tsk::classify_visibility(oriented, frame.d, view, flags);
    const tsk::PlanObliqueDrape drape(oriented, flags, frame, view, tsk::lowest_height(oriented));
    const double cells = static_cast<double>(drape.rows()) * static_cast<double>(drape.cols());
    if (drape.rows() < 1 || drape.cols() < 1 ||
        cells > 16.0 * static_cast<double>(dem.size()) + 1e6)
      __builtin_trap();
    if (drape.drape(dem).size() != drape.rows() * drape.cols()) __builtin_trap();
  } catch (const tsk::Error&) {
    // Refused with a message: a drape far larger than the DEM.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  const std::size_t rows = 1 + in.byte() % 48, cols = 1 + in.byte() % 48;
  tsk::SilhouetteParams p;
  const std::uint8_t az = in.byte();
  p.view.azimuth_deg = az < 200 ? az * 90.0 / 50.0 : (az - 200) * 7.3 - 30;  // cardinal and not
  p.view.ve = in.byte() % 32 == 0 ? 0.0 : 0.05 + 10 * in.unit();
  p.view.base_slope_pct = in.byte() % 32 == 0 ? -1.0 : 0.5 + 200 * in.unit();
  p.filter.row_cut_pct = 0.1 + 60 * in.unit();
  p.filter.col_cut_pct = 0.1 + 60 * in.unit();
  p.filter.ctrl_col_pct = 70 * in.unit();
  p.filter.diagonals = in.byte() & 1;
  p.chain.window = static_cast<int>(in.byte() % 12) - 1;
  p.chain.min_cells = 1 + in.byte() % 6;
  p.geometry = in.byte() & 1 ? tsk::Geometry::oblique : tsk::Geometry::map;
  p.placement = in.byte() & 1 ? tsk::Placement::near_and_far : tsk::Placement::far;
  p.subcell = in.byte() & 1;
  p.threads = 1 + in.byte() % 2;
  // Cells up to 5:1, with rare zero and extreme (10^4:1) sizes that must be refused quickly.
  const std::uint8_t shape = in.byte();
  const double dx = shape == 0 ? 0.0 : 0.5 + 100 * in.unit();
  const double dy = shape == 1 ? dx * 1e4 : dx * (0.2 + 4.8 * in.unit());
  const std::size_t strip = 1 + in.byte() % 16;
  tsk::HeightGrid dem(rows, cols);
  for (std::size_t k = 0; k < dem.size(); ++k) dem.data()[k] = in.height();
  try {
    const tsk::OrientedFrame frame = tsk::make_frame(rows, cols, dx, dy, p.view.azimuth_deg);
    const tsk::SilhouetteResult r = tsk::run_silhouettes(
        tsk::orient(dem, frame), frame, tsk::GeoTransform{}, tsk::ResolvedParams(p));
    // Invariants that must hold for any input.
    if (r.stats.filtered > r.stats.candidate || r.stats.thinned > r.stats.filtered ||
        r.stats.valid > frame.profiles * frame.length) {
      __builtin_trap();
    }
    for (const tsk::Stroke& s : r.strokes) {
      if (s.cells < p.chain.min_cells || s.points.size() != static_cast<std::size_t>(s.cells)) {
        __builtin_trap();
      }
      for (const tsk::StrokePoint& pt : s.points) {
        if (!std::isfinite(pt.x) || !std::isfinite(pt.y)) __builtin_trap();
      }
    }
    // The same DEM read window by window in strips, strokes handed on as they complete: a
    // resampled strip from its band must equal one from the whole DEM, bit for bit, and the
    // strokes must be the same ones.
    // One thread: no threads started per strip, so the fuzzer keeps its pace.
    tsk::SilhouetteParams in_turn = p;
    in_turn.threads = 1;
    std::size_t handed_on = 0;
    tsk::StripLoader loader(
        frame,
        [&dem](const tsk::DemWindow& w, float* out) {
          if (w.rows == 0 || w.cols == 0 || w.row0 + w.rows > dem.rows() ||
              w.col0 + w.cols > dem.cols()) {
            __builtin_trap();
          }
          for (std::size_t r = 0; r < w.rows; ++r)
            std::memcpy(out + r * w.cols, dem.row(w.row0 + r) + w.col0, w.cols * sizeof(float));
        },
        1);
    tsk::HeightGrid whole;
    const tsk::SilhouetteResult streamed = tsk::run_in_strips(
        frame, tsk::GeoTransform{}, tsk::ResolvedParams(in_turn),
        tsk::lowest_height(tsk::orient(dem, frame)), strip,
        [&](std::size_t first, std::size_t count, tsk::HeightGrid& heights) {
          loader.load(first, count, heights);
          if (frame.resampled) {
            tsk::resample_profiles(dem, frame, first, count, whole, 1);
            if (std::memcmp(whole.data(), heights.data(), whole.size() * sizeof(float)) != 0)
              __builtin_trap();
          }
        },
        {}, [&](tsk::Stroke&&) { ++handed_on; });
    if (handed_on != r.strokes.size() || streamed.stats.generalised != r.stats.generalised)
      __builtin_trap();
    fuzz_drape(dem, frame, p.view);
  } catch (const tsk::Error&) {
    // Refused with a message: the expected outcome for bad parameters.
  }
  fuzz_panorama(dem, dx, dy, in);
  return 0;
}
