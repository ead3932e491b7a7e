// The GeoPackage spatial index (an SQLite R*Tree) built in one pass instead of row by row.
//
// GDAL 3.6 fills a new GeoPackage's R-tree by inserting every feature's box through SQLite's
// rtree module, which costs 0.7 s for 100 000 strokes: more than the silhouettes themselves on
// 8000 x 8000. Here the boxes are packed by Sort-Tile-Recursive into full nodes and written
// straight into the R-tree's tables, in SQLite's own node format (as GDAL 3.7 and later do).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

class GDALDataset;
class OGRLayer;

namespace tsk::io {

class GdalErrorCapture;

// One feature's bounding box, keyed by its feature id.
struct IndexBox {
  std::int64_t id = 0;
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
};

// One node of an SQLite R*Tree: its number (the root is 1), its parent's (0 for the root) and
// its blob as the rtree module stores it.
struct RtreeNode {
  std::int64_t number = 0;
  std::int64_t parent = 0;
  std::vector<unsigned char> blob;
};

struct PackedRtree {
  std::vector<RtreeNode> nodes;                                // the root first
  std::vector<std::pair<std::int64_t, std::int64_t>> leaf_of;  // (box id, its leaf's number)
  int depth = 0;                                               // levels above the leaves
};

// Packs `boxes` into nodes of `node_bytes` bytes (the length of the table's root blob, which
// sets how many boxes a node holds). Any number of boxes, none included.
PackedRtree pack_rtree(std::vector<IndexBox> boxes, std::size_t node_bytes);

// Gives a GeoPackage line layer being written in a transaction its spatial index in bulk. Made
// right after the layer (created with SPATIAL_INDEX=NO) and before any feature: it has GDAL
// create the empty index with its triggers, then sets the triggers aside so that inserting a
// feature does not touch the index; finish() writes the packed index and restores them.
class GpkgSpatialIndex {
 public:
  GpkgSpatialIndex(GDALDataset& dataset, OGRLayer& layer, const GdalErrorCapture& capture);
  void add(const IndexBox& box) { boxes_.push_back(box); }
  void finish();

 private:
  // Runs one SQL statement on the dataset; its result's fields row after row.
  std::vector<std::string> query(const std::string& sql) const;

  GDALDataset& dataset_;
  const GdalErrorCapture& capture_;
  std::string rtree_;                  // the R-tree virtual table's name
  std::vector<std::string> triggers_;  // their CREATE TRIGGER statements
  std::vector<IndexBox> boxes_;
};

}  // namespace tsk::io
