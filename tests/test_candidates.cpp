#include <limits>
#include <vector>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

CellFlags candidates_of(const HeightGrid& dem, double azimuth, double cell,
                        const ViewParams& view) {
  const OrientedFrame f = make_frame(dem.rows(), dem.cols(), cell, cell, azimuth);
  const HeightGrid z = orient(dem, f);
  CellFlags flags;
  classify_visibility(z, f.d, view, flags);
  select_candidates(z, f.d, view, flags);
  return flags;
}

}  // namespace

TEST_CASE("column slope is a forward difference, undefined at the end and next to nodata",
          "[candidates]") {
  const float z[] = {10, 12, kNoData, 5};
  CHECK(column_slope(z, 4, 0, 10) == Approx(0.2));
  CHECK(std::isnan(column_slope(z, 4, 1, 10)));
  CHECK(std::isnan(column_slope(z, 4, 2, 10)));
  CHECK(std::isnan(column_slope(z, 4, 3, 10)));
}

TEST_CASE("the c-set bound is strict and uses the exaggerated slope", "[candidates]") {
  const ViewParams view;  // ve 2.5, B 40 %: candidates have -0.16 < gc < 0
  CHECK(is_candidate_slope(-0.1, view));
  CHECK(is_candidate_slope(-0.159, view));
  CHECK_FALSE(is_candidate_slope(-0.16, view));
  CHECK_FALSE(is_candidate_slope(-0.2, view));
  CHECK_FALSE(is_candidate_slope(0.0, view));
  CHECK_FALSE(is_candidate_slope(0.1, view));
  CHECK_FALSE(is_candidate_slope(std::nan(""), view));
}

TEST_CASE("a gentle ridge seen from the west: its whole back slope is the c-set", "[candidates]") {
  // Ridge along the centre column 30, 20 m high, 10 % slopes, 10 m cells: the east slope runs
  // from column 30 to the foot at column 50. ve 0.1 * 2.5 = 0.25 < B 0.4: brought into view.
  const HeightGrid dem = make_ridge(9, 61, 10, 20, 0.1);
  const ViewParams view;
  const CellFlags flags = candidates_of(dem, 90, 10, view);
  for (std::size_t p = 0; p < flags.rows(); ++p)
    for (std::size_t i = 0; i < flags.cols(); ++i) {
      CAPTURE(p, i);
      REQUIRE(bool(flags(p, i) & cell::candidate) == (i >= 30 && i < 50));
      REQUIRE_FALSE(flags(p, i) & cell::hidden);
    }
  // Seen from the east the same ridge gives the mirror image: oriented cell i is column 60 - i.
  const CellFlags east = candidates_of(dem, 270, 10, view);
  for (std::size_t i = 0; i < east.cols(); ++i) {
    CAPTURE(i);
    REQUIRE(bool(east(4, i) & cell::candidate) == (i >= 30 && i < 50));
  }
}

TEST_CASE("a steep ridge occludes instead: no c-set, a hidden back slope", "[candidates]") {
  // 30 % slopes: ve * 0.3 = 0.75 > B 0.4.
  const HeightGrid dem = make_ridge(5, 41, 10, 30, 0.3);
  const ViewParams view;
  const CellFlags flags = candidates_of(dem, 90, 10, view);
  for (std::size_t i = 0; i < flags.cols(); ++i) {
    CAPTURE(i);
    CHECK_FALSE(flags(2, i) & cell::candidate);
    CHECK(bool(flags(2, i) & cell::occluding) == (i == 20));
  }
  CHECK(flags(2, 21) & cell::hidden);
}

TEST_CASE("the c-set of a profile is the rule cell by cell, nodata and infinities included",
          "[candidates][oracle]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const float odd[] = {kNoData, std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::max(),
                       -std::numeric_limits<float>::max()};
  for (int round = 0; round < 200; ++round) {
    const std::size_t length = 1 + rng() % 70;
    ViewParams view;
    view.ve = 0.5 + 4 * u(rng);
    view.base_slope_pct = 5 + 80 * u(rng);
    const double d = 1 + 30 * u(rng);
    std::vector<float> z(length);
    for (float& h : z) {
      h = u(rng) < 0.15 ? odd[rng() % 5] : static_cast<float>(100 + 10 * u(rng));
    }
    std::vector<std::uint8_t> flags(length, 0);
    select_profile_candidates(z.data(), flags.data(), length, d, view);
    for (std::size_t i = 0; i < length; ++i) {
      INFO("round " << round << ", cell " << i);
      REQUIRE(static_cast<bool>(flags[i] & cell::candidate) ==
              is_candidate_slope(column_slope(z.data(), length, i, d), view));
    }
  }
}
