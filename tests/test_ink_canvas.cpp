// The PNG preview's pen lines against their definition: a pixel takes the ink of its centre's
// distance from the segment, here found by a numerical search along the segment.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <random>
#include <vector>

#include "catch_compat.h"
#include "io/pages/ink_canvas.h"

using tsk::io::InkCanvas;

namespace {

struct Segment {
  double x0, y0, x1, y1, radius;
  float darkness;
};

// The distance from (x, y) to the segment, minimised numerically along it: the squared distance
// is convex in the place along the segment, so narrowing by thirds finds its least value.
double distance_by_search(const Segment& s, double x, double y) {
  const auto distance_at = [&](double t) {
    return std::hypot(x - (s.x0 + t * (s.x1 - s.x0)), y - (s.y0 + t * (s.y1 - s.y0)));
  };
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double a = lo + (hi - lo) / 3.0, b = hi - (hi - lo) / 3.0;
    if (distance_at(a) < distance_at(b)) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return std::min({distance_at(0.0), distance_at(1.0), distance_at(0.5 * (lo + hi))});
}

// The grey level of every pixel, from each segment's distance to the pixel's centre.
std::vector<std::uint8_t> by_search(int width, int height, const std::vector<Segment>& segments) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double ink = 0.0;
      for (const Segment& s : segments) {
        const double nearest = distance_by_search(s, x + 0.5, y + 0.5);
        ink = std::max(ink, s.darkness * std::clamp(s.radius + 0.5 - nearest, 0.0, 1.0));
      }
      out[static_cast<std::size_t>(y) * width + x] =
          static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - std::min(1.0, ink))));
    }
  }
  return out;
}

int largest_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  REQUIRE(a.size() == b.size());
  int largest = 0;
  for (std::size_t k = 0; k < a.size(); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
  return largest;
}

}  // namespace

TEST_CASE("a pen line inks each pixel by its centre's distance from the segment", "[preview]") {
  // Row 20's centres lie on the line, rows 19 and 21 one pixel off, rows 18 and 22 two.
  InkCanvas canvas(40, 40);
  canvas.line(10.5, 20.5, 30.5, 20.5, 1.0, 1.f);
  const std::vector<std::uint8_t> grey = canvas.pixels();
  const auto at = [&](int x, int y) { return grey[static_cast<std::size_t>(y) * 40 + x]; };
  CHECK(at(20, 20) == 0);
  CHECK(at(20, 19) == 128);  // half covered: 255 * (1 - 0.5), rounded
  CHECK(at(20, 21) == 128);
  CHECK(at(20, 18) == 255);
  CHECK(at(20, 22) == 255);
  CHECK(at(30, 20) == 0);    // on the end
  CHECK(at(31, 20) == 128);  // the round cap: 1 pixel beyond the end
  CHECK(at(32, 20) == 255);
  CHECK(at(5, 20) == 255);
}

TEST_CASE("pen lines of any length and slope ink what their distances say", "[preview]") {
  std::mt19937 random(20261207);
  std::uniform_real_distribution<double> place(-8.0, 56.0), radius(0.0, 3.0), darkness(0.2, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    CAPTURE(trial);
    std::vector<Segment> segments;
    for (int k = 0; k < 6; ++k) {
      // Some segments a point, some shorter than a pixel, others across the canvas and off it.
      const double x0 = place(random), y0 = place(random);
      const double scale = k == 0 ? 0.0 : k == 1 ? 0.02 : 1.0;
      segments.push_back({x0, y0, x0 + scale * (place(random) - x0),
                          y0 + scale * (place(random) - y0), radius(random),
                          static_cast<float>(darkness(random))});
    }
    InkCanvas canvas(48, 40);
    for (const Segment& s : segments) canvas.line(s.x0, s.y0, s.x1, s.y1, s.radius, s.darkness);
    // Rounding apart, the same grey levels.
    CHECK(largest_difference(canvas.pixels(), by_search(48, 40, segments)) <= 1);
  }
}

TEST_CASE("a pen line far off the canvas, or not a number, inks only what it crosses",
          "[preview][robustness]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  InkCanvas nothing(30, 20);
  nothing.line(1e300, 5, 2e300, 5, 1.0, 1.f);
  nothing.line(-1e15, -1e15, -1e15 + 1, -1e15, 1.0, 1.f);
  nothing.line(nan, 5, 10, 5, 1.0, 1.f);
  nothing.line(5, 5, inf, 5, 1.0, 1.f);
  nothing.line(5, 5, 10, 5, nan, 1.f);
  nothing.line(5, 5, 10, 5, -1.0, 1.f);
  nothing.line(5, 5, 10, 5, inf, 1.f);
  const std::vector<std::uint8_t> grey = nothing.pixels();
  CHECK(std::count(grey.begin(), grey.end(), 255) == static_cast<long>(grey.size()));
  // A line across the canvas from a trillion pixels away inks what a short one across it does.
  InkCanvas far(30, 20), near(30, 20);
  far.line(-1e12, 7.3, 1e12, 12.1, 1.5, 0.8f);
  const double slope = (12.1 - 7.3) / 2e12;
  near.line(-5.0, 7.3 + slope * (1e12 - 5.0), 35.0, 7.3 + slope * (1e12 + 35.0), 1.5, 0.8f);
  CHECK(largest_difference(far.pixels(), near.pixels()) <= 1);
  InkCanvas empty(0, 0);
  empty.line(0, 0, 10, 10, 1.0, 1.f);
  CHECK(empty.pixels().empty());
}
