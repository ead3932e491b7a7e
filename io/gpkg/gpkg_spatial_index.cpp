#include "io/gpkg/gpkg_spatial_index.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

#include "core/base/errors.h"
#include "core/base/parallel.h"
#include "io/gpkg/gpkg_connection.h"

namespace tsk::io {
namespace {

using gpkg::Connection;
using gpkg::quoted_identifier;
using gpkg::quoted_literal;

// A box as the R-tree stores it (IndexBox): its `id` is a feature id in a leaf, a child's index in
// its level otherwise.
using Cell = IndexBox;

double centre_x(const Cell& c) {
  return 0.5 * (double{c.min_x} + double{c.max_x});
}
double centre_y(const Cell& c) {
  return 0.5 * (double{c.min_y} + double{c.max_y});
}

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

}  // namespace

IndexBox::IndexBox(std::int64_t feature, double x0, double x1, double y0, double y1)
    : id(feature),
      min_x(round_down(x0)),
      max_x(round_up(x1)),
      min_y(round_down(y0)),
      max_y(round_up(y1)) {}

IndexBox cover(const IndexBox* first, const IndexBox* last, std::int64_t id) {
  Cell c;
  c.id = id;
  c.min_x = c.min_y = kInf;
  c.max_x = c.max_y = -kInf;
  for (const Cell* child = first; child != last; ++child) {
    c.min_x = std::min(c.min_x, child->min_x);
    c.max_x = std::max(c.max_x, child->max_x);
    c.min_y = std::min(c.min_y, child->min_y);
    c.max_y = std::max(c.max_y, child->max_y);
  }
  return c;
}

namespace {

// A double's bits as an unsigned number in the double's order (-0 taken as +0).
std::uint64_t ordered_bits(double v) {
  v += 0.0;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

// An element to sort: its key's bits in the key's order, and where it is.
struct Keyed {
  std::uint64_t bits;
  std::size_t at;
};

// Orders `keyed` by its bits, those of equal bits kept in their order: a radix sort, 11 bits at a
// time from the least significant (`spare` is its scratch). Every digit's counts come from one
// read of the keys.
void radix_sort(std::vector<Keyed>& keyed, std::vector<Keyed>& spare) {
  constexpr int kDigitBits = 11, kPasses = (64 + kDigitBits - 1) / kDigitBits;
  constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;
  std::vector<std::size_t> start(kPasses * kDigits, 0);
  for (const Keyed& k : keyed) {
    for (int pass = 0; pass < kPasses; ++pass)
      ++start[pass * kDigits + ((k.bits >> (pass * kDigitBits)) & (kDigits - 1))];
  }
  spare.resize(keyed.size());
  for (int pass = 0; pass < kPasses; ++pass) {
    std::size_t* digit = start.data() + pass * kDigits;
    // A digit every key shares orders nothing.
    if (std::find(digit, digit + kDigits, keyed.size()) != digit + kDigits) continue;
    std::size_t placed = 0;
    for (std::size_t d = 0; d < kDigits; ++d) placed += std::exchange(digit[d], placed);
    const int shift = pass * kDigitBits;
    for (const Keyed& k : keyed) spare[digit[(k.bits >> shift) & (kDigits - 1)]++] = k;
    keyed.swap(spare);
  }
}

// Copies cells [begin, end) of `from` (finite keys) into `to` in the order of (key(cell), id): by
// their keys' bits, keeping the order of equal ones, then each run of equal keys (boxes sharing a
// centre, few) by id. On the 8000 x 8000 benchmark's 830 000 boxes, std::sort took 0.1 s of the
// serial end of a run for the slices and as long again for the nodes within them.
template <typename Cells, typename Key>
void sort_by_key(const Cells& from, std::size_t begin, std::size_t end, Key key, Cell* to) {
  std::vector<Keyed> keyed(end - begin), spare;
  bool ids_rise = true;  // with the cells' places: then equal keys, kept in order, are in id order
  for (std::size_t k = begin; k < end; ++k) {
    keyed[k - begin] = {ordered_bits(key(from[k])), k};
    if (k > begin && !(from[k - 1].id < from[k].id)) ids_rise = false;
  }
  radix_sort(keyed, spare);
  const auto by_id = [&from](const Keyed& a, const Keyed& b) {
    return from[a.at].id < from[b.at].id;
  };
  // (A writer's boxes, and every level's covers, come in id order: checking each run there read
  // the cells out of order, a cache miss each, about 0.2 s of a 16 000^2 run's serial end.)
  for (auto run = keyed.begin(); run != keyed.end() && !ids_rise;) {
    const auto run_end =
        std::find_if(run, keyed.end(), [&](const Keyed& k) { return k.bits != run->bits; });
    // Ids are unique: no order to keep. Boxes handed over in the order of their ids (a writer's)
    // keep it through the x sort, where runs are long (strokes sharing a column of cells).
    if (run_end - run > 1 && !std::is_sorted(run, run_end, by_id)) std::sort(run, run_end, by_id);
    run = run_end;
  }
  for (const Keyed& k : keyed) *to++ = from[k.at];
}

// Nodes to a slice that make as many slices as nodes in each: the square root of the node count,
// rounded up.
std::size_t square_slices(std::size_t cells, std::size_t per_node) {
  const std::size_t node_count = (cells + per_node - 1) / per_node;
  auto slices = static_cast<std::size_t>(std::sqrt(static_cast<double>(node_count)));
  while (slices * slices < node_count) ++slices;
  return slices;
}

// Sort-Tile-Recursive: `cells` in vertical slices of `nodes_per_slice` nodes by centre x, each cut
// into nodes by centre y, so that a node holds boxes that lie close together; into `cells` and
// `ends` of `level`.
template <typename Cells, typename Level>
void tile(const Cells& cells, std::size_t per_node, std::size_t nodes_per_slice, Level& level) {
  const std::size_t count = cells.size();
  const std::size_t slice_cells = std::max<std::size_t>(1, nodes_per_slice) * per_node;
  std::vector<Cell> by_x(count);
  sort_by_key(cells, 0, count, centre_x, by_x.data());
  level.cells.resize(count);
  parallel_for((count + slice_cells - 1) / slice_cells, 0, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t slice = lo; slice < hi; ++slice) {
      const std::size_t begin = slice * slice_cells;
      sort_by_key(by_x, begin, std::min(count, begin + slice_cells), centre_y,
                  level.cells.data() + begin);
    }
  });
  for (std::size_t start = 0; start < count; start += slice_cells) {
    const std::size_t end = std::min(count, start + slice_cells);
    for (std::size_t k = start; k < end; k += per_node)
      level.ends.push_back(std::min(end, k + per_node));
  }
  if (count == 0) level.ends.push_back(0);  // an empty root
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

}  // namespace

std::size_t boxes_per_node(std::size_t node_bytes) {
  if (node_bytes < 4 + 2 * kCellBytes) {
    throw Error("R-tree nodes of " + std::to_string(node_bytes) + " bytes cannot hold two boxes");
  }
  return (node_bytes - 4) / kCellBytes;
}

void node_blob(const IndexBox* first, const IndexBox* last, std::int64_t ref_offset,
               std::size_t node_bytes, int root_depth, std::vector<unsigned char>& blob) {
  const auto count = static_cast<std::size_t>(last - first);
  if (4 + count * kCellBytes > node_bytes) throw Error("internal: an R-tree node overfilled");
  blob.assign(node_bytes, 0);
  unsigned char* out = blob.data();
  if (root_depth >= 0) put_big_endian(out, static_cast<unsigned>(root_depth), 2);
  put_big_endian(out + 2, count, 2);
  for (unsigned char* at = out + 4; first != last; ++first, at += kCellBytes) {
    put_big_endian(at, static_cast<std::uint64_t>(first->id + ref_offset), 8);
    put_float(at + 8, first->min_x);
    put_float(at + 12, first->max_x);
    put_float(at + 16, first->min_y);
    put_float(at + 20, first->max_y);
  }
}

PackedLeaves pack_leaves(const IndexBoxes& boxes, std::size_t per_node,
                         std::size_t leaves_per_slice) {
  struct {
    std::vector<Cell> cells;
    std::vector<std::size_t> ends;
  } level;
  tile(boxes, per_node, leaves_per_slice, level);
  return {std::move(level.cells), std::move(level.ends)};
}

std::pair<std::int64_t, std::vector<std::int64_t>> leaf_of_each_id(
    const std::vector<IndexBox>& boxes, const std::vector<std::size_t>& ends,
    std::int64_t first_number) {
  if (boxes.empty()) return {};
  const auto lowest =
      std::min_element(boxes.begin(), boxes.end(), [](const IndexBox& a, const IndexBox& b) {
        return a.id < b.id;
      })->id;
  // 0 is no node's number: an id left at 0 has not been placed yet.
  std::vector<std::int64_t> leaf(boxes.size(), 0);
  for (std::size_t j = 0, begin = 0; j < ends.size(); begin = ends[j++]) {
    for (std::size_t k = begin; k < ends[j]; ++k) {
      const std::uint64_t at =
          static_cast<std::uint64_t>(boxes[k].id) - static_cast<std::uint64_t>(lowest);
      if (at >= leaf.size() || leaf[at] != 0) return {};  // a gap (somewhere), or a repeat
      leaf[at] = first_number + static_cast<std::int64_t>(j);
    }
  }
  return {lowest, std::move(leaf)};
}

template <typename F>
void PackedRtree::for_each_cell(const Level& level, F&& f) {
  for (std::size_t j = 0, begin = 0; j < level.ends.size(); begin = level.ends[j++]) {
    for (std::size_t k = begin; k < level.ends[j]; ++k)
      f(level.cells[k], level.first_number + static_cast<std::int64_t>(j));
  }
}

PackedRtree::PackedRtree(const IndexBoxes& boxes, std::size_t node_bytes, RtreeNumbering numbering)
    : node_bytes_(node_bytes), levels_below_(numbering.levels_below) {
  const std::size_t per_node = boxes_per_node(node_bytes);
  levels_.emplace_back();
  tile(boxes, per_node, square_slices(boxes.size(), per_node), levels_.back());
  while (levels_.back().ends.size() > 1) {
    const Level& below = levels_.back();
    std::vector<Cell> covers;
    covers.reserve(below.ends.size());
    for (std::size_t i = 0, begin = 0; i < below.ends.size(); begin = below.ends[i++]) {
      covers.push_back(cover(below.cells.data() + begin, below.cells.data() + below.ends[i],
                             static_cast<std::int64_t>(i)));
    }
    Level above;
    tile(covers, per_node, square_slices(covers.size(), per_node), above);
    levels_.push_back(std::move(above));  // `below` is not used after this
  }
  // Numbers top down from the root's 1; each node's parent from the cells above it.
  std::int64_t next = 1;
  for (std::size_t level = levels_.size(); level-- > 0;) {
    Level& l = levels_[level];
    l.first_number = next;
    next = level + 1 == levels_.size() ? numbering.below_root
                                       : next + static_cast<std::int64_t>(l.ends.size());
    l.parent.assign(l.ends.size(), 0);
    if (level + 1 == levels_.size()) continue;
    for_each_cell(levels_[level + 1], [&l](const Cell& cell, std::int64_t number) {
      l.parent[static_cast<std::size_t>(cell.id)] = number;
    });
  }
}

std::size_t PackedRtree::node_count() const {
  std::size_t count = 0;
  for (const Level& level : levels_) count += level.ends.size();
  return count;
}

void PackedRtree::node(std::size_t k, RtreeNode& node) const {
  std::size_t level = levels_.size() - 1;
  while (k >= levels_[level].ends.size()) k -= levels_[level--].ends.size();
  const Level& l = levels_[level];
  node.number = l.first_number + static_cast<std::int64_t>(k);
  node.parent = l.parent[k];
  const std::size_t begin = k > 0 ? l.ends[k - 1] : 0, end = l.ends[k];
  const std::int64_t ref_offset = level == 0 ? 0 : levels_[level - 1].first_number;
  node_blob(l.cells.data() + begin, l.cells.data() + end, ref_offset, node_bytes_,
            node.number == 1 ? depth() : -1, node.blob);
}

std::vector<std::pair<std::int64_t, std::int64_t>> PackedRtree::leaf_entries() const {
  std::vector<std::pair<std::int64_t, std::int64_t>> entries;
  entries.reserve(levels_.front().cells.size());
  for_each_cell(levels_.front(), [&entries](const Cell& cell, std::int64_t leaf) {
    entries.emplace_back(cell.id, leaf);
  });
  return entries;
}

std::pair<std::int64_t, std::vector<std::int64_t>> PackedRtree::leaves_by_id() const {
  const Level& leaves = levels_.front();
  return leaf_of_each_id(leaves.cells, leaves.ends, leaves.first_number);
}

namespace {

// The triggers of the GeoPackage R-tree extension (GeoPackage 1.2, F.3) on R-tree `r`, as GDAL 3.6
// makes them.
std::vector<std::string> rtree_triggers(const std::string& table, const std::string& column,
                                        const std::string& fid, const std::string& r) {
  const std::string t = quoted_identifier(table), c = quoted_identifier(column),
                    i = quoted_identifier(fid), rtree = quoted_identifier(r);
  const std::string upsert = "INSERT OR REPLACE INTO " + rtree + " VALUES (NEW." + i +
                             ",ST_MinX(NEW." + c + "), ST_MaxX(NEW." + c + "),ST_MinY(NEW." + c +
                             "), ST_MaxY(NEW." + c + "));";
  const std::string has_geometry = "(NEW." + c + " NOTNULL AND NOT ST_IsEmpty(NEW." + c + "))";
  const std::string no_geometry = "(NEW." + c + " ISNULL OR ST_IsEmpty(NEW." + c + "))";
  const auto trigger = [&](const std::string& name, const std::string& when,
                           const std::string& body) {
    return "CREATE TRIGGER " + quoted_identifier(r + "_" + name) + " " + when + " BEGIN " + body +
           " END";
  };
  return {
      trigger("insert",
              "AFTER INSERT ON " + t + " WHEN (new." + c + " NOT NULL AND NOT ST_IsEmpty(NEW." + c +
                  "))",
              upsert),
      trigger("update1",
              "AFTER UPDATE OF " + c + " ON " + t + " WHEN OLD." + i + " = NEW." + i + " AND " +
                  has_geometry,
              upsert),
      trigger("update2",
              "AFTER UPDATE OF " + c + " ON " + t + " WHEN OLD." + i + " = NEW." + i + " AND " +
                  no_geometry,
              "DELETE FROM " + rtree + " WHERE id = OLD." + i + ";"),
      trigger("update3",
              "AFTER UPDATE ON " + t + " WHEN OLD." + i + " != NEW." + i + " AND " + has_geometry,
              "DELETE FROM " + rtree + " WHERE id = OLD." + i + "; " + upsert),
      trigger("update4",
              "AFTER UPDATE ON " + t + " WHEN OLD." + i + " != NEW." + i + " AND " + no_geometry,
              "DELETE FROM " + rtree + " WHERE id IN (OLD." + i + ", NEW." + i + ");"),
      trigger("delete", "AFTER DELETE ON " + t + " WHEN old." + c + " NOT NULL",
              "DELETE FROM " + rtree + " WHERE id = OLD." + i + ";"),
  };
}

// Inserts `count` rows with `into` ("INSERT INTO t (a, b) VALUES "), `per_insert` rows of `row`
// ("(?, ?)") to a statement (insert_rows_sql; 0.5 s for the million rows of a million strokes'
// index, one to a statement). bind(statement, k, at) binds row k's values from parameter `at` on.
template <typename Bind>
void insert_in_batches(const Connection& db, const std::string& into, const std::string& row,
                       int values_per_row, std::size_t per_insert, std::size_t count, Bind bind) {
  const auto statement = [&](std::size_t rows) {
    return std::make_unique<Connection::Statement>(db, gpkg::insert_rows_sql(into, row, rows));
  };
  std::unique_ptr<Connection::Statement> full;
  for (std::size_t first = 0; first < count; first += per_insert) {
    const std::size_t rows = std::min(per_insert, count - first);
    if (rows == per_insert && !full) full = statement(rows);
    const std::unique_ptr<Connection::Statement> last =
        rows < per_insert ? statement(rows) : nullptr;
    Connection::Statement& insert = last ? *last : *full;
    for (std::size_t k = 0; k < rows; ++k)
      bind(insert, first + k, 1 + static_cast<int>(k) * values_per_row);
    insert.step();
  }
}

// Inserts pairs of integers with `into` ("INSERT INTO t (a, b) VALUES ").
void insert_pairs(const Connection& db, const std::string& into,
                  const std::vector<std::pair<std::int64_t, std::int64_t>>& pairs) {
  constexpr std::size_t kRowsPerInsert = 256;
  static_assert(2 * kRowsPerInsert <= gpkg::kMostBoundValues, "too many values a statement");
  insert_in_batches(db, into, "(?, ?)", 2, kRowsPerInsert, pairs.size(),
                    [&](Connection::Statement& insert, std::size_t k, int at) {
                      insert.bind(at, pairs[k].first).bind(at + 1, pairs[k].second);
                    });
}

// Inserts the leaf of each feature into the R-tree's rowid table `rowids`: `leaf[k]` is the leaf of
// feature `first + k`. In the order of the ids, so that each row lands at the end of the table's
// B-tree; SQLite numbers the rows after the first itself, so that each goes to the table's end
// without a search for its id (a million strokes' rows: 0.16 s became 0.08 s).
void insert_leaves_by_id(const Connection& db, const std::string& rowids, std::int64_t first,
                         const std::vector<std::int64_t>& leaf) {
  if (leaf.empty()) return;
  insert_pairs(db, "INSERT INTO " + rowids + "(rowid, nodeno) VALUES ",
               {std::make_pair(first, leaf.front())});
  constexpr std::size_t kRowsPerInsert = 512;
  static_assert(kRowsPerInsert <= gpkg::kMostBoundValues, "too many values a statement");
  insert_in_batches(
      db, "INSERT INTO " + rowids + "(nodeno) VALUES ", "(?)", 1, kRowsPerInsert, leaf.size() - 1,
      [&](Connection::Statement& insert, std::size_t k, int at) { insert.bind(at, leaf[k + 1]); });
  const std::int64_t last = first + static_cast<std::int64_t>(leaf.size()) - 1;
  if (db.last_row_id() != last)
    db.fail("SQLite numbered the spatial index's last row " + std::to_string(db.last_row_id()) +
            ", not " + std::to_string(last));
}

// Inserts the leaf of each feature of `packed` into the R-tree's rowid table `rowids`, by id where
// the ids count up one by one from the first, as a writer's do.
void insert_leaves(const Connection& db, const std::string& rowids, const PackedRtree& packed) {
  const auto [first, leaf] = packed.leaves_by_id();
  if (!leaf.empty()) return insert_leaves_by_id(db, rowids, first, leaf);
  std::vector<std::pair<std::int64_t, std::int64_t>> entries = packed.leaf_entries();
  std::sort(entries.begin(), entries.end());
  insert_pairs(db, "INSERT INTO " + rowids + "(rowid, nodeno) VALUES ", entries);
}

Connection index_connection(GDALDataset& dataset) {
  return Connection(dataset, "building a GeoPackage spatial index");
}

}  // namespace

RtreeNames rtree_names(GDALDataset& dataset, const std::string& table) {
  OGRLayer* layer = dataset.GetLayerByName(table.c_str());
  if (!layer) throw Error("no layer '" + table + "' to index");
  RtreeNames names;
  names.table = table;
  names.column = layer->GetGeometryColumn();
  names.fid = *layer->GetFIDColumn() ? layer->GetFIDColumn() : "fid";
  names.rtree = "rtree_" + table + "_" + names.column;
  return names;
}

std::size_t create_rtree(GDALDataset& dataset, const RtreeNames& names) {
  const Connection db = index_connection(dataset);
  db.run("CREATE VIRTUAL TABLE " + quoted_identifier(names.rtree) +
         " USING rtree(id, minx, maxx, miny, maxy)");
  Connection::Statement root(
      db,
      "SELECT length(data) FROM " + quoted_identifier(names.rtree + "_node") + " WHERE nodeno = 1");
  return root.step() ? static_cast<std::size_t>(root.integer(0)) : 0;
}

std::vector<IndexBox> write_rtree_leaves(GDALDataset& dataset, const RtreeNames& names,
                                         std::size_t node_bytes, const PackedLeaves& leaves,
                                         std::int64_t first_number) {
  if (leaves.boxes.empty()) return {};
  const Connection db = index_connection(dataset);
  Connection::Statement node(db, "INSERT INTO " + quoted_identifier(names.rtree + "_node") +
                                     "(nodeno, data) VALUES (?, ?)");
  const auto [first_id, leaf] = leaf_of_each_id(leaves.boxes, leaves.ends, first_number);
  if (leaf.empty()) db.fail("a window's feature ids skip or repeat");
  std::vector<IndexBox> covers;
  covers.reserve(leaves.ends.size());
  std::vector<unsigned char> blob;
  for (std::size_t j = 0, begin = 0; j < leaves.ends.size(); begin = leaves.ends[j++]) {
    const IndexBox* first = leaves.boxes.data() + begin;
    const IndexBox* last = leaves.boxes.data() + leaves.ends[j];
    const std::int64_t number = first_number + static_cast<std::int64_t>(j);
    node_blob(first, last, 0, node_bytes, -1, blob);
    node.bind(1, number).bind(2, blob).step();
    covers.push_back(cover(first, last, number));
  }
  insert_leaves_by_id(db, quoted_identifier(names.rtree + "_rowid"), first_id, leaf);
  return covers;
}

void write_rtree(GDALDataset& dataset, const RtreeNames& names, const PackedRtree& packed) {
  const Connection db = index_connection(dataset);
  db.run("DELETE FROM " + quoted_identifier(names.rtree + "_node") + " WHERE nodeno = 1");
  Connection::Statement node(db, "INSERT INTO " + quoted_identifier(names.rtree + "_node") +
                                     "(nodeno, data) VALUES (?, ?)");
  std::vector<std::pair<std::int64_t, std::int64_t>> parents;
  RtreeNode n;  // each node in turn, its blob's storage reused
  for (std::size_t k = 0; k < packed.node_count(); ++k) {
    packed.node(k, n);
    node.bind(1, n.number).bind(2, n.blob).step();
    if (n.parent != 0) parents.emplace_back(n.number, n.parent);
  }
  // The nodes below, written before, name their parents among this tree's leaves.
  if (packed.covers_nodes()) {
    const auto below = packed.leaf_entries();
    parents.insert(parents.end(), below.begin(), below.end());
  }
  insert_pairs(
      db,
      "INSERT INTO " + quoted_identifier(names.rtree + "_parent") + "(nodeno, parentnode) VALUES ",
      parents);
  if (!packed.covers_nodes()) insert_leaves(db, quoted_identifier(names.rtree + "_rowid"), packed);

  for (const std::string& trigger :
       rtree_triggers(names.table, names.column, names.fid, names.rtree))
    db.run(trigger);
  db.run(
      "CREATE TABLE IF NOT EXISTS gpkg_extensions (table_name TEXT,column_name TEXT,"
      "extension_name TEXT NOT NULL,definition TEXT NOT NULL,scope TEXT NOT NULL,"
      "CONSTRAINT ge_tce UNIQUE (table_name, column_name, extension_name))");
  db.run(
      "INSERT INTO gpkg_extensions (table_name, column_name, extension_name, definition, scope) "
      "VALUES (" +
      quoted_literal(names.table) + ", " + quoted_literal(names.column) +
      ", 'gpkg_rtree_index', 'http://www.geopackage.org/spec120/#extension_rtree', "
      "'write-only')");
}

void add_gpkg_spatial_index(GDALDataset& dataset, const std::string& table,
                            const IndexBoxes& boxes) {
  const RtreeNames names = rtree_names(dataset, table);
  const std::size_t node_bytes = create_rtree(dataset, names);
  write_rtree(dataset, names, PackedRtree(boxes, node_bytes));
}

}  // namespace tsk::io
