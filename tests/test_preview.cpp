// The command line's --preview as vector art: the SVG parsed back with GDAL's XML parser.
#include <cpl_minixml.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "catch_compat.h"
#include "cli/cli_app.h"
#include "cli_run.h"
#include "core/method/run_recipes.h"
#include "gdal_test_support.h"
#include "io/pages/filter_diagram_page.h"
#include "io/pages/preview.h"
#include "io/read/dem_reader.h"
#include "io/read/gdal_util.h"

using namespace tsk::test;

namespace {

const std::string kSample = TSK_SAMPLE_DEM;

long long json_count(const std::string& json, const std::string& key) {
  std::smatch m;
  REQUIRE(std::regex_search(json, m, std::regex("\"" + key + "\": ([0-9]+)")));
  return std::stoll(m[1]);
}

struct SvgPaths {
  std::map<std::string, long long> per_group, closed_per_group;
  long long points = 0, outside = 0;
};

// Counts the paths of each top-level group, and the points of their "M x y L x y ..." data that
// lie outside the picture.
SvgPaths read_svg(const std::string& text) {
  CPLXMLNode* root = CPLParseXMLString(text.c_str());
  REQUIRE(root != nullptr);
  const CPLXMLNode* svg = CPLGetXMLNode(root, "=svg");
  REQUIRE(svg != nullptr);
  const double width = CPLAtof(CPLGetXMLValue(svg, "width", "0"));
  const double height = CPLAtof(CPLGetXMLValue(svg, "height", "0"));
  SvgPaths found;
  for (const CPLXMLNode* g = svg->psChild; g; g = g->psNext) {
    if (g->eType != CXT_Element || std::string(g->pszValue) != "g") continue;
    const std::string id = CPLGetXMLValue(g, "id", "");
    for (const CPLXMLNode* p = g->psChild; p; p = p->psNext) {
      if (p->eType != CXT_Element || std::string(p->pszValue) != "path") continue;
      ++found.per_group[id];
      const std::string data = CPLGetXMLValue(p, "d", "");
      if (!data.empty() && data.back() == 'Z') ++found.closed_per_group[id];
      std::istringstream d(data);
      std::string x_with_command;
      double y = 0;
      while (d >> x_with_command >> y) {
        const double x = std::stod(x_with_command.substr(1));
        ++found.points;
        found.outside += !(x >= 0 && x <= width && y >= 0 && y <= height);
      }
    }
  }
  CPLDestroyXMLNode(root);
  return found;
}

}  // namespace

TEST_CASE("the SVG preview holds a layer per class and a path per stroke", "[cli][preview]") {
  ScratchDir dir("svg");
  const CliRun run = run_cli({"silhouettes", kSample, dir / "s.gpkg", "--geometry", "oblique",
                              "--preview", dir / "s.svg", "--stats-json", dir / "s.json"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const std::string json = slurp(dir / "s.json");
  const SvgPaths svg = read_svg(slurp(dir / "s.svg"));
  CHECK(svg.per_group.size() == 2);
  CHECK(svg.per_group.at("factual") == json_count(json, "factual_strokes"));
  CHECK(svg.per_group.at("formulated") == json_count(json, "formulated_strokes"));
  CHECK(svg.points > 2 * (svg.per_group.at("factual") + svg.per_group.at("formulated")));
  CHECK(svg.outside == 0);
  // Another extension is refused before any work.
  const CliRun jpeg = run_cli({"silhouettes", kSample, dir / "t.gpkg", "--preview", dir / "t.jpg"});
  CHECK(jpeg.code == 2);
  CHECK_THAT(jpeg.err, Catch::Contains(".png, .svg or .pdf name"));
  CHECK(dir.file_count() == 3);
}

TEST_CASE("drawn strokes are filled outlines in the vector art, exact strokes lines",
          "[cli][preview][drawn]") {
  ScratchDir dir("outlines");
  for (const char* strokes : {"drawn", "exact"}) {
    CAPTURE(strokes);
    const std::string name = strokes;
    const CliRun run =
        run_cli({"silhouettes", kSample, dir / (name + ".gpkg"), "--strokes", strokes, "--preview",
                 dir / (name + ".svg"), "--stats-json", dir / (name + ".json")});
    REQUIRE(run.code == 0);
    const std::string json = slurp(dir / (name + ".json"));
    SvgPaths svg = read_svg(slurp(dir / (name + ".svg")));
    const long long outlines = name == "drawn" ? 1 : 0;
    CHECK(svg.closed_per_group["factual"] == outlines * json_count(json, "factual_strokes"));
    CHECK(svg.closed_per_group["formulated"] == outlines * json_count(json, "formulated_strokes"));
  }
}

namespace {

// Renders page 1 of a PDF with poppler's pdftoppm and opens the picture.
GDALDataset* render_pdf(const std::string& pdf, const std::string& stem, int dpi) {
  const std::string command =
      "pdftoppm -png -singlefile -r " + std::to_string(dpi) + " '" + pdf + "' '" + stem + "' 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  GDALAllRegister();
  return static_cast<GDALDataset*>(GDALOpen((stem + ".png").c_str(), GA_ReadOnly));
}

// Checks a PDF's structure as a reader that trusts it would read it: startxref names the
// cross-reference table, each entry the offset of its object, and the content stream's length
// (an object of its own, written after the stream) where "endstream" follows.
void check_pdf_structure(const std::string& pdf) {
  const std::size_t start_xref = pdf.rfind("startxref\n");
  REQUIRE(start_xref != std::string::npos);
  const std::size_t xref = std::stoul(pdf.substr(start_xref + 10));
  REQUIRE(pdf.compare(xref, 5, "xref\n") == 0);
  std::istringstream table(pdf.substr(xref + 5));
  std::size_t first = 0, count = 0;
  table >> first >> count;
  REQUIRE(count > 1);
  std::string offset, generation, kind;
  table >> offset >> generation >> kind;  // the free entry 0
  for (std::size_t k = 1; k < count; ++k) {
    table >> offset >> generation >> kind;
    const std::string head = std::to_string(k) + " 0 obj\n";
    CAPTURE(k, offset);
    CHECK(pdf.compare(std::stoul(offset), head.size(), head) == 0);
  }
  const std::string length_ref = "/Length ";
  const std::size_t at = pdf.find(length_ref);
  REQUIRE(at != std::string::npos);
  const std::size_t object = std::stoul(pdf.substr(at + length_ref.size()));
  const std::size_t stream = pdf.find("stream\n", at) + 7;
  const std::string body = std::to_string(object) + " 0 obj\n";
  const std::size_t length = std::stoul(pdf.substr(pdf.find("\n" + body) + body.size() + 1));
  CHECK(pdf.compare(stream + length, 10, "\nendstream") == 0);
}

}  // namespace

TEST_CASE("the PDF preview is a page of the sketch with a layer per class", "[cli][preview]") {
  ScratchDir dir("pdf");
  const CliRun run =
      run_cli({"silhouettes", kSample, dir / "s.gpkg", "--preview", dir / "s.pdf", "--page", "A4"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const std::string pdf = slurp(dir / "s.pdf");
  CHECK_THAT(pdf, Catch::Contains("/Type /OCG /Name (Factual silhouettes)"));
  CHECK_THAT(pdf, Catch::Contains("/Type /OCG /Name (Formulated silhouettes)"));
  // The sample is about as tall as wide in the sketch: an A4 page, portrait, in points.
  CHECK_THAT(pdf, Catch::Contains("/MediaBox [0 0 595.276 841.890]"));
  check_pdf_structure(pdf);
  GDALDataset* page = render_pdf(dir / "s.pdf", dir / "page", 40);
  REQUIRE(page != nullptr);
  const int w = page->GetRasterXSize(), h = page->GetRasterYSize();
  CHECK(w == Approx(210 / 25.4 * 40).margin(1));
  CHECK(h == Approx(297 / 25.4 * 40).margin(1));
  REQUIRE(page->GetRasterCount() >= 3);
  std::vector<GByte> rgb(static_cast<std::size_t>(w) * h * 3);
  REQUIRE(page->RasterIO(GF_Read, 0, 0, w, h, rgb.data(), w, h, GDT_Byte, 3, nullptr, 3, 3 * w,
                         1) == CE_None);
  GDALClose(page);
  long long black = 0, sepia = 0, margin_ink = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const GByte* p = &rgb[3 * (static_cast<std::size_t>(y) * w + x)];
      const bool ink = p[0] < 200 || p[1] < 200 || p[2] < 200;
      black += p[0] < 80 && p[1] < 80 && p[2] < 80;
      sepia += p[0] > p[2] + 40 && p[0] < 220;
      // Nothing inside the 10 mm margin but a few pixels of the widest strokes' ends.
      const double mm_x = x * 25.4 / 40, mm_y = y * 25.4 / 40;
      margin_ink += ink && (mm_x < 9 || mm_x > 201 || mm_y < 9 || mm_y > 288);
    }
  }
  CHECK(black > 2000);
  CHECK(sepia > 200);
  CHECK(margin_ink == 0);
}

TEST_CASE("pages and scales are checked, and a sketch too large for its page is refused",
          "[cli][preview][robustness]") {
  ScratchDir dir("pages");
  struct Bad {
    std::vector<std::string> extra;
    std::string message;
    int code;  // 1: the DEM does not fit the page; 2: bad usage
  };
  const Bad cases[] = {
      {{"--preview", dir / "a.svg", "--page", "A4", "--page-scale", "100000"},
       "larger than the page",
       1},
      {{"--preview", dir / "a.svg", "--page-scale", "5000"}, "--page-scale needs a --page", 2},
      {{"--preview", dir / "a.svg", "--page", "B7"}, "--page must be A4", 2},
      {{"--preview", dir / "a.svg", "--page", "20x30"}, "each 50 to 5000", 2},
      {{"--preview", dir / "a.svg", "--page", "A3", "--page-scale", "0.5"}, "1:N, from 1", 2},
      {{"--preview", dir / "a.png", "--plotter"}, "give --preview a .svg or .pdf name", 2},
      {{"--page", "A4"}, "shape the --preview picture", 2},
  };
  for (const Bad& b : cases) {
    std::vector<std::string> args = {"silhouettes", kSample, dir / "s.gpkg"};
    args.insert(args.end(), b.extra.begin(), b.extra.end());
    const CliRun run = run_cli(args);
    CAPTURE(b.message);
    CHECK(run.code == b.code);
    CHECK_THAT(run.err, Catch::Contains(b.message));
    CHECK(dir.file_count() == 0);
  }
  // A page too small for the scale asked for is refused before the run: no progress is shown.
  std::ostringstream out, err;
  CHECK(tsk::cli::run({"silhouettes", kSample, dir / "s.gpkg", "--preview", dir / "a.svg", "--page",
                       "A4", "--page-scale", "100000"},
                      out, err, true) == 1);
  CHECK_THAT(err.str(), Catch::Contains("larger than the page"));
  CHECK_THAT(err.str(), !Catch::Contains("0..."));
  // At 1:250 000 the sample's 31 km fit an A3 page, in millimetres.
  const CliRun fits = run_cli({"silhouettes", kSample, dir / "s.gpkg", "--preview", dir / "a.svg",
                               "--page", "A3", "--page-scale", "250000"});
  INFO(fits.err);
  REQUIRE(fits.code == 0);
  CHECK_THAT(slurp(dir / "a.svg"), Catch::Contains("width=\"297.000mm\" height=\"420.000mm\""));
}

TEST_CASE("the plotter page merges strokes that meet and cuts the pen's travel",
          "[cli][preview][plotter]") {
  ScratchDir dir("plotter");
  const CliRun run = run_cli({"silhouettes", kSample, dir / "s.gpkg", "--preview", dir / "p.svg",
                              "--page", "A3", "--plotter", "--stats-json", dir / "s.json"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  std::smatch m;
  REQUIRE(std::regex_search(run.err, m,
                            std::regex("([0-9]+) strokes drawn as ([0-9]+) paths; pen-up travel "
                                       "([0-9]+) mm in the strokes' order, ([0-9]+) mm ordered")));
  const long long strokes = std::stoll(m[1]), paths = std::stoll(m[2]);
  const std::string json = slurp(dir / "s.json");
  CHECK(strokes == json_count(json, "factual_strokes") + json_count(json, "formulated_strokes"));
  CHECK(paths <= strokes);
  CHECK(std::stoll(m[4]) * 3 < std::stoll(m[3]));  // ordered, a third of the travel at most
  SvgPaths svg = read_svg(slurp(dir / "p.svg"));
  CHECK(svg.per_group["factual"] + svg.per_group["formulated"] == paths);
  CHECK(svg.closed_per_group["factual"] + svg.closed_per_group["formulated"] == 0);
  CHECK(svg.outside == 0);
}

TEST_CASE("the filter diagram page draws the removal polygon and the control point",
          "[filter diagram]") {
  using namespace tsk;
  SlopeScatter s;
  s.bins = 60, s.max_pct = 60.0;
  s.all.assign(60 * 60, 0), s.candidate.assign(60 * 60, 0), s.filtered.assign(60 * 60, 0);
  s.all[s.bin(10, 30)] = 5, s.candidate[s.bin(10, 30)] = 3, s.filtered[s.bin(10, 30)] = 1;
  const FilterParams filter;
  const std::string html = filter_diagram_html(s, filter, "test");
  // Control point (8.75, 5.25) at x = 60 + 8.75 * 560 / 60, y = 60 + 560 - 5.25 * 560 / 60.
  CHECK_THAT(html, Catch::Contains("<circle id=\"control\" cx=\"141.7\" cy=\"571\""));
  CHECK_THAT(html, Catch::Contains("points=\"60,620 172,620 141.7,571 60,433.3\""));
  CHECK_THAT(html, Catch::Contains("the c-set (3)"));
  // A title from a file name is text, never markup.
  CHECK_THAT(filter_diagram_html(s, filter, "<b>a&b</b>.tif"),
             Catch::Contains("<h2>&lt;b&gt;a&amp;b&lt;/b&gt;.tif</h2>"));
  FilterParams rectangle;
  rectangle.diagonals = false;
  CHECK_THAT(filter_diagram_html(s, rectangle, "t"),
             Catch::Contains("points=\"60,620 172,620 172,433.3 60,433.3\""));
}

TEST_CASE("a PNG preview reports its drawing, stops when told and is bounded in size",
          "[cli][preview][interrupt]") {
  ScratchDir dir("preview_stop");
  const CliRun run = run_cli(
      {"silhouettes", kSample, dir / "s.gpkg", "--page", "A2", "--preview", dir / "whole.png"});
  REQUIRE(run.code == 0);
  // The same page drawn again, told to stop at several points of its drawing and encoding.
  tsk::io::HeldDemFile held = tsk::io::hold_dem(kSample, {}, 90);
  tsk::SilhouetteParams params;
  const tsk::SilhouetteResult result = tsk::sketch_held_dem(held.held(), params);
  const tsk::io::Dem& dem = held.dem;
  tsk::io::PageOptions page;
  page.size = "A2";
  tsk::io::SketchLayout layout(dem.oriented, dem.frame, dem.geotransform, params.view,
                               params.geometry, page);
  for (const tsk::Stroke& stroke : result.strokes) layout.add(stroke);
  const tsk::io::SketchPage laid_out = layout.take_page(result.z_ref);
  std::vector<double> seen;
  tsk::io::write_page(dir / "again.png", laid_out, page, [&](double fraction) {
    seen.push_back(fraction);
    return true;
  });
  REQUIRE(seen.size() > 3);
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() == Approx(1.0));
  for (const double stop_at : {0.01, 0.5, 0.9}) {
    CAPTURE(stop_at);
    CHECK_THROWS_AS(tsk::io::write_page(dir / "stopped.png", laid_out, page,
                                        [&](double fraction) { return fraction < stop_at; }),
                    tsk::Cancelled);
    CHECK_FALSE(std::filesystem::exists(dir / "stopped.png"));
  }
  // A page whose picture would take gigabytes is refused before any work, with its size; as
  // vector art it is drawn.
  const CliRun huge = run_cli({"silhouettes", kSample, dir / "h.gpkg", "--page", "5000x5000",
                               "--preview", dir / "huge.png"});
  CHECK(huge.code == 2);
  CHECK_THAT(huge.err, Catch::Contains("29528 x 29528 pixels") && Catch::Contains("GB"));
  CHECK_FALSE(std::filesystem::exists(dir / "h.gpkg"));
  CHECK(run_cli({"silhouettes", kSample, dir / "h.gpkg", "--page", "5000x5000", "--preview",
                 dir / "huge.svg"})
            .code == 0);
}

namespace {

// What a vector dataset's layers hold, as GDAL reads them.
struct LayerRecord {
  std::string description;  // gpkg_contents' description: what made the layer
  long long features = 0;
};

std::vector<LayerRecord> layer_records(const std::string& path) {
  GDALAllRegister();
  tsk::io::DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  REQUIRE(ds);
  std::vector<LayerRecord> found;
  for (OGRLayer* layer : ds->GetLayers()) {
    const char* description = layer->GetMetadataItem("DESCRIPTION");
    found.push_back({description ? description : "", layer->GetFeatureCount()});
  }
  return found;
}

}  // namespace

TEST_CASE("the strokes and the vector art record the run that made them", "[cli][preview]") {
  ScratchDir dir("run_note");
  const CliRun run = run_cli({"silhouettes", kSample, dir / "s.gpkg", "--azimuth", "250",
                              "--filter", "fixed", "--preview", dir / "p.svg"});
  REQUIRE(run.code == 0);
  const std::string expected =
      "jacksboro_utm16n.tif, band 1. Seen from 250\xc2\xb0 (azimuth), vertical exaggeration 2.5, "
      "base slope 40 %; the thesis's slope filter: row 20 %, column 12 %, control point 8.75 %; "
      "drawn strokes. Terrain Sketch";
  CHECK_THAT(slurp(dir / "p.svg"), Catch::Contains("<desc>" + expected));
  // A GeoPackage keeps it as its layer's description (gpkg_contents), as GDAL reads it.
  const std::vector<LayerRecord> layers = layer_records(dir / "s.gpkg");
  REQUIRE(layers.size() == 1);
  REQUIRE(!layers[0].description.empty());
  CHECK_THAT(layers[0].description, Catch::Contains(expected));
}

TEST_CASE("strokes drawn for a scale say so, and keep fewer strokes", "[cli][preview]") {
  ScratchDir dir("drawn_for");
  REQUIRE(run_cli({"silhouettes", kSample, dir / "own.gpkg"}).code == 0);
  REQUIRE(run_cli({"silhouettes", kSample, dir / "small.gpkg", "--drawn-for", "1000000"}).code ==
          0);
  const std::vector<LayerRecord> own = layer_records(dir / "own.gpkg"),
                                 small = layer_records(dir / "small.gpkg");
  REQUIRE(own.size() == 1);
  REQUIRE(small.size() == 1);
  CHECK_THAT(own[0].description, Catch::Contains("; drawn strokes. Terrain Sketch"));
  // The sample's 75 m cells are 0.075 mm at 1:1 000 000: drawn from it averaged to 375 m.
  CHECK_THAT(small[0].description,
             Catch::Contains("; drawn strokes for 1:1000000 from the DEM averaged 5 x 5 cells. "
                             "Terrain Sketch"));
  CHECK(small[0].features > 0);
  CHECK(small[0].features < own[0].features / 4);
  // Not a scale: refused by name.
  const CliRun bad = run_cli({"silhouettes", kSample, dir / "bad.gpkg", "--drawn-for", "50"});
  CHECK(bad.code != 0);
  CHECK_THAT(bad.err, Catch::Contains("scale drawn for"));
}

TEST_CASE("a page smaller in scale than the DEM's own draws the strokes for the page",
          "[cli][preview]") {
  ScratchDir dir("page_scale");
  // The strokes of a run, as CSV: the same strokes give the same text.
  const auto strokes_of = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"silhouettes", kSample, dir / (name + ".csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun run = run_cli(args);
    INFO(run.err);
    REQUIRE(run.code == 0);
    return std::pair{slurp(dir / (name + ".csv")), run.err};
  };
  const auto [own, own_err] = strokes_of("own", {});
  // The sample's 75 m cells are 0.4 mm at 1:187 500. At 1:500 000 the page draws the strokes as
  // --drawn-for 500000 does; at 1:150 000 it leaves them as they are.
  const auto [small, small_err] =
      strokes_of("small", {"--preview", dir / "s.svg", "--page", "A4", "--page-scale", "500000"});
  CHECK_THAT(small_err, Catch::Contains("note: drawn for the page at 1:500000, smaller than the "
                                        "DEM's own 1:187500"));
  CHECK(small == strokes_of("for", {"--drawn-for", "500000"}).first);
  CHECK(small != own);
  const auto [large, large_err] =
      strokes_of("large", {"--preview", dir / "l.svg", "--page", "A3", "--page-scale", "150000"});
  CHECK(large == own);
  CHECK_THAT(large_err, !Catch::Contains("drawn for the page"));
  // --drawn-for given wins over the page's scale; exact strokes have no scale to draw for.
  CHECK(strokes_of("given", {"--preview", dir / "g.svg", "--page", "A4", "--page-scale", "500000",
                             "--drawn-for", "250000"})
            .first == strokes_of("given_alone", {"--drawn-for", "250000"}).first);
  CHECK(strokes_of("exact", {"--strokes", "exact", "--preview", dir / "e.svg", "--page", "A4",
                             "--page-scale", "500000"})
            .first == strokes_of("exact_alone", {"--strokes", "exact"}).first);
  // A page the sketch is fitted to: 30 mm inside the margins of a 50 mm page hold the sample's
  // 31 km across the view at 1:1 035 000 or smaller, rounded to two figures.
  const auto [fitted, fitted_err] =
      strokes_of("fitted", {"--preview", dir / "f.svg", "--page", "50x50"});
  std::smatch m;
  REQUIRE(std::regex_search(fitted_err, m, std::regex("drawn for the page at 1:([0-9]+),")));
  const long long scale = std::stoll(m[1]);
  CHECK(scale >= 1000000);
  CHECK(scale % 10000 == 0);
  CHECK(fitted == strokes_of("fitted_alone", {"--drawn-for", m[1]}).first);
  CHECK(read_svg(slurp(dir / "f.svg")).outside == 0);
}

TEST_CASE("a picture far smaller than its strokes are drawn for warns, and changes nothing",
          "[cli][preview]") {
  ScratchDir dir("picture_scale");
  // 2400 cells of 10 m across the 1600-pixel picture: 0.17 mm a cell at 96 pixels to the inch,
  // 2.3 times smaller than the 0.4 mm a cell the strokes are drawn for.
  const std::string dem = dir / "wide.tif";
  write_tiff(
      dem, 2400, 2400, 1,
      [](int, int r, int c) {
        return static_cast<float>(80 * std::sin(r / 40.0) * std::cos(c / 55.0));
      },
      kNorthUp, 32633);
  const CliRun picture = run_cli({"silhouettes", dem, dir / "p.csv", "--preview", dir / "p.png"});
  INFO(picture.err);
  REQUIRE(picture.code == 0);
  CHECK_THAT(picture.err,
             Catch::Contains("warning: the 1600-pixel preview shows the sketch at about "
                             "1:57000 (96 pixels to the inch), 2 times smaller than "
                             "its strokes are drawn for (the DEM's own 1:25000"));
  REQUIRE(run_cli({"silhouettes", dem, dir / "n.csv"}).code == 0);
  CHECK(slurp(dir / "p.csv") == slurp(dir / "n.csv"));
  // The sample's 414 cells fill the picture at 1.2 mm a cell: no warning.
  const CliRun sample =
      run_cli({"silhouettes", kSample, dir / "s.csv", "--preview", dir / "s.png"});
  REQUIRE(sample.code == 0);
  CHECK_THAT(sample.err, !Catch::Contains("times smaller"));
}

TEST_CASE("the P-strokes, profile lines and panorama record the run that made them",
          "[cli][preview]") {
  ScratchDir dir("product_notes");
  REQUIRE(run_cli({"pstrokes", kSample, dir / "p.gpkg", "--azimuth", "250", "--filter", "fixed"})
              .code == 0);
  REQUIRE(run_cli({"profiles", kSample, dir / "l.gpkg", "--azimuth", "200", "--ve", "3"}).code ==
          0);
  REQUIRE(run_cli({"panorama", kSample, dir / "v.gpkg", "--observer", "749008.1394,4009477.9308",
                   "--observer-height", "2", "--azimuth-from", "300", "--azimuth-to", "30",
                   "--panorama-exaggeration", "3"})
              .code == 0);
  // Every layer's description (gpkg_contents), as GDAL reads it.
  const auto descriptions = [](const std::string& path) {
    std::vector<std::string> found;
    for (const LayerRecord& layer : layer_records(path)) found.push_back(layer.description);
    return found;
  };
  const std::vector<std::string> pstrokes = descriptions(dir / "p.gpkg");
  REQUIRE(pstrokes.size() == 1);
  CHECK_THAT(pstrokes[0],
             Catch::StartsWith("jacksboro_utm16n.tif, band 1. P-strokes seen from 250\xc2\xb0 "
                               "(azimuth), vertical exaggeration 2.5, base slope 40 %; the "
                               "thesis's slope filter: row 20 %, column 12 %, control point 8.75 "
                               "%. Terrain Sketch "));
  const std::vector<std::string> profiles = descriptions(dir / "l.gpkg");
  REQUIRE(profiles.size() == 1);
  CHECK_THAT(profiles[0],
             Catch::StartsWith("jacksboro_utm16n.tif, band 1. Profile lines seen from "
                               "200\xc2\xb0 (azimuth), vertical exaggeration 3, base slope 40 %. "
                               "Terrain Sketch "));
  const std::vector<std::string> panorama = descriptions(dir / "v.gpkg");
  REQUIRE(panorama.size() == 2);  // the map and the panorama layer
  for (const std::string& description : panorama)
    CHECK_THAT(description,
               Catch::StartsWith("jacksboro_utm16n.tif, band 1. Panorama seen from 749008, "
                                 "4009478, 2 m above the ground, from 300\xc2\xb0 to 30\xc2\xb0 "
                                 "(azimuths from grid north); elevation angles drawn 3 times as "
                                 "tall as azimuths are wide. Terrain Sketch "));
}

TEST_CASE("the rasters record the run that made them", "[cli][preview]") {
  ScratchDir dir("raster_notes");
  REQUIRE(
      run_cli({"classify", kSample, dir / "c.tif", "--azimuth", "250", "--filter", "fixed"}).code ==
      0);
  REQUIRE(run_cli({"row-slope", kSample, dir / "r.tif", "--azimuth", "120"}).code == 0);
  REQUIRE(run_cli({"drape", kSample, dir / "d.tif", "--source", kSample, "--ve", "3"}).code == 0);
  REQUIRE(run_cli({"panorama", kSample, dir / "v.gpkg", "--observer", "749008.1394,4009477.9308",
                   "--azimuth-from", "300", "--azimuth-to", "30", "--visibility", dir / "v.tif"})
              .code == 0);
  // A GeoTIFF's image description, as GDAL reads it.
  const auto description = [](const std::string& path) {
    GDALAllRegister();
    tsk::io::DatasetPtr ds(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    REQUIRE(ds);
    const char* text = ds->GetMetadataItem("TIFFTAG_IMAGEDESCRIPTION");
    return std::string(text ? text : "");
  };
  CHECK_THAT(description(dir / "c.tif"),
             Catch::StartsWith("jacksboro_utm16n.tif, band 1. Silhouette stages seen from "
                               "250\xc2\xb0 (azimuth), vertical exaggeration 2.5, base slope 40 "
                               "%; the thesis's slope filter: row 20 %, column 12 %, control "
                               "point 8.75 %. Terrain Sketch "));
  CHECK_THAT(description(dir / "r.tif"),
             Catch::StartsWith("jacksboro_utm16n.tif, band 1. Row slope seen from 120\xc2\xb0 "
                               "(azimuth), vertical exaggeration 2.5, base slope 40 %. Terrain "
                               "Sketch "));
  CHECK_THAT(description(dir / "d.tif"),
             Catch::StartsWith("jacksboro_utm16n.tif, band 1. A drape of jacksboro_utm16n.tif "
                               "seen from 90\xc2\xb0 (azimuth), vertical exaggeration 3, base "
                               "slope 40 %. Terrain Sketch "));
  CHECK_THAT(description(dir / "v.tif"),
             Catch::StartsWith("jacksboro_utm16n.tif, band 1. Panorama seen from 749008, "
                               "4009478"));
}
