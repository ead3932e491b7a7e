// The GeoPackage spatial index (an SQLite R*Tree) built in one pass instead of row by row.
//
// GDAL 3.6 fills a GeoPackage's R-tree by inserting every feature's box through SQLite's rtree
// module, which costs 0.7 s for 100 000 strokes: more than the silhouettes themselves on
// 8000 x 8000 (QGIS writes GeoPackages through the same GDAL). Here the boxes are packed by
// Sort-Tile-Recursive into full nodes and written straight into the R-tree's tables in SQLite's
// own node format, as GDAL 3.7 and later do, through prepared statements on the SQLite connection
// that GDAL exposes (binding blobs and ids rather than SQL text: 102 000 strokes are indexed in
// 0.1 s). A writer's large layers are packed a window at a time as they are written
// (gpkg_rtree_stream.h), with the pieces here.
//
// GDAL 3.8 and later load the R-tree in bulk too. bench/gpkg_index_bench measured both on the
// 102 413 strokes of the 8000 x 8000 benchmark (medians of 5 alternated runs, one machine):
// GDAL 3.6.2 this loader 0.18 s, GDAL's CreateSpatialIndex 1.75 s; GDAL 3.10.3 0.17 s and
// 0.36 s; GDAL 3.13.3 0.16 s and 0.38 s. This loader stays for every GDAL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

class GDALDataset;

namespace tsk::io {

// One feature's bounding box, keyed by its feature id, as the R-tree stores it: float bounds
// rounded outwards (24 bytes rather than 40 in doubles).
struct IndexBox {
  IndexBox() = default;
  IndexBox(std::int64_t feature, double min_x, double max_x, double min_y, double max_y);
  std::int64_t id = 0;
  float min_x = 0, max_x = 0, min_y = 0, max_y = 0;
};

// The boxes of a layer's features, or of a window of them (gpkg_rtree_stream.h).
using IndexBoxes = std::vector<IndexBox>;

// The most boxes an SQLite R*Tree node holds (RTREE_MAXCELLS), whatever its page size.
constexpr std::size_t kMostBoxesPerNode = 51;

// How many boxes a node of `node_bytes` bytes holds; throws when fewer than two.
std::size_t boxes_per_node(std::size_t node_bytes);

// The box that covers boxes [first, last), named `id`.
IndexBox cover(const IndexBox* first, const IndexBox* last, std::int64_t id);

// Writes into `blob` (its storage reused) the node of `node_bytes` bytes holding boxes
// [first, last), each naming `id + ref_offset`: a feature in a leaf, a child node above. The root
// also records the tree's depth: `root_depth`, or -1 for any other node.
void node_blob(const IndexBox* first, const IndexBox* last, std::int64_t ref_offset,
               std::size_t node_bytes, int root_depth, std::vector<unsigned char>& blob);

// Boxes packed by Sort-Tile-Recursive into leaves of `per_node` boxes: sorted by centre x and cut
// into slices of `leaves_per_slice` leaves, each slice sorted by centre y and cut into leaves.
// Equal centres keep their boxes in id order.
struct PackedLeaves {
  std::vector<IndexBox> boxes;    // leaf by leaf
  std::vector<std::size_t> ends;  // one past each leaf's last box
};
PackedLeaves pack_leaves(const IndexBoxes& boxes, std::size_t per_node,
                         std::size_t leaves_per_slice);

// Where the ids of `boxes`, laid out leaf by leaf (`ends`: one past each leaf's last box; the
// leaves numbered from `first_number`), run without a gap or a repeat: the first id, and each
// box's leaf number by its id less the first; else an empty list.
std::pair<std::int64_t, std::vector<std::int64_t>> leaf_of_each_id(
    const std::vector<IndexBox>& boxes, const std::vector<std::size_t>& ends,
    std::int64_t first_number);

// One node of an SQLite R*Tree: its number (the root is 1), its parent's (0 for the root) and
// its blob as the rtree module stores it.
struct RtreeNode {
  std::int64_t number = 0;
  std::int64_t parent = 0;
  std::vector<unsigned char> blob;
};

// How a PackedRtree numbers its nodes and counts its depth, when its boxes are the covers of
// leaves written before (a streamed index's windows, named by their numbers).
struct RtreeNumbering {
  std::int64_t below_root = 2;  // the number of the first node below the root (always 1)
  int levels_below = 0;         // levels of nodes under the boxes: 1 for leaves written before
};

// Boxes packed by Sort-Tile-Recursive into full nodes of `node_bytes` bytes (the length of the
// table's root blob, which sets how many boxes a node holds). Any number of boxes, none included.
// Nodes are numbered level by level down from the root: 1, then from `numbering.below_root` on.
// Their blobs are made one at a time, as they are written, rather than all held.
class PackedRtree {
 public:
  PackedRtree(const IndexBoxes& boxes, std::size_t node_bytes, RtreeNumbering numbering = {});
  // Levels of the whole tree above its leaves.
  int depth() const { return static_cast<int>(levels_.size()) - 1 + levels_below_; }
  // Whether its boxes cover nodes written before rather than features.
  bool covers_nodes() const { return levels_below_ > 0; }
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
  int levels_below_;
  std::vector<Level> levels_;  // the leaves first, the root alone last
};

// Gives `table` of an open GeoPackage, whose features are in (its table written, as GDAL does when
// it syncs the layer) and which has no spatial index yet (made with the layer option
// SPATIAL_INDEX=NO), the R-tree of the features' `boxes`, the
// triggers that keep it up to date and the extension entry that GDAL would have made, in bulk.
// Runs in the caller's transaction, if any. Throws tsk::Error with SQLite's message on failure.
void add_gpkg_spatial_index(GDALDataset& dataset, const std::string& table,
                            const IndexBoxes& boxes);

// The R-tree of a GeoPackage layer and the names its triggers use.
struct RtreeNames {
  std::string table, column, fid, rtree;
};
RtreeNames rtree_names(GDALDataset& dataset, const std::string& table);

// Creates the empty R-tree `names.rtree` (its root node written by SQLite) and gives the length
// of its nodes' blobs.
std::size_t create_rtree(GDALDataset& dataset, const RtreeNames& names);

// Writes `leaves`, the leaves of a window of features whose ids run without a gap or a repeat, into
// the R-tree `names.rtree` made by create_rtree, numbered from `first_number` on, and each
// feature's leaf into its rowid table. Gives the box that covers each leaf, named by the leaf's
// number.
std::vector<IndexBox> write_rtree_leaves(GDALDataset& dataset, const RtreeNames& names,
                                         std::size_t node_bytes, const PackedLeaves& leaves,
                                         std::int64_t first_number);

// Writes the nodes of `packed` into the R-tree `names.rtree` made by create_rtree (its root
// replacing the one SQLite wrote), with each node's parent, and the boxes' own rows: each feature's
// leaf, or, when the boxes cover nodes written before (numbering.levels_below > 0), each such
// node's parent. Then the triggers that keep the R-tree up to date and the extension entry that
// GDAL would have made.
void write_rtree(GDALDataset& dataset, const RtreeNames& names, const PackedRtree& packed);

}  // namespace tsk::io
