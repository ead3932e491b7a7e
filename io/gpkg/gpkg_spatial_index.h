// The GeoPackage spatial index (an SQLite R*Tree) built in one pass instead of row by row.
//
// GDAL 3.6 fills a GeoPackage's R-tree by inserting every feature's box through SQLite's rtree
// module, which costs 0.7 s for 100 000 strokes: more than the silhouettes themselves on
// 8000 x 8000 (QGIS writes GeoPackages through the same GDAL). Here the boxes are packed by
// Sort-Tile-Recursive into full nodes and written straight into the R-tree's tables in SQLite's
// own node format, as GDAL 3.7 and later do, through prepared statements on the SQLite connection
// that GDAL exposes (binding blobs and ids rather than SQL text: 102 000 strokes are indexed in
// 0.1 s).
//
// GDAL 3.8 and later load the R-tree in bulk too. bench/gpkg_index_bench measured both on the
// 102 413 strokes of the 8000 x 8000 benchmark (medians of 5 alternated runs, one machine):
// GDAL 3.6.2 this loader 0.18 s, GDAL's CreateSpatialIndex 1.75 s; GDAL 3.10.3 0.17 s and
// 0.36 s; GDAL 3.13.3 0.16 s and 0.38 s. This loader stays for every GDAL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

class GDALDataset;

namespace tsk::io {

// One feature's bounding box, keyed by its feature id, as the R-tree stores it: float bounds
// rounded outwards. (24 bytes rather than 40 in doubles: a writer holds a box per feature until it
// builds the index, 1.2 million of them on the 8000 x 8000 benchmark's default run.)
struct IndexBox {
  IndexBox() = default;
  IndexBox(std::int64_t feature, double min_x, double max_x, double min_y, double max_y);
  std::int64_t id = 0;
  float min_x = 0, max_x = 0, min_y = 0, max_y = 0;
};

// The boxes of a layer's features as a writer gathers them: in a deque, as a vector doubling its
// 29 MB of boxes near the end of a run held 75 MB at once.
using IndexBoxes = std::deque<IndexBox>;

// One node of an SQLite R*Tree: its number (the root is 1), its parent's (0 for the root) and
// its blob as the rtree module stores it.
struct RtreeNode {
  std::int64_t number = 0;
  std::int64_t parent = 0;
  std::vector<unsigned char> blob;
};

// Boxes packed by Sort-Tile-Recursive into full nodes of `node_bytes` bytes (the length of the
// table's root blob, which sets how many boxes a node holds). Any number of boxes, none included.
// Nodes are numbered from the root's 1 down the levels; their blobs are made one at a time, as they
// are written, rather than all held (20 MB on the 8000 x 8000 benchmark's default run).
class PackedRtree {
 public:
  PackedRtree(const IndexBoxes& boxes, std::size_t node_bytes);
  int depth() const { return static_cast<int>(levels_.size()) - 1; }  // levels above the leaves
  std::size_t node_count() const;
  // Node `k` (below node_count()) in the order of their numbers, the root first, into `node`, its
  // blob's storage reused.
  void node(std::size_t k, RtreeNode& node) const;
  // (box id, its leaf's number) for every box, leaf by leaf.
  std::vector<std::pair<std::int64_t, std::int64_t>> leaf_entries() const;
  // Where the boxes' ids run without a gap or a repeat (as a writer gives them): the first id, and
  // each box's leaf number by its id less the first; else an empty list.
  std::pair<std::int64_t, std::vector<std::int64_t>> leaves_by_id() const;

 private:
  // One level's cells node by node; a cell's id is a feature id in a leaf, the index of a node of
  // the level below otherwise.
  struct Level {
    std::vector<IndexBox> cells;
    std::vector<std::size_t> ends;     // one past each node's last cell
    std::vector<std::int64_t> parent;  // each node's parent's number (0 for the root)
    std::int64_t first_number = 0;     // its first node's
  };
  // Calls f(cell, its node's number) for every cell of `level`, node by node.
  template <typename F>
  static void for_each_cell(const Level& level, F&& f);
  std::size_t node_bytes_;
  std::vector<Level> levels_;  // the leaves first, the root alone last
};

// Gives `table` of an open GeoPackage, whose features are in (its table written, as GDAL does when
// it syncs the layer) and which has no spatial index yet (made with the layer option
// SPATIAL_INDEX=NO), the R-tree of the features' `boxes`, the
// triggers that keep it up to date and the extension entry that GDAL would have made, in bulk.
// Runs in the caller's transaction, if any. Throws tsk::Error with SQLite's message on failure.
void add_gpkg_spatial_index(GDALDataset& dataset, const std::string& table,
                            const IndexBoxes& boxes);

}  // namespace tsk::io
