// Any view azimuth (SPEC 1.1): resampling onto a grid aligned with the line of sight.
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCell = 10.0;

// Ground coordinates (x east, y north) centred on an n x n DEM with 10 m cells.
GeoTransform centred(std::size_t n) {
  const double half = static_cast<double>(n) * kCell / 2;
  GeoTransform gt;
  gt.a = {-half, kCell, 0, half, 0, -kCell};
  return gt;
}

// A DEM sampled from f(x, y) in ground metres, centred.
template <typename F>
HeightGrid sample(std::size_t n, F f) {
  HeightGrid g(n, n);
  const double half = static_cast<double>(n) * kCell / 2;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c)
      g(r, c) = static_cast<float>(f((c + 0.5) * kCell - half, half - (r + 0.5) * kCell));
  return g;
}

// Hills inside a radius of 350 m, steep enough to occlude.
double hills(double x, double y) {
  const double centres[4][3] = {{-150, 80, 220}, {120, 150, 180}, {60, -160, 260}, {-90, -90, 150}};
  double z = 0;
  for (const auto& c : centres) {
    const double d2 = (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]);
    z += c[2] * std::exp(-d2 / (2 * 70.0 * 70.0));
  }
  return z;
}

struct Run {
  OrientedFrame frame;
  SilhouetteResult result;
};

Run run(const HeightGrid& dem, double azimuth, const GeoTransform& gt) {
  SilhouetteParams params;
  params.view.azimuth_deg = azimuth;
  Run r;
  r.frame = make_frame(dem.rows(), dem.cols(), kCell, kCell, azimuth);
  r.result = run_silhouettes(orient(dem, r.frame), r.frame, gt, ResolvedParams(params));
  return r;
}

std::vector<StrokePoint> factual_points(const SilhouetteResult& r) {
  std::vector<StrokePoint> points;
  for (const Stroke& s : r.strokes)
    if (s.cls == StrokeClass::factual)
      points.insert(points.end(), s.points.begin(), s.points.end());
  return points;
}

// Share of `a` within `tolerance` of some point of `b`.
double share_near(const std::vector<StrokePoint>& a, const std::vector<StrokePoint>& b,
                  double tolerance) {
  std::size_t near = 0;
  for (const StrokePoint& p : a) {
    for (const StrokePoint& q : b) {
      if (std::hypot(p.x - q.x, p.y - q.y) <= tolerance) {
        ++near;
        break;
      }
    }
  }
  return a.empty() ? 0.0 : static_cast<double>(near) / static_cast<double>(a.size());
}

}  // namespace

TEST_CASE("cardinal views take the exact path, others are resampled", "[azimuth]") {
  for (double az : {0.0, 90.0, 180.0, 270.0, 360.0, -90.0})
    CHECK_FALSE(make_frame(4, 6, 10, 10, az).resampled);
  for (double az : {30.0, 45.0, 90.5, 135.0, 359.0}) CHECK(make_frame(4, 6, 10, 10, az).resampled);
  CHECK_THROWS_AS(make_frame(4, 6, 10, 10, std::nan("")), Error);
}

TEST_CASE("a resampled grid far larger than the DEM is refused, not allocated", "[azimuth]") {
  // Found by the fuzzer: 0.01 m by 100 m cells resampled at 0.01 m spacing.
  CHECK_THROWS_WITH(make_frame(45, 2, 0.01, 100, 45), Catch::Contains("near-square cells"));
  CHECK_THROWS_WITH(make_frame(45, 2, 0.01, 100, 45),
                    Catch::StartsWith("seen at azimuth 45 this DEM would need"));
  // A one-row strip at 45 degrees stays allowed: its bounding square is small in absolute terms.
  CHECK(make_frame(1, 1000, 10, 10, 45).resampled);
}

TEST_CASE("the resampled grid steps by the spacing along and across the line of sight",
          "[azimuth]") {
  const double dx = 10, dy = 25;
  for (double az : {30.0, 45.0, 135.0, 200.0, 315.0}) {
    CAPTURE(az);
    const OrientedFrame f = make_frame(40, 30, dx, dy, az);
    CHECK(f.d == 10);
    CHECK(f.w == 10);
    const double theta = az * kPi / 180;
    const PixelPoint a = f.to_pixel(3, 4), along = f.to_pixel(3, 5), across = f.to_pixel(4, 4);
    // Pixel steps back to ground (east, north): forward is (sin, cos), right is (cos, -sin).
    CHECK((along.col - a.col) * dx == Approx(10 * std::sin(theta)).margin(1e-9));
    CHECK(-(along.row - a.row) * dy == Approx(10 * std::cos(theta)).margin(1e-9));
    CHECK((across.col - a.col) * dx == Approx(10 * std::cos(theta)).margin(1e-9));
    CHECK(-(across.row - a.row) * dy == Approx(-10 * std::sin(theta)).margin(1e-9));
    // The oriented grid covers the whole DEM: every DEM cell centre lies inside it.
    for (double col : {0.5, 29.5})
      for (double row : {0.5, 39.5}) {
        const double e = (col - f.px_col0) * dx, n = -(row - f.px_row0) * dy;
        const double along_m = e * std::sin(theta) + n * std::cos(theta);
        const double across_m = e * std::cos(theta) - n * std::sin(theta);
        CHECK(along_m / 10 >= -0.5 - 1e-9);
        CHECK(along_m / 10 <= f.length - 0.5 + 1e-9);
        CHECK(across_m / 10 >= -0.5 - 1e-9);
        CHECK(across_m / 10 <= f.profiles - 0.5 + 1e-9);
      }
  }
}

TEST_CASE("resampling at a cardinal azimuth reproduces the exact flip", "[azimuth]") {
  const HeightGrid dem = test::random_terrain(37, 52, 77, 0.02);
  for (double az : {0.0, 90.0, 180.0, 270.0}) {
    CAPTURE(az);
    const OrientedFrame exact = make_frame(37, 52, 10, 10, az);
    const OrientedFrame resampled = make_resampled_frame(37, 52, 10, 10, az);
    REQUIRE(resampled.profiles == exact.profiles);
    REQUIRE(resampled.length == exact.length);
    const HeightGrid a = orient(dem, exact), b = orient(dem, resampled);
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (!is_data(a.data()[k])) {
        REQUIRE_FALSE(is_data(b.data()[k]));
      } else {
        REQUIRE(b.data()[k] == Approx(a.data()[k]).margin(1e-3));
      }
    }
    const SilhouetteResult ra = run_silhouettes(a, exact, GeoTransform{}, {});
    const SilhouetteResult rb = run_silhouettes(b, resampled, GeoTransform{}, {});
    CHECK(ra.stats.occluding == rb.stats.occluding);
    CHECK(ra.strokes.size() == rb.strokes.size());
  }
}

TEST_CASE("bilinear sampling: exact at centres, nodata outside or next to nodata", "[azimuth]") {
  HeightGrid dem(2, 3);
  dem(0, 0) = 0, dem(0, 1) = 10, dem(0, 2) = 20, dem(1, 0) = 100, dem(1, 1) = 110,
         dem(1, 2) = kNoData;
  CHECK(sample_bilinear(dem, {0.5, 0.5}) == 0.f);
  CHECK(sample_bilinear(dem, {1.0, 0.5}) == Approx(5.0));
  CHECK(sample_bilinear(dem, {1.0, 1.0}) == Approx(55.0));
  CHECK(sample_bilinear(dem, {2.5, 0.5}) == Approx(20.0));  // far edge, zero weight on nodata
  CHECK_FALSE(is_data(sample_bilinear(dem, {2.0, 1.0})));   // touches the nodata cell
  CHECK_FALSE(is_data(sample_bilinear(dem, {0.2, 0.5})));   // outside the centres' hull
  HeightGrid one(1, 1, 7.f);
  CHECK(sample_bilinear(one, {0.5, 0.5}) == 7.f);
}

TEST_CASE("a line sampled by the vector loops is the bilinear sample at every position",
          "[azimuth]") {
  // Long lines through a DEM with nodata cells, in every direction and from off the DEM: the
  // vector loops (AVX2, and AVX-512 where the processor has it) against one sample at a time.
  HeightGrid dem = test::random_terrain(97, 131, 11, 0.3);
  for (std::size_t k = 0; k < 40; ++k) dem((k * 37) % 97, (k * 53) % 131) = kNoData;
  const std::size_t count = 260;
  std::vector<float> line(count);
  for (double az = 0.0; az < 360.0; az += 7.3) {
    for (const PixelPoint start : {PixelPoint{65.2, 48.7}, PixelPoint{-3.1, 10.4}}) {
      const double a = az * kPi / 180.0;
      const PixelPoint step{0.73 * std::sin(a), -0.73 * std::cos(a)};
      CAPTURE(az, start.col, start.row);
      sample_line(dem, start, step, count, line.data());
      for (std::size_t i = 0; i < count; ++i) {
        const auto s = static_cast<double>(i);
        const float expected =
            sample_bilinear(dem, {start.col + step.col * s, start.row + step.row * s});
        CAPTURE(i);
        REQUIRE(std::memcmp(&line[i], &expected, sizeof expected) == 0);
      }
    }
  }
}

TEST_CASE("the resampled grid is the bilinear sample at every position, margins included",
          "[azimuth]") {
  // orient() samples only where a profile can meet the DEM; the oracle samples every cell.
  HeightGrid dem = test::random_terrain(29, 41, 5, 0.1);
  dem(0, 0) = kNoData, dem(28, 40) = kNoData;
  for (double az : {0.0, 1e-7, 30.0, 45.0, 89.9999, 90.0, 135.0, 200.0, 300.0, 359.9}) {
    for (double dy : {10.0, 25.0}) {
      CAPTURE(az, dy);
      const OrientedFrame f = make_resampled_frame(29, 41, 10, dy, az);
      const HeightGrid z = orient(dem, f);
      for (std::size_t p = 0; p < f.profiles; ++p) {
        for (std::size_t i = 0; i < f.length; ++i) {
          const float expected =
              sample_bilinear(dem, f.to_pixel(static_cast<double>(p), static_cast<double>(i)));
          CAPTURE(p, i);
          if (is_data(expected)) {
            REQUIRE(z(p, i) == expected);
          } else {
            REQUIRE_FALSE(is_data(z(p, i)));
          }
        }
      }
    }
  }
}

TEST_CASE("a DEM turned by 30 degrees with the view turned too gives the same strokes",
          "[azimuth][invariance]") {
  const std::size_t n = 90;
  const double alpha = 30 * kPi / 180;
  // B(q) = A(M q) with M turning counter-clockwise by alpha: a viewer of A facing azimuth az
  // sees in B the same terrain facing az + 30, and B's point q is A's point M q.
  const HeightGrid a = sample(n, hills);
  const HeightGrid b = sample(n, [&](double x, double y) {
    return hills(x * std::cos(alpha) - y * std::sin(alpha),
                 x * std::sin(alpha) + y * std::cos(alpha));
  });
  const GeoTransform gt = centred(n);
  for (double az : {90.0, 60.0, 200.0}) {
    CAPTURE(az);
    const auto pa = factual_points(run(a, az, gt).result);
    auto pb = factual_points(run(b, az + 30, gt).result);
    for (StrokePoint& q : pb) {
      q = {q.x * std::cos(alpha) - q.y * std::sin(alpha),
           q.x * std::sin(alpha) + q.y * std::cos(alpha)};
    }
    REQUIRE(pa.size() > 50);
    CHECK(static_cast<double>(pb.size()) == Approx(static_cast<double>(pa.size())).epsilon(0.15));
    // Within a cell and a half (resampling moves points by up to a cell): nearly all of them.
    CHECK(share_near(pa, pb, 1.5 * kCell) > 0.9);
    CHECK(share_near(pb, pa, 1.5 * kCell) > 0.9);
  }
}

TEST_CASE("a steep cone occludes where theory says at 45 and 135 degrees", "[azimuth][analytic]") {
  // Cone of slope s: on the line at lateral offset y from the apex, the transformed profile peaks
  // where ve s x / r = B: forward x* = |y| k / sqrt(1 - k^2), k = B / (ve s).
  const std::size_t n = 101;
  const double s = 0.5, k = 0.4 / (2.5 * s);
  const HeightGrid cone =
      sample(n, [&](double x, double y) { return std::max(0.0, 400 - s * std::hypot(x, y)); });
  const GeoTransform gt = centred(n);
  for (double az : {45.0, 135.0, 90.0, 300.0}) {
    CAPTURE(az);
    const Run r = run(cone, az, gt);
    const double theta = az * kPi / 180;
    int checked = 0;
    for (std::size_t p = 0; p < r.frame.profiles; ++p)
      for (std::size_t i = 0; i < r.frame.length; ++i) {
        if (!(r.result.flags(p, i) & cell::occluding)) continue;
        double x, y;
        gt.apply(r.frame.to_pixel(static_cast<double>(p), static_cast<double>(i)), x, y);
        const double forward = x * std::sin(theta) + y * std::cos(theta);
        const double lateral = x * std::cos(theta) - y * std::sin(theta);
        if (std::fabs(lateral) > 200) continue;  // well inside the cone's foot (800 m radius)
        CAPTURE(p, i, forward, lateral);
        CHECK(std::fabs(forward - std::fabs(lateral) * k / std::sqrt(1 - k * k)) <= 1.5 * kCell);
        ++checked;
      }
    CHECK(checked >= 30);
  }
}

TEST_CASE("a Gaussian bump occludes only on its far side at 45 and 135 degrees",
          "[azimuth][analytic]") {
  const std::size_t n = 81;
  const HeightGrid bump = sample(
      n, [](double x, double y) { return 250 * std::exp(-(x * x + y * y) / (2 * 90.0 * 90.0)); });
  const GeoTransform gt = centred(n);
  for (double az : {45.0, 135.0}) {
    CAPTURE(az);
    const Run r = run(bump, az, gt);
    REQUIRE(r.result.stats.factual_strokes >= 1);
    const double theta = az * kPi / 180;
    for (const Stroke& st : r.result.strokes) {
      if (st.cls != StrokeClass::factual) continue;
      for (const StrokePoint& pt : st.points) {
        CHECK(pt.x * std::sin(theta) + pt.y * std::cos(theta) > 0);  // beyond the summit
      }
    }
  }
}

TEST_CASE("resampling strip by strip gives the strokes of the whole resampled grid",
          "[azimuth][strips]") {
  // Over 1024 profiles at these azimuths: the view is resampled in three strips or more.
  const HeightGrid dem = test::random_terrain(800, 760, 5, 0.03);
  const GeoTransform gt = centred(800);
  for (double az : {30.0, 300.0}) {
    for (Geometry geometry : {Geometry::map, Geometry::oblique}) {
      CAPTURE(az, static_cast<int>(geometry));
      SilhouetteParams params;
      params.view.azimuth_deg = az;
      params.geometry = geometry;
      params.subcell = true;
      const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), kCell, kCell, az);
      REQUIRE(frame.profiles > 1024);
      // The whole grid at once, with the DEM's lowest height as the plan-oblique reference.
      SilhouetteStream whole_stream(frame, gt, ResolvedParams(params), lowest_height(dem));
      whole_stream.add_strip(orient(dem, frame), 0, frame.profiles);
      const SilhouetteResult whole = whole_stream.finish();
      const SilhouetteResult strips = run_resampled_silhouettes(dem, frame, gt, params);
      CHECK(strips.stats.valid == whole.stats.valid);
      CHECK(strips.stats.hidden == whole.stats.hidden);
      CHECK(strips.stats.thinned == whole.stats.thinned);
      CHECK(strips.stats.generalised == whole.stats.generalised);
      REQUIRE(whole.strokes.size() > 100);
      test::require_same_strokes(whole, strips);
      CHECK(strips.timings.resampling > 0);
    }
  }
  const OrientedFrame cardinal = make_frame(dem.rows(), dem.cols(), kCell, kCell, 90);
  CHECK_THROWS_AS(run_resampled_silhouettes(dem, cardinal, gt, {}), Error);
}

namespace {

// Reads windows of `dem` as a raster adapter would, refusing any window outside it and logging
// the cells read.
WindowReader window_reader(const HeightGrid& dem, std::size_t* cells_read = nullptr) {
  return [&dem, cells_read](const DemWindow& w, float* out) {
    REQUIRE(w.rows > 0);
    REQUIRE(w.cols > 0);
    REQUIRE(w.row0 + w.rows <= dem.rows());
    REQUIRE(w.col0 + w.cols <= dem.cols());
    for (std::size_t r = 0; r < w.rows; ++r)
      std::copy(dem.row(w.row0 + r) + w.col0, dem.row(w.row0 + r) + w.col0 + w.cols,
                out + r * w.cols);
    if (cells_read) *cells_read += w.rows * w.cols;
  };
}

bool same_bits(const HeightGrid& a, const HeightGrid& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("a strip resampled from its band equals the strip resampled from the whole DEM",
          "[azimuth][strips]") {
  // Any cell the samples need but the band lacks shows as a different height (or, under the
  // sanitizers, as a read outside the band).
  const std::pair<std::size_t, std::size_t> shapes[] = {{1, 1}, {1, 13},  {13, 1},
                                                        {2, 2}, {37, 53}, {120, 90}};
  for (const auto& shape : shapes) {
    HeightGrid dem = test::random_terrain(shape.first, shape.second, 11, 0.05);
    for (double az : {1.0, 30.0, 45.0, 89.5, 133.7, 180.2, 225.0, 291.0, 359.9}) {
      for (double dy : {10.0, 17.0}) {
        const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), 10, dy, az);
        for (std::size_t width :
             {std::size_t{1}, std::size_t{5}, std::size_t{64}, frame.profiles}) {
          CAPTURE(shape.first, shape.second, az, dy, width);
          DemBand band;
          HeightGrid expected, actual;
          for (std::size_t first = 0; first < frame.profiles; first += width) {
            const std::size_t count = std::min(width, frame.profiles - first);
            resample_profiles(dem, frame, first, count, expected);
            band.load(frame, first, count, window_reader(dem));
            resample_profiles(band, frame, first, count, actual);
            CAPTURE(first);
            REQUIRE(same_bits(expected, actual));
          }
        }
      }
    }
  }
}

TEST_CASE("the band of a diagonal strip holds about the strip's cells, not its bounding box",
          "[azimuth][strips]") {
  const HeightGrid dem = test::random_terrain(400, 400, 3);
  const OrientedFrame frame = make_frame(400, 400, 10, 10, 45);
  const std::size_t count = 40;
  const std::size_t first = frame.profiles / 2 - count / 2;  // across the DEM's diagonal
  DemBand band;
  std::size_t cells_read = 0;
  band.load(frame, first, count, window_reader(dem, &cells_read));
  // The strip's footprint is count x length cells; the band adds a margin of a few cells a row,
  // and rows read together hold the columns of each other's runs, at most an eighth more.
  CHECK(band.rows() == 400);
  CHECK(band.cells() <= (count * frame.length + 10 * band.rows()) * 9 / 8);
  CHECK(band.cells() < dem.size() / 4);
  // Rows are read in chunks spanning their runs, straight into the band: each cell once.
  CHECK(cells_read == band.cells());
  // A second strip reuses the layout's memory and gives its own heights.
  HeightGrid expected, actual;
  band.load(frame, 0, 3, window_reader(dem));
  resample_profiles(dem, frame, 0, 3, expected);
  resample_profiles(band, frame, 0, 3, actual);
  CHECK(same_bits(expected, actual));
  CHECK_THROWS_AS(resample_profiles(band, frame, 2, 3, actual), Error);  // not its profiles
  CHECK_THROWS_AS(band.load(make_frame(400, 400, 10, 10, 90), 0, 3, window_reader(dem)), Error);
  CHECK_THROWS_AS(band.load(frame, frame.profiles - 1, 2, window_reader(dem)), Error);
}

TEST_CASE("a DEM read window by window in strips gives the strokes of the one-piece run",
          "[azimuth][strips]") {
  const HeightGrid dem = test::random_terrain(300, 260, 9, 0.01);
  const GeoTransform gt = centred(300);
  for (double az : {90.0, 180.0, 45.0, 200.0}) {
    SilhouetteParams params;
    params.view.azimuth_deg = az;
    params.geometry = Geometry::oblique;
    params.subcell = true;
    const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), kCell, kCell, az);
    const SilhouetteResult whole =
        frame.resampled ? run_resampled_silhouettes(dem, frame, gt, params)
                        : run_silhouettes(orient(dem, frame), frame, gt, ResolvedParams(params));
    REQUIRE(whole.strokes.size() > 20);
    for (std::size_t width : {std::size_t{16}, std::size_t{100}}) {
      CAPTURE(az, width);
      StripLoader loader(frame, window_reader(dem), params.threads);
      const SilhouetteResult strips =
          run_in_strips(frame, gt, ResolvedParams(params), lowest_height(dem), width,
                        [&loader](std::size_t first, std::size_t count, HeightGrid& strip) {
                          loader.load(first, count, strip);
                        });
      CHECK(strips.stats.valid == whole.stats.valid);
      CHECK(strips.stats.thinned == whole.stats.thinned);
      test::require_same_strokes(whole, strips);
    }
  }
}

TEST_CASE("a reader's error reaches the caller of a strip load", "[azimuth][strips]") {
  const OrientedFrame frame = make_frame(50, 50, 10, 10, 45);
  StripLoader loader(frame, [](const DemWindow&, float*) { throw Error("disk gone"); });
  HeightGrid strip;
  CHECK_THROWS_WITH(loader.load(0, 10, strip), "disk gone");
}

TEST_CASE("the lowest height read window by window is the one read whole, infinities aside",
          "[azimuth][strips]") {
  HeightGrid dem = test::random_terrain(70, 9, 6, 0.05);
  dem(3, 3) = -std::numeric_limits<float>::infinity();
  dem(60, 2) = std::numeric_limits<float>::infinity();
  const OrientedFrame frame = make_frame(70, 9, 10, 10, 45);
  OrientedGridBuilder builder(frame);
  builder.add_rows(0, 70, dem.data());
  std::size_t cells_read = 0;
  CHECK(dem_lowest_height(70, 9, window_reader(dem, &cells_read)) == builder.dem_lowest_height());
  CHECK(cells_read == dem.size());
  CHECK(std::isfinite(builder.dem_lowest_height()));
  CHECK(dem_lowest_height(70, 9, window_reader(HeightGrid(70, 9, kNoData))) == 0.0);
}
