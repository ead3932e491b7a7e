// The io/ layer's DEM reading: band windows down a tiled file, with GDAL's cache kept to the
// rows in use.
#include <gdal_priv.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "catch_compat.h"
#include "core/method/slope_survey.h"
#include "gdal_test_support.h"
#include "io/read/block_retention.h"
#include "io/read/dem_reader.h"
#include "io/read/gdal_util.h"

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

  // Bands of columns down the file, as from the south: after each band, GDAL still holds the
  // blocks along its last columns in every block row, for the next band, and little else.
  io::DatasetPtr dataset(static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)));
  REQUIRE(dataset != nullptr);
  GDALRasterBand* band = dataset->GetRasterBand(1);
  const io::BandWindows columns(std::move(dataset), path, 1);
  const auto cached = [band](int x, int y) {
    GDALRasterBlock* block = band->TryGetLockedBlockRef(x, y);
    if (block) block->DropLock();
    return block != nullptr;
  };
  const GIntBig block = static_cast<GIntBig>(kTile) * kTile * 4;
  const GIntBig start = GDALGetCacheUsed64();
  for (std::size_t first = 0; first + 100 < kCols; first += 100) {
    std::vector<float> heights(kRows * 102);
    for (std::size_t top = 0; top < kRows; top += 64)
      columns.read({top, first, 64, 102}, heights.data() + top * 102);
    CHECK(heights[(kRows - 1) * 102 + 101] ==
          static_cast<float>(kRows - 1) * 1000.0f + static_cast<float>(first + 101));
    const int edge = static_cast<int>((first + 101) / kTile);
    for (int y = 0; y + 1 < kRows / kTile; ++y) REQUIRE(cached(edge, y));
    // Each block row keeps a block at either side at most (the first band: no direction yet).
    CHECK(GDALGetCacheUsed64() - start <= (2 * kRows / kTile + 2 * kCols / kTile) * block);
  }
}

namespace {

// GDAL's block cache as BlockRetention sees it: a read inflates each block it touches that is not
// held, and a block stays held until it is dropped.
struct InflationCount {
  static constexpr std::size_t kRows = 512, kCols = 1024, kBlock = 64, kRun = 64;
  std::set<std::pair<std::size_t, std::size_t>> held;  // (x, y)
  std::map<std::pair<std::size_t, std::size_t>, int> inflated;
  std::size_t most_held = 0;
  io::BlockRetention retention{kRows, kCols, kBlock, kBlock, [this](std::size_t x, std::size_t y) {
                                 held.erase({x, y});
                               }};

  // A window read as BandWindows::read reads it: in runs of rows, letting go above each.
  void read(std::size_t row0, std::size_t rows, std::size_t col0, std::size_t cols) {
    const std::size_t end = row0 + rows;
    for (std::size_t top = row0; top < end;) {
      const std::size_t run_end = std::min(end, (top / kRun + 1) * kRun);
      for (std::size_t y = top / kBlock; y <= (run_end - 1) / kBlock; ++y) {
        for (std::size_t x = col0 / kBlock; x <= (col0 + cols - 1) / kBlock; ++x) {
          if (held.insert({x, y}).second) ++inflated[{x, y}];
        }
      }
      retention.read(top, run_end, col0, cols);
      retention.let_go_above((run_end - std::min<std::size_t>(run_end, 2)) / kBlock);
      most_held = std::max(most_held, held.size());
      top = run_end;
    }
  }
  // Bands read one after another, each down from its top in windows of 16 rows, as DemBand::load
  // reads a strip's band: band k spans columns columns(k, row) = [first, last) at each row.
  void read_bands(std::size_t bands,
                  const std::function<std::pair<long, long>(std::size_t, long)>& columns) {
    for (std::size_t k = 0; k < bands; ++k) {
      for (long top = 0; top < static_cast<long>(kRows); top += 16) {
        long first = static_cast<long>(kCols), last = 0;
        for (long r = top; r < top + 16; ++r) {
          const auto [c0, c1] = columns(k, r);
          first = std::min(first, std::max(0L, c0));
          last = std::max(last, std::min(static_cast<long>(kCols), c1));
        }
        if (first < last) {
          read(static_cast<std::size_t>(top), 16, static_cast<std::size_t>(first),
               static_cast<std::size_t>(last - first));
        }
      }
    }
  }
  bool each_inflated_once() const {
    return std::all_of(inflated.begin(), inflated.end(),
                       [](const auto& b) { return b.second == 1; });
  }
  std::size_t most_held_in_a_block_row() const {
    std::map<std::size_t, std::size_t> per_row;
    for (const auto& [x, y] : held) ++per_row[y];
    std::size_t most = 0;
    for (const auto& [y, n] : per_row) most = std::max(most, n);
    return most;
  }
};

}  // namespace

TEST_CASE("band windows keep the blocks along a band's edge for the next band, and only those",
          "[io][strips]") {
  using C = InflationCount;
  constexpr std::size_t kBlockRows = C::kRows / C::kBlock, kBlocksPerRow = C::kCols / C::kBlock;
  SECTION("strips down the whole width, as from the west: no block is kept") {
    C count;
    for (std::size_t top = 0; top + 2 < C::kRows; top += 98)
      count.read(top, std::min<std::size_t>(100, C::kRows - top), 0, C::kCols);
    CHECK(count.each_inflated_once());
    CHECK(count.inflated.size() == kBlockRows * kBlocksPerRow);
    CHECK(count.most_held <= 2 * kBlocksPerRow);
    CHECK(count.held.size() <= kBlocksPerRow);
  }
  // Bands of 100 columns that overlap by two (the neighbours slopes need), as from the south or
  // the north: a band's edge blocks are the next one's first.
  for (const bool rightwards : {true, false}) {
    DYNAMIC_SECTION("bands of columns, moving " << (rightwards ? "right" : "left")) {
      C count;
      count.read_bands(11, [rightwards](std::size_t k, long) {
        const long first =
            rightwards ? 100L * static_cast<long>(k) - 1
                       : static_cast<long>(C::kCols) - 100L * (static_cast<long>(k) + 1) - 1;
        return std::pair<long, long>{first, first + 102};
      });
      CHECK(count.each_inflated_once());
      CHECK(count.inflated.size() == kBlockRows * kBlocksPerRow);
      // A band's blocks and the last one's edge, not the blocks behind.
      CHECK(count.most_held <= kBlockRows * 4 + 2 * kBlocksPerRow);
      CHECK(count.most_held_in_a_block_row() <= 2);
    }
  }
  // Bands whose edges slant, one column a row (as from 45 degrees) and five (nearly along the
  // rows): in a block row, a band's edge spans as many columns as it slants across it.
  for (const long slant : {1L, 5L, -3L}) {
    DYNAMIC_SECTION("bands slanting " << slant << " columns a row") {
      C count;
      const long width = 230, reach = static_cast<long>(C::kRows) * std::abs(slant);
      const auto bands =
          static_cast<std::size_t>((static_cast<long>(C::kCols) + reach) / width + 2);
      count.read_bands(bands, [&](std::size_t k, long row) {
        const long first = static_cast<long>(k) * width - (slant > 0 ? reach : 0) + slant * row - 1;
        return std::pair<long, long>{first, first + width + 2};
      });
      CHECK(count.each_inflated_once());
      CHECK(count.inflated.size() == kBlockRows * kBlocksPerRow);
    }
  }
  SECTION("a file in strips, a block to a row, keeps none: every band reads each whole") {
    std::set<std::size_t> held;
    std::size_t most = 0;
    io::BlockRetention strips(C::kRows, C::kCols, 16, C::kCols,
                              [&held](std::size_t x, std::size_t y) {
                                CHECK(x == 0);
                                held.erase(y);
                              });
    for (std::size_t first = 0; first + 100 <= C::kCols; first += 100) {
      for (std::size_t top = 0; top < C::kRows; top += 16) {
        held.insert(top / 16);
        strips.read(top, top + 16, first, 100);
        strips.let_go_above((top + 14) / 16);
        most = std::max(most, held.size());
      }
    }
    CHECK(most <= 2);
  }
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

TEST_CASE("a large DEM's range is sampled through two datasets as through one", "[io][notes]") {
  // Over two million cells: 64 survey windows, the even ones sampled, every other pair of those
  // through the file's second dataset. A common fill value in one window is told wherever it
  // lies among those sampled, and not in a window the sample leaves out.
  ScratchDir dir("range_two");
  constexpr int kRows = 1700, kCols = 1400;
  const std::vector<DemWindow> windows = survey_windows(kRows, kCols);
  REQUIRE(windows.size() == 64);
  REQUIRE_FALSE(read_alongside(0));
  REQUIRE(read_alongside(2));
  const double gt[6] = {1000, 10, 0, 5000, 0, -10};
  for (const std::size_t k : {0, 2, 1}) {
    CAPTURE(k);
    const DemWindow& w = windows[k];
    const std::string path = dir / ("fill" + std::to_string(k) + ".tif");
    const auto fill_r = static_cast<int>(w.row0 + w.rows / 2);
    const auto fill_c = static_cast<int>(w.col0 + w.cols / 2);
    test::write_tiff(
        path, kRows, kCols, 1,
        [&](int, int r, int c) { return r == fill_r && c == fill_c ? -9999.0f : 100.0f; }, gt,
        32632);
    const io::DemFile two(path, io::DemOptions{});
    const io::DemFile one(io::open_raster(path), path, io::DemOptions{});  // no second dataset
    const auto fill_told = [](const io::DemFile& dem) {
      return std::any_of(
          dem.info().notes.begin(), dem.info().notes.end(),
          [](const io::DemNote& n) { return n.code == io::DemNoteCode::fill_value; });
    };
    CHECK(fill_told(two) == (k % 2 == 0));
    CHECK(fill_told(one) == fill_told(two));
    // The second reader reads what the first does.
    const DemSource source = two.source();
    REQUIRE(source.read_alongside);
    CHECK_FALSE(one.source().read_alongside);
    std::vector<float> a(w.rows * w.cols), b(w.rows * w.cols);
    source.read(w, a.data());
    source.read_alongside(w, b.data());
    CHECK(a == b);
    CHECK(*std::min_element(a.begin(), a.end()) == -9999.0f);
    // Without the range's sample, one reader.
    io::DemOptions unsampled;
    unsampled.sample_range = false;
    CHECK_FALSE(io::DemFile(path, unsampled).source().read_alongside);
  }
  // A DEM of one survey window has nothing to share: the file is opened once.
  const std::string small = dir / "small.tif";
  test::write_tiff(
      small, 64, 64, 1, [](int, int, int) { return 100.0f; }, gt, 32632);
  REQUIRE(survey_windows(64, 64).size() == 1);
  CHECK_FALSE(io::DemFile(small, io::DemOptions{}).source().read_alongside);
}

TEST_CASE("a declared nodata that float cannot hold is left out of the range, as the reads do",
          "[io][notes]") {
  // A VRT declaring -9999.9 over a Float32 file, which holds it as -9999.900390625: compared as a
  // double with the declared value, those cells were heights 10 km below the rest, and the
  // 640 m DEM was noted to span more relief than any terrain.
  ScratchDir dir("range_nodata");
  const std::string tiff = dir / "heights.tif", path = dir / "nodata.vrt";
  constexpr int kSize = 64;
  constexpr double kNodata = -9999.9;
  REQUIRE(static_cast<double>(static_cast<float>(kNodata)) != kNodata);
  test::write_tiff(
      tiff, kSize, kSize, 1,
      [](int, int r, int c) { return r < 4 ? static_cast<float>(kNodata) : 100.0f + c; },
      test::kNorthUp, 32632);
  {
    GDALDatasetUniquePtr source(GDALDataset::Open(tiff.c_str(), GDAL_OF_RASTER));
    GDALDatasetUniquePtr vrt(GetGDALDriverManager()->GetDriverByName("VRT")->CreateCopy(
        path.c_str(), source.get(), false, nullptr, nullptr, nullptr));
    REQUIRE(vrt);
    vrt->GetRasterBand(1)->SetNoDataValue(kNodata);
  }
  const io::DemFile dem(path, io::DemOptions{});
  int has_nodata = 0;
  REQUIRE(io::open_raster(path)->GetRasterBand(1)->GetNoDataValue(&has_nodata) == kNodata);
  CHECK(dem.info().notes.empty());
  // The reads take those cells as nodata.
  std::vector<float> row(kSize);
  dem.source().read({0, 0, 1, kSize}, row.data());
  CHECK(std::all_of(row.begin(), row.end(), [](float z) { return std::isnan(z); }));
}
