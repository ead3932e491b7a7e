#include "stroke_joining.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace tsk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One end of a stroke: where it is and the direction it leaves the stroke in (0, 0 when the
// stroke has a single point).
struct StrokeEnd {
  StrokePoint at;
  double dx, dy;
};

std::size_t stroke_of(std::size_t end) {
  return end / 2;
}
bool is_start(std::size_t end) {
  return end % 2 == 0;
}

// The outward direction of an end, over about `reach` of the stroke's length, so that a stroke
// stepping from cell to cell still has the direction it runs in.
StrokeEnd stroke_end(const std::vector<StrokePoint>& pts, bool start, double reach) {
  const std::size_t n = pts.size();
  const StrokePoint at = start ? pts.front() : pts.back();
  StrokePoint from = at;
  double walked = 0.0;
  for (std::size_t k = 1; k < n && walked < reach; ++k) {
    const StrokePoint next = start ? pts[k] : pts[n - 1 - k];
    walked += std::hypot(next.x - from.x, next.y - from.y);
    from = next;
  }
  const double len = std::hypot(at.x - from.x, at.y - from.y);
  if (len <= 0.0) return {at, 0.0, 0.0};
  return {at, (at.x - from.x) / len, (at.y - from.y) / len};
}

// Angle between two directions in degrees; 180 when either is missing.
double angle_between(double ax, double ay, double bx, double by) {
  const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
  if (la <= 0.0 || lb <= 0.0) return 180.0;
  const double c = std::clamp((ax * bx + ay * by) / (la * lb), -1.0, 1.0);
  return std::acos(c) * 180.0 / kPi;
}

// How badly end a leads on into end b (smaller is better), or a negative value when it does not.
double join_cost(const StrokeEnd& a, const StrokeEnd& b, const JoinRule& rule) {
  const double gx = b.at.x - a.at.x, gy = b.at.y - a.at.y;
  const double gap = std::hypot(gx, gy);
  if (gap > rule.gap) return -1.0;
  const bool a_dir = a.dx != 0.0 || a.dy != 0.0, b_dir = b.dx != 0.0 || b.dy != 0.0;
  if (!a_dir && !b_dir) return -1.0;
  double worst = 0.0;
  if (a_dir && b_dir) worst = angle_between(a.dx, a.dy, -b.dx, -b.dy);
  // A step shorter than a tenth of the gap has no direction of its own to compare.
  if (gap > 0.1 * rule.gap) {
    if (a_dir) worst = std::max(worst, angle_between(a.dx, a.dy, gx, gy));
    if (b_dir) worst = std::max(worst, angle_between(-b.dx, -b.dy, gx, gy));
  }
  if (worst > rule.angle_deg) return -1.0;
  return gap / std::max(rule.gap, 1e-300) + worst / std::max(rule.angle_deg, 1e-9);
}

struct EndPair {
  double cost;
  std::uint32_t a, b;
};

// Ends sorted into square buckets of the gap's size, to find an end's neighbours.
class EndBuckets {
 public:
  EndBuckets(const std::vector<StrokeEnd>& ends, double size) : size_(size) {
    keyed_.reserve(ends.size());
    for (std::size_t e = 0; e < ends.size(); ++e)
      keyed_.push_back(
          {key(bucket(ends[e].at.x), bucket(ends[e].at.y)), static_cast<std::uint32_t>(e)});
    std::sort(keyed_.begin(), keyed_.end());
  }
  // Calls f(end) for every end in the 3 x 3 buckets around p.
  template <typename F>
  void near(StrokePoint p, F&& f) const {
    const std::int64_t bx = bucket(p.x), by = bucket(p.y);
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const std::uint64_t k = key(bx + dx, by + dy);
        auto it = std::lower_bound(keyed_.begin(), keyed_.end(), std::make_pair(k, 0u));
        for (; it != keyed_.end() && it->first == k; ++it) f(it->second);
      }
    }
  }

 private:
  std::int64_t bucket(double v) const { return static_cast<std::int64_t>(std::floor(v / size_)); }
  static std::uint64_t key(std::int64_t bx, std::int64_t by) {
    return (static_cast<std::uint64_t>(bx) << 32) ^ (static_cast<std::uint64_t>(by) & 0xffffffffu);
  }
  double size_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed_;
};

// Every pair of ends of different strokes that may join, best first.
std::vector<EndPair> candidate_pairs(const std::vector<StrokeEnd>& ends, const JoinRule& rule) {
  std::vector<EndPair> pairs;
  const EndBuckets buckets(ends, std::max(rule.gap, 1e-9));
  for (std::size_t a = 0; a < ends.size(); ++a) {
    buckets.near(ends[a].at, [&](std::uint32_t b) {
      if (b <= a || stroke_of(b) == stroke_of(a)) return;
      const double cost = join_cost(ends[a], ends[b], rule);
      if (cost >= 0.0) pairs.push_back({cost, static_cast<std::uint32_t>(a), b});
    });
  }
  std::sort(pairs.begin(), pairs.end(), [](const EndPair& x, const EndPair& y) {
    return x.cost != y.cost ? x.cost < y.cost : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return pairs;
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t s) {
  while (parent[s] != s) s = parent[s] = parent[parent[s]];
  return s;
}

// For each end, the end it joins (or itself): best pairs first, each end once, no loops.
std::vector<std::size_t> choose_partners(const std::vector<StrokeEnd>& ends, const JoinRule& rule) {
  std::vector<std::size_t> partner(ends.size());
  std::iota(partner.begin(), partner.end(), std::size_t{0});
  std::vector<std::size_t> group(ends.size() / 2);
  std::iota(group.begin(), group.end(), std::size_t{0});
  for (const EndPair& pair : candidate_pairs(ends, rule)) {
    if (partner[pair.a] != pair.a || partner[pair.b] != pair.b) continue;
    const std::size_t ga = find_root(group, stroke_of(pair.a));
    const std::size_t gb = find_root(group, stroke_of(pair.b));
    if (ga == gb) continue;
    group[ga] = gb;
    partner[pair.a] = pair.b;
    partner[pair.b] = pair.a;
  }
  return partner;
}

// Weighted mean of two values, the finite one alone when the other is not.
double merged_mean(double a, double wa, double b, double wb) {
  if (!std::isfinite(a)) return b;
  if (!std::isfinite(b)) return a;
  return (a * wa + b * wb) / (wa + wb);
}

template <typename T>
void append_in_order(std::vector<T>& into, std::vector<T>& from, bool reversed) {
  if (reversed) std::reverse(from.begin(), from.end());
  into.insert(into.end(), from.begin(), from.end());
}

// Appends `piece` to `joined`, reversed when it is entered at its last point.
void append_piece(Stroke& joined, Stroke& piece, bool reversed) {
  if (joined.points.empty()) {
    joined = std::move(piece);
    if (reversed) {
      std::reverse(joined.points.begin(), joined.points.end());
      std::reverse(joined.vertices.begin(), joined.vertices.end());
      std::reverse(joined.chain.begin(), joined.chain.end());
    }
    return;
  }
  const StrokePoint last = joined.points.back();
  const StrokePoint first = reversed ? piece.points.back() : piece.points.front();
  const double wa = joined.cells, wb = piece.cells;
  joined.mean_slope_pct = merged_mean(joined.mean_slope_pct, wa, piece.mean_slope_pct, wb);
  joined.mean_row_slope_pct =
      merged_mean(joined.mean_row_slope_pct, wa, piece.mean_row_slope_pct, wb);
  joined.mean_depth_m = merged_mean(joined.mean_depth_m, wa, piece.mean_depth_m, wb);
  joined.mean_dist = merged_mean(joined.mean_dist, wa, piece.mean_dist, wb);
  joined.mean_z = merged_mean(joined.mean_z, wa, piece.mean_z, wb);
  if (std::isfinite(piece.max_depth_m))
    joined.max_depth_m = std::isfinite(joined.max_depth_m)
                             ? std::max(joined.max_depth_m, piece.max_depth_m)
                             : piece.max_depth_m;
  joined.length += std::hypot(first.x - last.x, first.y - last.y) + piece.length;
  joined.cells += piece.cells;
  append_in_order(joined.points, piece.points, reversed);
  append_in_order(joined.vertices, piece.vertices, reversed);
  append_in_order(joined.chain, piece.chain, reversed);
}

}  // namespace

std::vector<Stroke> join_strokes(std::vector<Stroke> strokes, const JoinRule& rule) {
  std::vector<StrokeEnd> ends;
  ends.reserve(2 * strokes.size());
  for (const Stroke& s : strokes) {
    ends.push_back(stroke_end(s.points, true, 2.0 * rule.gap));
    ends.push_back(stroke_end(s.points, false, 2.0 * rule.gap));
  }
  const std::vector<std::size_t> partner = choose_partners(ends, rule);
  const auto joins = [&](std::size_t end) { return partner[end] != end; };
  std::vector<Stroke> joined;
  std::vector<std::uint8_t> taken(strokes.size(), 0);
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    if (taken[s]) continue;
    // Walk back through the starts to the first piece, then forward through the pieces.
    std::size_t entry = 2 * s;  // the end the walk enters a piece at
    while (joins(entry)) entry = partner[entry] ^ 1u;
    Stroke whole;
    while (true) {
      const std::size_t piece = stroke_of(entry);
      taken[piece] = 1;
      append_piece(whole, strokes[piece], !is_start(entry));
      const std::size_t exit = entry ^ 1u;
      if (!joins(exit)) break;
      entry = partner[exit];
    }
    joined.push_back(std::move(whole));
  }
  return joined;
}

}  // namespace tsk
