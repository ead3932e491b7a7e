// The method on one ray of a panorama (docs/PANORAMA.md 1.2-1.7): its samples, their stages, and
// the chain candidates with the stroke cells they stand for. Each ray is classified on its own,
// so rays are classified in parallel and linked in order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/scratch_vector.h"
#include "core/method/chaining.h"
#include "core/method/params.h"
#include "core/method/slope_scale_map.h"
#include "core/method/stage_stats.h"
#include "core/method/strokes.h"
#include "core/panorama/panorama_rays.h"

namespace tsk {

// What the stages of a ray follow besides the view: the filter and thinning of SPEC 1.5-1.6.
struct RayRules {
  FilterParams filter;
  double height_tolerance = 0.0;  // the adaptive filter's: steps within it count as flat
  Placement placement = Placement::far;
  // Local adaptivity: each sample's slopes are divided by its neighbourhood's scale first
  // (null: none). It must outlive the run.
  const SlopeScaleMap* local_scale = nullptr;
};

// The samples' classes in the visibility record: two bits each, four to a byte.
namespace sample_class {
constexpr std::uint8_t out = 0, visible = 1, hidden = 2;
}

// Where a ray's samples' classes go: kBlockBytes bytes (four samples each) at `first`, the next
// `stride` bytes on, and so on (PanoramaResult::samples). Null `first`: not recorded.
struct RayRecord {
  std::uint8_t* first = nullptr;
  std::size_t stride = 0;
  static constexpr std::size_t kBlockBytes = 64;
};

// Per ray storage, reused ray after ray by one thread (for a batch of rays): each ray writes what
// it reads, so the numbers are not zeroed as they are sized.
struct RayScratch {
  ScratchVector<float> apparent;    // z' = z - drop, metres; NaN for nodata
  ScratchVector<double> tangent;    // (z' - h0) / d: the tangent of the elevation angle
  std::vector<std::uint8_t> flags;  // the cell:: bits, per sample
  // At an occluding sample: how far, in metres, the terrain of the hidden zone after it lies
  // below the sight line that grazes it, at its deepest (unset at other samples).
  ScratchVector<double> zone_depth;
  std::size_t end = 0;  // the samples from here on lie off the DEM
};

// One ray's chain candidates (SPEC 1.7) with their stroke cells (map geometry) and points in the
// panorama (x: azimuth, y: elevation angle, degrees), and the ray's stage counts.
struct RayChainCells {
  ProfileCandidates factual, formulated;
  std::vector<StrokeCell> factual_cells, formulated_cells;
  std::vector<StrokePoint> factual_view, formulated_view;
  StageStats counts;
};

// Classifies ray r of `rays` over `dem` into `out`. With a `visibility` record, writes its
// samples' classes there (rays.samples two-bit codes).
void classify_ray(const HeightGrid& dem, const PanoramaRays& rays, const RayRules& rules,
                  std::size_t r, RayScratch& scratch, RayChainCells& out, RayRecord visibility);

}  // namespace tsk
