#include "io/gpkg/gpkg_rtree_stream.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/base/errors.h"
#include "core/base/release_storage.h"

namespace tsk::io {
namespace {

// Leaves to a slice that make the leaves of `boxes` about square: with S slices across a band W
// wide and H tall, a leaf is W / S wide and H S / L tall, so S = sqrt(L W / H).
std::size_t square_leaves_per_slice(const IndexBoxes& boxes, std::size_t per_node) {
  const std::size_t leaves = (boxes.size() + per_node - 1) / per_node;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const IndexBox& b : boxes) {
    const double x = 0.5 * (double{b.min_x} + double{b.max_x});
    const double y = 0.5 * (double{b.min_y} + double{b.max_y});
    x0 = std::min(x0, x), x1 = std::max(x1, x);
    y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  const double wide = x1 - x0, tall = y1 - y0;
  const double slices =
      tall > 0 ? std::sqrt(static_cast<double>(leaves) * wide / tall) : static_cast<double>(leaves);
  const double kept = std::clamp(std::round(slices), 1.0, static_cast<double>(leaves));
  const auto whole = static_cast<std::size_t>(kept);
  return (leaves + whole - 1) / whole;
}

}  // namespace

RtreeStream::RtreeStream(GDALDataset& dataset, std::string table, std::size_t window_leaves)
    : dataset_(dataset),
      table_(std::move(table)),
      window_boxes_(std::max<std::size_t>(1, window_leaves) * kMostBoxesPerNode) {}

void RtreeStream::add(const IndexBox& box) {
  if (added_ > 0 && box.id != last_id_ + 1)
    throw Error("internal: a spatial index streamed features whose ids skip");
  window_.push_back(box);
  last_id_ = box.id;
  ++added_;
  if (window_.size() == window_boxes_) pack_window();
}

void RtreeStream::pack_window() {
  if (node_bytes_ == 0) {
    names_ = rtree_names(dataset_, table_);
    node_bytes_ = create_rtree(dataset_, names_);
  }
  const std::size_t per_node = boxes_per_node(node_bytes_);
  const PackedLeaves leaves =
      pack_leaves(window_, per_node, square_leaves_per_slice(window_, per_node));
  const std::vector<IndexBox> covers =
      write_rtree_leaves(dataset_, names_, node_bytes_, leaves, next_number_);
  leaf_covers_.insert(leaf_covers_.end(), covers.begin(), covers.end());
  next_number_ += static_cast<std::int64_t>(covers.size());
  window_.clear();
}

void RtreeStream::finish() {
  if (node_bytes_ == 0) {
    add_gpkg_spatial_index(dataset_, table_, window_);
  } else {
    if (!window_.empty()) pack_window();
    write_rtree(dataset_, names_,
                PackedRtree(leaf_covers_, node_bytes_, RtreeNumbering{next_number_, 1}));
  }
  release_storage(window_);
  release_storage(leaf_covers_);
}

}  // namespace tsk::io
