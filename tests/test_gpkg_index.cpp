// The GeoPackage spatial index built in bulk: SQLite's own rtreecheck() passes, window queries on
// the index give what a brute-force box test gives, and the index follows later edits.
#include <ogrsf_frmts.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>

#include "catch_compat.h"
#include "cli_run.h"
#include "gdal_test_support.h"
#include "gpkg_index_check.h"
#include "io/gpkg/gpkg_line_appender.h"
#include "io/gpkg/gpkg_spatial_index.h"
#include "io/write/vector_writer.h"

using namespace tsk;
using test::IndexedGpkg;
using test::ScratchDir;
using test::Window;

namespace {

constexpr double kEast = 500000, kNorth = 4800000;  // UTM-sized, where floats are coarse

// Strokes as short random walks; on whole metres, which floats hold exactly, if `whole`.
std::vector<Stroke> random_strokes(std::size_t count, bool whole, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> start(0, 20000), step(-40, 40);
  std::vector<Stroke> strokes(count);
  for (Stroke& s : strokes) {
    double x = start(rng), y = start(rng);
    for (int k = 0; k < 2 + static_cast<int>(rng() % 5); ++k, x += step(rng), y += step(rng)) {
      s.points.push_back(whole ? StrokePoint{kEast + std::round(x), kNorth + std::round(y)}
                               : StrokePoint{kEast + x, kNorth + y});
    }
    s.cells = static_cast<int>(s.points.size());
  }
  return strokes;
}

// Windows from a cell wide to a quarter of the extent, off the whole metres.
std::vector<Window> random_windows(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(-100, 20100), size(1, 5000);
  std::vector<Window> windows;
  for (int k = 0; k < 40; ++k) {
    const double x = kEast + std::floor(at(rng)) + 0.25, y = kNorth + std::floor(at(rng)) + 0.75;
    windows.push_back({x, y, x + std::floor(size(rng)) + 0.5, y + std::floor(size(rng)) + 0.5});
  }
  return windows;
}

// A GeoPackage with an empty line layer made as QGIS's sinks make theirs (no spatial index), its
// first `deleted` features added and deleted, so that the next id is deleted + 1.
void make_unindexed_layer(const std::string& path, int deleted) {
  GDALAllRegister();
  io::DatasetPtr ds(GetGDALDriverManager()->GetDriverByName("GPKG")->Create(path.c_str(), 0, 0, 0,
                                                                            GDT_Unknown, nullptr));
  REQUIRE(ds);
  const char* options[] = {"SPATIAL_INDEX=NO", nullptr};
  OGRLayer* layer = ds->CreateLayer("lines", nullptr, wkbLineString, const_cast<char**>(options));
  REQUIRE(layer);
  for (int k = 0; k < deleted; ++k) {
    OGRFeature feature(layer->GetLayerDefn());
    OGRLineString line;
    line.addPoint(kEast + k, kNorth);
    line.addPoint(kEast + k, kNorth + 5);
    feature.SetGeometry(&line);
    REQUIRE(layer->CreateFeature(&feature) == OGRERR_NONE);
  }
  for (int fid = 1; fid <= deleted; ++fid) REQUIRE(layer->DeleteFeature(fid) == OGRERR_NONE);
}

// Appends `strokes` to layer "lines" of `path`, its index packed `window_leaves` leaves at a time.
void append_windowed(const std::string& path, const std::vector<Stroke>& strokes,
                     std::size_t window_leaves) {
  io::GpkgFileAppender file(path, "lines", window_leaves);
  for (const Stroke& s : strokes) file.lines().add(s.points);
  file.finish();
}

}  // namespace

TEST_CASE("a packed R-tree grows a level each time the nodes fill", "[gpkg]") {
  const std::size_t node_bytes = 4 + 51 * 24;  // what SQLite makes on 4096-byte pages
  const auto packed = [&](std::size_t n) {
    io::IndexBoxes out(n);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = {static_cast<std::int64_t>(i + 1), 1.0 * i, 1.0 * i + 2, 0.5 * i, 0.5 * i + 1};
    return io::PackedRtree(out, node_bytes);
  };
  CHECK(packed(0).depth() == 0);
  CHECK(packed(0).node_count() == 1);
  CHECK(packed(51).depth() == 0);
  CHECK(packed(52).depth() == 1);
  CHECK(packed(52).node_count() == 3);
  CHECK(packed(51 * 51).depth() == 1);
  const io::PackedRtree deep = packed(51 * 51 + 1);
  CHECK(deep.depth() == 2);
  // The root first, numbered 1 and holding the tree's depth; then the nodes below, each holding
  // the number of the node above it as its parent.
  io::RtreeNode root, below;
  deep.node(0, root);
  CHECK(root.number == 1);
  CHECK(root.parent == 0);
  CHECK(root.blob.size() == node_bytes);
  CHECK(root.blob[0] == 0);
  CHECK(root.blob[1] == 2);
  CHECK(root.blob[3] == 2);  // two children
  deep.node(1, below);
  CHECK(below.number == 2);
  CHECK(below.parent == 1);
  CHECK(deep.leaf_entries().size() == 51 * 51 + 1);
  const auto [first, leaf] = deep.leaves_by_id();
  CHECK(first == 1);
  CHECK(leaf.size() == 51 * 51 + 1);
  CHECK_THROWS_AS(io::PackedRtree(io::IndexBoxes(3), 40), Error);
}

TEST_CASE("a packed R-tree numbers the leaves by id only where the ids run without a gap",
          "[gpkg]") {
  const std::size_t node_bytes = 4 + 51 * 24;
  const auto ids_by_leaf = [&](const std::vector<std::int64_t>& ids) {
    io::IndexBoxes boxes;
    for (std::int64_t id : ids) boxes.emplace_back(id, 1.0 * id, 1.0 * id + 1, 0.0, 1.0);
    return io::PackedRtree(boxes, node_bytes).leaves_by_id();
  };
  std::vector<std::int64_t> shuffled(200);
  std::iota(shuffled.begin(), shuffled.end(), std::int64_t{-50});
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(3));
  const auto [first, leaf] = ids_by_leaf(shuffled);
  CHECK(first == -50);
  REQUIRE(leaf.size() == 200);
  // Boxes side by side along x: 51 to a leaf in the order of x, the leaves numbered after the root.
  for (std::size_t k = 0; k < leaf.size(); ++k) CHECK(leaf[k] == 2 + static_cast<int>(k / 51));
  CHECK(ids_by_leaf({1, 2, 4, 5}).second.empty());  // a gap
  CHECK(ids_by_leaf({1, 2, 2, 3}).second.empty());  // a repeat
  CHECK(ids_by_leaf({}).second.empty());
}

TEST_CASE("a packed R-tree's leaves hold the boxes as Sort-Tile-Recursive places them", "[gpkg]") {
  // Boxes on a coarse lattice, so that many share a centre (ties go by id), some across zero
  // (-0 and +0 centres), handed over in id order and shuffled.
  const std::size_t per_node = 51, node_bytes = 4 + per_node * 24;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> at(-40, 40), size(0, 3);
  std::vector<io::IndexBox> boxes;
  for (std::int64_t id = 1; id <= 6000; ++id) {
    const double x = at(rng), y = at(rng), w = size(rng);
    // Every third box centred on x = 0.
    if (id % 3 == 0) {
      boxes.emplace_back(id, -w, w, y, y + size(rng));
    } else {
      boxes.emplace_back(id, x - w, x + size(rng), y - size(rng), y + w);
    }
  }
  boxes.emplace_back(6001, -0.0, -0.0, -0.0, -0.0);
  boxes.emplace_back(6002, 0.0, 0.0, 0.0, 0.0);
  // The reference: sorted by centre x then id, cut into slices of S nodes' boxes (S the square
  // root of the node count, rounded up), each sorted by centre y then id and cut into nodes.
  const auto centre = [](float lo, float hi) { return 0.5 * (double{lo} + double{hi}); };
  std::vector<io::IndexBox> order = boxes;
  std::sort(order.begin(), order.end(), [&](const io::IndexBox& a, const io::IndexBox& b) {
    const double ca = centre(a.min_x, a.max_x), cb = centre(b.min_x, b.max_x);
    return ca != cb ? ca < cb : a.id < b.id;
  });
  const std::size_t nodes = (order.size() + per_node - 1) / per_node;
  std::size_t slices = 1;
  while (slices * slices < nodes) ++slices;
  std::vector<std::vector<std::int64_t>> leaves;
  for (std::size_t from = 0; from < order.size(); from += slices * per_node) {
    const auto end = order.begin() +
                     static_cast<std::ptrdiff_t>(std::min(order.size(), from + slices * per_node));
    std::sort(order.begin() + static_cast<std::ptrdiff_t>(from), end,
              [&](const io::IndexBox& a, const io::IndexBox& b) {
                const double ca = centre(a.min_y, a.max_y), cb = centre(b.min_y, b.max_y);
                return ca != cb ? ca < cb : a.id < b.id;
              });
    for (auto k = order.begin() + static_cast<std::ptrdiff_t>(from); k < end;) {
      leaves.emplace_back();
      for (std::size_t n = 0; n < per_node && k < end; ++n, ++k) leaves.back().push_back(k->id);
    }
  }
  for (const bool shuffled : {false, true}) {
    CAPTURE(shuffled);
    std::vector<io::IndexBox> given = boxes;
    if (shuffled) std::shuffle(given.begin(), given.end(), rng);
    const io::PackedRtree packed(io::IndexBoxes(given.begin(), given.end()), node_bytes);
    // Each leaf's boxes, by the leaf's number, in the order the leaves were numbered.
    std::map<std::int64_t, std::vector<std::int64_t>> by_leaf;
    for (const auto& [id, leaf] : packed.leaf_entries()) by_leaf[leaf].push_back(id);
    std::vector<std::vector<std::int64_t>> got;
    for (auto& [leaf, ids] : by_leaf) got.push_back(ids);
    std::vector<std::vector<std::int64_t>> want = leaves;
    for (auto* v : {&got, &want}) {
      for (auto& ids : *v) std::sort(ids.begin(), ids.end());
      std::sort(v->begin(), v->end());
    }
    CHECK(got == want);
  }
}

TEST_CASE("GeoPackage spatial index is whole and answers like a brute-force search", "[gpkg]") {
  ScratchDir dir("gpkg-index");
  for (const std::size_t count : {0, 1, 51, 52, 2601, 2602, 20000}) {
    for (const bool whole : {true, false}) {
      CAPTURE(count, whole);
      const std::string path = dir / "s.gpkg";
      io::write_strokes(path, "", random_strokes(count, whole, static_cast<unsigned>(count)), "");
      IndexedGpkg gpkg(path, "silhouettes");
      CHECK(gpkg.rtree_check() == "ok");
      CHECK(gpkg.indexed() == static_cast<long long>(count));
      for (const Window& w : random_windows(static_cast<unsigned>(count) + 7)) {
        const std::set<GIntBig> by_index = gpkg.index_hits(w), by_box = gpkg.box_hits(w);
        if (whole) {
          CHECK(by_index == by_box);  // float-exact coordinates: the same features
        } else {
          CHECK(std::includes(by_index.begin(), by_index.end(), by_box.begin(), by_box.end()));
        }
      }
    }
  }
}

TEST_CASE("the command line's GeoPackages carry a whole spatial index", "[gpkg][cli]") {
  ScratchDir dir("gpkg-cli");
  REQUIRE(test::run_cli({"silhouettes", TSK_SAMPLE_DEM, dir / "s.gpkg"}).code == 0);
  test::check_spatial_index(dir / "s.gpkg", "silhouettes");
  REQUIRE(test::run_cli({"pstrokes", TSK_SAMPLE_DEM, dir / "p.gpkg"}).code == 0);
  test::check_spatial_index(dir / "p.gpkg", "pstrokes");
}

TEST_CASE("GeoPackages get pages sized for a bulk load unless the user sizes them", "[gpkg]") {
  ScratchDir dir("gpkg-pages");
  const std::string path = dir / "s.gpkg";
  io::write_strokes(path, "", random_strokes(100, true, 1), "");
  CHECK(IndexedGpkg(path, "silhouettes").page_size() == 16384);
  REQUIRE(test::run_cli({"silhouettes", TSK_SAMPLE_DEM, dir / "cli.gpkg"}).code == 0);
  CHECK(IndexedGpkg(dir / "cli.gpkg", "silhouettes").page_size() == 16384);
  // The user's pragmas come after ours, and SQLite takes the last page size.
  const std::string before = CPLGetConfigOption("OGR_SQLITE_PRAGMA", "");
  CPLSetConfigOption("OGR_SQLITE_PRAGMA", "page_size=8192");
  io::write_strokes(path, "", random_strokes(100, true, 1), "");
  CPLSetConfigOption("OGR_SQLITE_PRAGMA", before.empty() ? nullptr : before.c_str());
  IndexedGpkg user(path, "silhouettes");
  CHECK(user.page_size() == 8192);
  CHECK(user.rtree_check() == "ok");
  CHECK(user.indexed() == 100);
}

TEST_CASE("GeoPackage spatial index follows features added and deleted later", "[gpkg]") {
  ScratchDir dir("gpkg-edit");
  const std::string path = dir / "s.gpkg";
  io::write_strokes(path, "", random_strokes(3000, true, 5), "");
  const Window far_away{kEast - 1000.5, kNorth - 1000.5, kEast - 899.5, kNorth - 899.5};
  {
    IndexedGpkg gpkg(path, "silhouettes", /*update=*/true);
    OGRLayer* layer = &gpkg.layer();
    OGRFeature feature(layer->GetLayerDefn());
    OGRLineString line;
    line.addPoint(kEast - 950, kNorth - 950);
    line.addPoint(kEast - 940, kNorth - 930);
    feature.SetGeometry(&line);
    REQUIRE(layer->CreateFeature(&feature) == OGRERR_NONE);
    REQUIRE(layer->DeleteFeature(1) == OGRERR_NONE);
  }
  IndexedGpkg gpkg(path, "silhouettes");
  CHECK(gpkg.rtree_check() == "ok");
  CHECK(gpkg.index_hits(far_away) == std::set<GIntBig>{3001});
  CHECK(gpkg.indexed("id = 1") == 0);
  CHECK(gpkg.layer().GetFeatureCount() == 3000);
}

TEST_CASE("strokes written straight into a GeoPackage read back as OGR writes them elsewhere",
          "[gpkg]") {
  // The GeoPackage rows are inserted through SQLite, an SQLite file (not a GeoPackage) through OGR
  // features: both must read back the same through GDAL, geometry, attributes and nulls, count and
  // extent.
  ScratchDir dir("gpkg-rows");
  std::vector<Stroke> strokes = random_strokes(500, false, 9);
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    Stroke& s = strokes[k];
    s.cls = k % 3 ? StrokeClass::formulated : StrokeClass::factual;
    s.length = 10.5 * static_cast<double>(k);
    s.mean_depth_m = k % 3 ? std::numeric_limits<double>::quiet_NaN() : 0.25 * k;
    s.max_depth_m = std::numeric_limits<double>::infinity();
    s.mean_z = -3.0e5 + static_cast<double>(k);
  }
  io::write_strokes(dir / "s.gpkg", "", strokes, "");
  io::write_strokes(dir / "s.sqlite", "", strokes, "");
  IndexedGpkg gpkg(dir / "s.gpkg", "silhouettes");
  io::DatasetPtr other(static_cast<GDALDataset*>(
      GDALOpenEx((dir / "s.sqlite").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr)));
  REQUIRE(other);
  OGRLayer& a = gpkg.layer();
  OGRLayer& b = *other->GetLayer(0);
  CHECK(a.GetFeatureCount(FALSE) == 500);  // GDAL's stored count
  // The stored extent against the strokes' own. Not against the SQLite file's: GDAL takes that
  // from SpatiaLite's statistics when it trusts them, else from the spatial index's
  // single-precision boxes, which it did once in a clean-clone CI run (499962.75 for 499962.76).
  OGREnvelope ea, points;
  REQUIRE(a.GetExtent(&ea, FALSE) == OGRERR_NONE);
  for (const Stroke& s : strokes)
    for (const StrokePoint& p : s.points) points.Merge(p.x, p.y);
  // GDAL reads the stored extent back through text, to 15 digits or so.
  CHECK(ea.MinX == Approx(points.MinX).epsilon(1e-13));
  CHECK(ea.MaxX == Approx(points.MaxX).epsilon(1e-13));
  CHECK(ea.MinY == Approx(points.MinY).epsilon(1e-13));
  CHECK(ea.MaxY == Approx(points.MaxY).epsilon(1e-13));
  REQUIRE(a.GetLayerDefn()->GetFieldCount() == b.GetLayerDefn()->GetFieldCount());
  std::size_t rows = 0;
  for (auto& fa : a) {
    std::unique_ptr<OGRFeature> fb(b.GetNextFeature());
    REQUIRE(fb);
    INFO("feature " << rows);
    // Rows go in many to a statement, with their ids given: 1, 2, ... in the order written.
    CHECK(fa->GetFID() == static_cast<GIntBig>(rows + 1));
    const auto* la = fa->GetGeometryRef()->toLineString();
    const auto* lb = fb->GetGeometryRef()->toLineString();
    REQUIRE(la->getNumPoints() == lb->getNumPoints());
    for (int k = 0; k < la->getNumPoints(); ++k) {
      REQUIRE(la->getX(k) == lb->getX(k));
      REQUIRE(la->getY(k) == lb->getY(k));
    }
    for (int f = 0; f < a.GetLayerDefn()->GetFieldCount(); ++f) {
      INFO("field " << a.GetLayerDefn()->GetFieldDefn(f)->GetNameRef());
      REQUIRE(fa->IsFieldNull(f) == fb->IsFieldNull(f));
      REQUIRE(std::string(fa->GetFieldAsString(f)) == fb->GetFieldAsString(f));
    }
    CHECK(fa->IsFieldNull(a.GetLayerDefn()->GetFieldIndex("max_depth")));
    ++rows;
  }
  CHECK(rows == 500);
  CHECK(gpkg.rtree_check() == "ok");
}

TEST_CASE("lines appended after deleted features take the ids SQLite gives, and the index agrees",
          "[gpkg]") {
  // A layer made as QGIS's sinks make theirs (no spatial index), whose first features were deleted:
  // its AUTOINCREMENT key goes on from the largest id it gave, not from the rows left.
  ScratchDir dir("gpkg-append");
  const std::string path = dir / "a.gpkg";
  make_unindexed_layer(path, 7);
  append_windowed(path, random_strokes(300, true, 3), io::RtreeStream::kWindowLeaves);
  IndexedGpkg gpkg(path, "lines");
  CHECK(gpkg.rtree_check() == "ok");
  CHECK(gpkg.first_column("SELECT min(fid) FROM lines").at(0) == "8");
  CHECK(gpkg.first_column("SELECT max(fid) FROM lines").at(0) == "307");
  for (const Window& w : random_windows(11)) CHECK(gpkg.index_hits(w) == gpkg.box_hits(w));
}

TEST_CASE("an index built for features whose ids skip answers like a brute-force search",
          "[gpkg]") {
  // The R-tree's rowid table gets each id given where the ids do not count up one by one.
  ScratchDir dir("gpkg-skipping");
  const std::string path = dir / "s.gpkg";
  GDALAllRegister();
  {
    io::DatasetPtr ds(GetGDALDriverManager()->GetDriverByName("GPKG")->Create(
        path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    REQUIRE(ds);
    const char* options[] = {"SPATIAL_INDEX=NO", nullptr};
    OGRLayer* layer = ds->CreateLayer("lines", nullptr, wkbLineString, const_cast<char**>(options));
    REQUIRE(layer);
    for (const Stroke& s : random_strokes(900, true, 4)) {
      OGRFeature feature(layer->GetLayerDefn());
      OGRLineString line;
      for (const StrokePoint& p : s.points) line.addPoint(p.x, p.y);
      feature.SetGeometry(&line);
      REQUIRE(layer->CreateFeature(&feature) == OGRERR_NONE);
    }
    for (GIntBig fid = 3; fid <= 900; fid += 3) REQUIRE(layer->DeleteFeature(fid) == OGRERR_NONE);
  }
  {
    io::DatasetPtr ds(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr)));
    REQUIRE(ds);
    io::IndexBoxes boxes;
    for (auto& feature : *ds->GetLayerByName("lines")) {
      OGREnvelope e;
      feature->GetGeometryRef()->getEnvelope(&e);
      boxes.push_back({feature->GetFID(), e.MinX, e.MaxX, e.MinY, e.MaxY});
    }
    REQUIRE(boxes.size() == 600);
    REQUIRE(ds->StartTransaction() == OGRERR_NONE);
    io::add_gpkg_spatial_index(*ds, "lines", boxes);
    REQUIRE(ds->CommitTransaction() == OGRERR_NONE);
  }
  IndexedGpkg gpkg(path, "lines");
  CHECK(gpkg.rtree_check() == "ok");
  CHECK(gpkg.indexed() == 600);
  CHECK(gpkg.indexed("id % 3 = 0") == 0);
  for (const Window& w : random_windows(13)) CHECK(gpkg.index_hits(w) == gpkg.box_hits(w));
}

TEST_CASE("a spatial index packed window by window answers like a brute-force search", "[gpkg]") {
  // Windows of two leaves (102 boxes) on 4096-byte pages: none filled, one just filled, one and a
  // box, many and a part; the ids start after deleted features.
  ScratchDir dir("gpkg-windows");
  for (const std::size_t count : {50, 102, 103, 204, 3000}) {
    CAPTURE(count);
    const std::string path = dir / "w.gpkg";
    make_unindexed_layer(path, 7);
    append_windowed(path, random_strokes(count, true, static_cast<unsigned>(count)), 2);
    IndexedGpkg gpkg(path, "lines");
    CHECK(gpkg.rtree_check() == "ok");
    CHECK(gpkg.indexed() == static_cast<long long>(count));
    for (const Window& w : random_windows(static_cast<unsigned>(count) + 3))
      CHECK(gpkg.index_hits(w) == gpkg.box_hits(w));
    // Once a window fills, its leaves are numbered first, from 2, whatever lies where: the first
    // 102 features are in leaves 2 and 3 alone.
    if (count >= 102) {
      CHECK(gpkg.first_column("SELECT DISTINCT nodeno FROM rtree_lines_geom_rowid WHERE rowid < " +
                              std::to_string(8 + 102) + " ORDER BY nodeno") ==
            std::vector<std::string>{"2", "3"});
    }
  }
}

TEST_CASE("a window's leaves are about square across a band of features", "[gpkg]") {
  // Point features on a lattice 1020 wide and 10 tall, in rows: two windows of 100 leaves, each a
  // band 1020 x 5. Square leaves of 51 points are about 10 x 5; slices as many as the square root
  // of the leaves would make them 102 x 0.5.
  ScratchDir dir("gpkg-band");
  const std::string path = dir / "b.gpkg";
  make_unindexed_layer(path, 0);
  std::vector<Stroke> strokes;
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 1020; ++x) {
      strokes.emplace_back();
      strokes.back().points = {{kEast + x, kNorth + y}, {kEast + x, kNorth + y}};
    }
  }
  append_windowed(path, strokes, 100);
  IndexedGpkg gpkg(path, "lines");
  REQUIRE(gpkg.rtree_check() == "ok");
  const std::vector<std::string> widths = gpkg.first_column(
      "SELECT max(t.maxx) - min(t.minx) FROM rtree_lines_geom_rowid r JOIN rtree_lines_geom t ON "
      "t.id = r.rowid GROUP BY r.nodeno");
  const std::vector<std::string> heights = gpkg.first_column(
      "SELECT max(t.maxy) - min(t.miny) FROM rtree_lines_geom_rowid r JOIN rtree_lines_geom t ON "
      "t.id = r.rowid GROUP BY r.nodeno");
  REQUIRE(widths.size() == 200);
  for (std::size_t k = 0; k < widths.size(); ++k) {
    CAPTURE(k, widths[k], heights[k]);
    CHECK(std::stod(widths[k]) <= 20);
    CHECK(std::stod(heights[k]) >= 2);
  }
}
