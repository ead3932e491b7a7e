#include "core/drawn/pen_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "core/drawn/stroke_joining.h"
#include "core/drawn/stroke_smoothing.h"

namespace tsk {

double pen_up_travel(const std::vector<std::vector<StrokePoint>>& paths, StrokePoint start) {
  double travel = 0.0;
  StrokePoint pen = start;
  for (const auto& path : paths) {
    if (path.empty()) continue;
    travel += distance(pen, path.front());
    pen = path.back();
  }
  return travel;
}

namespace {

// Path ends in square buckets, found nearest first by searching rings of buckets outwards.
class NearestEnds {
 public:
  NearestEnds(const std::vector<std::vector<StrokePoint>>& paths, double cell)
      : paths_(paths), cell_(cell), drawn_(paths.size(), 0), left_(paths.size()) {
    for (std::size_t p = 0; p < paths.size(); ++p) {
      buckets_[key(paths[p].front())].push_back(2 * p);
      buckets_[key(paths[p].back())].push_back(2 * p + 1);
    }
    for (const auto& bucket : buckets_) {
      reach_ = std::max({reach_, std::abs(column(bucket.first)), std::abs(row(bucket.first))});
    }
  }

  // The nearest end of a path not yet drawn (2 p: its first point, 2 p + 1: its last); marks
  // the path drawn.
  std::size_t take_nearest(StrokePoint at) {
    const std::int64_t bx = cell_of(at.x), by = cell_of(at.y);
    Best best;
    const std::int64_t rings = reach_ + std::max(std::abs(bx), std::abs(by)) + 1;
    for (std::int64_t r = 0; r <= rings; ++r) {
      // Every bucket of ring r lies at least (r - 1) buckets away.
      if (best.end != kNone && best.dist <= static_cast<double>(r - 1) * cell_) break;
      // Rings far out cost more than looking at every path left.
      if (8 * r > static_cast<std::int64_t>(left_)) {
        for (std::size_t end = 0; end < 2 * paths_.size(); ++end) consider(at, end, best);
        break;
      }
      for (std::int64_t d = -r; d <= r; ++d) {
        visit(at, bx + d, by - r, best);
        if (r > 0) visit(at, bx + d, by + r, best);
        if (d != -r && d != r) {
          visit(at, bx - r, by + d, best);
          visit(at, bx + r, by + d, best);
        }
      }
    }
    if (best.end != kNone) drawn_[best.end / 2] = 1, --left_;
    return best.end;
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Best {
    std::size_t end = kNone;
    double dist = std::numeric_limits<double>::infinity();
  };
  void consider(StrokePoint at, std::size_t end, Best& best) const {
    if (drawn_[end / 2]) return;
    const auto& path = paths_[end / 2];
    const double d = distance(at, end % 2 ? path.back() : path.front());
    if (d < best.dist || (d == best.dist && end < best.end)) best = {end, d};
  }
  void visit(StrokePoint at, std::int64_t bx, std::int64_t by, Best& best) const {
    const auto found = buckets_.find(pack(bx, by));
    if (found == buckets_.end()) return;
    for (std::size_t end : found->second) consider(at, end, best);
  }
  std::int64_t cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t pack(std::int64_t bx, std::int64_t by) {
    return (static_cast<std::uint64_t>(bx) << 32) ^ (static_cast<std::uint64_t>(by) & 0xffffffffu);
  }
  static std::int64_t column(std::uint64_t k) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(k >> 32));
  }
  static std::int64_t row(std::uint64_t k) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(k));
  }
  std::uint64_t key(StrokePoint p) const { return pack(cell_of(p.x), cell_of(p.y)); }

  const std::vector<std::vector<StrokePoint>>& paths_;
  double cell_;
  std::vector<std::uint8_t> drawn_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;
  std::size_t left_;        // paths not yet drawn
  std::int64_t reach_ = 0;  // the farthest bucket from the origin, in buckets
};

// Paths whose ends meet, merged end to end: joining's rule with any turn allowed.
std::vector<std::vector<StrokePoint>> merge_meeting(std::vector<std::vector<StrokePoint>> paths,
                                                    double meet) {
  std::vector<Stroke> strokes(paths.size());
  for (std::size_t k = 0; k < paths.size(); ++k) strokes[k].points = std::move(paths[k]);
  std::vector<std::vector<StrokePoint>> merged;
  for (Stroke& s : join_strokes(std::move(strokes), {meet, 180.0}))
    merged.push_back(std::move(s.points));
  return merged;
}

}  // namespace

PenPlan plan_pen_paths(std::vector<std::vector<StrokePoint>> paths, double meet,
                       StrokePoint start) {
  paths.erase(std::remove_if(paths.begin(), paths.end(), [](const auto& p) { return p.empty(); }),
              paths.end());
  PenPlan plan;
  plan.travel_before = pen_up_travel(paths, start);
  if (meet > 0.0) paths = merge_meeting(std::move(paths), meet);
  // Buckets about as many as paths over the paths' extent.
  double x0 = start.x, x1 = start.x, y0 = start.y, y1 = start.y;
  for (const auto& p : paths) {
    for (const StrokePoint& q : {p.front(), p.back()}) {
      x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y),
      y1 = std::max(y1, q.y);
    }
  }
  const double extent = std::max({x1 - x0, y1 - y0, 1e-9});
  const double cell = extent / std::max(1.0, std::sqrt(static_cast<double>(paths.size())));
  NearestEnds ends(paths, cell);
  StrokePoint pen = start;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const std::size_t end = ends.take_nearest(pen);
    std::vector<StrokePoint> path = std::move(paths[end / 2]);
    if (end % 2) std::reverse(path.begin(), path.end());
    pen = path.back();
    plan.paths.push_back(std::move(path));
  }
  plan.travel_after = pen_up_travel(plan.paths, start);
  return plan;
}

}  // namespace tsk
