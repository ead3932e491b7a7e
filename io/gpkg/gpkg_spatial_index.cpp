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
using Node = std::vector<Cell>;

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

namespace {

Cell cover(const Node& node, std::int64_t index) {
  Cell c;
  c.id = index;
  c.min_x = c.min_y = kInf;
  c.max_x = c.max_y = -kInf;
  for (const Cell& child : node) {
    c.min_x = std::min(c.min_x, child.min_x);
    c.max_x = std::max(c.max_x, child.max_x);
    c.min_y = std::min(c.min_y, child.min_y);
    c.max_y = std::max(c.max_y, child.max_y);
  }
  return c;
}

// Sorts (id, value) pairs of unique ids by id. The ids a writer hands on run without a gap
// (1, 2, ... n), and each pair then has its place without a sort (on the 8000 x 8000 benchmark,
// sorting 830 000 pairs on two threads took 0.03 s of the serial end of a run).
void sort_by_id(std::vector<std::pair<std::int64_t, std::int64_t>>& pairs) {
  if (pairs.empty()) return;
  const auto [lowest, highest] = std::minmax_element(pairs.begin(), pairs.end());
  const std::int64_t first = lowest->first;
  if (static_cast<std::uint64_t>(highest->first - first) + 1 != pairs.size()) {
    std::sort(pairs.begin(), pairs.end());
    return;
  }
  std::vector<std::pair<std::int64_t, std::int64_t>> placed(pairs.size(), {first - 1, 0});
  for (const auto& pair : pairs) placed[static_cast<std::size_t>(pair.first - first)] = pair;
  for (std::size_t k = 0; k < placed.size(); ++k) {
    if (placed[k].first != first + static_cast<std::int64_t>(k)) {  // an id given twice
      std::sort(pairs.begin(), pairs.end());
      return;
    }
  }
  pairs.swap(placed);
}

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

// Sorts the cells [first, last) by (key(cell), id), keys finite: by their keys' bits, keeping the
// order of equal ones, then each run of equal keys (boxes sharing a centre, few) by id. On the
// 8000 x 8000 benchmark's 830 000 boxes, std::sort took 0.1 s of the serial end of a run for the
// slices and as long again for the nodes within them.
template <typename Key>
void sort_by_key(Cell* first, Cell* last, Key key) {
  const auto count = static_cast<std::size_t>(last - first);
  std::vector<Keyed> keyed(count), spare;
  for (std::size_t k = 0; k < count; ++k) keyed[k] = {ordered_bits(key(first[k])), k};
  radix_sort(keyed, spare);
  const auto by_id = [first](const Keyed& a, const Keyed& b) {
    return first[a.at].id < first[b.at].id;
  };
  for (auto run = keyed.begin(); run != keyed.end();) {
    const auto end =
        std::find_if(run, keyed.end(), [&](const Keyed& k) { return k.bits != run->bits; });
    if (end - run > 1) std::sort(run, end, by_id);  // ids are unique: no order to keep
    run = end;
  }
  std::vector<Cell> sorted(count);
  for (std::size_t k = 0; k < count; ++k) sorted[k] = first[keyed[k].at];
  std::copy(sorted.begin(), sorted.end(), first);
}

// Sort-Tile-Recursive: vertical slices by centre x, each cut into nodes by centre y, so that a
// node holds boxes that lie close together.
std::vector<Node> tile(std::vector<Cell> cells, std::size_t per_node) {
  const std::size_t node_count = (cells.size() + per_node - 1) / per_node;
  auto slices = static_cast<std::size_t>(std::sqrt(static_cast<double>(node_count)));
  while (slices * slices < node_count) ++slices;
  const std::size_t slice_cells = std::max<std::size_t>(1, slices) * per_node;
  // The cell at index i, or the end.
  const auto at = [&cells](std::size_t i) { return cells.data() + std::min(i, cells.size()); };
  sort_by_key(at(0), at(cells.size()), centre_x);
  parallel_for((cells.size() + slice_cells - 1) / slice_cells, 0,
               [&](std::size_t lo, std::size_t hi) {
                 for (std::size_t slice = lo; slice < hi; ++slice) {
                   sort_by_key(at(slice * slice_cells), at((slice + 1) * slice_cells), centre_y);
                 }
               });
  std::vector<Node> nodes;
  for (std::size_t start = 0; start < cells.size(); start += slice_cells) {
    const std::size_t end = std::min(cells.size(), start + slice_cells);
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

}  // namespace

PackedRtree pack_rtree(std::vector<IndexBox> boxes, std::size_t node_bytes) {
  if (node_bytes < 4 + 2 * kCellBytes) {
    throw Error("R-tree nodes of " + std::to_string(node_bytes) + " bytes cannot hold two boxes");
  }
  const std::size_t per_node = (node_bytes - 4) / kCellBytes;

  // levels[0] holds the leaves (the boxes, as the R-tree stores them), levels.back() the root
  // alone.
  std::vector<std::vector<Node>> levels;
  // Pushed, not listed in braces: an initializer list would copy every leaf.
  levels.push_back(boxes.empty() ? std::vector<Node>(1) : tile(std::move(boxes), per_node));
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
          parent[level][static_cast<std::size_t>(c.id)] = number[level + 1][j];
        }
      }
    }
  }

  PackedRtree packed;
  packed.depth = static_cast<int>(levels.size()) - 1;
  std::size_t leaf_cells = 0;
  for (const Node& leaf : levels.front()) leaf_cells += leaf.size();
  packed.leaf_of.reserve(leaf_cells);
  for (std::size_t level = levels.size(); level-- > 0;) {
    for (std::size_t i = 0; i < levels[level].size(); ++i) {
      const Node& node = levels[level][i];
      RtreeNode out{number[level][i], parent[level][i], std::vector<unsigned char>(node_bytes)};
      if (out.number == 1) put_big_endian(out.blob.data(), static_cast<unsigned>(packed.depth), 2);
      put_big_endian(out.blob.data() + 2, node.size(), 2);
      for (std::size_t k = 0; k < node.size(); ++k) {
        const Cell& c = node[k];
        const std::int64_t ref =
            level == 0 ? c.id : number[level - 1][static_cast<std::size_t>(c.id)];
        unsigned char* cell = out.blob.data() + 4 + k * kCellBytes;
        put_big_endian(cell, static_cast<std::uint64_t>(ref), 8);
        put_float(cell + 8, c.min_x);
        put_float(cell + 12, c.max_x);
        put_float(cell + 16, c.min_y);
        put_float(cell + 20, c.max_y);
        if (level == 0) packed.leaf_of.emplace_back(c.id, out.number);
      }
      packed.nodes.push_back(std::move(out));
    }
  }
  return packed;
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

// Inserts the leaf of each feature into the R-tree's rowid table `rowids`, the pairs (id, leaf)
// sorted by id. Where the ids count up one by one from the first, as a writer's do, SQLite numbers
// the rows after the first itself, so that each goes to the table's end without a search for its
// id (a million strokes' rows: 0.16 s became 0.08 s).
void insert_leaves(const Connection& db, const std::string& rowids,
                   const std::vector<std::pair<std::int64_t, std::int64_t>>& leaf_of) {
  const std::string into = "INSERT INTO " + rowids + "(rowid, nodeno) VALUES ";
  const auto gap = [](const auto& a, const auto& b) { return b.first != a.first + 1; };
  if (leaf_of.empty() || std::adjacent_find(leaf_of.begin(), leaf_of.end(), gap) != leaf_of.end())
    return insert_pairs(db, into, leaf_of);
  insert_pairs(db, into, {leaf_of.front()});
  constexpr std::size_t kRowsPerInsert = 512;
  static_assert(kRowsPerInsert <= gpkg::kMostBoundValues, "too many values a statement");
  insert_in_batches(db, "INSERT INTO " + rowids + "(nodeno) VALUES ", "(?)", 1, kRowsPerInsert,
                    leaf_of.size() - 1, [&](Connection::Statement& insert, std::size_t k, int at) {
                      insert.bind(at, leaf_of[k + 1].second);
                    });
  if (db.last_row_id() != leaf_of.back().first)
    db.fail("SQLite numbered the spatial index's last row " + std::to_string(db.last_row_id()) +
            ", not " + std::to_string(leaf_of.back().first));
}

}  // namespace

void add_gpkg_spatial_index(GDALDataset& dataset, const std::string& table,
                            std::vector<IndexBox> boxes) {
  OGRLayer* layer = dataset.GetLayerByName(table.c_str());
  if (!layer) throw Error("no layer '" + table + "' to index");
  const std::string column = layer->GetGeometryColumn();
  const std::string fid = *layer->GetFIDColumn() ? layer->GetFIDColumn() : "fid";
  const std::string rtree = "rtree_" + table + "_" + column;
  const Connection db(dataset, "building a GeoPackage spatial index");

  db.run("CREATE VIRTUAL TABLE " + quoted_identifier(rtree) +
         " USING rtree(id, minx, maxx, miny, maxy)");
  std::size_t node_bytes = 0;
  {
    Connection::Statement root(
        db, "SELECT length(data) FROM " + quoted_identifier(rtree + "_node") + " WHERE nodeno = 1");
    if (root.step()) node_bytes = static_cast<std::size_t>(root.integer(0));
  }
  PackedRtree packed = pack_rtree(std::move(boxes), node_bytes);
  db.run("DELETE FROM " + quoted_identifier(rtree + "_node"));
  Connection::Statement node(
      db, "INSERT INTO " + quoted_identifier(rtree + "_node") + "(nodeno, data) VALUES (?, ?)");
  std::vector<std::pair<std::int64_t, std::int64_t>> parents;
  for (const RtreeNode& n : packed.nodes) {
    node.bind(1, n.number).bind(2, n.blob).step();
    if (n.parent != 0) parents.emplace_back(n.number, n.parent);
  }
  insert_pairs(
      db, "INSERT INTO " + quoted_identifier(rtree + "_parent") + "(nodeno, parentnode) VALUES ",
      parents);
  // In the order of the ids, so that each row lands at the end of the table's B-tree.
  std::vector<std::pair<std::int64_t, std::int64_t>> leaf_of = std::move(packed.leaf_of);
  sort_by_id(leaf_of);
  insert_leaves(db, quoted_identifier(rtree + "_rowid"), leaf_of);

  for (const std::string& trigger : rtree_triggers(table, column, fid, rtree)) db.run(trigger);
  db.run(
      "CREATE TABLE IF NOT EXISTS gpkg_extensions (table_name TEXT,column_name TEXT,"
      "extension_name TEXT NOT NULL,definition TEXT NOT NULL,scope TEXT NOT NULL,"
      "CONSTRAINT ge_tce UNIQUE (table_name, column_name, extension_name))");
  db.run(
      "INSERT INTO gpkg_extensions (table_name, column_name, extension_name, definition, scope) "
      "VALUES (" +
      quoted_literal(table) + ", " + quoted_literal(column) +
      ", 'gpkg_rtree_index', 'http://www.geopackage.org/spec120/#extension_rtree', "
      "'write-only')");
}

}  // namespace tsk::io
