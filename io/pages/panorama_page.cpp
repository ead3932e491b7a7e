#include "io/pages/panorama_page.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "core/drawn/stroke_smoothing.h"
#include "core/drawn/stroke_weights.h"

namespace tsk::io {
namespace {

constexpr double kMostExaggeration = 3.0;
// A drawn stroke is cut where its chain steps more samples than this along the next ray.
constexpr std::int32_t kLeapSamples = 4;

// The page's frame: its size and margins, and how degrees map onto it.
struct PanoramaFrame {
  double width = 0, height = 0, margin = 0;
  double top = 0;  // where the highest elevation is drawn
  bool millimetres = false;
  double from_deg = 0, top_deg = 0;  // the left edge's azimuth, the top edge's elevation
  double per_deg_x = 1, per_deg_y = 1;
  StrokePoint at(const StrokePoint& view, double turns) const {
    return {margin + (view.x + 360.0 * turns - from_deg) * per_deg_x,
            top + (top_deg - view.y) * per_deg_y};
  }
};

PanoramaFrame frame_page(const PanoramaResult& result, const std::vector<PeakLeader>& leaders,
                         const PageOptions& options) {
  PanoramaFrame f;
  const FieldOfView& field = result.rays.field;
  if (!options.size.empty()) {
    const PageSize size = parse_page_size(options.size);
    f.millimetres = true;
    f.width = std::max(size.width_mm, size.height_mm);
    f.height = std::min(size.width_mm, size.height_mm);
    f.margin = 10.0;
  } else {
    // A wide field needs a wide picture; its height a quarter of its width.
    f.width =
        std::clamp(4000.0 * field.width_deg / 360.0, static_cast<double>(options.width_px), 4000.0);
    f.height = std::max(300.0, std::round(f.width / 4.0));
    f.margin = 20.0;
  }
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const PanoramaStroke& s : result.strokes)
    for (const StrokePoint& p : s.view) low = std::min(low, p.y), high = std::max(high, p.y);
  for (const PeakLeader& l : leaders)
    low = std::min(low, l.top.y), high = std::max(high, l.label.y);
  if (!(high > low)) low = -1.0, high = 1.0;
  f.from_deg = field.from_deg;
  f.top_deg = high;
  f.per_deg_x = (f.width - 2 * f.margin) / field.width_deg;
  // Heights fill the page, but are never drawn more than kMostExaggeration times as tall as the
  // azimuths are wide: panorama boards exaggerate gently. A picture without a page is as tall
  // as that needs.
  f.per_deg_y = std::min((f.height - 2 * f.margin) / (high - low), kMostExaggeration * f.per_deg_x);
  const double drawn_height = (high - low) * f.per_deg_y;
  if (options.size.empty()) f.height = std::max(200.0, std::ceil(2 * f.margin + drawn_height));
  f.top = 0.5 * (f.height - drawn_height);  // centred on a page taller than the panorama
  return f;
}

// The paths of one stroke on the page, `turns` turns on (-1: a full circle's overflow at the
// left). Drawn strokes are cut where the chain leaps along the rays, as drawn strokes of the
// parallel view are (a leap is no line on the terrain), then smoothed and tapered.
void add_stroke_paths(const PanoramaStroke& s, const PanoramaFrame& f, double turns, double depth,
                      const DrawnParams& strokes, std::vector<PagePath>& out) {
  const bool factual = s.map.cls == StrokeClass::factual;
  // Far strokes lighter and thinner, down to a quarter of the ink and half the width.
  const double far = std::clamp(s.map.mean_dist / depth, 0.0, 1.0);
  const double width =
      (f.millimetres ? (factual ? 0.5 : 0.3) : (factual ? 2.2 : 1.3)) * (1.0 - 0.5 * far);
  const bool drawn = strokes.drawn() && s.map.chain.size() == s.view.size();
  // A leap: many samples along the next ray, or (near the observer, where a sample spans much
  // of the picture) a step up or down the page far steeper than across it.
  const double jump = f.millimetres ? 1.0 : 4.0;
  const auto leaps = [&](std::size_t k) {
    const StrokePoint a = f.at(s.view[k - 1], turns), b = f.at(s.view[k], turns);
    const double up = std::fabs(b.y - a.y);
    return std::abs(s.map.chain[k].i - s.map.chain[k - 1].i) > kLeapSamples ||
           (up > jump && up > 3.0 * std::fabs(b.x - a.x));
  };
  std::size_t begin = 0;
  while (begin < s.view.size()) {
    std::size_t end = begin + 1;
    while (end < s.view.size() && !(drawn && leaps(end))) ++end;
    Stroke piece;
    for (std::size_t k = begin; k < end; ++k) piece.points.push_back(f.at(s.view[k], turns));
    begin = end;
    if (drawn && piece.points.size() < 2) continue;
    if (drawn) {
      // Gentle on the page: the rays are closer than a pixel, so the stair steps are sub-pixel.
      const double unit = f.millimetres ? 0.25 : 1.0;
      smooth_stroke(piece, 1.5 * unit, unit);
      weigh_stroke(piece, {strokes.taper, 0.0, 0.0});
    }
    PagePath path;
    path.cls = s.map.cls;
    path.ink = 1.0 - 0.75 * far;
    path.points = std::move(piece.points);
    path.widths.assign(path.points.size(), width);
    for (std::size_t k = 0; k < piece.weights.size(); ++k) path.widths[k] *= piece.weights[k];
    out.push_back(std::move(path));
  }
}

}  // namespace

PanoramaPage lay_out_panorama(const PanoramaResult& result, const DrawnParams& strokes,
                              const PageOptions& options, const std::vector<PeakLeader>& leaders) {
  const PanoramaFrame f = frame_page(result, leaders, options);
  PanoramaPage out;
  out.page.width = f.width;
  out.page.height = f.height;
  out.page.millimetres = f.millimetres;
  out.exaggeration = f.per_deg_y / f.per_deg_x;
  const double depth = result.rays.max_distance;
  const double right_edge = f.from_deg + result.rays.field.width_deg;
  for (const PanoramaStroke& s : result.strokes) {
    add_stroke_paths(s, f, 0.0, depth, strokes, out.page.paths);
    // A stroke across a full circle's seam runs past the right edge: its rest shows at the left.
    if (result.rays.field.full_circle && s.azimuth_max > right_edge)
      add_stroke_paths(s, f, -1.0, depth, strokes, out.page.paths);
  }
  for (const PeakLeader& l : leaders)
    out.page.labels.push_back({f.at(l.top, 0.0), f.at(l.label, 0.0), l.peak.name});
  return out;
}

}  // namespace tsk::io
