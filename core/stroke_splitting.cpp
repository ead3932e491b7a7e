#include "stroke_splitting.h"

#include "stroke_smoothing.h"

namespace tsk {

void split_at_leaps(Stroke&& stroke, double max_step, std::vector<Stroke>& pieces) {
  const std::size_t n = stroke.points.size();
  std::size_t first_leap = 1;
  while (first_leap < n &&
         distance(stroke.points[first_leap - 1], stroke.points[first_leap]) <= max_step)
    ++first_leap;
  if (first_leap >= n || stroke.vertices.size() != n || stroke.chain.size() != n) {
    pieces.push_back(std::move(stroke));
    return;
  }
  StrokeBuilder builder;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0 && distance(stroke.points[k - 1], stroke.points[k]) > max_step) {
      pieces.push_back(builder.stroke(stroke.cls));
      builder.clear();
    }
    StrokeCell c;
    c.cell = stroke.chain[k];
    c.map = c.point = stroke.points[k];
    const StrokeVertex& v = stroke.vertices[k];
    c.dist = v.dist, c.z = v.z, c.slope_pct = v.slope_pct, c.row_slope_pct = v.row_slope_pct;
    c.depth_m = v.depth_m, c.offset = v.offset;
    builder.add(c, true);
  }
  pieces.push_back(builder.stroke(stroke.cls));
}

}  // namespace tsk
