// The io/ layer's DEM reading: band windows down a tiled file, with GDAL's cache kept to the
// rows in use.
#include <gdal_priv.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "catch_compat.h"
#include "gdal_test_support.h"
#include "io/read/dem_reader.h"

using namespace tsk;
using test::ScratchDir;

namespace {
const std::string kData = TSK_TEST_DATA;
}  // namespace

TEST_CASE("band windows read a file's heights and let GDAL keep only the rows in use",
          "[io][strips]") {
  ScratchDir dir("windows");
  const std::string path = dir / "tiled.tif";
  constexpr int kRows = 2048, kCols = 512, kTile = 64;
  {
    GDALAllRegister();
    const char* options[] = {"TILED=YES", "BLOCKXSIZE=64", "BLOCKYSIZE=64", nullptr};
    GDALDataset* ds = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
        path.c_str(), kCols, kRows, 1, GDT_Float32, const_cast<char**>(options));
    REQUIRE(ds != nullptr);
    std::vector<float> values(static_cast<std::size_t>(kRows) * kCols);
    for (int r = 0; r < kRows; ++r)
      for (int c = 0; c < kCols; ++c)
        values[static_cast<std::size_t>(r) * kCols + c] = r * 1000.0f + c;
    values[5 * kCols + 7] = -9999;  // nodata
    ds->GetRasterBand(1)->SetNoDataValue(-9999);
    REQUIRE(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, kCols, kRows, values.data(), kCols,
                                           kRows, GDT_Float32, 0, 0) == CE_None);
    GDALClose(ds);
  }
  const io::BandWindows windows(path, 1);
  CHECK(windows.rows() == kRows);
  CHECK(windows.cols() == kCols);
  const auto check_window = [&](const DemWindow& w) {
    std::vector<float> heights(w.rows * w.cols);
    windows.read(w, heights.data());
    for (std::size_t r = 0; r < w.rows; ++r) {
      for (std::size_t c = 0; c < w.cols; ++c) {
        const std::size_t row = w.row0 + r, col = w.col0 + c;
        const float z = heights[r * w.cols + c];
        if (row == 5 && col == 7) {
          REQUIRE(std::isnan(z));
        } else {
          REQUIRE(z == static_cast<float>(row) * 1000.0f + static_cast<float>(col));
        }
      }
    }
  };
  // Strips down the file, each starting on the row before the last one's end, as a cardinal
  // view reads them: GDAL keeps no more than the block rows of the last rows read.
  const GIntBig before = GDALGetCacheUsed64();
  const GIntBig block_row = static_cast<GIntBig>(kTile) * kCols * 4;
  GIntBig most = 0;
  for (std::size_t top = 0; top + 2 < kRows; top += 98) {
    check_window({top, 0, std::min<std::size_t>(100, kRows - top), kCols});
    most = std::max(most, GDALGetCacheUsed64() - before);
  }
  CHECK(most > 0);
  CHECK(most <= 2 * block_row);
  // Bands jump back up at each new strip, a few columns further on.
  for (std::size_t band = 0; band < 3; ++band) {
    for (std::size_t top = band * 100; top < kRows - 200; top += 300)
      check_window({top, band * 50, 60, 120});
  }
  CHECK_THROWS_AS(io::BandWindows(path, 2), Error);
  CHECK_THROWS_AS(io::BandWindows(dir / "missing.tif", 1), Error);
}

TEST_CASE("Web Mercator cells are scaled to ground metres with a note", "[io]") {
  io::DemOptions options;
  const io::Dem dem = io::read_dem(kData + "/topobathy_3857.tif", options, 90.0);
  // Strait of Georgia, about 49.5 N: cos = 0.65.
  CHECK(dem.ground_scale == Approx(0.65).margin(0.02));
  CHECK(dem.frame.d == Approx(3710.65 * dem.ground_scale).epsilon(1e-6));
  REQUIRE(dem.notes.size() == 1);
  CHECK(dem.notes[0].code == io::DemNoteCode::mercator_scaled);
  CHECK(dem.notes[0].numbers.at(0) == dem.ground_scale);
}

TEST_CASE("a stop asked for ends every read of a DEM, whole or window by window", "[io]") {
  // The command line's Ctrl-C and SIGTERM: the lowest-height pass of a plan-oblique run and the
  // whole-DEM reads used to run to their end before the first check.
  const std::string sample = TSK_SAMPLE_DEM;
  std::atomic<int> reads{0}, allowed{0};  // the halves of a whole DEM are read at once
  io::DemOptions options;
  options.stop = [&reads, &allowed] {
    if (++reads > allowed) throw Cancelled();
  };
  CHECK_THROWS_AS(io::read_dem(sample, options, 90.0), Cancelled);  // read in one block of rows
  reads = 0, allowed = 1;
  const io::DemFile file(sample, options);
  const DemSource dem = file.source();
  std::vector<float> heights(10);
  dem.read({0, 0, 1, 10}, heights.data());  // the first read passes
  CHECK_THROWS_AS(dem.read({1, 0, 1, 10}, heights.data()), Cancelled);
  CHECK(reads == 2);
  options.stop = {};
  const io::DemFile unstopped(sample, options);
  const DemSource whole = unstopped.source();
  CHECK(dem_lowest_height(whole.grid.rows, whole.grid.cols, whole.read) > 0);
}

TEST_CASE("a DEM on its own grid is read whole in two halves, as a turned one is", "[io]") {
  ScratchDir dir("halves");
  const std::string path = dir / "halves.tif";
  constexpr int kRows = 1100, kCols = 300;
  std::vector<float> values(static_cast<std::size_t>(kRows) * kCols);
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kCols; ++c)
      values[static_cast<std::size_t>(r) * kCols + c] = 500.0f + r * 0.5f - c * 0.25f;
  values[3 * kCols + 4] = -9999;      // nodata in the upper half
  values[900 * kCols + 299] = -9999;  // and in the lower
  values[1000 * kCols + 10] = 12.5f;  // the lowest height, in the lower half
  const double gt[6] = {1000, 10, 0, 9000, 0, -10};
  test::write_tiff(
      path, kRows, kCols, 1,
      [&](int, int r, int c) { return values[static_cast<std::size_t>(r) * kCols + c]; }, gt, 0,
      -9999);
  const io::DemOptions options;
  const io::Dem as_it_lies = io::read_dem(path, options, 90.0);  // the DEM as it lies
  REQUIRE(as_it_lies.oriented.rows() == kRows);
  REQUIRE(as_it_lies.oriented.cols() == kCols);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const float z = as_it_lies.oriented.data()[k];
    if (values[k] == -9999) {
      REQUIRE(std::isnan(z));
    } else {
      REQUIRE(z == values[k]);
    }
  }
  CHECK(as_it_lies.lowest_height == 12.5);
  const io::Dem turned = io::read_dem(path, options, 270.0);  // block by block, turned
  CHECK(turned.lowest_height == 12.5);
  CHECK(turned.oriented(kRows - 1 - 1000, kCols - 1 - 10) == 12.5f);
}

TEST_CASE("a DEM opened without its range sample lacks only the notes on its values",
          "[io][notes]") {
  ScratchDir dir("range");
  const std::string path = dir / "filled.tif";
  constexpr int kSize = 64;
  // A common fill value in a corner, undeclared: the range's note, beside "no CRS".
  const double gt[6] = {1000, 10, 0, 5000, 0, -10};
  test::write_tiff(
      path, kSize, kSize, 1, [](int, int r, int c) { return r == 0 && c == 0 ? -9999.0f : 100.0f; },
      gt, 0);
  const auto codes = [&](bool sample_range) {
    io::DemOptions options;
    options.sample_range = sample_range;
    const io::DemFile dem(path, options);
    CHECK(dem.info().grid.rows == kSize);
    CHECK(dem.info().grid.dx == 10);
    std::vector<io::DemNoteCode> found;
    for (const io::DemNote& note : dem.info().notes) found.push_back(note.code);
    return found;
  };
  CHECK(codes(true) ==
        std::vector<io::DemNoteCode>{io::DemNoteCode::no_crs, io::DemNoteCode::fill_value});
  CHECK(codes(false) == std::vector<io::DemNoteCode>{io::DemNoteCode::no_crs});
}
