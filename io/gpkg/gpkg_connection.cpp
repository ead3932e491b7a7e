#include "io/gpkg/gpkg_connection.h"

#include <utility>

namespace tsk::io::gpkg {

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

std::string insert_rows_sql(const std::string& into, const std::string& row, std::size_t rows) {
  std::string sql = into;
  for (std::size_t k = 0; k < rows; ++k) sql += (k ? ", " : "") + row;
  return sql;
}

Connection::Connection(GDALDataset& dataset, std::string what)
    : db_(static_cast<sqlite3*>(dataset.GetInternalHandle("SQLITE_HANDLE"))),
      what_(std::move(what)) {
  if (!db_) fail("GDAL does not expose the file's SQLite connection");
}

Connection::Statement::Statement(const Connection& connection, const std::string& sql)
    : connection_(connection) {
  if (sqlite3_prepare_v2(connection_.db_, sql.c_str(), -1, &statement_, nullptr) != SQLITE_OK) {
    connection_.fail_with_message();
  }
}

bool Connection::Statement::step() {
  const int result = sqlite3_step(statement_);
  if (result == SQLITE_ROW) return true;
  sqlite3_reset(statement_);
  if (result != SQLITE_DONE) connection_.fail_with_message();
  return false;
}

void Connection::run(const std::string& sql) const {
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) {
    fail_with_message();
  }
}

void Connection::fail(const std::string& why) const {
  throw Error(what_ + " failed: " + why);
}

}  // namespace tsk::io::gpkg
