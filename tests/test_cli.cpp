// The terrain-sketch command line, run in-process: outputs, formats, and every bad input it must
// refuse with a message and without leaving a file behind.
#include <fcntl.h>
#include <ogrsf_frmts.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <set>
#include <thread>

#include "catch_compat.h"
#include "cli/command_support.h"
#include "cli_run.h"
#include "core/method/silhouettes.h"
#include "gdal_test_support.h"
#include "io/read/dem_reader.h"
#include "io/read/gdal_util.h"
#include "io/write/vector_writer.h"

using namespace tsk;
using test::CliRun;
using test::run_cli;
using test::ScratchDir;

namespace {

const std::string kSample = TSK_SAMPLE_DEM;
const std::string kData = TSK_TEST_DATA;

struct VectorSummary {
  long long features = 0;
  std::map<std::string, long long> per_class;
  long long null_depth_formulated = 0;
  long long measured = 0;                      // features whose geometry read back has M values
  OGRwkbGeometryType layer_type = wkbUnknown;  // as the layer declares it
  int epsg = 0;
  std::vector<std::string> fields;
};

VectorSummary summarise(const std::string& path) {
  GDALAllRegister();
  GDALDataset* ds = static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  REQUIRE(ds != nullptr);
  OGRLayer* layer = ds->GetLayer(0);
  VectorSummary s;
  s.layer_type = layer->GetGeomType();
  OGRFeatureDefn* defn = layer->GetLayerDefn();
  for (int k = 0; k < defn->GetFieldCount(); ++k)
    s.fields.push_back(defn->GetFieldDefn(k)->GetNameRef());
  if (const OGRSpatialReference* srs = layer->GetSpatialRef()) {
    const char* code = srs->GetAuthorityCode(nullptr);
    s.epsg = code ? std::atoi(code) : -1;
  }
  const int class_field = defn->GetFieldIndex("class");
  const int depth_field = defn->GetFieldIndex("mean_depth");
  for (auto& feature : *layer) {
    ++s.features;
    const std::string cls = class_field >= 0 ? feature->GetFieldAsString(class_field) : "";
    ++s.per_class[cls];
    if (cls == "formulated" && depth_field >= 0 && feature->IsFieldNull(depth_field)) {
      ++s.null_depth_formulated;
    }
    REQUIRE(feature->GetGeometryRef() != nullptr);
    s.measured += feature->GetGeometryRef()->IsMeasured() ? 1 : 0;
  }
  GDALClose(ds);
  return s;
}

using test::hill;
using test::kNorthUp;
using test::slurp;

}  // namespace

TEST_CASE("the sample DEM becomes a GeoPackage equal to the core's result", "[cli]") {
  ScratchDir dir("sample");
  // The thesis's filter and strokes, which the core runs by default (SPEC 1.5, 1.7-1.9).
  const CliRun run =
      run_cli({"silhouettes", kSample, dir / "out.gpkg", "--stats-json", dir / "stats.json",
               "--preview", dir / "sketch.png", "--filter", "fixed", "--strokes", "exact"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK(run.err.empty());

  io::DemOptions options;
  const io::Dem dem = io::read_dem(kSample, options, 90.0);
  const SilhouetteResult core = run_silhouettes(dem.oriented, dem.frame, dem.geotransform, {});
  VectorSummary s = summarise(dir / "out.gpkg");
  CHECK(s.features == static_cast<long long>(core.strokes.size()));
  CHECK(s.per_class["factual"] == static_cast<long long>(core.stats.factual_strokes));
  CHECK(s.per_class["formulated"] == static_cast<long long>(core.stats.formulated_strokes));
  CHECK(s.null_depth_formulated == s.per_class["formulated"]);
  CHECK(s.epsg == 32616);
  for (const char* field :
       {"class", "cells", "length", "mean_slope", "mean_row_slope", "mean_depth", "mean_dist"}) {
    CHECK(std::find(s.fields.begin(), s.fields.end(), field) != s.fields.end());
  }

  const std::string json = slurp(dir / "stats.json");
  for (const char* k : {"hidden_pct", "occluding_pct", "cset_pct", "fset_pct", "tset_pct",
                        "gset_pct", "factual_strokes", "formulated_strokes"}) {
    CHECK_THAT(json, Catch::Contains(std::string("\"") + k + "\": "));
  }
  CHECK_THAT(json,
             Catch::Contains("\"factual_strokes\": " + std::to_string(core.stats.factual_strokes)));

  GDALDataset* png = static_cast<GDALDataset*>(GDALOpen((dir / "sketch.png").c_str(), GA_ReadOnly));
  REQUIRE(png != nullptr);
  CHECK(std::string(png->GetDriver()->GetDescription()) == "PNG");
  CHECK(png->GetRasterXSize() == 1600);
  GDALClose(png);
  CHECK(dir.file_count() == 3);  // no temporary leftovers
}

TEST_CASE("drawn strokes go out as LineString M with their weights, exact ones as LineString",
          "[cli][drawn]") {
  ScratchDir dir("drawn");
  const CliRun drawn = run_cli({"silhouettes", kSample, dir / "drawn.gpkg", "--filter", "fixed"});
  const CliRun exact = run_cli(
      {"silhouettes", kSample, dir / "exact.gpkg", "--filter", "fixed", "--strokes", "exact"});
  REQUIRE(drawn.code == 0);
  REQUIRE(exact.code == 0);
  io::DemOptions options;
  const io::Dem dem = io::read_dem(kSample, options, 90.0);
  SilhouetteParams params;
  params.strokes.mode = StrokeMode::drawn;
  const SilhouetteResult core =
      run_silhouettes(dem.oriented, dem.frame, dem.geotransform, ResolvedParams(params));
  GDALAllRegister();
  for (const char* name : {"drawn.gpkg", "exact.gpkg"}) {
    const bool weighted = std::string(name) == "drawn.gpkg";
    GDALDataset* ds = static_cast<GDALDataset*>(GDALOpenEx(
        (dir / name).c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    REQUIRE(ds != nullptr);
    OGRLayer* layer = ds->GetLayer(0);
    CHECK(layer->GetGeomType() == (weighted ? wkbLineStringM : wkbLineString));
    // The core's strokes of each class in the core's order, with the core's weights as M; the
    // command line writes the classes interleaved as strokes complete.
    std::size_t next[2] = {0, core.stats.factual_strokes};
    for (auto& feature : *layer) {
      const auto* line = feature->GetGeometryRef()->toLineString();
      CHECK(line->IsMeasured() == weighted);
      if (!weighted) continue;
      std::size_t& k = next[std::string(feature->GetFieldAsString("class")) == "factual" ? 0 : 1];
      REQUIRE(k < core.strokes.size());
      const Stroke& s = core.strokes[k++];
      REQUIRE(line->getNumPoints() == static_cast<int>(s.points.size()));
      for (int j = 0; j < line->getNumPoints(); ++j) {
        CHECK(line->getM(j) == s.weights[static_cast<std::size_t>(j)]);
        CHECK(line->getX(j) == s.points[static_cast<std::size_t>(j)].x);
      }
    }
    if (weighted) {
      CHECK(next[0] == core.stats.factual_strokes);
      CHECK(next[1] == core.strokes.size());
    }
    CHECK(layer->GetFeatureCount() ==
          static_cast<GIntBig>(weighted ? core.strokes.size()
                                        : summarise(dir / "exact.gpkg").features));
    GDALClose(ds);
  }
}

TEST_CASE("a shapefile keeps every attribute under its shortened name", "[cli]") {
  ScratchDir dir("shp");
  const CliRun run = run_cli({"silhouettes", kData + "/volcano.tif", dir / "s.shp"});
  REQUIRE(run.code == 0);
  GDALDataset* ds = static_cast<GDALDataset*>(
      GDALOpenEx((dir / "s.shp").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
  REQUIRE(ds != nullptr);
  OGRLayer* layer = ds->GetLayer(0);
  const int row_slope = layer->GetLayerDefn()->GetFieldIndex("mean_row_s");
  REQUIRE(row_slope >= 0);
  bool any = false;
  for (auto& f : *layer)
    any = any || (f->IsFieldSetAndNotNull(row_slope) && f->GetFieldAsDouble(row_slope) > 0);
  CHECK(any);
  GDALClose(ds);
}

// Each feature of a vector file as text (its fields and its geometry's WKT), in file order.
std::vector<std::string> features_as_text(const std::string& path) {
  GDALDataset* ds = static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  REQUIRE(ds != nullptr);
  std::vector<std::string> features;
  for (auto& feature : *ds->GetLayer(0)) {
    std::string text;
    for (int k = 0; k < feature->GetFieldCount(); ++k)
      text += std::string(feature->GetFieldAsString(k)) + ";";
    if (const OGRGeometry* g = feature->GetGeometryRef()) text += g->exportToWkt();
    features.push_back(text);
  }
  GDALClose(ds);
  return features;
}

TEST_CASE("FlatGeobuf holds the GeoPackage's strokes, in its spatial index's order", "[cli]") {
  // The README says so: every other format keeps the scan's order, FlatGeobuf's index its own.
  ScratchDir dir("fgb-order");
  for (const char* name : {"out.gpkg", "out.fgb"}) {
    const CliRun run = run_cli({"silhouettes", kSample, dir / name});
    INFO(run.err);
    REQUIRE(run.code == 0);
  }
  const std::vector<std::string> scan = features_as_text(dir / "out.gpkg");
  std::vector<std::string> indexed = features_as_text(dir / "out.fgb");
  REQUIRE(scan.size() > 100);
  CHECK(indexed != scan);
  std::vector<std::string> sorted_scan = scan;
  std::sort(sorted_scan.begin(), sorted_scan.end());
  std::sort(indexed.begin(), indexed.end());
  CHECK(indexed == sorted_scan);
}

TEST_CASE("output formats follow the extension", "[cli]") {
  ScratchDir dir("formats");
  std::set<std::string> lost_m;  // the formats whose drawn strokes read back without M values
  for (const char* name :
       {"out.geojson", "out.shp", "out.fgb", "out.gml", "out.kml", "out.sqlite", "out.csv"}) {
    CAPTURE(name);
    // The second run replaces the first run's output.
    for (const char* command : {"silhouettes", "silhouettes", "profiles", "pstrokes"}) {
      CAPTURE(command);
      const CliRun run = run_cli({command, kData + "/gorillas_utm32n.tif", dir / name});
      INFO(run.err);
      REQUIRE(run.code == 0);
      const VectorSummary written = summarise(dir / name);
      CHECK(written.features > 0);
      // Drawn strokes' weights are M values: told exactly when the file read back has none (GDAL
      // 3.10's GeoJSON driver says it takes M values, and drops them).
      const bool told = run.err.find("keeps no M values") != std::string::npos;
      if (std::string(command) == "silhouettes") {
        CHECK(told == (written.measured == 0));
        if (written.measured == 0) lost_m.insert(name);
        // A layer of lines with M values is not declared 3D: QGIS took a SQLite file's so, and
        // saving it elsewhere lost the weights.
        CHECK_FALSE(OGR_GT_HasZ(written.layer_type));
        if (written.measured > 0 && written.layer_type != wkbUnknown)
          CHECK(written.layer_type == wkbLineStringM);
      } else {
        CHECK_FALSE(told);
      }
    }
  }
  // GML and KML keep no M values in any GDAL the project meets.
  CHECK(lost_m.count("out.gml") == 1);
  CHECK(lost_m.count("out.kml") == 1);
  const CliRun exact = run_cli(
      {"silhouettes", kData + "/gorillas_utm32n.tif", dir / "exact.geojson", "--strokes", "exact"});
  CHECK(exact.code == 0);
  CHECK_THAT(exact.err, !Catch::Contains("M values"));
  const CliRun bad = run_cli({"silhouettes", kSample, dir / "out.xyz"});
  CHECK(bad.code == 1);
  CHECK_THAT(bad.err, Catch::Contains("--format"));
  const CliRun forced = run_cli({"silhouettes", kSample, dir / "out.xyz", "--format", "GeoJSON"});
  CHECK(forced.code == 0);
  // A name of another format's extension is refused (CSV into x.gpkg made a folder of CSV files).
  const CliRun mismatched = run_cli({"silhouettes", kSample, dir / "x.gpkg", "--format", "CSV"});
  CHECK(mismatched.code == 1);
  CHECK_FALSE(std::filesystem::exists(dir / "x.gpkg"));
}

TEST_CASE("plan-oblique output and view options are passed through", "[cli]") {
  ScratchDir dir("options");
  const CliRun run = run_cli({"silhouettes",
                              kSample,
                              dir / "o.gpkg",
                              "--geometry",
                              "oblique",
                              "--azimuth",
                              "180",
                              "--ve",
                              "2",
                              "--base-slope",
                              "66.67",
                              "--row-cut",
                              "18",
                              "--col-cut",
                              "10",
                              "--ctrl",
                              "6",
                              "--no-diagonals",
                              "--window",
                              "2",
                              "--min-cells",
                              "4",
                              "--subcell",
                              "--placement",
                              "near_and_far",
                              "--threads",
                              "1"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK(summarise(dir / "o.gpkg").features > 0);
}

TEST_CASE("bad input is refused with a message and leaves nothing behind", "[cli][robustness]") {
  ScratchDir dir("bad");
  std::ofstream(dir / "not_a_raster.tif") << "hello";
  test::write_tiff(
      dir / "multi.tif", 40, 40, 2, [](int b, int r, int c) { return hill(b, r, c) * b; }, kNorthUp,
      32616);
  const double rotated[6] = {500000, 10, 2, 4000000, 2, -10};
  test::write_tiff(dir / "rotated.tif", 40, 40, 1, hill, rotated, 32616);
  const double south_up[6] = {500000, 10, 0, 4000000, 0, 10};
  test::write_tiff(dir / "southup.tif", 40, 40, 1, hill, south_up, 32616);
  test::write_tiff(dir / "nogeo.tif", 40, 40, 1, hill, nullptr, 0);
  // Georeferencing that places no cell: a corner not a number (a run drew nothing and blamed
  // short chains), or so far out that doubles cannot tell the cells apart (strokes collapsed).
  const double nan_origin[6] = {std::nan(""), 10, 0, 4000000, 0, -10};
  test::write_tiff(dir / "nan_origin.tif", 40, 40, 1, hill, nan_origin, 32616);
  const double far_origin[6] = {500000, 10, 0, 1e300, 0, -10};
  test::write_tiff(dir / "far_origin.tif", 40, 40, 1, hill, far_origin, 32616);
  const double tiny_cells[6] = {500000, 1e-300, 0, 4000000, 0, -1e-300};
  test::write_tiff(dir / "tiny_cells.tif", 40, 40, 1, hill, tiny_cells, 32616);
  // A DEM in a GeoPackage, where the strokes could go too.
  test::write_tiff(dir / "hill.tif", 40, 40, 1, hill, kNorthUp, 32616);
  test::copy_raster_to_gpkg(dir / "hill.tif", dir / "dem.gpkg");
  const std::string dem_gpkg_bytes = slurp(dir / "dem.gpkg");
  REQUIRE(!dem_gpkg_bytes.empty());
  std::filesystem::create_directory(dir / "taken.png");
  // Outputs named as what no output may replace.
  std::filesystem::create_directory(dir / "folder.gpkg");
  std::filesystem::create_directory(dir / "folder.tif");
  REQUIRE(mkfifo((dir / "pipe.geojson").c_str(), 0644) == 0);
  {
    GDALDataset* complex = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
        (dir / "complex.tif").c_str(), 20, 20, 1, GDT_CFloat32, nullptr);
    REQUIRE(complex != nullptr);
    complex->SetGeoTransform(const_cast<double*>(kNorthUp));
    GDALClose(complex);
  }
  const std::size_t inputs = dir.file_count();

  struct Bad {
    std::vector<std::string> args;
    std::string message;
  };
  const std::string out = dir / "out.gpkg";
  // Input or output that cannot be used: exit code 1.
  const Bad refused[] = {
      {{"silhouettes", kData + "/jacksboro_geo.tif", out}, "gdalwarp -t_srs EPSG:32616"},
      {{"silhouettes", dir / "not_a_raster.tif", out}, "cannot open"},
      {{"silhouettes", dir / "missing.tif", out}, "cannot open"},
      {{"silhouettes", dir / "rotated.tif", out}, "rotated"},
      {{"silhouettes", dir / "southup.tif", out}, "north-up"},
      {{"silhouettes", dir / "nogeo.tif", out}, "--cell-size"},
      {{"silhouettes", dir / "nan_origin.tif", out}, "not all finite numbers (nan, 10"},
      {{"silhouettes", dir / "far_origin.tif", out}, "too far for coordinates to tell"},
      {{"silhouettes", dir / "tiny_cells.tif", out}, "thousandth of its 1e-300 cells"},
      {{"profiles", dir / "far_origin.tif", out}, "gdal_edit.py -a_ullr"},
      {{"silhouettes", dir / "multi.tif", out, "--band", "3"}, "band 3 does not exist"},
      {{"silhouettes", kData + "/volcano.tif", dir / "out.kml"}, "no CRS to find them from"},
      {{"silhouettes", kSample, dir / "no/such/folder/out.gpkg"}, "does not exist"},
      {{"silhouettes", kSample, dir / "x.gpkg", "--format", "CSV"}, "a .gpkg name is GPKG's"},
      {{"silhouettes", dir / "complex.tif", out}, "complex numbers (CFloat32)"},
      {{"silhouettes", kSample, out, "--format", "NoSuchDriver"}, "not an OGR vector driver"},
      {{"silhouettes", dir / "dem.gpkg", dir / "dem.gpkg"}, "names a file the INPUT raster reads"},
      {{"classify", dir / "multi.tif", dir / "./multi.tif"}, "names a file the INPUT raster reads"},
      {{"drape", kSample, dir / "multi.tif", "--source", dir / "multi.tif"},
       "names a file the --source raster reads"},
      {{"silhouettes", kSample, dir / "o.json", "--stats-json", dir / "o.json"},
       "names OUTPUT too"},
      {{"silhouettes", kSample, dir / "folder.gpkg"}, "is not a file"},
      {{"silhouettes", kSample, dir / "pipe.geojson"}, "is not a file"},
      {{"classify", kSample, dir / "folder.tif"}, "is not a file"},
      // The strokes would be written, then the preview or statistics fail.
      {{"silhouettes", kSample, out, "--preview", dir / "no/such/p.png"}, "does not exist"},
      {{"silhouettes", kSample, out, "--stats-json", dir / "no/such/s.json"}, "does not exist"},
      {{"classify", kSample, dir / "c.tif", "--stats-json", dir / "no/s.json"}, "does not exist"},
      // A preview that cannot be put in place (a folder of its name) takes the strokes with it.
      {{"silhouettes", kSample, out, "--preview", dir / "taken.png"}, "taken.png"},
  };
  // Bad usage (an option, its value, an output name of the wrong kind): exit code 2.
  const Bad misused[] = {
      {{"silhouettes", kSample, out, "--filter", "thesis"}, "'adaptive' or 'fixed'"},
      {{"silhouettes", kSample, out, "--strokes", "smooth"}, "'drawn' or 'exact'"},
      {{"silhouettes", kSample, out, "--smooth", "-1"}, "smoothing (cells) must be between 0"},
      {{"silhouettes", kSample, out, "--smooth-tolerance", "3"}, "tolerance (cells) must be"},
      {{"silhouettes", kSample, out, "--join-gap", "nan"}, "--join-gap needs a number"},
      {{"silhouettes", kSample, out, "--join-angle", "120"}, "join angle (degrees) must be"},
      {{"silhouettes", kSample, out, "--taper", "0.6"}, "taper (share"},
      {{"silhouettes", kSample, out, "--depth-cue", "1"}, "depth cue"},
      {{"silhouettes", kSample, out, "--extend", "11"}, "over-extension (cells) must be"},
      {{"silhouettes", kSample, out, "--adapt", "regional"}, "'whole' or 'local'"},
      {{"silhouettes", kSample, out, "--adapt-window", "4"}, "between 8 and 100000"},
      {{"silhouettes", kSample, out, "--ve", "0"}, "exaggeration"},
      {{"silhouettes", kSample, out, "--ve", "abc"}, "needs a number"},
      {{"silhouettes", kSample, out, "--ctrl", "13"}, "control point"},
      {{"silhouettes", kSample, out, "--azimuth", "400"}, "azimuth"},
      {{"silhouettes", kSample, out, "--azimuth", "nan"}, "azimuth"},
      {{"silhouettes", kSample, out, "--base-slope", "-5"}, "base slope"},
      {{"silhouettes", kSample, out, "--min-cells", "1"}, "at least 2"},
      {{"silhouettes", kSample, out, "--window", "2.5"}, "whole number"},
      // Read as something else before: hexadecimal, exponents in whole numbers, a JPEG name
      // for a PNG, a folder of CSV files named .gpkg, a complex band's real part.
      {{"silhouettes", kSample, out, "--azimuth", "0x5A"}, "needs a number"},
      {{"silhouettes", kSample, out, "--band", "1e0"}, "whole number"},
      {{"silhouettes", kSample, out, "--preview", dir / "x.jpg"}, ".png, .svg or .pdf name"},
      {{"silhouettes", dir / "nogeo.tif", out, "--cell-size", "0"}, "--cell-size must be positive"},
      {{"silhouettes", dir / "nogeo.tif", out, "--cell-size", "-1"},
       "--cell-size must be positive"},
      {{"silhouettes", dir / "nogeo.tif", out, "--cell-size", "nan"}, "--cell-size needs a number"},
      {{"silhouettes", kSample, out, "--min-cells", "1e20"}, "whole number from"},
      {{"silhouettes", kSample, out, "--window", "nan"}, "whole number from"},
      {{"silhouettes", kSample, out, "--ctrl", "1e-400"}, "too large or too small"},
      {{"silhouettes", kSample, out, "--ve", "1e400"}, "too large or too small"},
      {{"silhouettes", kSample, out, "--geometry", "sideways"}, "geometry"},
      {{"silhouettes", kSample, out, "--bogus"}, "unknown option"},
      {{"silhouettes", kSample, out, "--ve"}, "needs a value"},
      // A second value would silently win over the first.
      {{"silhouettes", kSample, out, "--azimuth", "90", "--ve", "2", "--azimuth", "45"},
       "--azimuth is given twice ('90', then '45'); give each option once"},
      {{"silhouettes", kSample, out, "--subcell", "--subcell"}, "--subcell is given twice;"},
      {{"silhouettes", kSample}, "expected INPUT and OUTPUT"},
      // An output's name says what it holds: no other file is written over.
      {{"silhouettes", kSample, out, "--stats-json", dir / "dem.gpkg"}, "give it a .json name"},
      {{"filter-plot", kSample, dir / "dem.gpkg"}, "give it an .html name"},
      {{"silhouettes", kSample, out, "--preview", dir / "p.json", "--stats-json", dir / "p.json"},
       "give it a .png, .svg or"},
  };
  const auto check_refused = [&](const Bad& b, int code) {
    const CliRun run = run_cli(b.args);
    CAPTURE(b.args.back(), run.err);
    CHECK(run.code == code);
    CHECK_THAT(run.err, Catch::Contains(b.message));
    CHECK(dir.file_count() == inputs);
  };
  for (const Bad& b : refused) check_refused(b, 1);
  for (const Bad& b : misused) check_refused(b, 2);
  CHECK(slurp(dir / "dem.gpkg") == dem_gpkg_bytes);
  CHECK(run_cli({"frobnicate"}).code == 2);
  CHECK(run_cli({}).code == 2);
  CHECK(run_cli({"--help"}).code == 0);
  // The version is the plugin's (metadata.txt), so the two cannot drift apart.
  const CliRun version = run_cli({"--version"});
  CHECK(version.code == 0);
  std::ifstream metadata(TSK_METADATA);
  std::string line, plugin_version;
  while (std::getline(metadata, line))
    if (line.rfind("version=", 0) == 0) plugin_version = line.substr(8);
  REQUIRE(!plugin_version.empty());
  CHECK_THAT(version.out, Catch::StartsWith("terrain-sketch " + plugin_version + " (GDAL "));
}

TEST_CASE("an output over a file holding other data is refused, the file kept",
          "[cli][robustness]") {
  ScratchDir dir("other_data");
  // A project's GeoPackage and SQLite database each with a layer of its own next to an earlier
  // silhouettes layer, and a GeoPackage holding a DEM.
  const std::string project = dir / "project.gpkg", database = dir / "project.sqlite";
  const std::string dem = dir / "dem.gpkg";
  for (const std::string& file : {project, database}) {
    REQUIRE(run_cli({"silhouettes", kData + "/volcano.tif", file}).code == 0);
    GDALDatasetH ds =
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr);
    REQUIRE(ds != nullptr);
    REQUIRE(GDALDatasetCreateLayer(ds, "roads", nullptr, wkbLineString, nullptr) != nullptr);
    GDALClose(ds);
  }
  test::copy_raster_to_gpkg(kSample, dem);
  const std::string project_bytes = slurp(project), database_bytes = slurp(database);
  const std::string dem_bytes = slurp(dem);
  const std::size_t files = dir.file_count();
  struct Refused {
    std::string command, path, message;
  };
  const Refused cases[] = {{"silhouettes", project, "holds the layer 'roads'"},
                           {"profiles", project, "holds the layer 'roads'"},
                           {"pstrokes", project, "holds the layer 'roads'"},
                           {"silhouettes", database, "holds the layer 'roads'"},
                           {"silhouettes", dem, "holds a raster"}};
  for (const Refused& r : cases) {
    CAPTURE(r.command, r.path);
    const CliRun run = run_cli({r.command, kData + "/volcano.tif", r.path});
    CHECK(run.code == 1);
    CHECK_THAT(run.err, Catch::Contains(r.message));
  }
  CHECK(slurp(project) == project_bytes);
  CHECK(slurp(database) == database_bytes);
  CHECK(slurp(dem) == dem_bytes);
  CHECK(dir.file_count() == files);
}

TEST_CASE("a failed run keeps an earlier output intact", "[cli][robustness]") {
  ScratchDir dir("keep");
  std::ofstream(dir / "out.geojson") << "earlier";
  const CliRun run = run_cli({"silhouettes", kData + "/jacksboro_geo.tif", dir / "out.geojson"});
  CHECK(run.code == 1);
  CHECK(slurp(dir / "out.geojson") == "earlier");
  CHECK(dir.file_count() == 1);
}

TEST_CASE("a read that fails after strokes were written leaves no output", "[cli][robustness]") {
  // Strokes are written as they complete; the top half of this DEM reads, the bottom half's
  // file is gone, so the run fails after the first strips' strokes are in the file.
  ScratchDir dir("midway");
  test::write_tiff(dir / "top.tif", 40, 40, 1, hill, kNorthUp, 32616);
  test::write_half_missing_vrt(dir / "dem.vrt", "top.tif");
  const CliRun top = run_cli({"silhouettes", dir / "top.tif", dir / "top.gpkg"});
  REQUIRE(top.code == 0);
  REQUIRE(summarise(dir / "top.gpkg").features > 0);
  const std::size_t files = dir.file_count();
  for (const char* out : {"out.gpkg", "out.shp", "out.geojson"}) {
    CAPTURE(out);
    // The adaptive filter reads a sample of the DEM first, which fails before any stroke.
    for (const char* filter : {"fixed", "adaptive"}) {
      CAPTURE(filter);
      const CliRun run =
          run_cli({"silhouettes", dir / "dem.vrt", dir / out, "--strips", "5", "--filter", filter});
      CHECK(run.code == 1);
      CHECK_THAT(run.err, Catch::Contains("gone.tif"));
      CHECK(dir.file_count() == files);
    }
  }
}

TEST_CASE("infinite heights are nodata to the plan-oblique reference of a strip run too",
          "[cli][robustness]") {
  // The strip run finds the DEM's lowest height in a pass of its own before the first strip;
  // -Inf must not become the reference there (GDAL's own minimum would be -Inf).
  ScratchDir dir("infinite");
  test::write_tiff(
      dir / "inf.tif", 40, 40, 1,
      [](int b, int r, int c) {
        return r == 5 && c == 5    ? -std::numeric_limits<float>::infinity()
               : r == 30 && c == 7 ? std::numeric_limits<float>::infinity()
                                   : hill(b, r, c);
      },
      kNorthUp, 32616);
  for (const char* az : {"90", "45"}) {
    CAPTURE(az);
    const std::vector<std::string> common = {"--geometry", "oblique", "--azimuth", az};
    std::vector<std::string> whole = {"silhouettes", dir / "inf.tif", dir / "w.geojson",
                                      "--preview", dir / "w.png"};
    std::vector<std::string> strips = {"silhouettes", dir / "inf.tif", dir / "s.geojson",
                                       "--strips", "7"};
    whole.insert(whole.end(), common.begin(), common.end());
    strips.insert(strips.end(), common.begin(), common.end());
    REQUIRE(run_cli(whole).code == 0);
    const CliRun run = run_cli(strips);
    INFO(run.err);
    REQUIRE(run.code == 0);
    CHECK(summarise(dir / "s.geojson").features > 0);
    CHECK(slurp(dir / "w.geojson") == slurp(dir / "s.geojson"));
  }
}

TEST_CASE("edge-case rasters give valid, possibly empty, outputs", "[cli][robustness]") {
  ScratchDir dir("edge");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  test::write_tiff(
      dir / "one.tif", 1, 1, 1, [](int, int, int) { return 5.f; }, kNorthUp, 32616);
  test::write_tiff(
      dir / "allnan.tif", 30, 30, 1, [=](int, int, int) { return nan; }, kNorthUp, 32616);
  test::write_tiff(
      dir / "multi.tif", 40, 40, 2, [](int b, int r, int c) { return hill(b, r, c) * b; }, kNorthUp,
      32616);
  test::write_tiff(dir / "nogeo.tif", 40, 40, 1, hill, nullptr, 0);
  for (const char* name : {"one.tif", "allnan.tif"}) {
    const CliRun run = run_cli({"silhouettes", dir / name, dir / (std::string(name) + ".gpkg")});
    INFO(run.err);
    REQUIRE(run.code == 0);
    CHECK(summarise(dir / (std::string(name) + ".gpkg")).features == 0);
  }
  // The drape of rasters with no cell in sight (at an oblique azimuth, or no data at all) is one
  // cell without data; GDAL refused to make the raster of no cells it was.
  test::write_tiff(
      dir / "row.tif", 1, 20, 1, [](int, int, int c) { return 5.f + c; }, kNorthUp, 32616);
  test::write_tiff(
      dir / "column.tif", 20, 1, 1, [](int, int r, int) { return 5.f + r; }, kNorthUp, 32616);
  test::write_tiff(
      dir / "onevalid.tif", 20, 20, 1,
      [=](int, int r, int c) { return r == 5 && c == 5 ? 100.f : nan; }, kNorthUp, 32616);
  for (const char* name : {"one.tif", "row.tif", "column.tif", "onevalid.tif", "allnan.tif"}) {
    for (const char* azimuth : {"33", "90"}) {
      CAPTURE(name, azimuth);
      const std::string draped = dir / (std::string("draped_") + azimuth + name);
      const CliRun run =
          run_cli({"drape", dir / name, draped, "--source", dir / name, "--azimuth", azimuth});
      INFO(run.err);
      REQUIRE(run.code == 0);
      io::DatasetPtr ds(static_cast<GDALDataset*>(GDALOpen(draped.c_str(), GA_ReadOnly)));
      REQUIRE(ds);
      CHECK(ds->GetRasterXSize() >= 1);
    }
  }
  // An RGB image is refused whichever band is named (band 1 gave strokes of nonsense).
  test::write_tiff(
      dir / "rgb.tif", 40, 40, 3, [](int b, int r, int c) { return hill(b, r, c) * b; }, kNorthUp,
      32616);
  test::mark_rgb(dir / "rgb.tif");
  for (const char* band : {"1", "3"}) {
    const CliRun rgb = run_cli({"silhouettes", dir / "rgb.tif", dir / "rgb.gpkg", "--band", band});
    CHECK(rgb.code == 1);
    CHECK_THAT(rgb.err, Catch::Contains("is a colour channel") && Catch::Contains("give a DEM"));
  }
  CHECK_FALSE(std::filesystem::exists(dir / "rgb.gpkg"));
  const CliRun band2 = run_cli({"silhouettes", dir / "multi.tif", dir / "b2.gpkg", "--band", "2"});
  INFO(band2.err);
  CHECK(band2.code == 0);
  const CliRun nogeo =
      run_cli({"silhouettes", dir / "nogeo.tif", dir / "ng.gpkg", "--cell-size", "10"});
  CHECK(nogeo.code == 0);
  CHECK_THAT(nogeo.err, Catch::Contains("no georeferencing"));
  // A raster placed by ground control points has georeferencing, only not a geotransform: it was
  // told it had none, and with a cell size drawn in the grid's own frame without a word.
  test::write_tiff(dir / "gcp.tif", 40, 40, 1, hill, nullptr, 0);
  {
    io::DatasetPtr gcp(static_cast<GDALDataset*>(GDALOpen((dir / "gcp.tif").c_str(), GA_Update)));
    REQUIRE(gcp);
    GDAL_GCP points[3];
    GDALInitGCPs(3, points);
    const double place[3][4] = {
        {0, 0, 500000, 4000000}, {40, 0, 500400, 4000000}, {0, 40, 500000, 3999600}};
    for (int k = 0; k < 3; ++k) {
      points[k].dfGCPPixel = place[k][0], points[k].dfGCPLine = place[k][1];
      points[k].dfGCPX = place[k][2], points[k].dfGCPY = place[k][3];
    }
    OGRSpatialReference utm;
    utm.importFromEPSG(32616);
    REQUIRE(gcp->SetGCPs(3, points, &utm) == CE_None);
    GDALDeinitGCPs(3, points);
  }
  const CliRun by_gcps = run_cli({"silhouettes", dir / "gcp.tif", dir / "gcp.gpkg"});
  CHECK(by_gcps.code == 1);
  CHECK_THAT(by_gcps.err, Catch::Contains("is placed by 3 ground control points") &&
                              Catch::Contains("gdalwarp -dstnodata -9999"));
  CHECK_FALSE(std::filesystem::exists(dir / "gcp.gpkg"));
  const CliRun gcps_unused =
      run_cli({"silhouettes", dir / "gcp.tif", dir / "gcp.gpkg", "--cell-size", "10"});
  CHECK(gcps_unused.code == 0);
  CHECK_THAT(gcps_unused.err, Catch::Contains("its 3 ground control points are not used"));
  const CliRun ignored =
      run_cli({"silhouettes", kSample, dir / "ignored.gpkg", "--cell-size", "10"});
  CHECK(ignored.code == 0);
  CHECK_THAT(ignored.err, Catch::Contains("--cell-size 10 is ignored"));
}

TEST_CASE("a DEM with no sloping cell says so, not that its median slope is nan", "[cli]") {
  ScratchDir dir("no_slope");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  test::write_tiff(
      dir / "flat.tif", 20, 20, 1, [](int, int, int) { return 100.f; }, kNorthUp, 32616);
  test::write_tiff(
      dir / "allnan.tif", 20, 20, 1, [=](int, int, int) { return nan; }, kNorthUp, 32616);
  for (const char* name : {"flat.tif", "allnan.tif"}) {
    CAPTURE(name);
    for (const char* command : {"filter-plot", "silhouettes"}) {
      const std::string out = dir / (std::string(name) + (command[0] == 'f' ? ".html" : ".gpkg"));
      const CliRun run = run_cli({command, dir / name, out});
      REQUIRE(run.code == 0);
      CHECK_THAT(run.err, Catch::Contains("no cell slopes") && !Catch::Contains("nan"));
    }
  }
}

TEST_CASE("a drape of heights beyond any terrain is refused with its size", "[cli][robustness]") {
  // Heights of 1e25 beside 0 shift cells 1e24 cells away, or beyond any number: the size was
  // cast to 9223372036854775808 x 0 cells, or to none at all. (Heights from 1e30 on are float's
  // fill values, read as nodata.)
  ScratchDir dir("huge_heights");
  test::write_tiff(
      dir / "spike.tif", 20, 20, 1, [](int, int r, int c) { return r + c == 0 ? 0.f : 1e25f; },
      kNorthUp, 32616);
  for (const char* azimuth : {"33", "90", "200"}) {
    CAPTURE(azimuth);
    const CliRun run = run_cli({"drape", dir / "spike.tif", dir / "d.tif", "--source",
                                dir / "spike.tif", "--azimuth", azimuth});
    CHECK(run.code == 1);
    CHECK_THAT(run.err, Catch::Contains("far larger than the DEM's 20 x 20 cells") &&
                            Catch::Contains("check the DEM's heights"));
    CHECK_THAT(run.err, !Catch::Contains("9223372036854775808"));
    CHECK(dir.file_count() == 1);
  }
}

TEST_CASE("an undeclared fill value among the heights gets a note", "[cli]") {
  ScratchDir dir("fill");
  const auto filled = [](int band, int r, int c) { return c < 6 ? -9999.0f : hill(band, r, c); };
  test::write_tiff(dir / "filled.tif", 40, 40, 1, filled, kNorthUp, 32616);
  const CliRun run = run_cli({"silhouettes", dir / "filled.tif", dir / "out.gpkg"});
  CHECK(run.code == 0);
  CHECK_THAT(run.err, Catch::Contains("-9999, a common fill value"));
  CHECK_THAT(run.err, Catch::Contains("gdal_edit.py -a_nodata -9999"));
  // Declared as nodata, it is no height at all.
  test::write_tiff(dir / "declared.tif", 40, 40, 1, filled, kNorthUp, 32616, -9999.0);
  const CliRun declared = run_cli({"silhouettes", dir / "declared.tif", dir / "declared.gpkg"});
  CHECK(declared.code == 0);
  CHECK_THAT(declared.err, !Catch::Contains("fill value"));
}

TEST_CASE("float's fill values are read as nodata, with a note", "[cli]") {
  // Undeclared, a strip of float's highest value stood as a wall that hid the hill behind it (5
  // strokes instead of 1 426 on jacksboro), and its lowest skewed plan-oblique's reference height.
  ScratchDir dir("fill_taken");
  const auto strip = [](float fill) {
    return [fill](int band, int r, int c) { return c < 6 ? fill : hill(band, r, c); };
  };
  test::write_tiff(dir / "declared.tif", 40, 40, 1, strip(-1.0f), kNorthUp, 32616, -1.0);
  for (const std::string geometry : {"map", "oblique"}) {
    const CliRun declared = run_cli({"silhouettes", dir / "declared.tif", dir / "declared.csv",
                                     "--azimuth", "270", "--geometry", geometry});
    REQUIRE(declared.code == 0);
    CHECK_THAT(declared.err, !Catch::Contains("fill value"));
    const std::string oracle = slurp(dir / "declared.csv");
    CHECK(oracle.size() > 1000);
    for (const float fill : {3.4028235e38f, -3.4028235e38f, 1e30f}) {
      CAPTURE(geometry, fill);
      test::write_tiff(dir / "filled.tif", 40, 40, 1, strip(fill), kNorthUp, 32616);
      const CliRun run = run_cli({"silhouettes", dir / "filled.tif", dir / "filled.csv",
                                  "--azimuth", "270", "--geometry", geometry});
      CHECK(run.code == 0);
      CHECK_THAT(run.err, Catch::Contains("a fill value (of magnitude 1e30 or more") &&
                              Catch::Contains("taken as nodata") && !Catch::Contains("gdal_edit"));
      CHECK(slurp(dir / "filled.csv") == oracle);
    }
  }
}

TEST_CASE("a band's scale and offset turn its values into heights, as QGIS turns them", "[cli]") {
  ScratchDir dir("scaled");
  // Heights in 1/64 m, so that (z - 100) * 2 stored and read back as x 0.5 + 100 is exact.
  const auto height = [](int band, int r, int c) {
    return std::round(hill(band, r, c) * 64.0f) / 64.0f;
  };
  test::write_tiff(dir / "metres.tif", 40, 40, 1, height, kNorthUp, 32616);
  const auto stored = [&](int band, int r, int c) { return (height(band, r, c) - 100.0f) * 2.0f; };
  const auto scaled = [&](const std::string& name, double scale, double offset) {
    test::write_tiff(dir / name, 40, 40, 1, stored, kNorthUp, 32616);
    GDALDatasetH ds = GDALOpen((dir / name).c_str(), GA_Update);
    REQUIRE(ds != nullptr);
    GDALSetRasterScale(GDALGetRasterBand(ds, 1), scale);
    GDALSetRasterOffset(GDALGetRasterBand(ds, 1), offset);
    GDALClose(ds);
  };
  scaled("scaled.tif", 0.5, 100.0);
  const io::BandWindows windows(dir / "scaled.tif", 1);
  std::vector<float> heights(40 * 40);
  windows.read({0, 0, 40, 40}, heights.data());
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 40; ++c)
      REQUIRE(heights[static_cast<std::size_t>(r * 40 + c)] == height(1, r, c));
  const CliRun metres = run_cli({"silhouettes", dir / "metres.tif", dir / "metres.geojson"});
  const CliRun run = run_cli({"silhouettes", dir / "scaled.tif", dir / "scaled.geojson"});
  REQUIRE(metres.code == 0);
  REQUIRE(run.code == 0);
  CHECK_THAT(run.err, Catch::Contains("values x 0.5 + 100, its scale and offset"));
  CHECK(summarise(dir / "metres.geojson").features > 0);
  CHECK(slurp(dir / "metres.geojson") == slurp(dir / "scaled.geojson"));
  // A scale of 0 would make every height the offset.
  scaled("zero.tif", 0.0, 100.0);
  const CliRun zero = run_cli({"silhouettes", dir / "zero.tif", dir / "zero.geojson"});
  CHECK(zero.code == 1);
  CHECK_THAT(zero.err, Catch::Contains("scale of 0"));
  CHECK_FALSE(std::filesystem::exists(dir / "zero.geojson"));
}

TEST_CASE("heights that rise more than any terrain get a note", "[cli]") {
  // The hill in millimetres: 300 000 over a DEM 400 m across, and in millimetres with the scale
  // that makes them metres.
  ScratchDir dir("relief");
  const auto millimetres = [](int band, int r, int c) { return 1000 * hill(band, r, c); };
  test::write_tiff(dir / "mm.tif", 40, 40, 1, millimetres, kNorthUp, 32616);
  const CliRun run = run_cli({"silhouettes", dir / "mm.tif", dir / "mm.gpkg"});
  CHECK(run.code == 0);
  CHECK_THAT(run.err, Catch::Contains("more than any terrain") &&
                          Catch::Contains("gdal_edit.py -scale 0.001"));
  GDALDatasetH ds = GDALOpen((dir / "mm.tif").c_str(), GA_Update);
  REQUIRE(ds != nullptr);
  GDALSetRasterScale(GDALGetRasterBand(ds, 1), 0.001);
  GDALClose(ds);
  const CliRun scaled = run_cli({"silhouettes", dir / "mm.tif", dir / "scaled.gpkg"});
  CHECK(scaled.code == 0);
  CHECK_THAT(scaled.err, !Catch::Contains("more than any terrain"));
}

TEST_CASE("a CRS in feet runs with a note that heights must be in feet too", "[cli]") {
  ScratchDir dir("feet");
  const double geotransform[6] = {2000000, 30, 0, 700000, 0, -30};
  test::write_tiff(dir / "feet.tif", 40, 40, 1, hill, geotransform, 2264);
  const CliRun run = run_cli({"silhouettes", dir / "feet.tif", dir / "out.gpkg"});
  CHECK(run.code == 0);
  CHECK_THAT(run.err, Catch::Contains("linear unit is US survey foot, not the metre"));
  const CliRun metres = run_cli({"silhouettes", kSample, dir / "metres.gpkg"});
  CHECK(metres.code == 0);
  CHECK_THAT(metres.err, !Catch::Contains("linear unit"));
}

TEST_CASE("the adaptive filter says which cut-offs it chose", "[cli][filter]") {
  ScratchDir dir("filter-report");
  const CliRun run =
      run_cli({"silhouettes", kSample, dir / "a.gpkg", "--stats-json", dir / "a.json"});
  REQUIRE(run.code == 0);
  CHECK_THAT(run.err, Catch::Contains("adaptive slope filter: median slope 23.9 %"));
  const std::string json = slurp(dir / "a.json");
  CHECK_THAT(json, Catch::Contains("\"mode\": \"adaptive\"") &&
                       Catch::Contains("\"median_slope_pct\": 23.9") &&
                       Catch::Contains("\"height_tolerance\""));
  // Local adaptivity reports the range of its scales; the fixed filter its cut-offs as given.
  const CliRun local = run_cli({"silhouettes", kSample, dir / "l.gpkg", "--adapt", "local",
                                "--adapt-window", "50", "--stats-json", dir / "l.json"});
  REQUIRE(local.code == 0);
  CHECK_THAT(local.err, Catch::Contains("local adaptivity over 50 cells"));
  CHECK_THAT(slurp(dir / "l.json"), Catch::Contains("\"local_scale_lowest\""));
  const CliRun fixed = run_cli({"silhouettes", kSample, dir / "f.gpkg", "--filter", "fixed",
                                "--row-cut", "25", "--stats-json", dir / "f.json"});
  REQUIRE(fixed.code == 0);
  CHECK(fixed.err.empty());
  CHECK_THAT(slurp(dir / "f.json"), Catch::Contains("\"mode\": \"fixed\"") &&
                                        Catch::Contains("\"row_cut_pct\": 25.000000") &&
                                        Catch::Contains("\"median_slope_pct\": null"));
}

TEST_CASE("classify writes the stage of every DEM cell with a colour table", "[cli][diagnostics]") {
  ScratchDir dir("classify");
  const CliRun run = run_cli({"silhouettes", kSample, dir / "s.gpkg"});
  REQUIRE(run.code == 0);
  const CliRun cls = run_cli({"classify", kSample, dir / "classes.tif", "--filter", "fixed"});
  INFO(cls.err);
  REQUIRE(cls.code == 0);
  GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen((dir / "classes.tif").c_str(), GA_ReadOnly));
  REQUIRE(ds != nullptr);
  GDALRasterBand* band = ds->GetRasterBand(1);
  CHECK(band->GetColorTable() != nullptr);
  REQUIRE(band->GetCategoryNames() != nullptr);
  CHECK(std::string(band->GetCategoryNames()[3]) == "occluding");
  // Class counts equal the core's stage counts (cardinal view: one DEM cell per oriented cell).
  io::DemOptions options;
  const io::Dem dem = io::read_dem(kSample, options, 90.0);
  const SilhouetteResult core = run_silhouettes(dem.oriented, dem.frame, dem.geotransform, {});
  std::vector<GByte> pixels(dem.rows * dem.cols);
  REQUIRE(band->RasterIO(GF_Read, 0, 0, static_cast<int>(dem.cols), static_cast<int>(dem.rows),
                         pixels.data(), static_cast<int>(dem.cols), static_cast<int>(dem.rows),
                         GDT_Byte, 0, 0) == CE_None);
  std::size_t thinned = 0, valid = 0;
  for (GByte v : pixels) thinned += v == 6, valid += v != 0;
  CHECK(thinned == core.stats.thinned);
  CHECK(valid == core.stats.valid);
  GDALClose(ds);
  CHECK(run_cli({"classify", kSample, dir / "classes.png"}).code == 2);
}

TEST_CASE("row-slope and profiles write their outputs", "[cli][profile plot]") {
  ScratchDir dir("apps");
  const CliRun slope = run_cli({"row-slope", kSample, dir / "rs.tif", "--azimuth", "30"});
  INFO(slope.err);
  REQUIRE(slope.code == 0);
  GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen((dir / "rs.tif").c_str(), GA_ReadOnly));
  REQUIRE(ds != nullptr);
  double minmax[2];
  REQUIRE(ds->GetRasterBand(1)->ComputeRasterMinMax(FALSE, minmax) == CE_None);
  CHECK(minmax[0] >= 0.0);
  CHECK(minmax[1] > 20.0);  // the Jacksboro ridges are steep
  GDALClose(ds);
  const CliRun prof = run_cli({"profiles", kSample, dir / "p.geojson", "--every", "20"});
  INFO(prof.err);
  REQUIRE(prof.code == 0);
  CHECK(summarise(dir / "p.geojson").features > 20);
  CHECK(run_cli({"profiles", kSample, dir / "q.geojson", "--every", "0"}).code == 2);
}

TEST_CASE("filter-plot writes the diagram page", "[cli][filter diagram]") {
  ScratchDir dir("filter");
  const CliRun run = run_cli({"filter-plot", kSample, dir / "f.html", "--no-diagonals"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const std::string html = slurp(dir / "f.html");
  CHECK_THAT(html, Catch::Contains("<svg"));
  CHECK_THAT(html, Catch::Contains("no diagonals"));
}

TEST_CASE("drape projects every band of a raster on the DEM's grid", "[cli][drape]") {
  ScratchDir dir("drape");
  test::write_tiff(
      dir / "rgb.tif", 87, 61, 3,
      [](int b, int r, int c) { return static_cast<float>(b * 1000 + r + c); }, nullptr, 0);
  const CliRun run =
      run_cli({"drape", kData + "/volcano.tif", dir / "d.tif", "--source", dir / "rgb.tif"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen((dir / "d.tif").c_str(), GA_ReadOnly));
  REQUIRE(ds != nullptr);
  CHECK(ds->GetRasterCount() == 3);
  double minmax[2];
  REQUIRE(ds->GetRasterBand(3)->ComputeRasterMinMax(FALSE, minmax) == CE_None);
  CHECK(minmax[0] >= 3000);
  GDALClose(ds);
  const CliRun off = run_cli({"drape", kSample, dir / "e.tif", "--source", dir / "rgb.tif"});
  CHECK(off.code == 1);
  CHECK_THAT(off.err, Catch::Contains("on the DEM's grid"));
  CHECK(run_cli({"drape", kSample, dir / "f.tif"}).code == 2);
  // The same size is not enough: the same ground, in the same CRS. Both were draped silently.
  const double shifted[6] = {732795.639415354, 75, 0, 4038415.4307843, 0, -75};
  const double on_dem[6] = {731795.639415354467928, 75, 0, 4037415.430784302297980, 0, -75};
  const auto flat = [](int, int, int) { return 1.0f; };
  test::write_tiff(dir / "shifted.tif", 436, 414, 1, flat, shifted, 32616);
  test::write_tiff(dir / "zone17.tif", 436, 414, 1, flat, on_dem, 32617);
  const CliRun moved = run_cli({"drape", kSample, dir / "g.tif", "--source", dir / "shifted.tif"});
  CHECK(moved.code == 1);
  CHECK_THAT(moved.err, Catch::Contains("lies on another grid than the DEM: origin 732795.6394"));
  const CliRun zone = run_cli({"drape", kSample, dir / "h.tif", "--source", dir / "zone17.tif"});
  CHECK(zone.code == 1);
  CHECK_THAT(zone.err, Catch::Contains("UTM zone 17N"));
  CHECK(!std::filesystem::exists(dir / "g.tif"));
}

TEST_CASE("pstrokes writes classes and scores, and refuses bad tolerances", "[cli][pstrokes]") {
  ScratchDir dir("pstrokes");
  const CliRun run = run_cli({"pstrokes", kSample, dir / "p.geojson", "--geometry", "oblique"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK(summarise(dir / "p.geojson").features > 100);
  const CliRun bad = run_cli({"pstrokes", kSample, dir / "q.geojson", "--convex-row", "-1"});
  CHECK(bad.code == 2);
  CHECK_THAT(bad.err, Catch::Contains("tolerances"));
}

TEST_CASE("strips give byte-identical output to the whole DEM", "[cli][strips]") {
  // The tool reads strips of 1024 profiles (the sample DEM in one), or of --strips N: windows of
  // rows or columns for the cardinal views, the bands the strips sample for the others. The
  // whole DEM read, turned and run in one piece by the core, written by the same writer, is the
  // reference.
  ScratchDir dir("strips");
  for (const char* az : {"0", "90", "180", "270", "45", "200"}) {
    CAPTURE(az);
    const io::DemOptions options;
    const io::Dem whole = io::read_dem(kSample, options, std::stod(az));
    SilhouetteParams asked;
    asked.view.azimuth_deg = std::stod(az);
    asked.geometry = Geometry::oblique;
    asked.adaptive.mode = FilterMode::adaptive;  // the command line's defaults
    asked.strokes.mode = StrokeMode::drawn;
    const ResolvedParams params =
        adapt_filter(asked, whole.grid, io::DemFile(kSample, options).source().read);
    const FilterReport& filter = params.filter();
    StageStats reference;
    io::write_strokes(
        dir / "whole.geojson", "", whole.srs_wkt,
        [&](const io::StrokeWriter& write) {
          SilhouetteStream stream(whole.frame, whole.geotransform, params, whole.lowest_height, {},
                                  [&](Stroke&& stroke) { write(stroke); });
          stream.add_strip(whole.oriented, 0, whole.frame.profiles);
          reference = stream.finish().stats;
        },
        io::kStrokeLayer, true);
    std::ofstream(dir / "whole.json") << cli::stats_json(reference, filter);
    const std::vector<std::string> common = {"--azimuth", az, "--geometry", "oblique"};
    auto run = [&](const std::string& name, std::vector<std::string> extra) {
      std::vector<std::string> args = {"silhouettes", kSample, dir / (name + ".geojson"),
                                       "--stats-json", dir / (name + ".json")};
      args.insert(args.end(), common.begin(), common.end());
      args.insert(args.end(), extra.begin(), extra.end());
      const CliRun r = run_cli(args);
      INFO(r.err);
      REQUIRE(r.code == 0);
      return r;
    };
    run("previewed", {"--preview", dir / "w.png"});
    const CliRun by_default = run("default", {"--timings"});
    run("narrow", {"--strips", "23"});
    CHECK(summarise(dir / "whole.geojson").features > 100);
    CHECK(slurp(dir / "whole.geojson") == slurp(dir / "default.geojson"));
    CHECK(slurp(dir / "whole.geojson") == slurp(dir / "narrow.geojson"));
    CHECK(slurp(dir / "whole.geojson") == slurp(dir / "previewed.geojson"));
    CHECK(slurp(dir / "whole.json") == slurp(dir / "default.json"));
    CHECK(slurp(dir / "whole.json") == slurp(dir / "narrow.json"));
    CHECK_THAT(by_default.err, Catch::Contains("read") && Catch::Contains("alongside the stages"));
  }
  // The preview reads the whole DEM once more after the strokes, whatever the strips.
  const CliRun preview = run_cli(
      {"silhouettes", kSample, dir / "y.gpkg", "--strips", "10", "--preview", dir / "p.png"});
  CHECK(preview.code == 0);
  CHECK(std::filesystem::file_size(dir / "p.png") > 1000);
  CHECK(run_cli({"silhouettes", kSample, dir / "z.gpkg", "--strips", "0"}).code == 2);
}

TEST_CASE("a DEM too large to hold whole is refused by the commands that need it whole",
          "[cli][robustness]") {
  ScratchDir dir("huge");
  test::write_huge_vrt(dir / "huge.vrt");
  for (const char* command : {"classify", "row-slope"}) {
    CAPTURE(command);
    const CliRun run = run_cli({command, dir / "huge.vrt", dir / "out.tif"});
    CHECK(run.code == 1);
    CHECK_THAT(run.err, Catch::Contains("too large") && Catch::Contains("strip by strip"));
  }
  CHECK(dir.file_count() == 1);
  // The silhouettes' preview is laid out over the DEM averaged instead: test_page_heights.cpp.
}

TEST_CASE("a preview of a DEM too large to hold is laid out over it averaged", "[cli][preview]") {
  ScratchDir dir("averaged_preview");
  const CliRun held =
      run_cli({"silhouettes", kSample, dir / "held.gpkg", "--preview", dir / "held.svg"});
  REQUIRE(held.code == 0);
  CHECK_THAT(held.err, !Catch::Contains("averaged"));
  // Half a megabyte may hold 100 000 cells turned to the view; the sample has 180 000.
  setenv("TSK_MEMORY_MB", "1", 1);
  const CliRun small =
      run_cli({"silhouettes", kSample, dir / "small.gpkg", "--preview", dir / "small.svg"});
  setenv("TSK_MEMORY_MB", "half", 1);
  const CliRun nonsense = run_cli({"silhouettes", kSample, dir / "x.gpkg"});
  unsetenv("TSK_MEMORY_MB");
  REQUIRE(small.code == 0);
  CHECK_THAT(
      small.err,
      Catch::Contains("the preview is laid out over the DEM averaged 2 x 2 cells (414 x 436"));
  CHECK(features_as_text(dir / "small.gpkg") == features_as_text(dir / "held.gpkg"));
  const auto paths = [](const std::string& svg) {
    const std::string text = test::slurp(svg);
    std::size_t count = 0;
    for (std::size_t at = text.find("<path"); at != std::string::npos;
         at = text.find("<path", at + 1))
      ++count;
    return count;
  };
  CHECK(paths(dir / "small.svg") > 1000);
  CHECK(paths(dir / "small.svg") == paths(dir / "held.svg"));
  CHECK(nonsense.code == 1);
  CHECK_THAT(nonsense.err, Catch::Contains("TSK_MEMORY_MB") && Catch::Contains("'half'"));
}

TEST_CASE("a command line run interrupted leaves nothing behind", "[cli][robustness]") {
  ScratchDir dir("interrupt");
  // Half a second of work or more on one thread at azimuth 45, a few dozen strokes.
  const auto rolling = [](int, int r, int c) {
    return static_cast<float>(400 + 150 * std::sin(c * 0.011 + 0.4 * std::sin(r * 0.007)) +
                              60 * std::sin(r * 0.013 + c * 0.004));
  };
  test::write_tiff(dir / "dem.tif", 4000, 4000, 1, rolling, kNorthUp, 32616);
  const std::string dem = dir / "dem.tif", output = dir / "strokes.gpkg";
  struct Case {
    int signal;
    bool ignored_at_start;  // as nohup starts a program: the run goes on
  };
  for (const Case& c :
       {Case{SIGINT, false}, Case{SIGTERM, false}, Case{SIGHUP, false}, Case{SIGHUP, true}}) {
    CAPTURE(c.signal, c.ignored_at_start);
    posix_spawn_file_actions_t quiet;
    posix_spawn_file_actions_init(&quiet);
    posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
    const char* argv[] = {"terrain-sketch", "silhouettes", dem.c_str(),
                          output.c_str(),   "--azimuth",   "45",
                          "--threads",      "1",           nullptr};
    pid_t child = 0;
    const auto before = std::signal(c.signal, c.ignored_at_start ? SIG_IGN : SIG_DFL);
    REQUIRE(posix_spawn(&child, TSK_CLI_BINARY, &quiet, nullptr, const_cast<char**>(argv),
                        environ) == 0);
    std::signal(c.signal, before);
    posix_spawn_file_actions_destroy(&quiet);
    // Once its staging folder is there, the run is writing strokes.
    const auto writing = [&] {
      for (const auto& entry : std::filesystem::directory_iterator(dir.path))
        if (entry.path().filename().string().rfind(".strokes.gpkg.partial", 0) == 0) return true;
      return false;
    };
    int status = 0;
    bool ended_early = false;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!writing() && !ended_early && std::chrono::steady_clock::now() < give_up) {
      ended_early = waitpid(child, &status, WNOHANG) == child;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    REQUIRE_FALSE(ended_early);
    kill(child, c.signal);
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    if (c.ignored_at_start) {
      CHECK(WEXITSTATUS(status) == 0);
      CHECK(dir.file_count() == 2);  // the DEM and the strokes
      CHECK(summarise(output).features > 10);
    } else {
      CHECK(WEXITSTATUS(status) == 130);
      CHECK(dir.file_count() == 1);  // the DEM alone
    }
  }
}

TEST_CASE("the command line shows its progress as GDAL's tools do", "[cli]") {
  ScratchDir dir("progress");
  std::ostringstream out, err;
  REQUIRE(cli::run({"silhouettes", kSample, dir / "out.gpkg"}, out, err, true) == 0);
  CHECK_THAT(err.str(),
             Catch::Contains("0...10...20...30...40...50...60...70...80...90...100 - done.\n"));
  CHECK(run_cli({"silhouettes", kSample, dir / "quiet.gpkg"}).err.find("...") == std::string::npos);
}

TEST_CASE("an output name up to the file system's 255 bytes can be written", "[cli]") {
  ScratchDir dir("long");
  const std::string name = std::string(255 - 8, 'n') + ".geojson";  // staged under a shorter one
  const CliRun run = run_cli({"silhouettes", kSample, dir / name});
  INFO(run.err);
  CHECK(run.code == 0);
  CHECK(summarise(dir / name).features > 100);
  CHECK(dir.file_count() == 1);
  // A GeoPackage's name must leave room for SQLite's journal beside it: said before any work,
  // in a line (GDAL's message quoted hundreds of characters of SQL).
  const std::string journal_fits = std::string(255 - 8 - 5, 'g') + ".gpkg";
  CHECK(run_cli({"silhouettes", kSample, dir / journal_fits}).code == 0);
  const CliRun too_long = run_cli({"silhouettes", kSample, dir / ("g" + journal_fits)});
  CHECK(too_long.code == 1);
  CHECK_THAT(too_long.err, Catch::Contains("shorten the name by 1 byte(s)"));
  CHECK(too_long.err.size() < 600);
}

TEST_CASE("a disk that fills up fails the run in every format and leaves nothing behind",
          "[cli][robustness]") {
  // A file size limit stands in for a full disk: writes past it fail as they would (EFBIG
  // rather than ENOSPC). GeoJSON, KML and GML ignore whether their writes succeed; they used to
  // close the cut-off file as if whole, and the run reported success.
  ScratchDir dir("full");
  struct Case {
    std::string command, output;
  };
  std::vector<Case> cases;
  for (const char* extension : {"geojson", "kml", "gml", "csv", "fgb", "shp", "gpkg", "sqlite"})
    cases.push_back({"silhouettes", std::string("strokes.") + extension});
  cases.push_back({"classify", "classes.tif"});
  cases.push_back({"row-slope", "slope.tif"});
  cases.push_back({"profiles", "profiles.geojson"});
  cases.push_back({"filter-plot", "filter.html"});
  for (const Case& c : cases) {
    CAPTURE(c.command, c.output);
    const std::string output = dir / c.output;
    const std::string errors = dir.path.parent_path() / "full-disk-errors.txt";
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      const rlimit limit{8 * 1024, 8 * 1024};  // less than any output here, compressed or not
      setrlimit(RLIMIT_FSIZE, &limit);
      std::signal(SIGXFSZ, SIG_IGN);  // a failed write, not the end of the program
      const int err = open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(err, 2);
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 1);
      execl(TSK_CLI_BINARY, "terrain-sketch", c.command.c_str(), kSample.c_str(), output.c_str(),
            nullptr);
      _exit(127);
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    const std::string message = slurp(errors);
    INFO(message);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 1);
    CHECK(dir.file_count() == 0);
    // A text output says why it could not be written (it said "cannot write" alone).
    if (c.command == "filter-plot") CHECK_THAT(message, Catch::Contains("File too large"));
    std::filesystem::remove(errors);
  }
  // Without the limit every format is written.
  const CliRun whole = run_cli({"silhouettes", kSample, dir / "strokes.kml"});
  CHECK(whole.code == 0);
  CHECK(summarise(dir / "strokes.kml").features > 100);
}

TEST_CASE("what runs killed outright left in a folder is removed by the next run there", "[cli]") {
  ScratchDir dir("stale");
  // The staging folder of a process that has ended, and one of a process that lives (ours).
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) _exit(0);
  REQUIRE(waitpid(child, nullptr, 0) == child);
  const std::string stale = dir / (".strokes.gpkg.partial-" + std::to_string(child));
  const std::string live = dir / (".strokes.gpkg.partial-" + std::to_string(getppid()));
  const std::string other = dir / (".other.gpkg.partial-" + std::to_string(child));
  for (const std::string& folder : {stale, live, other}) {
    std::filesystem::create_directory(folder);
    std::ofstream(folder + "/.terrain-sketch-staging");  // the mark of a run's staging folder
    std::ofstream(folder + "/strokes.gpkg") << "half an output";
  }
  // A user's folders of the same shape, without the mark, and a link to one: never touched.
  const std::string photos = dir / (".photos.partial-" + std::to_string(child));
  std::filesystem::create_directories(photos + "/sub");
  std::ofstream(photos + "/sub/img.jpg") << "a picture";
  const std::string linked = dir / (".linked.partial-" + std::to_string(child));
  std::filesystem::create_directory_symlink(photos, linked);
  const CliRun run = run_cli({"silhouettes", kSample, dir / "strokes.gpkg"});
  REQUIRE(run.code == 0);
  CHECK_FALSE(std::filesystem::exists(stale));
  CHECK(std::filesystem::exists(live));         // a run still going
  CHECK_FALSE(std::filesystem::exists(other));  // another output's, of a run gone too
  CHECK(std::filesystem::exists(photos + "/sub/img.jpg"));
  CHECK(std::filesystem::is_symlink(linked));
  CHECK(summarise(dir / "strokes.gpkg").features > 100);
}

TEST_CASE("each command takes its own options, and refuses the others by name", "[cli]") {
  ScratchDir dir("per_command");
  struct Refused {
    std::vector<std::string> args;  // after the command, INPUT and OUTPUT
    std::string command, output, message;
  };
  const std::vector<Refused> cases = {
      {{"--observer", "1,2"}, "classify", "c.tif", "classify does not take --observer"},
      {{"--strokes", "exact"}, "profiles", "p.gpkg", "profiles does not take --strokes"},
      {{"--every", "3"}, "silhouettes", "s.gpkg", "silhouettes does not take --every"},
      {{"--azimuth", "45"}, "panorama", "o.gpkg", "panorama does not take --azimuth"},
      {{"--ve", "3"}, "row-slope", "r.tif", "row-slope does not take --ve"},
      {{"--source", kSample}, "classify", "c.tif", "classify does not take --source"},
      {{"--page-scale", "5000"}, "panorama", "o.gpkg", "panorama does not take --page-scale"},
      // A scale would average the DEM for the strokes that classify counts, not for its raster.
      {{"--drawn-for", "1000000"}, "classify", "c.tif", "classify does not take --drawn-for"},
  };
  for (const Refused& r : cases) {
    std::vector<std::string> args = {r.command, kSample, dir / r.output};
    args.insert(args.end(), r.args.begin(), r.args.end());
    const CliRun run = run_cli(args);
    CAPTURE(r.command, r.args.front(), run.err);
    CHECK(run.code == 2);
    CHECK_THAT(run.err, Catch::Contains(r.message));
    CHECK_THAT(run.err, Catch::Contains("terrain-sketch " + r.command + " --help"));
    CHECK(!std::filesystem::exists(dir / r.output));
  }
  // An option no command takes is unknown, as before.
  CHECK_THAT(run_cli({"classify", kSample, dir / "c.tif", "--bogus"}).err,
             Catch::Contains("unknown option '--bogus'"));
}

TEST_CASE("COMMAND --help lists that command's options only", "[cli]") {
  struct Expect {
    std::string command;
    std::vector<std::string> listed, unlisted;
  };
  // Each option as it starts a line of the help: "  --azimuth DEG" is not "  --azimuth-from".
  const std::vector<Expect> cases = {
      {"classify",
       {"  --azimuth DEG", "  --filter F", "  --stats-json"},
       {"--observer", "--every"}},
      {"panorama",
       {"  --observer X,Y", "  --filter F", "  --preview", "  --visibility"},
       {"  --azimuth DEG", "  --ve ", "--every", "--page-scale", "--subcell"}},
      {"row-slope",
       {"  --azimuth DEG", "  --band"},
       {"--ve", "--filter", "--strokes", "--threads"}},
      {"profiles", {"  --every N", "  --ve X"}, {"--filter", "--strokes", "--observer"}},
      {"drape", {"  --source RASTER"}, {"--filter", "--every", "--preview"}},
      {"silhouettes",
       {"  --strokes S", "  --join-gap", "  --preview", "  --strips", "  --subcell"},
       {"--observer", "--every", "--source", "--convex-row"}},
  };
  for (const Expect& e : cases) {
    const CliRun run = run_cli({e.command, "--help"});
    CAPTURE(e.command);
    CHECK(run.code == 0);
    CHECK_THAT(run.out, Catch::StartsWith("usage: terrain-sketch " + e.command + " INPUT OUTPUT"));
    for (const std::string& option : e.listed) CHECK_THAT(run.out, Catch::Contains(option));
    for (const std::string& option : e.unlisted) {
      CAPTURE(option);
      CHECK(run.out.find(option) == std::string::npos);
    }
  }
  // The program's usage names every command and sends to their own help.
  const CliRun usage = run_cli({"--help"});
  for (const char* command : {"silhouettes", "profiles", "classify", "row-slope", "pstrokes",
                              "drape", "panorama", "filter-plot"})
    CHECK_THAT(usage.out, Catch::Contains(std::string("  ") + command + " "));
  CHECK_THAT(usage.out, Catch::Contains("COMMAND --help"));
}

TEST_CASE("an output is refused when an input reads it, however deeply nested or wrapped",
          "[cli][robustness]") {
  ScratchDir dir("nested_inputs");
  const std::string src = dir / "src.tif";
  std::filesystem::copy_file(kSample, src);
  // v.vrt reads src.tif; vv.vrt reads v.vrt, and GDAL lists only v.vrt for it.
  test::build_vrt(dir / "v.vrt", src);
  test::build_vrt(dir / "vv.vrt", dir / "v.vrt");
  const std::string before = slurp(src);
  const std::string subfile = "/vsisubfile/0_" + std::to_string(before.size()) + "," + src;
  const std::vector<std::vector<std::string>> cases = {
      {"classify", dir / "vv.vrt", src},
      {"row-slope", dir / "vv.vrt", src},
      {"drape", kSample, src, "--source", dir / "vv.vrt"},
      {"panorama", dir / "vv.vrt", dir / "p.gpkg", "--observer", "749008.1394,4009477.9308",
       "--visibility", src},
      {"classify", subfile, src},
  };
  for (const std::vector<std::string>& args : cases) {
    const CliRun run = run_cli(args);
    CAPTURE(args.front(), args.at(1), run.err);
    CHECK(run.code == 1);
    CHECK_THAT(run.err, Catch::Contains("raster reads, which writing it would replace"));
    REQUIRE(slurp(src) == before);
  }
  CHECK(!std::filesystem::exists(dir / "p.gpkg"));
}
