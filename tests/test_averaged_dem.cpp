// A sketch drawn for a scale far coarser than its DEM is drawn from the DEM averaged to that
// scale's cells (issue 31, item 7): the averaging against a brute-force one written here, and the
// same sketch from a DEM and from the same DEM averaged beforehand.
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "catch_compat.h"
#include "core/drawn/drawing_scale.h"
#include "core/method/averaged_dem.h"
#include "core/method/silhouettes.h"
#include "test_support.h"

using namespace tsk;
using tsk::test::random_terrain;

namespace {

// A DEM held in memory, read window by window as the front ends read files; its cells `cell`
// map units a side, north up.
DemSource memory_source(const HeightGrid& dem, double cell) {
  GeoTransform gt;
  gt.a = {1000.0, cell, 0.0, 9000.0, 0.0, -cell};
  return {DemGrid{dem.rows(), dem.cols(), cell, cell}, gt, [&dem](const DemWindow& w, float* out) {
            REQUIRE(w.row0 + w.rows <= dem.rows());
            REQUIRE(w.col0 + w.cols <= dem.cols());
            for (std::size_t r = 0; r < w.rows; ++r)
              for (std::size_t c = 0; c < w.cols; ++c)
                out[r * w.cols + c] = dem(w.row0 + r, w.col0 + c);
          }};
}

// Each k x k block's cells with data, summed row by row and averaged; NaN where none has data.
HeightGrid averaged_by_hand(const HeightGrid& dem, std::size_t k) {
  HeightGrid out((dem.rows() + k - 1) / k, (dem.cols() + k - 1) / k);
  for (std::size_t R = 0; R < out.rows(); ++R) {
    for (std::size_t C = 0; C < out.cols(); ++C) {
      double sum = 0.0;
      int count = 0;
      for (std::size_t r = R * k; r < std::min(dem.rows(), (R + 1) * k); ++r) {
        for (std::size_t c = C * k; c < std::min(dem.cols(), (C + 1) * k); ++c) {
          if (std::isnan(dem(r, c))) continue;
          sum += static_cast<double>(dem(r, c));
          ++count;
        }
      }
      out(R, C) = count ? static_cast<float>(sum / count) : kNoData;
    }
  }
  return out;
}

// A DEM held in memory that counts how often each cell is read, and through which of its two
// readers: for reads from two threads (no Catch assertions inside, which are not thread-safe).
struct CountedSource {
  CountedSource(const HeightGrid& heights, double side)
      : dem(heights), reads(heights.rows() * heights.cols()), cell(side) {}
  WindowReader reader(int which) {
    return [this, which](const DemWindow& w, float* out) {
      if (w.row0 + w.rows > dem.rows() || w.col0 + w.cols > dem.cols())
        throw std::out_of_range("a window beyond the DEM");
      ++through[which];
      for (std::size_t r = 0; r < w.rows; ++r) {
        for (std::size_t c = 0; c < w.cols; ++c) {
          out[r * w.cols + c] = dem(w.row0 + r, w.col0 + c);
          ++reads[(w.row0 + r) * dem.cols() + w.col0 + c];
        }
      }
    };
  }
  DemSource source(bool two_readers) {
    GeoTransform gt;
    gt.a = {1000.0, cell, 0.0, 9000.0, 0.0, -cell};
    return {DemGrid{dem.rows(), dem.cols(), cell, cell}, gt, reader(0),
            two_readers ? reader(1) : WindowReader()};
  }
  // The cells not read exactly once.
  std::size_t misread() const {
    std::size_t n = 0;
    for (const std::atomic<int>& count : reads) n += count != 1;
    return n;
  }
  const HeightGrid& dem;
  std::vector<std::atomic<int>> reads;
  std::atomic<int> through[2] = {0, 0};
  double cell;
};

bool same_height(float a, float b) {
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

}  // namespace

TEST_CASE("an averaged DEM reads as the mean of each block's cells with data", "[averaged]") {
  // 103 x 70 cells: partial blocks at the south and east edges, and holes of nodata (one block
  // of 3 x 3 without any data).
  HeightGrid dem = random_terrain(103, 70, 5, 0.2);
  for (std::size_t r = 30; r < 33; ++r)
    for (std::size_t c = 9; c < 12; ++c) dem(r, c) = kNoData;
  const DemSource source = memory_source(dem, 10.0);
  for (const std::size_t k : {2, 3, 7}) {
    const HeightGrid expected = averaged_by_hand(dem, k);
    const DemSource coarse = averaged_dem(source, k);
    CHECK(coarse.grid.rows == expected.rows());
    CHECK(coarse.grid.cols == expected.cols());
    CHECK(coarse.grid.dx == Approx(10.0 * static_cast<double>(k)));
    CHECK(coarse.geotransform.a[0] == 1000.0);
    CHECK(coarse.geotransform.a[1] == Approx(10.0 * static_cast<double>(k)));
    CHECK(coarse.geotransform.a[5] == Approx(-10.0 * static_cast<double>(k)));
    // Whole, and in windows that start and end anywhere.
    const std::vector<DemWindow> windows = {{0, 0, expected.rows(), expected.cols()},
                                            {1, 2, 3, 4},
                                            {expected.rows() - 2, expected.cols() - 3, 2, 3}};
    for (const DemWindow& w : windows) {
      std::vector<float> got(w.rows * w.cols);
      coarse.read(w, got.data());
      int differ = 0;
      for (std::size_t r = 0; r < w.rows; ++r)
        for (std::size_t c = 0; c < w.cols; ++c)
          differ += !same_height(got[r * w.cols + c], expected(w.row0 + r, w.col0 + c));
      CHECK(differ == 0);
    }
    std::vector<float> one(1);
    CHECK_THROWS_WITH(coarse.read({expected.rows(), 0, 1, 1}, one.data()),
                      Catch::Contains("does not lie in the averaged DEM"));
  }
  std::vector<float> hole(1);
  averaged_dem(source, 3).read({10, 3, 1, 1}, hole.data());  // rows 30-32, columns 9-11
  CHECK(std::isnan(hole[0]));
  CHECK_THROWS_WITH(averaged_dem(source, 0), Catch::Contains("factor of 0"));
}

TEST_CASE("drawn for a scale the DEM is averaged to cells of about 0.4 mm on paper",
          "[averaged][scale]") {
  GeoTransform gt;
  gt.a = {0.0, 75.0, 0.0, 0.0, 0.0, -75.0};
  const DemGrid sample{436, 414, 75.0, 75.0};
  // 1:1 000 000 draws 0.4 mm as 400 m: 5 cells of 75 m. 1:250 000 asks 100 m: the DEM is fine.
  CHECK(scale_averaging(1e6, sample, gt) == 5);
  CHECK(scale_averaging(250000, sample, gt) == 1);
  CHECK(scale_averaging(375000, sample, gt) == 2);
  CHECK(scale_averaging(0.0, sample, gt) == 1);
  // Never below 32 cells on the shorter side: 436 x 414 cells averaged at most 12 a side.
  CHECK(scale_averaging(1e8, sample, gt) == 12);
  CHECK(scale_averaging(1e8, DemGrid{60, 5000, 75.0, 75.0}, gt) == 1);
}

TEST_CASE("a DEM averaged and held reads each of its cells once through its two readers",
          "[averaged]") {
  HeightGrid dem = random_terrain(103, 70, 5, 0.2);
  for (std::size_t r = 30; r < 33; ++r)
    for (std::size_t c = 9; c < 12; ++c) dem(r, c) = kNoData;
  for (const bool two : {true, false}) {
    for (const std::size_t k : {2, 3, 7}) {
      CAPTURE(two, k);
      CountedSource counted(dem, 10.0);
      std::vector<double> told;
      const HeightGrid got = read_averaged(counted.source(two), k, [&](double f) {
        told.push_back(f);
        return true;
      });
      const HeightGrid expected = averaged_by_hand(dem, k);
      REQUIRE(got.rows() == expected.rows());
      REQUIRE(got.cols() == expected.cols());
      int differ = 0;
      for (std::size_t r = 0; r < got.rows(); ++r)
        for (std::size_t c = 0; c < got.cols(); ++c)
          differ += !same_height(got(r, c), expected(r, c));
      CHECK(differ == 0);
      CHECK(counted.misread() == 0);
      CHECK(counted.through[0] > 0);
      CHECK((counted.through[1] > 0) == two);
      // Progress rises to the whole of the read.
      REQUIRE(!told.empty());
      CHECK(std::is_sorted(told.begin(), told.end()));
      CHECK(told.back() == Approx(1.0));
    }
  }
  // Cancelled from the progress, and a failing reader's error, reach the caller.
  CountedSource counted(dem, 10.0);
  CHECK_THROWS_AS(read_averaged(counted.source(true), 2, [](double) { return false; }), Cancelled);
  DemSource failing = counted.source(true);
  failing.read_alongside = [](const DemWindow&, float*) { throw Error("block 7 is unreadable"); };
  CHECK_THROWS_WITH(read_averaged(failing, 2), Catch::Contains("block 7 is unreadable"));
}

TEST_CASE("heights held are read in windows as the grid holds them", "[averaged]") {
  const auto heights = std::make_shared<const HeightGrid>(random_terrain(31, 17, 3, 0.5));
  const DemGrid grid{31, 17, 20.0, 20.0};
  GeoTransform gt;
  gt.a = {5.0, 20.0, 0.0, 7.0, 0.0, -20.0};
  const DemSource held = held_source(heights, grid, gt);
  CHECK(held.geotransform.a == gt.a);
  for (const WindowReader& read : {held.read, held.read_alongside}) {
    REQUIRE(read);
    const DemWindow w{4, 5, 9, 12};
    std::vector<float> got(w.rows * w.cols);
    read(w, got.data());
    int differ = 0;
    for (std::size_t r = 0; r < w.rows; ++r)
      for (std::size_t c = 0; c < w.cols; ++c)
        differ += !same_height(got[r * w.cols + c], (*heights)(w.row0 + r, w.col0 + c));
    CHECK(differ == 0);
    std::vector<float> one(1);
    CHECK_THROWS_AS(read({31, 0, 1, 1}, one.data()), Error);
  }
  CHECK_THROWS_AS(held_source(heights, DemGrid{30, 17, 20.0, 20.0}, gt), Error);
}

TEST_CASE("a DEM averaged held or not and the DEM averaged beforehand draw one sketch",
          "[averaged][scale]") {
  // Averaged 4 x 4, 275 x 250 cells: held within a run's budget, read window by window from the
  // fine DEM when the run may plan for only a megabyte (a quarter of it).
  const HeightGrid fine = random_terrain(1100, 1000, 13, 0.01);
  const HeightGrid coarse = averaged_by_hand(fine, 4);
  SilhouetteParams p;
  p.strokes.mode = StrokeMode::drawn;
  p.strokes.scale = 100000;  // 10 m cells: 0.4 mm is 40 m, 4 cells of the fine DEM
  // Plan-oblique geometry reads the DEM once more, for its lowest height.
  for (const Geometry geometry : {Geometry::map, Geometry::oblique}) {
    p.geometry = geometry;
    p.view.azimuth_deg = geometry == Geometry::map ? 250 : 120;
    CountedSource counted(fine, 10.0);
    const SilhouetteResult held = sketch_silhouettes(counted.source(true), p);
    CHECK(counted.misread() == 0);  // held: the fine DEM read once
    setenv("TSK_MEMORY_MB", "1", 1);
    const SilhouetteResult streamed = sketch_silhouettes(memory_source(fine, 10.0), p);
    unsetenv("TSK_MEMORY_MB");
    const SilhouetteResult by_hand = sketch_silhouettes(memory_source(coarse, 40.0), p);
    CHECK(held.averaged == 4);
    CHECK(streamed.averaged == 4);
    CHECK(by_hand.averaged == 1);
    REQUIRE(!held.strokes.empty());
    for (const SilhouetteResult* other : {&streamed, &by_hand}) {
      REQUIRE(other->strokes.size() == held.strokes.size());
      std::size_t differ = 0;
      for (std::size_t s = 0; s < held.strokes.size(); ++s) {
        REQUIRE(other->strokes[s].points.size() == held.strokes[s].points.size());
        for (std::size_t k = 0; k < held.strokes[s].points.size(); ++k) {
          differ += other->strokes[s].points[k].x != held.strokes[s].points[k].x ||
                    other->strokes[s].points[k].y != held.strokes[s].points[k].y;
        }
      }
      CHECK(differ == 0);
    }
  }
  // Exact strokes are the thesis's method on the DEM as it is, whatever the scale.
  p.strokes.mode = StrokeMode::exact;
  CHECK(sketch_silhouettes(memory_source(fine, 10.0), p).averaged == 1);
}
