// The SQLite connection under a GDAL GeoPackage dataset, used directly: prepared statements bind
// blobs, numbers and text instead of SQL text that SQLite would have to parse, and skip GDAL's
// per-feature work. Private to the gpkg library.
#pragma once

#include <gdal_priv.h>
#include <sqlite3.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/errors.h"

namespace tsk::io::gpkg {

// `name` as an SQL identifier or string literal, its quotes doubled.
std::string quoted_identifier(const std::string& name);
std::string quoted_literal(const std::string& text);

// The most values a statement may bind: SQLite's limit before release 3.32.
constexpr std::size_t kMostBoundValues = 999;

// One statement inserting `rows` rows: `into` ("INSERT INTO t (a, b) VALUES ") and `row` ("(?, ?)")
// that many times. SQLite's work per statement (and per AUTOINCREMENT key) is then shared by the
// rows.
std::string insert_rows_sql(const std::string& into, const std::string& row, std::size_t rows);

class Connection {
 public:
  // `what` names the work in error messages ("building a GeoPackage spatial index").
  Connection(GDALDataset& dataset, std::string what);

  // A prepared statement, reset after each step() that ends it.
  class Statement {
   public:
    Statement(const Connection& connection, const std::string& sql);
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    ~Statement() { sqlite3_finalize(statement_); }

    Statement& bind(int index, std::int64_t value) {
      return check(sqlite3_bind_int64(statement_, index, value));
    }
    Statement& bind(int index, double value) {
      return check(sqlite3_bind_double(statement_, index, value));
    }
    // The text and blob must outlive the next step().
    Statement& bind(int index, const char* text) {
      return check(sqlite3_bind_text(statement_, index, text, -1, SQLITE_STATIC));
    }
    Statement& bind(int index, const std::vector<unsigned char>& blob) {
      return check(sqlite3_bind_blob(statement_, index, blob.data(), static_cast<int>(blob.size()),
                                     SQLITE_STATIC));
    }
    Statement& bind_null(int index) { return check(sqlite3_bind_null(statement_, index)); }
    // Runs the statement to its next row: true if there is one, false when it is done (and it is
    // reset, its bindings kept, to run again).
    bool step();
    std::int64_t integer(int column) const { return sqlite3_column_int64(statement_, column); }
    std::string text(int column) const {
      const unsigned char* t = sqlite3_column_text(statement_, column);
      return t ? reinterpret_cast<const char*>(t) : "";
    }

   private:
    Statement& check(int result) {
      if (result != SQLITE_OK) connection_.fail_with_message();
      return *this;
    }
    const Connection& connection_;
    sqlite3_stmt* statement_ = nullptr;
  };

  // Runs statements that return no rows.
  void run(const std::string& sql) const;
  // The row id of the last row inserted.
  std::int64_t last_row_id() const { return sqlite3_last_insert_rowid(db_); }
  [[noreturn]] void fail(const std::string& why) const;

 private:
  [[noreturn]] void fail_with_message() const { fail(sqlite3_errmsg(db_)); }

  sqlite3* db_;
  std::string what_;
};

}  // namespace tsk::io::gpkg
