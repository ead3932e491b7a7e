// The notes on a DEM that both front ends word (io/dem_notes.h), on facts with known answers.
#include <algorithm>
#include <cmath>
#include <limits>

#include "catch_compat.h"
#include "io/read/dem_notes.h"

using namespace tsk::io;

namespace {

// A 100 x 200 DEM of 30 m cells in UTM 16N, heights 200 to 600 m.
DemFacts utm_facts() {
  DemFacts f;
  f.rows = 100, f.cols = 200, f.cell_x = 30, f.cell_y = 30;
  f.west = 731000, f.north = 4040000;
  f.has_crs = true, f.crs_id = "EPSG:32616";
  f.proj = "+proj=utm +zone=16 +datum=WGS84 +units=m +no_defs";
  f.has_centre = true, f.centre_lon = -84.1, f.centre_lat = 36.3;
  f.has_range = true, f.lowest_value = 200, f.highest_value = 600;
  return f;
}

bool has(const DemAssessment& a, DemNoteCode code) {
  return std::any_of(a.notes.begin(), a.notes.end(),
                     [code](const DemNote& n) { return n.code == code; });
}

}  // namespace

TEST_CASE("a projected metric DEM gets no notes and its cells stay as they are", "[io][notes]") {
  const DemAssessment a = assess_dem(utm_facts());
  CHECK_FALSE(a.refused);
  CHECK(a.notes.empty());
  CHECK(a.ground_scale == 1.0);
}

TEST_CASE("a geographic DEM is refused with the UTM zone of its centre", "[io][notes]") {
  DemFacts f = utm_facts();
  f.geographic = true, f.crs_id = "EPSG:4326", f.proj = "+proj=longlat +datum=WGS84";
  const DemAssessment a = assess_dem(f);
  REQUIRE(a.refused);
  REQUIRE(a.notes.front().code == DemNoteCode::geographic_crs);
  CHECK(a.notes.front().numbers.at(0) == 32616);  // 84.1 W: zone 16, north
  CHECK(a.notes.front().text == "EPSG:4326");
  const auto zone_of = [&f](double lon, double lat) {
    f.centre_lon = lon, f.centre_lat = lat;
    return assess_dem(f).notes.front().numbers.at(0);
  };
  CHECK(zone_of(151.2, -33.9) == 32756);  // Sydney: zone 56, south
  CHECK(zone_of(-180, 0) == 32601);
  CHECK(zone_of(180, 0) == 32660);
}

TEST_CASE("a DEM whose coordinates cannot tell its cells apart is refused", "[io][notes]") {
  const auto refusal = [](double west, double north, double cell) {
    DemFacts f = utm_facts();
    f.west = west, f.north = north, f.cell_x = f.cell_y = cell;
    return assess_dem(f);
  };
  // Doubles near 1e14 are 1/64 apart, a two-thousandth of a 30 m cell: still told apart. Near
  // 1e16 they are 2 apart; at 1e300 a whole DEM is one number.
  CHECK_FALSE(refusal(-1e14, 1e14, 30).refused);
  CHECK_FALSE(refusal(0, 0, 1e-6).refused);  // a micrometre grid at the origin
  for (const double far : {1e16, -1e16, 1e300}) {
    const DemAssessment a = refusal(731000, far, 30);
    REQUIRE(a.refused);
    REQUIRE(a.notes.size() == 1);
    CHECK(a.notes.front().code == DemNoteCode::too_far);
    CHECK(a.notes.front().numbers.at(0) == Approx(std::fabs(far)));
    CHECK(a.notes.front().numbers.at(1) == 30);
  }
  // Cells of 1e-300 m near a UTM origin; a corner not a number; cells so large that the far
  // corner overflows.
  CHECK(refusal(731000, 4040000, 1e-300).refused);
  const DemAssessment nan_corner = refusal(std::nan(""), 4040000, 30);
  REQUIRE(nan_corner.refused);
  CHECK(std::isnan(nan_corner.notes.front().numbers.at(0)));
  const DemAssessment overflow = refusal(0, 0, 1e307);
  REQUIRE(overflow.refused);
  CHECK(std::isinf(overflow.notes.front().numbers.at(0)));
  // Before the CRS's checks: a geographic DEM far out is refused for its coordinates.
  DemFacts geographic = utm_facts();
  geographic.geographic = true, geographic.north = 1e300;
  CHECK(assess_dem(geographic).notes.front().code == DemNoteCode::too_far);
}

TEST_CASE("a Mercator DEM's cells are scaled by the cosine of its centre's latitude",
          "[io][notes]") {
  DemFacts f = utm_facts();
  f.proj = "+proj=merc +a=6378137 +b=6378137 +lat_ts=0 +lon_0=0 +units=m +nadgrids=@null";
  f.centre_lat = 60;
  const DemAssessment a = assess_dem(f);
  CHECK(a.ground_scale == Approx(0.5));
  CHECK(has(a, DemNoteCode::mercator_scaled));
  // Transverse Mercator (UTM) keeps its metres; an unknown centre leaves the cells unscaled.
  f.proj = "+proj=tmerc +lat_0=0 +lon_0=9 +k=0.9996 +x_0=500000 +units=m";
  CHECK(assess_dem(f).ground_scale == 1.0);
  f.proj = "+proj=merc +lon_0=0";
  f.has_centre = false;
  CHECK(assess_dem(f).ground_scale == 1.0);
}

TEST_CASE("units, bands, fill values, relief and scales each get their note", "[io][notes]") {
  DemFacts f = utm_facts();
  f.has_crs = false;
  CHECK(has(assess_dem(f), DemNoteCode::no_crs));
  f = utm_facts();
  f.unit_is_metre = false, f.unit = "US survey foot";
  CHECK(has(assess_dem(f), DemNoteCode::unit_not_metre));
  f = utm_facts();
  f.bands = 3, f.band = 2;
  const DemAssessment bands = assess_dem(f);
  REQUIRE(has(bands, DemNoteCode::several_bands));
  CHECK(bands.notes.front().numbers == std::vector<double>{3, 2});
  for (double fill : {-9999.0, -32767.0, -32768.0, -99999.0}) {
    f = utm_facts();
    f.lowest_value = fill;
    CAPTURE(fill);
    CHECK(has(assess_dem(f), DemNoteCode::fill_value));
    CHECK_FALSE(has(assess_dem(f), DemNoteCode::implausible_relief));
  }
  // QGIS's statistics of a band without a valid cell: least +DBL_MAX, greatest -DBL_MAX.
  f = utm_facts();
  f.lowest_value = std::numeric_limits<double>::max();
  f.highest_value = -std::numeric_limits<double>::max();
  CHECK(assess_dem(f).notes.empty());
  // Float's fill values, lowest or highest, are read as nodata, and told so; the highest used to
  // be told as an implausible relief at most.
  for (double fill : {3.4028234663852886e38, -3.4e38, 1e30, -1e30}) {
    f = utm_facts();
    (fill > 0 ? f.highest_value : f.lowest_value) = fill;
    CAPTURE(fill);
    const DemAssessment a = assess_dem(f);
    REQUIRE(has(a, DemNoteCode::fill_taken));
    CHECK(a.notes.back().numbers == std::vector<double>{fill});
    CHECK_FALSE(has(a, DemNoteCode::fill_value));
    CHECK_FALSE(has(a, DemNoteCode::implausible_relief));
  }
  // 200 x 30 m = 6 km across: a relief over 30 km is no terrain's.
  f = utm_facts();
  f.highest_value = 200 + 30001;
  CHECK(has(assess_dem(f), DemNoteCode::implausible_relief));
  f.scale = 0.001;  // millimetres: 30 m of relief
  const DemAssessment scaled = assess_dem(f);
  CHECK_FALSE(has(scaled, DemNoteCode::implausible_relief));
  CHECK(has(scaled, DemNoteCode::scaled_values));
  f = utm_facts();
  f.highest_value = 200 + 29999;
  CHECK_FALSE(has(assess_dem(f), DemNoteCode::implausible_relief));
}
