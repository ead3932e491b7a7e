#include <vector>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

// Classifies one profile given as a vector of heights.
std::vector<std::uint8_t> classify(const std::vector<float>& z, double d, const ViewParams& view) {
  std::vector<std::uint8_t> flags(z.size(), 0);
  classify_profile_visibility(z.data(), flags.data(), z.size(), d, view);
  return flags;
}

// The oracle: every cell checked against every valid cell in front of it.
std::vector<std::uint8_t> brute_force(const std::vector<float>& z, double d,
                                      const ViewParams& view) {
  const std::size_t n = z.size();
  std::vector<std::uint8_t> flags(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_data(z[i])) continue;
    flags[i] = cell::valid;
    for (std::size_t j = 0; j < i; ++j) {
      if (is_data(z[j]) &&
          transformed_height(z[j], j, d, view) > transformed_height(z[i], i, d, view)) {
        flags[i] |= cell::hidden;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!(flags[i] & cell::valid) || (flags[i] & cell::hidden)) continue;
    std::size_t next = i + 1;
    while (next < n && !(flags[next] & cell::valid)) ++next;
    if (next < n && (flags[next] & cell::hidden)) flags[i] |= cell::occluding;
  }
  return flags;
}

}  // namespace

TEST_CASE("a plane rising away from the viewer hides nothing", "[visibility]") {
  const ViewParams view;
  std::vector<float> z;
  for (int i = 0; i < 50; ++i) z.push_back(100.f + 2.f * i);
  for (std::uint8_t f : classify(z, 10, view)) CHECK(f == cell::valid);
}

TEST_CASE("a plane falling away faster than the base slope hides all but its first cell",
          "[visibility]") {
  ViewParams view;
  view.ve = 1.0;
  // Falls 50 % per cell of 10 m: t = -5 i + 4 i decreases.
  std::vector<float> z;
  for (int i = 0; i < 20; ++i) z.push_back(100.f - 5.f * i);
  const auto flags = classify(z, 10, view);
  CHECK(flags[0] == (cell::valid | cell::occluding));
  for (std::size_t i = 1; i < flags.size(); ++i) CHECK(flags[i] == (cell::valid | cell::hidden));
  const HiddenZone zone = hidden_zone(z.data(), flags.data(), z.size(), 0, 10, view);
  CHECK(zone.last == 19);
  CHECK(zone.hidden_cells == 19);
  CHECK(zone.depth_m == Approx(19.0));  // t = 100 - i: the last cell is 19 m below the first
}

TEST_CASE("a cliff seen from above hides a zone of computable length and depth", "[visibility]") {
  // 10 m cliff top at cell 4, then flat ground 10 m lower; d = 5 m, ve 2.5, B 40 %.
  // Behind the top, t_j = B d j stays below ve h + B d 4 while j < 4 + ve h / (B d) = 16.5.
  const ViewParams view;
  std::vector<float> z(40, 0.f);
  for (int i = 0; i <= 4; ++i) z[static_cast<std::size_t>(i)] = 10.f;
  const auto flags = classify(z, 5, view);
  for (std::size_t i = 0; i < z.size(); ++i) {
    CAPTURE(i);
    CHECK(bool(flags[i] & cell::hidden) == (i >= 5 && i <= 16));
    CHECK(bool(flags[i] & cell::occluding) == (i == 4));
  }
  const HiddenZone zone = hidden_zone(z.data(), flags.data(), z.size(), 4, 5, view);
  CHECK(zone.last == 16);
  CHECK(zone.hidden_cells == 12);
  // Deepest right behind the edge: (ve h - B d) / ve = (25 - 2) / 2.5.
  CHECK(zone.depth_m == Approx(9.2));
}

TEST_CASE("equal transformed height is visible", "[visibility]") {
  ViewParams view;
  view.ve = 1.0;
  view.base_slope_pct = 50.0;
  // Each cell drops exactly B d = 5 m: t stays constant, so nothing is hidden.
  const std::vector<float> z = {100, 95, 90, 85};
  for (std::uint8_t f : classify(z, 10, view)) CHECK(f == cell::valid);
}

TEST_CASE("the running maximum carries over nodata and the occluder skips it", "[visibility]") {
  ViewParams view;
  view.ve = 1.0;
  const float nan = kNoData;
  const std::vector<float> z = {100, nan, nan, 0, 0, 200, 0};
  const auto flags = classify(z, 10, view);
  CHECK(flags[0] == (cell::valid | cell::occluding));  // next valid cell (3) is hidden
  CHECK(flags[1] == 0);
  CHECK(flags[2] == 0);
  CHECK(flags[3] == (cell::valid | cell::hidden));
  CHECK(flags[5] == (cell::valid | cell::occluding));
  CHECK(flags[6] == (cell::valid | cell::hidden));
  const HiddenZone zone = hidden_zone(z.data(), flags.data(), z.size(), 0, 10, view);
  CHECK(zone.last == 4);
  CHECK(zone.hidden_cells == 2);
}

TEST_CASE("the fast pass agrees with the brute-force oracle on random profiles",
          "[visibility][oracle]") {
  std::mt19937 seeds(20261122);
  for (int round = 0; round < 300; ++round) {
    const std::uint32_t seed = seeds();
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> height(-50.f, 150.f);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t n = 1 + rng() % 80;
    const double holes = unit(rng) * 0.4;
    std::vector<float> z(n);
    for (float& v : z) v = unit(rng) < holes ? kNoData : height(rng);
    if (round % 7 == 0) z[rng() % n] = std::numeric_limits<float>::infinity();
    ViewParams view;
    view.ve = 0.5 + 3 * unit(rng);
    view.base_slope_pct = 5 + 100 * unit(rng);
    const double d = 1 + 50 * unit(rng);
    REQUIRE(classify(z, d, view) == brute_force(z, d, view));
  }
}

TEST_CASE("whole-grid visibility equals the per-profile pass on every profile", "[visibility]") {
  const HeightGrid z = test::random_terrain(40, 60, 7, 0.05);
  const ViewParams view;
  CellFlags flags;
  classify_visibility(z, 10, view, flags, 2);
  for (std::size_t p = 0; p < z.rows(); ++p) {
    std::vector<float> row(z.row(p), z.row(p) + z.cols());
    const auto expected = brute_force(row, 10, view);
    REQUIRE(std::equal(expected.begin(), expected.end(), flags.row(p)));
  }
}
