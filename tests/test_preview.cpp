// The command line's --preview as vector art: the SVG parsed back with GDAL's XML parser.
#include <cpl_minixml.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "catch_compat.h"
#include "cli_run.h"
#include "gdal_test_support.h"

using namespace tsk::test;

namespace {

const std::string kSample = TSK_SAMPLE_DEM;

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

long long json_count(const std::string& json, const std::string& key) {
  std::smatch m;
  REQUIRE(std::regex_search(json, m, std::regex("\"" + key + "\": ([0-9]+)")));
  return std::stoll(m[1]);
}

struct SvgPaths {
  std::map<std::string, long long> per_group;
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
      std::istringstream d(CPLGetXMLValue(p, "d", ""));
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
  const std::string json = read_all(dir / "s.json");
  const SvgPaths svg = read_svg(read_all(dir / "s.svg"));
  CHECK(svg.per_group.size() == 2);
  CHECK(svg.per_group.at("factual") == json_count(json, "factual_strokes"));
  CHECK(svg.per_group.at("formulated") == json_count(json, "formulated_strokes"));
  CHECK(svg.points > 2 * (svg.per_group.at("factual") + svg.per_group.at("formulated")));
  CHECK(svg.outside == 0);
  // Another extension is refused before any work.
  const CliRun jpeg = run_cli({"silhouettes", kSample, dir / "t.gpkg", "--preview", dir / "t.jpg"});
  CHECK(jpeg.code == 1);
  CHECK_THAT(jpeg.err, Catch::Contains(".png, .svg or .pdf name"));
  CHECK(dir.file_count() == 3);
}
