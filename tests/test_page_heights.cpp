// A preview of a DEM too large to hold is laid out over the DEM averaged for its page
// (io/read/page_heights.h): the heights are the DEM's block means, turned to the view, and strokes
// laid out over them land where they land over the DEM's own cells.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "catch_compat.h"
#include "core/base/errors.h"
#include "core/method/orient.h"
#include "core/method/run_recipes.h"
#include "gdal_test_support.h"
#include "io/pages/sketch_page.h"
#include "io/read/page_heights.h"

namespace {

using tsk::test::ScratchDir;

// TSK_MEMORY_MB for one test (each ctest test runs in a process of its own), cleared after it.
struct MemoryLimit {
  explicit MemoryLimit(const char* megabytes) { setenv("TSK_MEMORY_MB", megabytes, 1); }
  ~MemoryLimit() { unsetenv("TSK_MEMORY_MB"); }
};

// 53 x 37 cells of smooth hills, 10 m, with a block of nodata: odd sizes leave short blocks at
// the east and south edges.
float smooth_hills(int, int r, int c) {
  if (r >= 10 && r < 14 && c >= 20 && c < 25) return -9999.0f;
  return static_cast<float>(200 + 80 * std::sin(c / 9.0) * std::cos(r / 13.0) + 0.5 * r);
}

// The oracle: block means of the DEM read through GDAL, NaN where a block has no data.
tsk::HeightGrid block_means(const std::string& path, std::size_t factor) {
  GDALAllRegister();
  GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly));
  REQUIRE(ds != nullptr);
  const auto rows = static_cast<std::size_t>(ds->GetRasterYSize());
  const auto cols = static_cast<std::size_t>(ds->GetRasterXSize());
  int has_nodata = 0;
  const double nodata = ds->GetRasterBand(1)->GetNoDataValue(&has_nodata);
  std::vector<double> z(rows * cols);
  REQUIRE(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, static_cast<int>(cols),
                                         static_cast<int>(rows), z.data(), static_cast<int>(cols),
                                         static_cast<int>(rows), GDT_Float64, 0, 0) == CE_None);
  GDALClose(ds);
  tsk::HeightGrid means((rows + factor - 1) / factor, (cols + factor - 1) / factor);
  for (std::size_t R = 0; R < means.rows(); ++R) {
    for (std::size_t C = 0; C < means.cols(); ++C) {
      double sum = 0;
      int count = 0;
      for (std::size_t r = R * factor; r < std::min(rows, (R + 1) * factor); ++r) {
        for (std::size_t c = C * factor; c < std::min(cols, (C + 1) * factor); ++c) {
          const double v = z[r * cols + c];
          if (has_nodata && v == nodata) continue;
          sum += v;
          ++count;
        }
      }
      means(R, C) = count ? static_cast<float>(sum / count) : tsk::kNoData;
    }
  }
  return means;
}

// Whether a stroke's point (in map geometry) lies amid the page's cells: every cell within three
// of it holds data.
bool amid_cells(const tsk::io::PageHeights& page, tsk::StrokePoint at) {
  double p = 0, s = 0;
  page.frame.from_pixel(page.geotransform.to_pixel(at.x, at.y), p, s);
  for (long r = std::lround(p) - 3; r <= std::lround(p) + 3; ++r) {
    for (long c = std::lround(s) - 3; c <= std::lround(s) + 3; ++c) {
      if (r < 0 || c < 0 || r >= static_cast<long>(page.oriented.rows()) ||
          c >= static_cast<long>(page.oriented.cols()))
        return false;
      if (!tsk::is_data(page.oriented(static_cast<std::size_t>(r), static_cast<std::size_t>(c))))
        return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("a preview's page heights are the DEM's block means turned to the view", "[preview]") {
  ScratchDir dir("page_heights");
  const std::string dem = dir / "dem.tif";
  tsk::test::write_tiff(dem, 53, 37, 1, smooth_hills, tsk::test::kNorthUp, 32616, -9999.0);
  const tsk::io::DemFile file(dem, {});
  // The DEM's own range, which the page keeps for the sketch's extent, as GDAL finds it.
  double range[2] = {0, 0};
  {
    GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen(dem.c_str(), GA_ReadOnly));
    REQUIRE(ds != nullptr);
    REQUIRE(ds->GetRasterBand(1)->ComputeRasterMinMax(FALSE, range) == CE_None);
    GDALClose(ds);
  }
  for (const std::size_t factor : {2, 3, 5}) {
    const tsk::HeightGrid means = block_means(dem, factor);
    for (const double azimuth : {0.0, 90.0, 180.0, 270.0}) {
      CAPTURE(factor, azimuth);
      const tsk::io::PageHeights page = tsk::io::read_page_heights(file, azimuth, factor);
      CHECK(page.averaged == factor);
      CHECK(page.lowest == Approx(range[0]));
      CHECK(page.highest == Approx(range[1]));
      const std::array<double, 6>& gt = page.geotransform.a;
      CHECK(gt[0] == tsk::test::kNorthUp[0]);
      CHECK(gt[3] == tsk::test::kNorthUp[3]);
      CHECK(gt[1] == Approx(tsk::test::kNorthUp[1] * static_cast<double>(factor)));
      CHECK(gt[5] == Approx(tsk::test::kNorthUp[5] * static_cast<double>(factor)));
      const tsk::HeightGrid expected = tsk::orient(
          means,
          tsk::make_frame(means.rows(), means.cols(), 10.0 * factor, 10.0 * factor, azimuth));
      REQUIRE(page.oriented.rows() == expected.rows());
      REQUIRE(page.oriented.cols() == expected.cols());
      std::size_t differ = 0;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        const float a = page.oriented.data()[k], b = expected.data()[k];
        if (std::isnan(a) != std::isnan(b) || (!std::isnan(a) && std::abs(a - b) > 1e-3f)) ++differ;
      }
      CHECK(differ == 0);
    }
  }
}

TEST_CASE("a page holds a DEM that can be held, else the least average that can be", "[preview]") {
  const tsk::DemGrid sample{436, 414, 75.0, 75.0};
  CHECK(tsk::io::page_averaging(sample, 90.0) == 1);
  // The oracle: a DEM turned whole takes 5 bytes a cell (4 more for the DEM beside a resampled
  // view), and may take half of the memory.
  const auto least_fitting = [&](double azimuth, double memory, double most_cells) {
    for (std::size_t factor = 1;; ++factor) {
      const tsk::DemGrid g{(sample.rows + factor - 1) / factor, (sample.cols + factor - 1) / factor,
                           sample.dx * factor, sample.dy * factor};
      const tsk::OrientedFrame f = tsk::make_frame(g, azimuth);
      const double cells = static_cast<double>(f.profiles) * static_cast<double>(f.length);
      const double bytes =
          5.0 * cells + (f.resampled ? 4.0 * static_cast<double>(g.rows * g.cols) : 0.0);
      if (bytes <= memory / 2 && (factor == 1 || cells <= most_cells)) return factor;
    }
  };
  const MemoryLimit limit("1");
  for (const double azimuth : {90.0, 0.0, 45.0, 200.0}) {
    CAPTURE(azimuth);
    const std::size_t factor = tsk::io::page_averaging(sample, azimuth);
    CHECK(factor > 1);
    CHECK(factor == least_fitting(azimuth, 1024.0 * 1024.0, tsk::io::kPageCells));
    CHECK(tsk::io::page_averaging(sample, azimuth, 2000) ==
          least_fitting(azimuth, 1024.0 * 1024.0, 2000));
  }
  const MemoryLimit nonsense("1e3MB");
  CHECK_THROWS_AS(tsk::io::page_averaging(sample, 90.0), tsk::Error);
}

TEST_CASE("strokes laid out over a DEM's averaged heights land where they do over its cells",
          "[preview]") {
  ScratchDir dir("page_layout");
  const std::string dem = dir / "dem.tif";
  // Long smooth ridges, 240 x 240 cells of 10 m: averaging 2 x 2 cells moves their heights by
  // centimetres, which the page does not show.
  const auto ridges = [](int, int r, int c) {
    return static_cast<float>(300 + 120 * std::sin(c / 12.0 + 0.8 * std::sin(r / 20.0)) +
                              60 * std::cos(r / 15.0 + c / 40.0));
  };
  tsk::test::write_tiff(dem, 240, 240, 1, ridges, tsk::test::kNorthUp, 32616);
  const tsk::io::DemFile file(dem, {});
  for (const double azimuth : {90.0, 200.0}) {
    const tsk::io::HeldDemFile held = tsk::io::hold_dem(dem, {}, azimuth);
    const tsk::io::PageHeights page = tsk::io::read_page_heights(file, azimuth, 2);
    for (const bool drawn : {false, true}) {
      for (const tsk::Geometry geometry : {tsk::Geometry::map, tsk::Geometry::oblique}) {
        CAPTURE(azimuth, drawn, static_cast<int>(geometry));
        tsk::SilhouetteParams params;
        params.view.azimuth_deg = azimuth;
        params.geometry = geometry;
        if (drawn) params.strokes.mode = tsk::StrokeMode::drawn;
        const tsk::SilhouetteResult run = tsk::sketch_held_dem(held.held(), params);
        REQUIRE(run.strokes.size() >= 5);
        // A picture of a pixel an averaged cell, as page_averaging makes them for a page.
        tsk::io::PageOptions options;
        options.width_px = 140;  // 120 cells and the margins
        tsk::io::SketchLayout own(held.dem.oriented, held.dem.frame, held.dem.geotransform,
                                  params.view, geometry, options);
        tsk::io::SketchLayout averaged(page.oriented, page.frame, page.geotransform, params.view,
                                       geometry, options,
                                       tsk::io::HeightRange{page.lowest, page.highest});
        for (const tsk::Stroke& stroke : run.strokes) {
          own.add(stroke);
          averaged.add(stroke);
        }
        const tsk::io::SketchPage a = own.take_page(run.z_ref), b = averaged.take_page(run.z_ref);
        REQUIRE(a.paths.size() == b.paths.size());
        // Positions from the foot of the picture, whose height is rounded to whole pixels. In map
        // geometry a point is lifted by the height under it: compared amid the averaged DEM's
        // cells, since where the DEM ends, or beside nodata, a point takes the nearest cell's
        // height, which lies farther off among larger cells.
        double farthest = 0;
        std::size_t amid = 0, points = 0;
        for (std::size_t k = 0; k < a.paths.size(); ++k) {
          REQUIRE(a.paths[k].points.size() == b.paths[k].points.size());
          CHECK(a.paths[k].widths == b.paths[k].widths);
          for (std::size_t n = 0; n < a.paths[k].points.size(); ++n, ++points) {
            if (geometry == tsk::Geometry::map && !amid_cells(page, run.strokes[k].points[n]))
              continue;
            ++amid;
            const tsk::StrokePoint p = a.paths[k].points[n], q = b.paths[k].points[n];
            farthest = std::max(
                {farthest, std::abs(p.x - q.x), std::abs((a.height - p.y) - (b.height - q.y))});
          }
        }
        CAPTURE(amid, points);
        CHECK(amid > points / 2);
        CAPTURE(farthest);
        CHECK(farthest < 0.5);  // pixels
      }
    }
  }
}
