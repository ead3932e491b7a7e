// terrain-sketch panorama: its outputs, its visibility against an exact line of sight and against
// GDAL's viewshed, and the bad input it refuses without writing anything.
#include <gdal_alg.h>
#include <ogrsf_frmts.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "catch_compat.h"
#include "cli_run.h"
#include "gdal_test_support.h"
#include "io/read/gdal_util.h"

using namespace tsk;
using test::CliRun;
using test::run_cli;
using test::ScratchDir;

namespace {

const std::string kSample = TSK_SAMPLE_DEM;
const std::string kData = TSK_TEST_DATA;
// The sample's highest cell's centre: a summit with a view.
const std::string kSummit = "749008.1394,4009477.9308";

struct Raster {
  int rows = 0, cols = 0;
  std::array<double, 6> gt{};
  std::vector<float> values;
  float at(int r, int c) const { return values[static_cast<std::size_t>(r) * cols + c]; }
};

Raster read_raster(const std::string& path) {
  GDALAllRegister();
  io::DatasetPtr ds(static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)));
  REQUIRE(ds);
  Raster r;
  r.rows = ds->GetRasterYSize(), r.cols = ds->GetRasterXSize();
  ds->GetGeoTransform(r.gt.data());
  r.values.resize(static_cast<std::size_t>(r.rows) * r.cols);
  REQUIRE(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.cols, r.rows, r.values.data(), r.cols,
                                         r.rows, GDT_Float32, 0, 0) == CE_None);
  return r;
}

// The cell centre of (row, col) on the map.
std::pair<double, double> centre(const Raster& r, int row, int col) {
  return {r.gt[0] + (col + 0.5) * r.gt[1], r.gt[3] + (row + 0.5) * r.gt[5]};
}

std::string coordinates(std::pair<double, double> p) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4f,%.4f", p.first, p.second);
  return text;
}

// Whether cell (row, col) is seen from the eye over cell (r0, c0): the straight sight line to its
// centre, sampled four times a cell, passes above the bilinear surface, every height lowered by
// curvature and refraction. Written from docs/PANORAMA.md, apart from the code under test.
bool seen_exactly(const Raster& dem, int r0, int c0, double eye, int row, int col) {
  const double k = 0.13, R = 6371000.0, cell = dem.gt[1];
  const double length = std::hypot(row - r0, col - c0);
  if (length < 1.0) return true;
  const auto drop = [&](double d) { return (1.0 - k) * d * d / (2.0 * R); };
  const auto bilinear = [&](double r, double c) {
    const int ri = std::min(static_cast<int>(std::floor(r)), dem.rows - 2);
    const int ci = std::min(static_cast<int>(std::floor(c)), dem.cols - 2);
    const double fr = r - ri, fc = c - ci;
    return (dem.at(ri, ci) * (1 - fc) + dem.at(ri, ci + 1) * fc) * (1 - fr) +
           (dem.at(ri + 1, ci) * (1 - fc) + dem.at(ri + 1, ci + 1) * fc) * fr;
  };
  const double target_d = length * cell;
  const double target = (dem.at(row, col) - drop(target_d) - eye) / target_d;
  const int steps = static_cast<int>(length * 4);
  for (int s = 1; s < steps; ++s) {
    const double t = static_cast<double>(s) / steps, d = t * target_d;
    const double z = bilinear(r0 + t * (row - r0), c0 + t * (col - c0)) - drop(d);
    if ((z - eye) / d > target + 1e-12) return false;
  }
  return true;
}

// The share of cells in range of both on which two visibility rasters (1 visible, 0 hidden) agree.
double agreement(const Raster& a, const Raster& b) {
  std::size_t both = 0, same = 0;
  for (std::size_t k = 0; k < a.values.size(); ++k) {
    if (a.values[k] > 1 || b.values[k] > 1) continue;
    ++both;
    same += a.values[k] == b.values[k];
  }
  return both ? static_cast<double>(same) / static_cast<double>(both) : 0.0;
}

Raster gdal_viewshed(const std::string& dem, std::pair<double, double> observer, double height,
                     const std::string& out) {
  io::DatasetPtr ds(static_cast<GDALDataset*>(GDALOpen(dem.c_str(), GA_ReadOnly)));
  REQUIRE(ds);
  GDALDatasetH shed = GDALViewshedGenerate(
      ds->GetRasterBand(1), "GTiff", out.c_str(), nullptr, observer.first, observer.second, height,
      0.0, 1, 0, 255, 255, 1.0 - 0.13, GVM_Edge, 0.0, nullptr, nullptr, GVOT_NORMAL, nullptr);
  REQUIRE(shed != nullptr);
  GDALClose(shed);
  return read_raster(out);
}

std::size_t layer_features(GDALDataset& ds, const char* name, bool& has_crs) {
  OGRLayer* layer = ds.GetLayerByName(name);
  REQUIRE(layer != nullptr);
  // A layer without a CRS may read back as an undefined local (engineering) one.
  const OGRSpatialReference* srs = layer->GetSpatialRef();
  has_crs = srs != nullptr && !srs->IsLocal();
  return static_cast<std::size_t>(layer->GetFeatureCount());
}

}  // namespace

TEST_CASE("panorama writes its strokes on the map and in the panorama, and its pictures",
          "[cli][panorama]") {
  ScratchDir dir("panorama-outputs");
  const CliRun run = run_cli({"panorama", kSample, dir / "p.gpkg", "--observer", kSummit,
                              "--observer-height", "2", "--visibility", dir / "seen.tif",
                              "--preview", dir / "p.svg", "--stats-json", dir / "p.json"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  io::DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx((dir / "p.gpkg").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr)));
  REQUIRE(ds);
  bool map_crs = false, panorama_crs = true;
  const std::size_t on_map = layer_features(*ds, "map", map_crs);
  const std::size_t in_panorama = layer_features(*ds, "panorama", panorama_crs);
  CHECK(on_map == in_panorama);
  CHECK(on_map > 100);
  CHECK(map_crs);
  CHECK_FALSE(panorama_crs);
  // Panorama x is the azimuth, within the full circle (a turn on across its seam).
  for (auto& feature : *ds->GetLayerByName("panorama")) {
    OGREnvelope box;
    feature->GetGeometryRef()->getEnvelope(&box);
    CHECK(box.MinX >= 0.0);
    CHECK(box.MaxX <= 720.0);
    CHECK(feature->GetFieldAsDouble("azimuth_min") <= feature->GetFieldAsDouble("azimuth_max"));
  }
  // The visibility raster lies on the DEM's grid with its three values.
  const Raster dem = read_raster(kSample), seen = read_raster(dir / "seen.tif");
  CHECK(seen.rows == dem.rows);
  CHECK(seen.cols == dem.cols);
  CHECK(seen.gt == dem.gt);
  std::set<float> values(seen.values.begin(), seen.values.end());
  CHECK(values == std::set<float>{0, 1, 255});
  // Far strokes are lighter: the factual strokes come in more than one shade.
  const std::string svg = test::slurp(dir / "p.svg");
  CHECK(svg.find("id=\"factual\"") != std::string::npos);
  std::set<std::string> shades;
  for (std::size_t at = svg.find("fill=\"#"); at != std::string::npos;
       at = svg.find("fill=\"#", at + 1))
    shades.insert(svg.substr(at + 6, 7));
  CHECK(shades.size() > 5);
}

namespace {

// The seconds that --timings gives each step in `err` ("timings (s): read 0.5, write strokes
// 0.1, ..."), by name.
std::map<std::string, double> timings_of(const std::string& err) {
  const std::string key = "timings (s): ";
  const std::size_t at = err.find(key);
  REQUIRE(at != std::string::npos);
  std::istringstream line(err.substr(at + key.size(), err.find('\n', at) - at - key.size()));
  std::map<std::string, double> seconds;
  for (std::string step; std::getline(line, step, ',');) {
    const std::size_t space = step.find_last_of(' ');
    REQUIRE(space != std::string::npos);
    const std::size_t start = step.find_first_not_of(' ');
    seconds[step.substr(start, space - start)] = std::stod(step.substr(space + 1));
  }
  return seconds;
}

}  // namespace

TEST_CASE("panorama --timings gives each step its seconds, which add up to no more than the run",
          "[cli][panorama]") {
  ScratchDir dir("panorama-timings");
  const std::vector<std::string> view = {"--observer", kSummit, "--observer-height", "2"};
  auto args = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> all = {"panorama", kSample, dir / name};
    all.insert(all.end(), view.begin(), view.end());
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  };
  const CliRun quiet = run_cli(args("q.gpkg", {}));
  REQUIRE(quiet.code == 0);
  CHECK(quiet.err.find("timings") == std::string::npos);

  const auto start = std::chrono::steady_clock::now();
  const CliRun all = run_cli(
      args("a.gpkg", {"--timings", "--visibility", dir / "seen.tif", "--preview", dir / "p.png"}));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(all.err);
  REQUIRE(all.code == 0);
  const std::map<std::string, double> seconds = timings_of(all.err);
  const std::set<std::string> steps = {"read",          "survey",     "rays",   "peaks",
                                       "write strokes", "visibility", "preview"};
  std::set<std::string> named;
  double sum = 0;
  for (const auto& [step, s] : seconds) {
    named.insert(step);
    CHECK(std::isfinite(s));
    CHECK(s >= 0);
    sum += s;
  }
  CHECK(named == steps);
  for (const char* step : {"read", "rays", "write strokes", "visibility", "preview"})
    CHECK(seconds.at(step) > 0);
  // The steps follow one another: together they cannot take longer than the run.
  CHECK(sum <= wall);

  // Outputs not asked for take no time.
  const CliRun bare = run_cli(args("b.gpkg", {"--timings"}));
  REQUIRE(bare.code == 0);
  const std::map<std::string, double> bare_seconds = timings_of(bare.err);
  CHECK(bare_seconds.at("visibility") == 0);
  CHECK(bare_seconds.at("preview") == 0);
  CHECK(bare_seconds.at("rays") > 0);
}

TEST_CASE("the panorama layer draws its elevation angles exaggerated, as chosen or asked",
          "[cli][panorama]") {
  // A field of 360 degrees spans some 6 degrees of elevation: drawn true it was a flat strip.
  ScratchDir dir("panorama-exaggeration");
  const auto heights = [&](const std::string& name, const std::string& exaggeration) {
    const CliRun run = run_cli({"panorama", kSample, dir / name, "--observer", kSummit,
                                "--observer-height", "2", "--panorama-exaggeration", exaggeration});
    REQUIRE(run.code == 0);
    io::DatasetPtr ds(static_cast<GDALDataset*>(
        GDALOpenEx((dir / name).c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr)));
    REQUIRE(ds);
    OGREnvelope box;
    REQUIRE(ds->GetLayerByName("panorama")->GetExtent(&box) == OGRERR_NONE);
    return std::make_pair(box, run.err);
  };
  const auto [true_box, true_said] = heights("one.gpkg", "1");
  const auto [twice, twice_said] = heights("two.gpkg", "2");
  const auto [chosen, chosen_said] = heights("chosen.gpkg", "0");
  CHECK(twice.MinY == Approx(2 * true_box.MinY));
  CHECK(twice.MaxY == Approx(2 * true_box.MaxY));
  CHECK(twice.MaxX == Approx(true_box.MaxX));  // azimuths as they are
  const double span = true_box.MaxY - true_box.MinY, field = true_box.MaxX - true_box.MinX;
  const double k = (chosen.MaxY - chosen.MinY) / span;
  CHECK(k == Approx(std::clamp(360.0 / (8.0 * span), 1.0, 5.0)).epsilon(0.01));
  CHECK(field > 300);
  CHECK_THAT(chosen_said, Catch::Contains("elevation angles") && Catch::Contains("times as tall"));
  // Not exaggerated: said so, not "1 times as tall".
  CHECK_THAT(true_said, Catch::Contains("elevation angles to the same scale as azimuths") &&
                            !Catch::Contains("times as tall"));
}

TEST_CASE("panorama visibility agrees with exact sight lines, closer sampled finer, and GDAL's",
          "[cli][panorama][gdal]") {
  ScratchDir dir("panorama-viewshed");
  for (const std::string name : {"gorillas_utm32n.tif", "bei_5m_local.tif", "volcano.tif"}) {
    const std::string path = kData + "/" + name;
    const Raster dem = read_raster(path);
    // Three observers spread over the DEM, each 10 m above the ground.
    for (const auto& [fr, fc] : {std::pair{0.3, 0.4}, {0.5, 0.5}, {0.7, 0.8}}) {
      const int r0 = static_cast<int>(fr * dem.rows), c0 = static_cast<int>(fc * dem.cols);
      CAPTURE(name, r0, c0);
      const double height = 10.0;
      const CliRun run =
          run_cli({"panorama", path, dir / "p.gpkg", "--observer", coordinates(centre(dem, r0, c0)),
                   "--observer-height", "10", "--visibility", dir / "seen.tif"});
      INFO(run.err);
      REQUIRE(run.code == 0);
      const Raster seen = read_raster(dir / "seen.tif");
      Raster exact = seen;
      const double eye = dem.at(r0, c0) + height;
      for (int r = 0; r < dem.rows; ++r)
        for (int c = 0; c < dem.cols; ++c)
          exact.values[static_cast<std::size_t>(r) * dem.cols + c] =
              seen_exactly(dem, r0, c0, eye, r, c) ? 1.0f : 0.0f;
      const double coarse = agreement(seen, exact);
      CHECK(coarse >= 0.97);
      // Four samples a cell, as the exact sight line is walked, see more nearly what it sees.
      const CliRun fine = run_cli({"panorama", path, dir / "p4.gpkg", "--observer",
                                   coordinates(centre(dem, r0, c0)), "--observer-height", "10",
                                   "--visibility", dir / "seen4.tif", "--samples-per-cell", "4"});
      REQUIRE(fine.code == 0);
      const double fine_agreement = agreement(read_raster(dir / "seen4.tif"), exact);
      CHECK(fine_agreement >= 0.99);
      CHECK(fine_agreement > coarse);
      const Raster shed = gdal_viewshed(path, centre(dem, r0, c0), height, dir / "gdal.tif");
      // GDAL's viewshed interpolates its horizon its own way (docs/PANORAMA.md 2): bench/
      // evaluate_panorama.py reports the agreement, which is held here well above chance.
      CHECK(agreement(seen, shed) >= 0.9);
    }
  }
}

TEST_CASE("panorama refuses a view it cannot draw, and writes nothing", "[cli][panorama]") {
  ScratchDir dir("panorama-refusals");
  const std::string geographic = kData + "/jacksboro_geo.tif";
  const std::string holes = dir / "holes.tif";
  test::write_tiff(
      holes, 40, 40, 1, [](int, int r, int c) { return r < 20 && c < 20 ? -9999.0f : 100.0f; },
      test::kNorthUp, 32616, -9999);
  // A DEM of one cell reaches less than a sample from any observer on it: a longer
  // --max-distance, which the refusal advised, cannot help.
  const std::string one_cell = dir / "one_cell.tif";
  test::write_tiff(
      one_cell, 1, 1, 1, [](int, int, int) { return 100.0f; }, test::kNorthUp, 32616);
  struct Refusal {
    std::vector<std::string> args;
    std::string message;
    int code;  // 1: the DEM or a file cannot be used; 2: bad usage
  };
  const std::vector<Refusal> cases = {
      {{one_cell, "--observer", "500005,3999995"}, "the DEM reaches only 7.07", 1},
      {{kSample, "--observer", "0,0"}, "outside the DEM", 1},
      {{holes, "--observer", "500050,3999950"}, "without data", 1},
      {{kSample, "--observer", kSummit, "--max-distance", "0"}, "must be a positive distance", 2},
      {{kSample, "--observer", kSummit, "--max-distance", "-5"}, "must be a positive distance", 2},
      {{kSample, "--observer", kSummit, "--azimuth-from", "30", "--azimuth-to", "30"},
       "field of view from 30 to 30 degrees is empty",
       2},
      {{geographic, "--observer", "-84,36"}, "gdalwarp", 1},
      {{kSample}, "needs --observer", 2},
      {{kSample, "--observer", "749008"}, "needs X,Y", 2},
      {{kSample, "--observer", kSummit, "--refraction", "1"}, "refraction coefficient", 2},
      {{kSample, "--observer", kSummit, "--samples-per-cell", "9"}, "samples per cell", 2},
      {{kSample, "--observer", kSummit, "--panorama-exaggeration", "0.5"},
       "exaggeration must be from 1 to 50",
       2},
      // The figures as given, not rounded to nothing.
      {{kSample, "--observer", kSummit, "--max-distance", "1e-9"},
       "the range of 1e-09 map units",
       1},
      {{kSample, "--observer", kSummit, "--azimuth-from", "1e20"}, "got 1e+20 and 360", 2},
      {{kSample, "--observer", kSummit, "--observer-height", "-2"}, "observer height", 2},
      {{kSample, "--observer", kSummit, "--visibility", dir / "seen.png"}, "GeoTIFF", 2},
      {{kSample, "--observer", kSummit, "--preview", dir / "p.png", "--page", "A3", "--page-scale",
        "50000"},
       "--page-scale",
       2},
  };
  for (const auto& [args, message, code] : cases) {
    std::vector<std::string> full = {"panorama", args.front(), dir / "out.gpkg"};
    full.insert(full.end(), args.begin() + 1, args.end());
    CAPTURE(full);
    const CliRun run = run_cli(full);
    CHECK(run.code == code);
    CHECK_THAT(run.err, Catch::Contains(message));
    CHECK_FALSE(test::fs::exists(dir / "out.gpkg"));
    CHECK_FALSE(test::fs::exists(dir / "seen.png"));
  }
  // One layer per file cannot hold the map and the panorama.
  const CliRun shp = run_cli({"panorama", kSample, dir / "out.shp", "--observer", kSummit});
  CHECK(shp.code == 2);
  CHECK_THAT(shp.err, Catch::Contains(".gpkg"));
  CHECK(dir.file_count() == 2);  // holes.tif and one_cell.tif alone
}

namespace {

// A GeoJSON of named points given in the DEM's CRS (EPSG:32616), written in longitude and
// latitude, as a gazetteer's would be.
void write_peaks(const std::string& path,
                 const std::vector<std::pair<std::string, std::pair<double, double>>>& peaks,
                 const char* geometry = "Point") {
  OGRSpatialReference utm, wgs84;
  utm.importFromEPSG(32616);
  wgs84.importFromEPSG(4326);
  utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> to_degrees(
      OGRCreateCoordinateTransformation(&utm, &wgs84));
  std::ofstream out(path);
  out << std::setprecision(12) << R"({"type": "FeatureCollection", "features": [)";
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    double x = peaks[k].second.first, y = peaks[k].second.second;
    REQUIRE(to_degrees->Transform(1, &x, &y));
    const bool point = std::string(geometry) == "Point";
    out << (k ? "," : "") << R"({"type": "Feature", "properties": {"label": ")" << peaks[k].first
        << R"("}, "geometry": {"type": ")" << geometry << R"(", "coordinates": )";
    if (point) {
      out << "[" << x << ", " << y << "]}}";
    } else {  // a line from the point a little east
      out << "[[" << x << ", " << y << "], [" << x + 0.001 << ", " << y << "]]}}";
    }
  }
  out << "]}\n";
}

}  // namespace

TEST_CASE("panorama labels the peaks in sight, from points in another CRS", "[cli][panorama]") {
  ScratchDir dir("panorama-peaks");
  // A wall 8 m high 1 km east of the observer, a ridge 30 m high 3.5 km east; 10 m cells.
  const std::string dem = dir / "wall.tif";
  test::write_tiff(
      dem, 41, 400, 1,
      [](int, int, int c) {
        if (c >= 100 && c <= 102) return 8.0f;
        return static_cast<float>(std::max(0.0, 30.0 - 6.0 * std::abs(c - 355)));
      },
      test::kNorthUp, 32616);
  const auto at_col = [](int c) { return std::pair{500000.0 + 10 * c + 5, 4000000.0 - 205}; };
  write_peaks(dir / "peaks.geojson",
              {{"Wall top", at_col(101)}, {"In the shadow", at_col(150)}, {"Ridge", at_col(355)}});
  const CliRun run =
      run_cli({"panorama", dem, dir / "p.gpkg", "--observer", coordinates(at_col(0)),
               "--observer-height", "12", "--azimuth-from", "45", "--azimuth-to", "135", "--peaks",
               dir / "peaks.geojson", "--peak-names", "label", "--preview", dir / "p.svg"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK_THAT(run.out, Catch::Contains("2 of the 3 peaks are in sight"));
  io::DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx((dir / "p.gpkg").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr)));
  REQUIRE(ds);
  OGRLayer* peaks = ds->GetLayerByName("peaks");
  REQUIRE(peaks != nullptr);
  std::vector<std::string> names;
  for (auto& feature : *peaks) {
    names.push_back(feature->GetFieldAsString("name"));
    CHECK(feature->GetFieldAsDouble("azimuth") == Approx(90.0).margin(1e-6));
  }
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"Ridge", "Wall top"});
  const std::string svg = test::slurp(dir / "p.svg");
  CHECK(svg.find(">Ridge</text>") != std::string::npos);
  CHECK(svg.find("In the shadow") == std::string::npos);
  // A name field that is not there, and lines where points belong, are refused.
  const CliRun no_field = run_cli({"panorama", dem, dir / "q.gpkg", "--observer",
                                   coordinates(at_col(0)), "--peaks", dir / "peaks.geojson"});
  CHECK(no_field.code == 1);
  CHECK_THAT(no_field.err, Catch::Contains("no field 'name'"));
  CHECK_THAT(no_field.err, Catch::Contains("label"));
  write_peaks(dir / "lines.geojson", {{"A", at_col(10)}}, "LineString");
  const CliRun lines =
      run_cli({"panorama", dem, dir / "q.gpkg", "--observer", coordinates(at_col(0)), "--peaks",
               dir / "lines.geojson", "--peak-names", "label"});
  CHECK(lines.code == 1);
  CHECK_THAT(lines.err, Catch::Contains("must be points"));
  // A raster, and a pipe, given as peaks say what they are ("unknown GDAL error", "give a raster
  // file" before).
  const CliRun raster = run_cli(
      {"panorama", dem, dir / "q.gpkg", "--observer", coordinates(at_col(0)), "--peaks", dem});
  CHECK(raster.code == 1);
  CHECK_THAT(raster.err, Catch::Contains("it is a raster; give points"));
  REQUIRE(mkfifo((dir / "pipe.gpkg").c_str(), 0600) == 0);
  const CliRun pipe = run_cli({"panorama", dem, dir / "q.gpkg", "--observer",
                               coordinates(at_col(0)), "--peaks", dir / "pipe.gpkg"});
  CHECK(pipe.code == 1);
  CHECK_THAT(pipe.err, Catch::Contains("is not a file") && !Catch::Contains("raster"));
  CHECK_FALSE(test::fs::exists(dir / "q.gpkg"));
}

TEST_CASE("panorama adapts its filter to each neighbourhood with --adapt local",
          "[cli][panorama]") {
  ScratchDir dir("panorama-local");
  const auto fset = [&](const std::string& adapt) {
    const CliRun run = run_cli({"panorama", kSample, dir / (adapt + ".gpkg"), "--observer", kSummit,
                                "--adapt", adapt, "--stats-json", dir / (adapt + ".json")});
    INFO(run.err);
    REQUIRE(run.code == 0);
    const std::string json = test::slurp(dir / (adapt + ".json"));
    const std::size_t at = json.find("\"fset_pct\": ");
    REQUIRE(at != std::string::npos);
    return std::stod(json.substr(at + 12));
  };
  const double whole = fset("whole"), local = fset("local");
  CHECK(whole > 0.0);
  // The summit's rugged neighbourhoods get lower cut-offs than the whole DEM's: more f-set.
  CHECK(local > 1.5 * whole);
}
