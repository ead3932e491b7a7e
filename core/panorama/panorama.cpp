#include "core/panorama/panorama.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/method/profile_stages.h"

namespace tsk {
namespace {

// Rays to a batch: about a million samples, at least 16 rays.
std::size_t batch_rays(std::size_t samples) {
  return std::clamp<std::size_t>((std::size_t{1} << 20) / std::max<std::size_t>(1, samples), 16,
                                 4096);
}

void add_strokes(std::vector<PanoramaStroke>&& strokes, PanoramaResult& result, bool factual) {
  for (PanoramaStroke& s : strokes) {
    result.stats.generalised += static_cast<std::size_t>(s.map.cells);
    ++(factual ? result.stats.factual_strokes : result.stats.formulated_strokes);
    result.strokes.push_back(std::move(s));
  }
}

}  // namespace

void PanoramaParams::validate() const {
  view.validate();
  rules.filter.validate();
  chain.validate();
  if (!(rules.height_tolerance >= 0.0 && std::isfinite(rules.height_tolerance)))
    throw Error("the height tolerance must be 0 or more");
}

PanoramaResult sketch_panorama(const HeightGrid& dem, const GeoTransform& geotransform,
                               const PanoramaParams& params, const ProgressFn& progress) {
  params.validate();
  PanoramaResult result;
  result.rays = plan_rays(dem, geotransform, params.view);
  const PanoramaRays& rays = result.rays;
  if (params.record_visibility) {
    const std::size_t bytes = result.record_bytes();
    check_fits_in_memory(
        static_cast<double>(bytes),
        "the visibility of " +
            number_text(static_cast<double>(rays.rays) * static_cast<double>(rays.samples)) +
            " samples",
        "sample fewer times a cell, give a shorter range or leave the "
        "visibility out");
    result.samples.assign(bytes, 0);
  }
  const bool full = rays.field.full_circle;
  // The shortest stroke and a leap are counted in cells: as many rays or samples as a cell holds.
  const int per_cell = params.view.samples_per_cell;
  const std::int32_t leap = params.cut_leaps ? PanoramaLinker::kLeapCells * per_cell : 0;
  const int min_samples = params.chain.min_cells * per_cell;
  PanoramaLinker factual(true, 0, min_samples, full, leap);
  PanoramaLinker formulated(false, params.chain.window, min_samples, full, leap);
  const unsigned threads = resolve_threads(params.threads);
  RayRules rules = params.rules;
  rules.local_scale = params.local_scale.get();
  using Batch = std::vector<RayChainCells>;
  const std::size_t size = batch_rays(rays.samples);
  const auto collect = [&](std::size_t first, Batch& batch) {
    batch.resize(std::min(size, rays.rays - first));
    parallel_for(batch.size(), threads, [&](std::size_t lo, std::size_t hi) {
      RayScratch scratch;
      for (std::size_t k = lo; k < hi; ++k) {
        const std::size_t r = first + k;
        const RayRecord record = params.record_visibility ? result.record_of(r) : RayRecord();
        classify_ray(dem, rays, rules, r, scratch, batch[k], record);
      }
    });
  };
  std::size_t next_ray = 0;
  const auto link = [&](const Batch& batch) {
    for (const RayChainCells& ray : batch) {
      add_counts(ray.counts, result.stats);
      factual.add_ray(next_ray, ray.factual, ray.factual_cells, ray.factual_view);
      formulated.add_ray(next_ray, ray.formulated, ray.formulated_cells, ray.formulated_view);
      ++next_ray;
    }
  };
  const auto after = [&](std::size_t done) {
    tell_progress(progress, static_cast<double>(done) / static_cast<double>(rays.rays));
  };
  pipeline_batches<Batch>(rays.rays, size, threads > 1, collect, link, after);
  add_strokes(factual.finish(), result, true);
  add_strokes(formulated.finish(), result, false);
  return result;
}

std::vector<PeakLeader> lead_peaks(const PanoramaResult& result,
                                   const std::vector<SeenPeak>& seen) {
  double low = 0.0, high = 0.0;  // the horizontal, when there are no strokes
  bool first = true;
  for (const PanoramaStroke& s : result.strokes) {
    for (const StrokePoint& p : s.view) {
      low = first ? p.y : std::min(low, p.y);
      high = first ? p.y : std::max(high, p.y);
      first = false;
    }
  }
  for (const SeenPeak& p : seen) high = std::max(high, p.elevation_deg);
  const double row = std::max(0.05, 0.1 * (high - low));
  return peak_leaders(seen, high, row, result.rays.field.width_deg / 20.0);
}

namespace {

// The cells of one raster row as seen from O: their offsets (east, north), distances and nearest
// samples (rounded half up, without libm's calls). Worked out in a pass of their own, free of
// branches, so that the square roots and divisions of neighbouring cells overlap.
struct RowFromObserver {
  std::vector<double> east, north, distance, sample;

  explicit RowFromObserver(std::size_t cols)
      : east(cols), north(cols), distance(cols), sample(cols) {}

  void measure(std::size_t row, const GeoTransform& geotransform, const PanoramaRays& rays) {
    for (std::size_t col = 0; col < east.size(); ++col) {
      double x, y;
      geotransform.apply({static_cast<double>(col) + 0.5, static_cast<double>(row) + 0.5}, x, y);
      const double dx = x - rays.observer_x, dy = y - rays.observer_y;
      const double d = std::sqrt(dx * dx + dy * dy);
      east[col] = dx, north[col] = dy, distance[col] = d;
      sample[col] = static_cast<double>(static_cast<std::int64_t>(d / rays.step + 0.5));
    }
  }
};

}  // namespace

Grid<std::uint8_t> visibility_raster(const PanoramaResult& result, std::size_t rows,
                                     std::size_t cols, const GeoTransform& geotransform,
                                     unsigned threads, const ProgressFn& progress) {
  const PanoramaRays& rays = result.rays;
  if (result.samples.size() != result.record_bytes())
    throw Error("the panorama did not record its samples' visibility");
  Grid<std::uint8_t> raster(rows, cols, kUnset);
  const RayLocator locator(rays);
  // `ray` is the previous cell's ray, where the walk to this cell's starts; rays.rays for none.
  const auto code_of = [&](const RowFromObserver& cells, std::size_t col,
                           std::size_t& ray) -> std::uint8_t {
    const double i = cells.sample[col];
    if (i < 1.0) return visibility_code::visible;  // the cell under O
    if (i > static_cast<double>(rays.samples)) return visibility_code::out_of_range;
    const std::size_t r =
        locator.ray_near(cells.east[col], cells.north[col], cells.distance[col], ray);
    if (r == rays.rays) return visibility_code::out_of_range;
    ray = r;
    const std::uint8_t bits = result.sample_class_of(r, static_cast<std::size_t>(i) - 1);
    return bits == sample_class::visible  ? visibility_code::visible
           : bits == sample_class::hidden ? visibility_code::hidden
                                          : visibility_code::out_of_range;
  };
  parallel_for(
      rows, threads,
      [&](std::size_t lo, std::size_t hi) {
        RowFromObserver cells(cols);
        for (std::size_t row = lo; row < hi; ++row) {
          cells.measure(row, geotransform, rays);
          std::size_t ray = rays.rays;
          for (std::size_t col = 0; col < cols; ++col) raster(row, col) = code_of(cells, col, ray);
        }
      },
      progress);
  return raster;
}

double panorama_exaggeration(const PanoramaResult& result, double asked) {
  if (asked > 0.0) return asked;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const PanoramaStroke& s : result.strokes) {
    for (const StrokePoint& p : s.view) low = std::min(low, p.y), high = std::max(high, p.y);
  }
  if (!(high > low)) return 1.0;
  return std::clamp(result.rays.field.width_deg / (8.0 * (high - low)), 1.0, 5.0);
}

std::vector<StrokePoint> exaggerated(std::vector<StrokePoint> view, double exaggeration) {
  for (StrokePoint& p : view) p.y *= exaggeration;
  return view;
}

std::string elevation_drawn(double exaggeration) {
  if (exaggeration == 1.0) return "to the same scale as azimuths";
  std::ostringstream text;
  text << exaggeration << " times as tall as azimuths are wide";
  return text.str();
}

std::string panorama_note(const std::string& dem, int band, const PanoramaView& view,
                          double exaggeration, const std::string& version) {
  std::ostringstream note;
  note << std::fixed << std::setprecision(0) << dem << ", band " << band << ". Panorama seen from "
       << view.observer_x << ", " << view.observer_y << ", " << std::defaultfloat
       << std::setprecision(4) << view.observer_height << " m above the ground, from "
       << view.azimuth_from << "\xc2\xb0 to " << view.azimuth_to
       << "\xc2\xb0 (azimuths from grid north); elevation angles drawn "
       << elevation_drawn(exaggeration);
  if (view.samples_per_cell > 1)
    note << "; " << view.samples_per_cell << " samples per cell along each ray";
  note << ". Terrain Sketch " << version << ".";
  return note.str();
}

}  // namespace tsk
