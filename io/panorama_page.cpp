#include "panorama_page.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stroke_smoothing.h"
#include "stroke_weights.h"

namespace tsk::io {
namespace {

// The page's frame: its size and margins, and how degrees map onto it.
struct PanoramaFrame {
  double width = 0, height = 0, margin = 0;
  bool millimetres = false;
  double from_deg = 0, top_deg = 0;  // the left edge's azimuth, the top edge's elevation
  double per_deg_x = 1, per_deg_y = 1;
  StrokePoint at(const StrokePoint& view, double turns) const {
    return {margin + (view.x + 360.0 * turns - from_deg) * per_deg_x,
            margin + (top_deg - view.y) * per_deg_y};
  }
};

PanoramaFrame frame_page(const PanoramaResult& result, const PageOptions& options) {
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
  if (!(high > low)) low = -1.0, high = 1.0;
  f.from_deg = field.from_deg;
  f.top_deg = high;
  f.per_deg_x = (f.width - 2 * f.margin) / field.width_deg;
  f.per_deg_y = (f.height - 2 * f.margin) / (high - low);
  return f;
}

// The path of one stroke on the page, `turns` turns on (-1: a full circle's overflow at the left).
PagePath stroke_path(const PanoramaStroke& s, const PanoramaFrame& f, double turns, double depth,
                     const DrawnParams& strokes) {
  PagePath path;
  path.cls = s.map.cls;
  const bool factual = s.map.cls == StrokeClass::factual;
  // Far strokes lighter and thinner, down to a quarter of the ink and half the width.
  const double far = std::clamp(s.map.mean_dist / depth, 0.0, 1.0);
  path.ink = 1.0 - 0.75 * far;
  const double width =
      (f.millimetres ? (factual ? 0.5 : 0.3) : (factual ? 2.2 : 1.3)) * (1.0 - 0.5 * far);
  Stroke page_stroke;
  for (const StrokePoint& v : s.view) page_stroke.points.push_back(f.at(v, turns));
  if (strokes.drawn() && page_stroke.points.size() >= 2) {
    // Gentle on the page: the rays are closer than a pixel, so the stair steps are sub-pixel.
    const double unit = f.millimetres ? 0.25 : 1.0;
    smooth_stroke(page_stroke, 1.5 * unit, unit);
    weigh_stroke(page_stroke, {strokes.taper, 0.0, 0.0});
  }
  path.points = std::move(page_stroke.points);
  path.widths.assign(path.points.size(), width);
  for (std::size_t k = 0; k < page_stroke.weights.size(); ++k)
    path.widths[k] *= page_stroke.weights[k];
  return path;
}

}  // namespace

PanoramaPage lay_out_panorama(const PanoramaResult& result, const DrawnParams& strokes,
                              const PageOptions& options) {
  const PanoramaFrame f = frame_page(result, options);
  PanoramaPage out;
  out.page.width = f.width;
  out.page.height = f.height;
  out.page.millimetres = f.millimetres;
  out.exaggeration = f.per_deg_y / f.per_deg_x;
  const double depth = result.rays.max_distance;
  const double right_edge = f.from_deg + result.rays.field.width_deg;
  for (const PanoramaStroke& s : result.strokes) {
    out.page.paths.push_back(stroke_path(s, f, 0.0, depth, strokes));
    // A stroke across a full circle's seam runs past the right edge: its rest shows at the left.
    if (result.rays.field.full_circle && s.azimuth_max > right_edge)
      out.page.paths.push_back(stroke_path(s, f, -1.0, depth, strokes));
  }
  return out;
}

}  // namespace tsk::io
