#include "core/panorama/panorama_ray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/base/vector_clones.h"
#include "core/method/candidates.h"
#include "core/method/profile_stages.h"
#include "core/method/resample.h"
#include "core/method/slope_filter.h"
#include "core/method/thinning.h"

namespace tsk {
namespace {

// Where ray r's samples lie on the DEM: sample i (1-based) at pixel origin + i * along, and the
// points a step to either side of it at -/+ across.
struct RayPlace {
  PixelPoint origin, along, across;
  PixelPoint direction;  // unit vector in map units (east, north)

  RayPlace(const PanoramaRays& rays, std::size_t r)
      : origin(rays.observer), direction(rays.direction(r)) {
    along = {direction.col * rays.step * rays.col_per_x,
             direction.row * rays.step * rays.row_per_y};
    // The right of the ray, (north, -east), a step long.
    across = {direction.row * rays.step * rays.col_per_x,
              -direction.col * rays.step * rays.row_per_y};
  }
  PixelPoint at(std::size_t k) const {  // sample index k = i - 1
    const double i = static_cast<double>(k + 1);
    return {origin.col + i * along.col, origin.row + i * along.row};
  }
};

// The first sample index from `from` (up to `end`) at which `leaves` holds, for a property
// that, once it holds along the ray, holds from there on.
template <typename Leaves>
std::size_t first_leaving(std::size_t from, std::size_t end, Leaves&& leaves) {
  while (from < end) {
    const std::size_t mid = from + (end - from) / 2;
    if (leaves(mid)) {
      end = mid;
    } else {
      from = mid + 1;
    }
  }
  return from;
}

// The heights of samples [0, end) lowered by the curvature drop, in place, and the tangents of
// their elevation angles: a loop of its own, which the compiler vectorises (the scan for the
// running maximum after it cannot be).
TSK_VECTOR_CLONES
void lower_by_drop(const PanoramaRays& rays, std::size_t end, float* apparent, double* tangents) {
  const double* drop = rays.drop.data();
  const double* inverse_distance = rays.inverse_distance.data();
  const double eye = rays.eye;
  for (std::size_t k = 0; k < end; ++k) {
    const double height = static_cast<double>(apparent[k]) - drop[k];
    tangents[k] = (height - eye) * inverse_distance[k];
    apparent[k] = static_cast<float>(height);
  }
}

// Heights along the ray, lowered by the curvature drop, the tangents of their elevation angles,
// and SPEC 1.2 on them: hidden below the running maximum, occluding before a hidden one; with
// each hidden zone's depth below the sight line grazing its occluder. Sets s.end: the samples
// from there on lie off the DEM.
void sample_ray(const HeightGrid& dem, const PanoramaRays& rays, const RayPlace& place,
                RayScratch& s) {
  const std::size_t n = rays.samples;
  s.apparent.resize(n);
  s.tangent.resize(n);
  s.zone_depth.resize(n);
  s.flags.assign(n, 0);
  const double cols = static_cast<double>(dem.cols()), rows = static_cast<double>(dem.rows());
  // Off the DEM, all four cells outside it: O lies on the DEM, so a ray leaves it for good.
  const auto off_dem = [&](std::size_t k) {
    const PixelPoint p = place.at(k);
    return p.col < -0.5 || p.row < -0.5 || p.col >= cols + 0.5 || p.row >= rows + 0.5;
  };
  s.end = first_leaving(0, n, off_dem);
  std::fill(s.apparent.begin() + static_cast<std::ptrdiff_t>(s.end), s.apparent.end(), kNoData);
  sample_line(dem, place.at(0), place.along, s.end, s.apparent.data());
  lower_by_drop(rays, s.end, s.apparent.data(), s.tangent.data());
  // The hot loop of a panorama: the arrays as plain pointers, which a flag's store cannot move.
  const float* apparent = s.apparent.data();
  const double* tangents = s.tangent.data();
  std::uint8_t* flags = s.flags.data();
  const double eye = rays.eye, step_m = rays.step_metres();
  double running_max = -std::numeric_limits<double>::infinity();
  std::size_t last_visible = n;  // the last visible sample, waiting for the next valid one
  std::size_t occluder = n;      // the occluding sample of the hidden zone under way
  double deepest = 0.0;          // its depth so far
  for (std::size_t k = 0; k < s.end; ++k) {
    if (!is_data(apparent[k])) continue;  // nodata: the maximum carries over it
    const double tangent = tangents[k];
    const bool hidden = tangent < running_max;
    flags[k] = static_cast<std::uint8_t>(cell::valid | (hidden ? cell::hidden : 0));
    if (hidden) {
      if (last_visible != n) {
        flags[last_visible] |= cell::occluding;
        occluder = last_visible;
        deepest = 0.0;
      }
      // The sight line grazing the occluder, whose tangent is the running maximum.
      const double sight = eye + running_max * static_cast<double>(k + 1) * step_m;
      deepest = std::max(deepest, sight - static_cast<double>(apparent[k]));
    } else if (occluder != n) {
      s.zone_depth[occluder] = deepest;
      occluder = n;
    }
    running_max = hidden ? running_max : tangent;
    last_visible = hidden ? n : k;
  }
  if (occluder != n) s.zone_depth[occluder] = deepest;
}

// The c-set (docs/PANORAMA.md 1.4) among samples [0, end - 1), marked in `flags`: the slope along
// the ray falls away less steeply than the sight line descends onto it, -B < gc < 0 with
// B = -tangent, each bound moved in by the height tolerance. Compared as height steps (gc times
// the step), without a division; in a loop the compiler vectorises (the arrays do not overlap).
TSK_VECTOR_CLONES
void mark_candidates(const float* __restrict apparent, const double* __restrict tangents,
                     std::uint8_t* __restrict flags, std::size_t end, double step_m,
                     double tolerance) {
  for (std::size_t k = 0; k + 1 < end; ++k) {
    const double rise = static_cast<double>(apparent[k + 1]) - static_cast<double>(apparent[k]);
    const bool candidate = (rise > tangents[k] * step_m + tolerance) & (rise < -tolerance);
    flags[k] |= static_cast<std::uint8_t>(candidate * cell::candidate);
  }
}

void select_candidates(const PanoramaRays& rays, double tolerance, RayScratch& s) {
  mark_candidates(s.apparent.data(), s.tangent.data(), s.flags.data(), s.end, rays.step_metres(),
                  tolerance);
}

// The slope across the ray at sample k, over two steps, one-sided beside nodata (SPEC 1.3).
double across_slope(const HeightGrid& dem, const RayPlace& place, std::size_t k, double step_m) {
  const PixelPoint p = place.at(k);
  const float centre = sample_bilinear(dem, p);
  const float right = sample_bilinear(dem, {p.col + place.across.col, p.row + place.across.row});
  const float left = sample_bilinear(dem, {p.col - place.across.col, p.row - place.across.row});
  return row_slope(ProfileRows{&left, &centre, &right}, 0, step_m);
}

// The slope along the ray at sample k (SPEC 1.3), on the heights lowered by the curvature drop.
double along_slope(const RayScratch& s, std::size_t k, double step_m) {
  return column_slope(s.apparent.data(), s.apparent.size(), k, step_m);
}

// The first sample from k on in the visible c-set (cell::candidate without cell::hidden), or
// `end`: eight at a time, as most of a panorama's samples are hidden.
std::size_t next_visible_candidate(const std::uint8_t* f, std::size_t k, std::size_t end) {
  constexpr std::uint64_t kLowBits = 0x0101010101010101ull;
  for (std::uint64_t word; k + 8 <= end; k += 8) {
    std::memcpy(&word, f + k, sizeof word);
    if ((word >> 3) & ~(word >> 1) & kLowBits) break;  // cell::candidate, not cell::hidden
  }
  while (k < end && (f[k] & (cell::candidate | cell::hidden)) != cell::candidate) ++k;
  return k;
}

// SPEC 1.5 on the visible c-set; with local scales, each sample's slopes are divided by its
// neighbourhood's scale first.
void filter_samples(const HeightGrid& dem, const PanoramaRays& rays, const RayPlace& place,
                    const FilterRule& rule, const SlopeScaleMap* local_scale, RayScratch& s) {
  const double step_m = rays.step_metres();
  for (std::size_t k = next_visible_candidate(s.flags.data(), 0, s.end); k < s.end;
       k = next_visible_candidate(s.flags.data(), k + 1, s.end)) {
    const double unscale = local_scale ? 1.0 / local_scale->scale_at(place.at(k)) : 1.0;
    const double col_pct = std::fabs(along_slope(s, k, step_m)) * 100.0 * unscale;
    const double row_pct = std::fabs(across_slope(dem, place, k, step_m)) * 100.0 * unscale;
    s.flags[k] |= static_cast<std::uint8_t>(rule.accepts(col_pct, row_pct) * cell::filtered);
  }
}

// The stroke cells of one class's candidates.
void collect_cells(const HeightGrid& dem, const PanoramaRays& rays, const RayPlace& place,
                   std::size_t r, const RayScratch& s, bool factual, RayChainCells& out) {
  const ProfileCandidates& candidates = factual ? out.factual : out.formulated;
  std::vector<StrokeCell>& cells = factual ? out.factual_cells : out.formulated_cells;
  std::vector<StrokePoint>& view = factual ? out.factual_view : out.formulated_view;
  cells.clear();
  view.clear();
  const double step_m = rays.step_metres(), azimuth = rays.azimuth_deg(r);
  for (std::int32_t i : candidates.cell) {
    const std::size_t k = static_cast<std::size_t>(i);
    StrokeCell c;
    c.cell = {static_cast<std::int32_t>(r), i};
    c.dist = rays.distance(k + 1);
    c.map = {rays.observer_x + c.dist * place.direction.col,
             rays.observer_y + c.dist * place.direction.row};
    c.point = c.map;
    c.z = static_cast<double>(s.apparent[k]) + rays.drop[k];
    c.slope_pct = std::fabs(along_slope(s, k, step_m)) * 100.0;
    c.row_slope_pct = std::fabs(across_slope(dem, place, k, step_m)) * 100.0;
    c.depth_m = factual ? s.zone_depth[k] : std::numeric_limits<double>::quiet_NaN();
    cells.push_back(c);
    view.push_back({azimuth, std::atan(s.tangent[k]) * kDegPerRad});
  }
}

void record_visibility(const RayScratch& s, RayRecord out) {
  const std::size_t samples = s.flags.size();
  for (std::size_t byte = 0; byte * 4 < samples; ++byte) {
    std::uint8_t four = 0;
    for (std::size_t k = byte * 4; k < std::min(samples, byte * 4 + 4); ++k) {
      const std::uint8_t f = s.flags[k];
      const std::uint8_t code = !(f & cell::valid)   ? sample_class::out
                                : (f & cell::hidden) ? sample_class::hidden
                                                     : sample_class::visible;
      four |= static_cast<std::uint8_t>(code << (2 * (k % 4)));
    }
    const std::size_t block = byte / RayRecord::kBlockBytes;
    out.first[block * out.stride + byte % RayRecord::kBlockBytes] = four;
  }
}

}  // namespace

void classify_ray(const HeightGrid& dem, const PanoramaRays& rays, const RayRules& rules,
                  std::size_t r, RayScratch& scratch, RayChainCells& out, RayRecord visibility) {
  const RayPlace place(rays, r);
  sample_ray(dem, rays, place, scratch);
  select_candidates(rays, rules.height_tolerance, scratch);
  filter_samples(dem, rays, place, FilterRule(rules.filter), rules.local_scale, scratch);
  const std::size_t n = scratch.end;  // the samples after it have no data
  thin_profile(scratch.flags.data(), n, rules.placement);
  out.counts = StageStats{};
  count_profile(scratch.flags.data(), n, out.counts);
  profile_candidates(scratch.flags.data(), n, true, out.factual);
  profile_candidates(scratch.flags.data(), n, false, out.formulated);
  collect_cells(dem, rays, place, r, scratch, true, out);
  collect_cells(dem, rays, place, r, scratch, false, out);
  if (visibility.first) record_visibility(scratch, visibility);
}

}  // namespace tsk
