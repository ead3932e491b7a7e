#include "gpkg_spatial_index.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "gdal_util.h"

namespace tsk::io {
namespace {

// A box as the R-tree stores it: float bounds rounded outwards. `ref` is a feature id in a
// leaf, a child's index in its level otherwise.
struct Cell {
  std::int64_t ref = 0;
  float min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  double centre_x() const { return 0.5 * (double{min_x} + double{max_x}); }
  double centre_y() const { return 0.5 * (double{min_y} + double{max_y}); }
};
using Node = std::vector<Cell>;

constexpr std::size_t kCellBytes = 8 + 4 * 4;  // the id, then min and max of x and y
constexpr float kInf = std::numeric_limits<float>::infinity();

float round_down(double v) {
  const auto f = static_cast<float>(v);
  return double{f} > v ? std::nextafter(f, -kInf) : f;
}

float round_up(double v) {
  const auto f = static_cast<float>(v);
  return double{f} < v ? std::nextafter(f, kInf) : f;
}

Cell cover(const Node& node, std::int64_t ref) {
  Cell c{ref, kInf, -kInf, kInf, -kInf};
  for (const Cell& child : node) {
    c.min_x = std::min(c.min_x, child.min_x);
    c.max_x = std::max(c.max_x, child.max_x);
    c.min_y = std::min(c.min_y, child.min_y);
    c.max_y = std::max(c.max_y, child.max_y);
  }
  return c;
}

// Sort-Tile-Recursive: vertical slices by centre x, each cut into nodes by centre y, so that a
// node holds boxes that lie close together.
std::vector<Node> tile(std::vector<Cell> cells, std::size_t per_node) {
  const std::size_t node_count = (cells.size() + per_node - 1) / per_node;
  auto slices = static_cast<std::size_t>(std::sqrt(static_cast<double>(node_count)));
  while (slices * slices < node_count) ++slices;
  const std::size_t slice_cells = std::max<std::size_t>(1, slices) * per_node;
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) {
    return a.centre_x() != b.centre_x() ? a.centre_x() < b.centre_x() : a.ref < b.ref;
  });
  const auto at = [&cells](std::size_t i) {
    return cells.begin() + static_cast<std::ptrdiff_t>(i);
  };
  std::vector<Node> nodes;
  for (std::size_t start = 0; start < cells.size(); start += slice_cells) {
    const std::size_t end = std::min(cells.size(), start + slice_cells);
    std::sort(at(start), at(end), [](const Cell& a, const Cell& b) {
      return a.centre_y() != b.centre_y() ? a.centre_y() < b.centre_y() : a.ref < b.ref;
    });
    for (std::size_t k = start; k < end; k += per_node) {
      nodes.emplace_back(at(k), at(std::min(end, k + per_node)));
    }
  }
  return nodes;
}

void put_big_endian(unsigned char* out, std::uint64_t value, int bytes) {
  for (int k = bytes - 1; k >= 0; --k) {
    out[k] = static_cast<unsigned char>(value & 0xff);
    value >>= 8;
  }
}

void put_float(unsigned char* out, float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  put_big_endian(out, bits, 4);
}

std::string quoted_identifier(const std::string& name) {
  std::string out = "\"";
  for (char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string quoted_literal(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string hex_blob(const std::vector<unsigned char>& bytes) {
  static const char digits[] = "0123456789ABCDEF";
  std::string out = "X'";
  out.reserve(bytes.size() * 2 + 3);
  for (unsigned char b : bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out + "'";
}

}  // namespace

PackedRtree pack_rtree(std::vector<IndexBox> boxes, std::size_t node_bytes) {
  if (node_bytes < 4 + 2 * kCellBytes) {
    throw Error("R-tree nodes of " + std::to_string(node_bytes) + " bytes cannot hold two boxes");
  }
  const std::size_t per_node = (node_bytes - 4) / kCellBytes;

  std::vector<Cell> leaves(boxes.size());
  std::transform(boxes.begin(), boxes.end(), leaves.begin(), [](const IndexBox& b) {
    return Cell{b.id, round_down(b.min_x), round_up(b.max_x), round_down(b.min_y),
                round_up(b.max_y)};
  });
  boxes = {};
  // levels[0] holds the leaves, levels.back() the root alone.
  std::vector<std::vector<Node>> levels{leaves.empty() ? std::vector<Node>(1)
                                                       : tile(std::move(leaves), per_node)};
  while (levels.back().size() > 1) {
    const std::vector<Node>& below = levels.back();
    std::vector<Cell> covers;
    covers.reserve(below.size());
    for (std::size_t i = 0; i < below.size(); ++i) {
      covers.push_back(cover(below[i], static_cast<std::int64_t>(i)));
    }
    levels.push_back(tile(std::move(covers), per_node));
  }

  // Numbers top down from the root's 1; each node's parent from the cells above it.
  std::vector<std::vector<std::int64_t>> number(levels.size());
  std::vector<std::vector<std::int64_t>> parent(levels.size());
  std::int64_t next = 1;
  for (std::size_t level = levels.size(); level-- > 0;) {
    number[level].resize(levels[level].size());
    parent[level].assign(levels[level].size(), 0);
    for (auto& n : number[level]) n = next++;
    if (level + 1 < levels.size()) {
      for (std::size_t j = 0; j < levels[level + 1].size(); ++j) {
        for (const Cell& c : levels[level + 1][j]) {
          parent[level][static_cast<std::size_t>(c.ref)] = number[level + 1][j];
        }
      }
    }
  }

  PackedRtree packed;
  packed.depth = static_cast<int>(levels.size()) - 1;
  for (std::size_t level = levels.size(); level-- > 0;) {
    for (std::size_t i = 0; i < levels[level].size(); ++i) {
      const Node& node = levels[level][i];
      RtreeNode out{number[level][i], parent[level][i], std::vector<unsigned char>(node_bytes)};
      if (out.number == 1) put_big_endian(out.blob.data(), static_cast<unsigned>(packed.depth), 2);
      put_big_endian(out.blob.data() + 2, node.size(), 2);
      for (std::size_t k = 0; k < node.size(); ++k) {
        const Cell& c = node[k];
        const std::int64_t ref =
            level == 0 ? c.ref : number[level - 1][static_cast<std::size_t>(c.ref)];
        unsigned char* cell = out.blob.data() + 4 + k * kCellBytes;
        put_big_endian(cell, static_cast<std::uint64_t>(ref), 8);
        put_float(cell + 8, c.min_x);
        put_float(cell + 12, c.max_x);
        put_float(cell + 16, c.min_y);
        put_float(cell + 20, c.max_y);
        if (level == 0) packed.leaf_of.emplace_back(c.ref, out.number);
      }
      packed.nodes.push_back(std::move(out));
    }
  }
  return packed;
}

namespace {

// Inserts rows into `table` a few hundred kilobytes of SQL at a time.
class RowInserter {
 public:
  RowInserter(std::string head, std::function<void(const std::string&)> run)
      : head_(std::move(head)), run_(std::move(run)) {}
  void add(const std::string& row) {
    sql_ += sql_.empty() ? head_ + " VALUES " : std::string(",");
    sql_ += row;
    if (sql_.size() > (1u << 18)) flush();
  }
  void flush() {
    if (!sql_.empty()) run_(sql_);
    sql_.clear();
  }

 private:
  std::string head_;
  std::function<void(const std::string&)> run_;
  std::string sql_;
};

}  // namespace

GpkgSpatialIndex::GpkgSpatialIndex(GDALDataset& dataset, OGRLayer& layer,
                                   const GdalErrorCapture& capture)
    : dataset_(dataset), capture_(capture) {
  const std::string table = layer.GetName();
  const std::string column = layer.GetGeometryColumn();
  rtree_ = "rtree_" + table + "_" + column;
  if (query("SELECT CreateSpatialIndex(" + quoted_literal(table) + ", " + quoted_literal(column) +
            ")") != std::vector<std::string>{"1"}) {
    throw Error("cannot create the spatial index of layer '" + table + "': " + capture.message());
  }
  const std::vector<std::string> found =
      query("SELECT name, sql FROM sqlite_master WHERE type = 'trigger' AND tbl_name = " +
            quoted_literal(table) + " AND substr(name, 1, " + std::to_string(rtree_.size()) +
            ") = " + quoted_literal(rtree_));
  for (std::size_t k = 0; k + 1 < found.size(); k += 2) {
    query("DROP TRIGGER " + quoted_identifier(found[k]));
    triggers_.push_back(found[k + 1]);
  }
}

void GpkgSpatialIndex::finish() {
  const std::vector<std::string> root_bytes = query(
      "SELECT length(data) FROM " + quoted_identifier(rtree_ + "_node") + " WHERE nodeno = 1");
  if (root_bytes.size() != 1) throw Error("the spatial index " + rtree_ + " has no root node");
  const PackedRtree packed =
      pack_rtree(std::move(boxes_), static_cast<std::size_t>(std::stoul(root_bytes[0])));
  const auto run = [this](const std::string& sql) { query(sql); };
  query("DELETE FROM " + quoted_identifier(rtree_ + "_node"));
  RowInserter nodes("INSERT INTO " + quoted_identifier(rtree_ + "_node") + "(nodeno, data)", run);
  RowInserter parents(
      "INSERT INTO " + quoted_identifier(rtree_ + "_parent") + "(nodeno, parentnode)", run);
  for (const RtreeNode& node : packed.nodes) {
    nodes.add("(" + std::to_string(node.number) + "," + hex_blob(node.blob) + ")");
    if (node.parent != 0) {
      parents.add("(" + std::to_string(node.number) + "," + std::to_string(node.parent) + ")");
    }
  }
  nodes.flush();
  parents.flush();
  RowInserter rows("INSERT INTO " + quoted_identifier(rtree_ + "_rowid") + "(rowid, nodeno)", run);
  for (const auto& [id, leaf] : packed.leaf_of) {
    rows.add("(" + std::to_string(id) + "," + std::to_string(leaf) + ")");
  }
  rows.flush();
  for (const std::string& trigger : triggers_) query(trigger);
}

std::vector<std::string> GpkgSpatialIndex::query(const std::string& sql) const {
  CPLErrorReset();
  OGRLayer* result = dataset_.ExecuteSQL(sql.c_str(), nullptr, nullptr);
  std::vector<std::string> values;
  if (result) {
    while (OGRFeature* row = result->GetNextFeature()) {
      for (int k = 0; k < row->GetFieldCount(); ++k) values.emplace_back(row->GetFieldAsString(k));
      OGRFeature::DestroyFeature(row);
    }
    dataset_.ReleaseResultSet(result);
  }
  if (CPLGetLastErrorType() >= CE_Failure) {
    throw Error("building the spatial index " + rtree_ + " failed: " + capture_.message());
  }
  return values;
}

}  // namespace tsk::io
