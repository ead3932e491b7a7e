#include "panorama_ray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "candidates.h"
#include "profile_stages.h"
#include "resample.h"
#include "slope_filter.h"
#include "thinning.h"

namespace tsk {
namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

// Where ray r's samples lie on the DEM: sample i (1-based) at pixel origin + i * along, and the
// points a step to either side of it at -/+ across.
struct RayPlace {
  PixelPoint origin, along, across;
  PixelPoint direction;  // unit vector in map units (east, north)

  RayPlace(const PanoramaRays& rays, PixelPoint unit) : origin(rays.observer), direction(unit) {
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

// The first sample of a ray off the DEM (all four cells outside it): O lies on the DEM, so a
// ray leaves it for good.
std::size_t ray_end(const HeightGrid& dem, const PanoramaRays& rays, const RayPlace& place) {
  const double cols = static_cast<double>(dem.cols()), rows = static_cast<double>(dem.rows());
  return first_leaving(0, rays.samples, [&](std::size_t k) {
    const PixelPoint p = place.at(k);
    return p.col < -0.5 || p.row < -0.5 || p.col >= cols + 0.5 || p.row >= rows + 0.5;
  });
}

// SPEC 1.2 along a ray as it stands after the samples so far: carried from a shared segment into
// each ray that goes on from it.
struct SightState {
  double running_max = -std::numeric_limits<double>::infinity();
  std::size_t last_visible;  // the last visible sample, waiting for the next valid one (or none)
  std::size_t occluder;      // the occluding sample of the hidden zone under way (or none)
  double deepest = 0.0;      // that zone's depth so far
  explicit SightState(std::size_t none) : last_visible(none), occluder(none) {}
};

// Samples [begin, stop) along `place`: heights lowered by the curvature drop, the tangents of
// their elevation angles, and SPEC 1.2 on them, going on from `sight`: hidden below the running
// maximum, occluding before a hidden one, each hidden zone's depth below the sight line grazing
// its occluder.
void sample_segment(const HeightGrid& dem, const PanoramaRays& rays, const RayPlace& place,
                    std::size_t begin, std::size_t stop, RayScratch& s, SightState& sight) {
  if (begin >= stop) return;
  const std::size_t none = rays.samples;
  sample_line(dem, place.at(begin), place.along, stop - begin, s.apparent.data() + begin);
  std::fill(s.flags.begin() + static_cast<std::ptrdiff_t>(begin),
            s.flags.begin() + static_cast<std::ptrdiff_t>(stop), std::uint8_t{0});
  // The hot loop of a panorama: the arrays as plain pointers, which a flag's store cannot move.
  float* apparent = s.apparent.data();
  double* tangents = s.tangent.data();
  std::uint8_t* flags = s.flags.data();
  const double* drop = rays.drop.data();
  const double* inverse_distance = rays.inverse_distance.data();
  const double eye = rays.eye, step_m = rays.step_metres();
  SightState v = sight;
  for (std::size_t k = begin; k < stop; ++k) {
    const double height = static_cast<double>(apparent[k]) - drop[k];
    const double tangent = (height - eye) * inverse_distance[k];
    apparent[k] = static_cast<float>(height);
    tangents[k] = tangent;
    if (!is_data(apparent[k])) continue;  // nodata: the maximum carries over it
    const bool hidden = tangent < v.running_max;
    flags[k] = static_cast<std::uint8_t>(cell::valid | (hidden ? cell::hidden : 0));
    if (hidden) {
      if (v.last_visible != none) {
        flags[v.last_visible] |= cell::occluding;
        v.occluder = v.last_visible;
        v.deepest = 0.0;
      }
      // The sight line grazing the occluder, whose tangent is the running maximum.
      const double sight_line = eye + v.running_max * static_cast<double>(k + 1) * step_m;
      v.deepest = std::max(v.deepest, sight_line - static_cast<double>(apparent[k]));
    } else if (v.occluder != none) {
      s.zone_depth[v.occluder] = v.deepest;
      v.occluder = none;
    }
    v.running_max = hidden ? v.running_max : tangent;
    v.last_visible = hidden ? none : k;
  }
  sight = v;
}

// Makes `s`'s first `count` samples those of `from`, which the rays of `s` share.
void copy_shared(const RayScratch& from, std::size_t count, RayScratch& s) {
  std::copy_n(from.apparent.begin(), count, s.apparent.begin());
  std::copy_n(from.tangent.begin(), count, s.tangent.begin());
  std::copy_n(from.flags.begin(), count, s.flags.begin());
  std::copy_n(from.zone_depth.begin(), count, s.zone_depth.begin());
}

// The c-set (docs/PANORAMA.md 1.4): the slope along the ray falls away less steeply than the
// sight line descends onto it, -B < gc < 0 with B = -tangent, each bound moved in by the
// height tolerance. Compared as height steps (gc times the step), without a division.
void select_candidates(const PanoramaRays& rays, double tolerance, RayScratch& s) {
  const double step_m = rays.step_metres();
  const float* apparent = s.apparent.data();
  const double* tangents = s.tangent.data();
  std::uint8_t* flags = s.flags.data();
  for (std::size_t k = 0; k + 1 < s.end; ++k) {
    const double rise = static_cast<double>(apparent[k + 1]) - static_cast<double>(apparent[k]);
    const bool candidate = (rise > tangents[k] * step_m + tolerance) & (rise < -tolerance);
    flags[k] |= static_cast<std::uint8_t>(candidate * cell::candidate);
  }
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

// SPEC 1.5 on the visible c-set; with local scales, each sample's slopes are divided by its
// neighbourhood's scale first.
void filter_samples(const HeightGrid& dem, const PanoramaRays& rays, const RayPlace& place,
                    const FilterRule& rule, const SlopeScaleMap* local_scale, RayScratch& s) {
  const double step_m = rays.step_metres();
  for (std::size_t k = 0; k < s.end; ++k) {
    if ((s.flags[k] & (cell::candidate | cell::hidden)) != cell::candidate) continue;
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

void record_visibility(const RayScratch& s, std::uint8_t* out) {
  std::memset(out, 0, (s.flags.size() + 3) / 4);
  for (std::size_t k = 0; k < s.flags.size(); ++k) {
    const std::uint8_t f = s.flags[k];
    const std::uint8_t code = !(f & cell::valid)   ? sample_class::out
                              : (f & cell::hidden) ? sample_class::hidden
                                                   : sample_class::visible;
    out[k / 4] |= static_cast<std::uint8_t>(code << (2 * (k % 4)));
  }
}

// The stages after SPEC 1.2 on ray r, whose samples `s` holds: SPEC 1.3-1.7 and the stroke cells.
void classify_samples(const HeightGrid& dem, const PanoramaRays& rays, const RayRules& rules,
                      std::size_t r, const RayPlace& place, RayScratch& s, RayChainCells& out,
                      std::uint8_t* visibility) {
  select_candidates(rays, rules.height_tolerance, s);
  filter_samples(dem, rays, place, FilterRule(rules.filter), rules.local_scale, s);
  const std::size_t n = s.end;  // the samples after it have no data
  thin_profile(s.flags.data(), n, rules.placement);
  out.counts = StageStats{};
  count_profile(s.flags.data(), n, out.counts);
  profile_candidates(s.flags.data(), n, true, out.factual);
  profile_candidates(s.flags.data(), n, false, out.formulated);
  collect_cells(dem, rays, place, r, s, true, out);
  collect_cells(dem, rays, place, r, s, false, out);
  if (visibility) record_visibility(s, visibility);
}

// One group of sharing rays, classified node by node: a node of m rays samples along its middle
// direction from where its parent stopped, then each half goes on from there.
class RayGroup {
 public:
  RayGroup(const HeightGrid& dem, const PanoramaRays& rays, const RayRules& rules,
           std::size_t first, RayGroupScratch& scratch, RayChainCells* out,
           std::uint8_t* visibility, std::size_t record_bytes)
      : dem_(dem),
        rays_(rays),
        rules_(rules),
        first_(first),
        scratch_(scratch),
        out_(out),
        visibility_(visibility),
        record_bytes_(record_bytes) {
    std::size_t levels = 0;
    while ((std::size_t{1} << levels) < PanoramaRays::kSharingRays) ++levels;
    scratch_.levels.resize(levels + 1);
    for (RayScratch& s : scratch_.levels) {
      s.apparent.resize(rays.samples);
      s.tangent.resize(rays.samples);
      s.flags.resize(rays.samples);
      s.zone_depth.resize(rays.samples);
    }
    scratch_.ends.resize(PanoramaRays::kSharingRays);
    for (std::size_t k = 0; k < scratch_.ends.size(); ++k)
      scratch_.ends[k] = ray_end(dem, rays, RayPlace(rays, rays.direction(first + k)));
  }

  void classify() {
    SightState sight(rays_.samples);
    node(0, PanoramaRays::kSharingRays, scratch_.levels.size() - 1, 0, sight);
  }

 private:
  // Rays [a, a + m) of the group (m a power of two, aligned), their samples before `begin` in
  // the scratch a level up, SPEC 1.2 standing at `sight` there.
  void node(std::size_t a, std::size_t m, std::size_t level, std::size_t begin, SightState sight) {
    RayScratch& s = scratch_.levels[level];
    if (level + 1 < scratch_.levels.size()) copy_shared(scratch_.levels[level + 1], begin, s);
    const std::size_t r = first_ + a;
    if (m == 1) {
      const RayPlace place(rays_, rays_.direction(r));
      s.end = scratch_.ends[a];
      sample_segment(dem_, rays_, place, begin, s.end, s, sight);
      if (sight.occluder != rays_.samples) s.zone_depth[sight.occluder] = sight.deepest;
      std::fill(s.apparent.begin() + static_cast<std::ptrdiff_t>(s.end), s.apparent.end(), kNoData);
      std::fill(s.flags.begin() + static_cast<std::ptrdiff_t>(s.end), s.flags.end(),
                std::uint8_t{0});
      classify_samples(dem_, rays_, rules_, r, place, s, out_[a],
                       visibility_ ? visibility_ + a * record_bytes_ : nullptr);
      return;
    }
    // Shared while every ray of the node is still on the DEM.
    const auto ends = scratch_.ends.begin() + static_cast<std::ptrdiff_t>(a);
    const std::size_t stop =
        std::max(begin, std::min(rays_.shared_samples(m),
                                 *std::min_element(ends, ends + static_cast<std::ptrdiff_t>(m))));
    sample_segment(dem_, rays_, RayPlace(rays_, rays_.middle_direction(r, m)), begin, stop, s,
                   sight);
    node(a, m / 2, level - 1, stop, sight);
    node(a + m / 2, m / 2, level - 1, stop, sight);
  }

  const HeightGrid& dem_;
  const PanoramaRays& rays_;
  const RayRules& rules_;
  std::size_t first_;
  RayGroupScratch& scratch_;
  RayChainCells* out_;
  std::uint8_t* visibility_;
  std::size_t record_bytes_;
};

}  // namespace

void classify_ray_group(const HeightGrid& dem, const PanoramaRays& rays, const RayRules& rules,
                        std::size_t first, RayGroupScratch& scratch, RayChainCells* out,
                        std::uint8_t* visibility, std::size_t record_bytes) {
  if (first % PanoramaRays::kSharingRays != 0 || first + PanoramaRays::kSharingRays > rays.rays)
    throw Error("internal: a group of panorama rays must be whole and aligned");
  RayGroup(dem, rays, rules, first, scratch, out, visibility, record_bytes).classify();
}

}  // namespace tsk
