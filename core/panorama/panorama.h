// Panorama sketches from a viewpoint (docs/PANORAMA.md): SPEC's method carried over to a point
// observer, its rays cast all round or over a field of view, on a DEM held whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/base/parallel.h"
#include "core/method/params.h"
#include "core/method/stage_stats.h"
#include "core/panorama/panorama_peaks.h"
#include "core/panorama/panorama_ray.h"
#include "core/panorama/panorama_rays.h"
#include "core/panorama/panorama_strokes.h"

namespace tsk {

struct PanoramaParams {
  PanoramaView view;
  RayRules rules;  // its local_scale is set from local_scale below
  std::shared_ptr<const SlopeScaleMap> local_scale;  // local adaptivity (adapt_filter's), or null
  ChainParams chain;
  unsigned threads = 0;            // 0: one per hardware thread
  bool record_visibility = false;  // keep every sample's class for visibility_raster()
  // Cut strokes where their chains leap along the rays (PanoramaLinker): the front ends' drawn
  // strokes. Off, the strokes are the chains, as SPEC 1.8 makes them.
  bool cut_leaps = false;
  void validate() const;
};

struct PanoramaResult {
  PanoramaRays rays;
  StageStats stats;                     // shares of the valid samples in range
  std::vector<PanoramaStroke> strokes;  // factual first, each class in the order chains started
  // With record_visibility: two bits per sample (sample_class), in blocks of kBlockSamples
  // samples of a ray (one cache line): the first block of every ray, ray after ray, then the
  // second. A raster's row of cells crosses many rays at much the same distance, and so reads a
  // few neighbouring lines rather than a line and a page per cell.
  std::vector<std::uint8_t> samples;
  static constexpr std::size_t kBlockBytes = RayRecord::kBlockBytes,
                               kBlockSamples = 4 * kBlockBytes;
  std::size_t sample_blocks() const { return (rays.samples + kBlockSamples - 1) / kBlockSamples; }
  std::size_t record_bytes() const { return sample_blocks() * rays.rays * kBlockBytes; }
  RayRecord record_of(std::size_t r) {
    return {samples.data() + r * kBlockBytes, rays.rays * kBlockBytes};
  }
  // The class (sample_class) recorded for sample k (0-based) of ray r.
  std::uint8_t sample_class_of(std::size_t r, std::size_t k) const {
    const std::size_t block = k / kBlockSamples, within = k % kBlockSamples;
    const std::uint8_t byte = samples[(block * rays.rays + r) * kBlockBytes + within / 4];
    return static_cast<std::uint8_t>((byte >> (2 * (within % 4))) & 3u);
  }
};

// Throws Error naming the cause on a view it cannot draw (panorama_rays.h), Cancelled when
// `progress` says stop.
PanoramaResult sketch_panorama(const HeightGrid& dem, const GeoTransform& geotransform,
                               const PanoramaParams& params, const ProgressFn& progress = {});

// The panorama layer's exaggeration: `asked` when it is not 0, else one that draws the strokes'
// span of elevation an eighth as tall as the field of view is wide, from 1 to 5 times (a field of
// 360 degrees spans some 6 degrees of elevation: a flat strip drawn true).
double panorama_exaggeration(const PanoramaResult& result, double asked);

// A panorama's run in one sentence, for what its outputs record of it: "jacksboro_utm16n.tif,
// band 1. Panorama seen from 749008, 4009478, 2 m above the ground, from 300° to 30° (azimuths
// from grid north); elevation angles drawn 2.41 times as tall as azimuths are wide. Terrain
// Sketch 0.1.0."
std::string panorama_note(const std::string& dem, int band, const PanoramaView& view,
                          double exaggeration, const std::string& version);
// How tall elevation angles are drawn against azimuths: "K times as tall as azimuths are wide",
// or "to the same scale as azimuths" when K is 1.
std::string elevation_drawn(double exaggeration);
// Points of the panorama (x azimuth, y elevation angle) with their elevation `exaggeration` times.
std::vector<StrokePoint> exaggerated(std::vector<StrokePoint> view, double exaggeration);

// The leaders of the peaks `seen` over the strokes of `result`: their labels a little above the
// highest stroke, in rows a tenth of the strokes' span of elevation apart, each label taking a
// twentieth of the field of view.
std::vector<PeakLeader> lead_peaks(const PanoramaResult& result, const std::vector<SeenPeak>& seen);

// The visibility raster on the DEM's grid (docs/PANORAMA.md 2): each cell takes the class of the
// sample nearest its centre. `result` must hold the samples (record_visibility). Throws
// Cancelled when `progress` says stop.
namespace visibility_code {
constexpr std::uint8_t hidden = 0, visible = 1, out_of_range = 255;
}
Grid<std::uint8_t> visibility_raster(const PanoramaResult& result, std::size_t rows,
                                     std::size_t cols, const GeoTransform& geotransform,
                                     unsigned threads = 0, const ProgressFn& progress = {});

}  // namespace tsk
