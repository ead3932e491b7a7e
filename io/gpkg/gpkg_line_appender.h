// Line features appended to a GeoPackage layer straight through SQLite.
//
// GDAL creates the file, the layer and its fields; the rows are then inserted through prepared
// statements, each line's GeoPackage geometry blob built in reused memory, rather than through an
// OGRFeature and GDAL's GeoPackage writer per stroke (102 000 strokes: 0.3 s of a 0.9 s run).
// Rows go in many to a statement: SQLite's work per statement (and per AUTOINCREMENT key) is then
// shared by the rows (the 954 000 exact strokes of the 8000 x 8000 benchmark: 2.1 s of writing
// became 1.2 s). SQLite numbers them as it appends them (0.61 s of writing became 0.52 s).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/method/strokes.h"
#include "io/gpkg/gpkg_rtree_stream.h"
#include "io/write/early_writeback.h"

class GDALDataset;

namespace tsk::io {

class GpkgLineAppender {
 public:
  // `table` is a line layer of `dataset` with no features yet; set() numbers its attribute
  // fields in the layer's order, and every row sets them all. Its spatial index is packed
  // `index_window_leaves` leaves at a time (RtreeStream).
  GpkgLineAppender(GDALDataset& dataset, const std::string& table,
                   std::size_t index_window_leaves = RtreeStream::kWindowLeaves);
  ~GpkgLineAppender();
  GpkgLineAppender(const GpkgLineAppender&) = delete;
  GpkgLineAppender& operator=(const GpkgLineAppender&) = delete;

  // The value of attribute `field` for the next row.
  void set_null(int field);
  void set(int field, std::int64_t value);
  void set(int field, double value);  // NaN and infinities are written as null
  void set(int field, const char* text);
  // Inserts a row: the line through `points` with the attributes set since the last row, a
  // LineString M with `m` (one per point) when given, else a LineString.
  void add(const std::vector<StrokePoint>& points, const std::vector<double>& m = {});
  // Writes the rows still waiting, the layer's extent and feature count, its spatial index in
  // bulk, and its description (gpkg_contents) when `description` is not empty.
  void finish(const std::string& description = {});

 private:
  class Rows;
  // An attribute's value, kept until its row is inserted.
  struct Value {
    enum class Kind { null, integer, real, text } kind = Kind::null;
    std::int64_t integer = 0;
    double real = 0.0;
    std::string text;
  };
  // A row waiting to be inserted: its geometry blob and attributes.
  struct Row {
    std::vector<unsigned char> blob;
    std::vector<Value> values;
  };
  Value& value(int field);
  // Inserts the rows waiting.
  void insert_waiting();

  GDALDataset& dataset_;
  std::string table_;
  std::unique_ptr<Rows> rows_;
  std::vector<unsigned char> header_;  // the start of every geometry blob
  std::vector<Row> waiting_;           // their storage reused batch after batch
  std::size_t waiting_count_ = 0;
  EarlyWriteback writeback_;        // of the file the dataset writes
  std::size_t rows_unflushed_ = 0;  // rows inserted since the last writeback was started
  std::size_t fields_ = 0;
  std::int64_t next_id_ = 1;
  RtreeStream index_;
  std::string count_trigger_;  // GDAL's, dropped while rows are inserted
  double min_x_ = std::numeric_limits<double>::infinity(), max_x_ = -min_x_;
  double min_y_ = min_x_, max_y_ = -min_x_;
};

// Lines appended to a layer of a GeoPackage file that someone else created and closed (QGIS's
// feature sinks, made with no spatial index), in a transaction of its own: whole or not at all.
class GpkgFileAppender {
 public:
  // An empty `table` names the file's only layer.
  GpkgFileAppender(const std::string& path, const std::string& table,
                   std::size_t index_window_leaves = RtreeStream::kWindowLeaves);
  ~GpkgFileAppender();  // without finish(), nothing of the lines is kept
  GpkgFileAppender(const GpkgFileAppender&) = delete;
  GpkgFileAppender& operator=(const GpkgFileAppender&) = delete;

  GpkgLineAppender& lines() { return *lines_; }
  // Writes the layer's extent, count, spatial index and description (when not empty), commits
  // and closes the file.
  void finish(const std::string& description = {});

 private:
  std::string path_;
  std::unique_ptr<GDALDataset> dataset_;
  std::unique_ptr<GpkgLineAppender> lines_;
};

}  // namespace tsk::io
