#include "io/gpkg/gpkg_line_appender.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "io/gpkg/gpkg_connection.h"

namespace tsk::io {
namespace {

using gpkg::Connection;
using gpkg::quoted_identifier;

const char* const kWhat = "writing lines to a GeoPackage";

// Geometry blobs in the machine's byte order, which their flag bytes declare.
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr unsigned char kLittleEndian = 0;
#else
constexpr unsigned char kLittleEndian = 1;
#endif

template <typename T>
void append(std::vector<unsigned char>& out, T value) {
  const std::size_t at = out.size();
  out.resize(at + sizeof value);
  std::memcpy(out.data() + at, &value, sizeof value);
}

}  // namespace

// Rows inserted by one statement (gpkg::insert_rows_sql), fewer when a row binds many values.
constexpr std::size_t kRowsPerInsert = 64;
// Rows between two writebacks started early (early_writeback.h): about 7 MB of drawn strokes.
constexpr std::size_t kRowsPerWriteback = 16384;

// The connection and the statement that inserts a full batch of rows (prepared on the connection,
// so declared after it).
class GpkgLineAppender::Rows {
 public:
  // `into`: "INSERT INTO table (columns) VALUES "; `row`: a row's "(?, ...)".
  Rows(GDALDataset& dataset, std::string into_sql, std::string row_sql, std::size_t rows)
      : db(dataset, kWhat),
        into(std::move(into_sql)),
        row(std::move(row_sql)),
        many(db, gpkg::insert_rows_sql(into, row, rows)) {}
  Connection db;
  std::string into, row;
  Connection::Statement many;
};

GpkgLineAppender::GpkgLineAppender(GDALDataset& dataset, const std::string& table,
                                   std::size_t index_window_leaves)
    : dataset_(dataset),
      table_(table),
      writeback_(dataset.GetDescription()),
      index_(dataset, table, index_window_leaves) {
  OGRLayer* layer = dataset.GetLayerByName(table.c_str());
  if (!layer) throw Error("no layer '" + table + "' to write to");
  // GDAL creates the table when it syncs the layer.
  if (layer->SyncToDisk() != OGRERR_NONE) {
    throw Error(std::string(kWhat) + " failed: " + CPLGetLastErrorMsg());
  }
  const std::string id_column = quoted_identifier(layer->GetFIDColumn());
  std::string columns = quoted_identifier(layer->GetGeometryColumn());
  std::string row = "(?";
  const OGRFeatureDefn* fields = layer->GetLayerDefn();
  fields_ = static_cast<std::size_t>(fields->GetFieldCount());
  for (std::size_t k = 0; k < fields_; ++k) {
    columns += ", " + quoted_identifier(fields->GetFieldDefn(static_cast<int>(k))->GetNameRef());
    row += ", ?";
  }
  const std::size_t rows =
      std::max<std::size_t>(1, std::min(kRowsPerInsert, gpkg::kMostBoundValues / (fields_ + 1)));
  rows_ = std::make_unique<Rows>(
      dataset, "INSERT INTO " + quoted_identifier(table) + " (" + columns + ") VALUES ", row + ")",
      rows);
  waiting_.resize(rows, Row{{}, std::vector<Value>(fields_)});
  // SQLite numbers the rows after the largest id the table has had: its rows' (none, as made)
  // and, for an AUTOINCREMENT key, the largest it ever gave.
  Connection::Statement last_id(rows_->db,
                                "SELECT max(" + id_column + ") FROM " + quoted_identifier(table));
  if (last_id.step()) next_id_ = last_id.integer(0) + 1;
  const bool sequenced =
      Connection::Statement(
          rows_->db,
          "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'sqlite_sequence'")
          .step();
  if (sequenced) {
    Connection::Statement sequence(rows_->db, "SELECT seq FROM sqlite_sequence WHERE name = ?");
    sequence.bind(1, table.c_str());
    if (sequence.step()) next_id_ = std::max(next_id_, sequence.integer(0) + 1);
  }
  Connection::Statement srs(rows_->db,
                            "SELECT srs_id FROM gpkg_geometry_columns WHERE table_name = ?");
  srs.bind(1, table_.c_str());
  if (!srs.step()) rows_->db.fail("the layer '" + table + "' has no geometry column");
  const auto srs_id = static_cast<std::int32_t>(srs.integer(0));
  // GDAL's trigger that counts every insert: costly row by row, and the count is set in finish().
  Connection::Statement trigger(
      rows_->db, "SELECT sql FROM sqlite_master WHERE type = 'trigger' AND name = ?");
  const std::string trigger_name = "trigger_insert_feature_count_" + table;
  trigger.bind(1, trigger_name.c_str());
  if (trigger.step()) {
    count_trigger_ = trigger.text(0);
    rows_->db.run("DROP TRIGGER " + quoted_identifier(trigger_name));
  }
  // The blob's header: magic, version, flags (byte order, an x-y envelope), the CRS id.
  constexpr unsigned char kEnvelopeXY = 1 << 1;
  header_ = {'G', 'P', 0, static_cast<unsigned char>(kLittleEndian | kEnvelopeXY)};
  append(header_, srs_id);
}

GpkgLineAppender::~GpkgLineAppender() = default;

GpkgLineAppender::Value& GpkgLineAppender::value(int field) {
  if (field < 0 || static_cast<std::size_t>(field) >= fields_)
    rows_->db.fail("no attribute field " + std::to_string(field));
  return waiting_[waiting_count_].values[static_cast<std::size_t>(field)];
}

void GpkgLineAppender::set_null(int field) {
  value(field).kind = Value::Kind::null;
}

void GpkgLineAppender::set(int field, std::int64_t value) {
  Value& v = this->value(field);
  v.kind = Value::Kind::integer;
  v.integer = value;
}

void GpkgLineAppender::set(int field, double value) {
  if (!std::isfinite(value)) return set_null(field);
  Value& v = this->value(field);
  v.kind = Value::Kind::real;
  v.real = value;
}

void GpkgLineAppender::set(int field, const char* text) {
  Value& v = value(field);
  v.kind = Value::Kind::text;
  v.text = text;
}

void GpkgLineAppender::add(const std::vector<StrokePoint>& points, const std::vector<double>& m) {
  const bool measured = !m.empty();
  if (measured && m.size() != points.size()) rows_->db.fail("a line with an M value missing");
  if (points.size() > std::numeric_limits<std::uint32_t>::max()) {
    rows_->db.fail("a line of " + std::to_string(points.size()) + " points");
  }
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const StrokePoint& p : points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  // The blob, sized once and written in place: the header, the envelope, then well-known binary
  // (byte order, type 2 (LineString) or 2002 (LineString M), the number of points, the points).
  const std::size_t per_point = (measured ? 3 : 2) * sizeof(double);
  std::vector<unsigned char>& blob = waiting_[waiting_count_].blob;
  blob.resize(header_.size() + 4 * sizeof(double) + 1 + 2 * sizeof(std::uint32_t) +
              points.size() * per_point);
  unsigned char* out = std::copy(header_.begin(), header_.end(), blob.data());
  const auto put = [&out](auto value) {
    std::memcpy(out, &value, sizeof value);
    out += sizeof value;
  };
  for (double v : {x0, x1, y0, y1}) put(v);
  put(kLittleEndian);
  put(std::uint32_t{measured ? 2002u : 2u});
  put(static_cast<std::uint32_t>(points.size()));
  static_assert(sizeof(StrokePoint) == 2 * sizeof(double), "points are x, y pairs");
  if (measured) {
    for (std::size_t k = 0; k < points.size(); ++k)
      put(std::array<double, 3>{points[k].x, points[k].y, m[k]});
  } else if (!points.empty()) {
    std::memcpy(out, points.data(), points.size() * sizeof(StrokePoint));
  }
  index_.add({next_id_++, x0, x1, y0, y1});
  min_x_ = std::min(min_x_, x0), max_x_ = std::max(max_x_, x1);
  min_y_ = std::min(min_y_, y0), max_y_ = std::max(max_y_, y1);
  if (++waiting_count_ == waiting_.size()) insert_waiting();
}

void GpkgLineAppender::insert_waiting() {
  if (waiting_count_ == 0) return;
  // A last batch short of full has a statement of its own.
  std::unique_ptr<Connection::Statement> short_batch;
  if (waiting_count_ < waiting_.size())
    short_batch = std::make_unique<Connection::Statement>(
        rows_->db, gpkg::insert_rows_sql(rows_->into, rows_->row, waiting_count_));
  Connection::Statement& insert = short_batch ? *short_batch : rows_->many;
  int at = 1;
  for (std::size_t r = 0; r < waiting_count_; ++r) {
    Row& row = waiting_[r];
    insert.bind(at++, row.blob);
    for (Value& v : row.values) {
      switch (v.kind) {
        case Value::Kind::null:
          insert.bind_null(at);
          break;
        case Value::Kind::integer:
          insert.bind(at, v.integer);
          break;
        case Value::Kind::real:
          insert.bind(at, v.real);
          break;
        case Value::Kind::text:
          insert.bind(at, v.text.c_str());
          break;
      }
      ++at;
      v.kind = Value::Kind::null;  // unless the next row sets it
    }
  }
  insert.step();
  rows_unflushed_ += waiting_count_;
  waiting_count_ = 0;
  if (rows_unflushed_ >= kRowsPerWriteback) {
    writeback_.start();
    rows_unflushed_ = 0;
  }
  // SQLite numbers the rows, so that each goes to the table's end without a search for its id (15 %
  // of writing); the index's boxes were given the ids it gives.
  if (rows_->db.last_row_id() != next_id_ - 1)
    rows_->db.fail("SQLite numbered the last row " + std::to_string(rows_->db.last_row_id()) +
                   " where its spatial index expects " + std::to_string(next_id_ - 1));
}

void GpkgLineAppender::finish(const std::string& description) {
  insert_waiting();
  const Connection& db = rows_->db;
  if (!description.empty()) {
    Connection::Statement describe(
        db, "UPDATE gpkg_contents SET description = ? WHERE lower(table_name) = lower(?)");
    describe.bind(1, description.c_str()).bind(2, table_.c_str());
    describe.step();
  }
  if (index_.size() > 0) {
    Connection::Statement extent(db,
                                 "UPDATE gpkg_contents SET min_x = ?, min_y = ?, max_x = ?, "
                                 "max_y = ? WHERE lower(table_name) = lower(?)");
    extent.bind(1, min_x_).bind(2, min_y_).bind(3, max_x_).bind(4, max_y_).bind(5, table_.c_str());
    extent.step();
  }
  // GDAL keeps a feature count when the file has the table for it.
  const bool counted =
      Connection::Statement(
          db, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'gpkg_ogr_contents'")
          .step();
  if (counted) {
    Connection::Statement count(
        db, "UPDATE gpkg_ogr_contents SET feature_count = ? WHERE lower(table_name) = lower(?)");
    count.bind(1, static_cast<std::int64_t>(index_.size())).bind(2, table_.c_str());
    count.step();
  }
  if (!count_trigger_.empty()) db.run(count_trigger_);
  index_.finish();
}

GpkgFileAppender::GpkgFileAppender(const std::string& path, const std::string& table,
                                   std::size_t index_window_leaves)
    : path_(path) {
  GDALAllRegister();
  CPLErrorReset();
  dataset_.reset(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr)));
  if (!dataset_) throw Error("cannot open '" + path + "' to write lines: " + CPLGetLastErrorMsg());
  OGRLayer* layer = table.empty() && dataset_->GetLayerCount() == 1
                        ? dataset_->GetLayer(0)
                        : dataset_->GetLayerByName(table.c_str());
  if (!layer) throw Error("'" + path + "' has no layer '" + table + "' to write lines to");
  if (dataset_->StartTransaction() != OGRERR_NONE) {
    throw Error("cannot start a transaction in '" + path + "': " + CPLGetLastErrorMsg());
  }
  lines_ = std::make_unique<GpkgLineAppender>(*dataset_, layer->GetName(), index_window_leaves);
}

GpkgFileAppender::~GpkgFileAppender() {
  if (!dataset_) return;
  lines_.reset();
  dataset_->RollbackTransaction();
}

void GpkgFileAppender::finish(const std::string& description) {
  lines_->finish(description);
  lines_.reset();  // its statements end before the commit
  if (dataset_->CommitTransaction() != OGRERR_NONE) {
    throw Error("cannot commit the lines written to '" + path_ + "': " + CPLGetLastErrorMsg());
  }
  CPLErrorReset();
  dataset_.reset();
  if (CPLGetLastErrorType() >= CE_Failure) {
    throw Error("closing '" + path_ + "' failed: " + CPLGetLastErrorMsg());
  }
}

}  // namespace tsk::io
