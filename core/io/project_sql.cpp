#include "core/io/project_sql.h"

#include <cctype>
#include <ctime>
#include <utility>

namespace mozzi::core::io::sql {

Error sqliteError(sqlite3* db, const std::string& what, const std::string& where) {
  const int code = db ? sqlite3_errcode(db) : SQLITE_NOMEM;
  ErrorCode kind = ErrorCode::IoError;
  if (code == SQLITE_NOTADB || code == SQLITE_CORRUPT) kind = ErrorCode::Corrupt;
  if (code == SQLITE_BUSY || code == SQLITE_LOCKED) kind = ErrorCode::Locked;
  if (code == SQLITE_CONSTRAINT) kind = ErrorCode::InvalidArgument;
  return makeError(kind, what + ": " + (db ? sqlite3_errmsg(db) : "out of memory"), where);
}

Result<void> exec(sqlite3* db, const char* sql, const std::string& where) {
  char* message = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    std::string text = message ? message : "unknown error";
    sqlite3_free(message);
    return sqliteError(db, text, where);
  }
  return {};
}

Result<std::int64_t> queryInt(sqlite3* db, const char* sql, const std::string& where) {
  Statement stmt(db, sql);
  if (!stmt.ok()) return sqliteError(db, sql, where);
  MOZZI_TRY_ASSIGN(const bool atRow, stmt.next(sql, where));
  return atRow ? sqlite3_column_int64(stmt.get(), 0) : std::int64_t{0};
}

std::string fileUri(const std::string& path) {
  std::string uri = "file:";
  // An absolute path starts "file:/..." ; a relative one must not start with
  // '/', which it does not. Percent-encode everything outside a safe set.
  static const char* kHex = "0123456789ABCDEF";
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_' || c == '~' || c == ',' || c == '+' ||
        c == '=' || c == '@' || c == ':') {
      uri += static_cast<char>(c);
    } else {
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 15];
    }
  }
  return uri;
}

std::string nowUtc() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

std::string columnText(sqlite3_stmt* stmt, int column) {
  const unsigned char* text = sqlite3_column_text(stmt, column);
  if (!text) return {};
  return std::string(reinterpret_cast<const char*>(text), static_cast<std::size_t>(sqlite3_column_bytes(stmt, column)));
}

Result<Dof> columnDof(sqlite3_stmt* stmt, int nodeColumn, int directionColumn, const std::string& where) {
  if (sqlite3_column_type(stmt, nodeColumn) != SQLITE_INTEGER ||
      sqlite3_column_type(stmt, directionColumn) != SQLITE_INTEGER) {
    return makeError(ErrorCode::Corrupt, "a DOF column is not an integer", where);
  }
  const std::int64_t node = sqlite3_column_int64(stmt, nodeColumn);
  const std::int64_t code = sqlite3_column_int64(stmt, directionColumn);
  if (node < INT32_MIN || node > INT32_MAX || code < -6 || code > 6) {
    return makeError(ErrorCode::Corrupt, "DOF out of range", where);
  }
  auto dof = dofFromUff(static_cast<int>(node), static_cast<int>(code));
  if (!dof) return makeError(ErrorCode::Corrupt, dof.error().message, where);
  return *dof;
}

std::optional<Dof> columnOptionalDof(sqlite3_stmt* stmt, int nodeColumn, int directionColumn) {
  auto dof = columnDof(stmt, nodeColumn, directionColumn, {});
  if (!dof) return std::nullopt;
  return *dof;
}

Statement::Statement(sqlite3* db, const char* sql) : db_(db) {
  if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) {
    sqlite3_finalize(stmt_);
    stmt_ = nullptr;
  }
}

Statement::~Statement() {
  sqlite3_finalize(stmt_);
}

Statement& Statement::bind(int index, std::int64_t value) {
  sqlite3_bind_int64(stmt_, index, value);
  return *this;
}
Statement& Statement::bind(int index, double value) {
  sqlite3_bind_double(stmt_, index, value);
  return *this;
}
Statement& Statement::bind(int index, const std::string& value) {
  sqlite3_bind_text(stmt_, index, value.c_str(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
  return *this;
}
Statement& Statement::bindBlob(int index, const void* data, std::size_t size) {
  // sqlite3_bind_blob64 copies nothing with SQLITE_STATIC: the caller keeps the
  // buffer alive until step() has run.
  sqlite3_bind_blob64(stmt_, index, size ? data : "", static_cast<sqlite3_uint64>(size), SQLITE_STATIC);
  return *this;
}
Statement& Statement::bindNull(int index) {
  sqlite3_bind_null(stmt_, index);
  return *this;
}
Statement& Statement::bind(int index, const std::optional<std::int64_t>& value) {
  return value ? bind(index, *value) : bindNull(index);
}
Statement& Statement::bindDof(int index, const std::optional<Dof>& dof) {
  if (!dof) return bindNull(index).bindNull(index + 1);
  return bind(index, dof->node).bind(index + 1, dof->uffCode());
}

int Statement::step() {
  return stmt_ ? sqlite3_step(stmt_) : SQLITE_MISUSE;
}

void Statement::reset() {
  if (!stmt_) return;
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

Result<void> Statement::run(const std::string& what, const std::string& where) {
  if (step() != SQLITE_DONE) return sqliteError(db_, what, where);
  return {};
}

Result<std::int64_t> Statement::insert(const std::string& what, const std::string& where) {
  MOZZI_TRY(run(what, where));
  return static_cast<std::int64_t>(sqlite3_last_insert_rowid(db_));
}

Result<void> Statement::single(const std::string& what, const std::string& absent, const std::string& where) {
  MOZZI_TRY_ASSIGN(const bool atRow, next(what, where));
  if (!atRow) return makeError(ErrorCode::NotFound, absent, where);
  return {};
}

Result<bool> Statement::next(const std::string& what, const std::string& where) {
  const int rc = step();
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  return sqliteError(db_, what, where);
}

Transaction::Transaction(sqlite3* db, std::string where) : db_(db), where_(std::move(where)) {
  begun_ = exec(db_, "BEGIN IMMEDIATE", where_);
  open_ = begun_.ok();
}

Transaction::~Transaction() {
  if (open_) (void)exec(db_, "ROLLBACK", where_);
}

Result<void> Transaction::commit() {
  if (!open_) return makeError(ErrorCode::InvalidArgument, "no transaction to commit", where_);
  auto r = exec(db_, "COMMIT", where_);
  if (r) open_ = false;
  return r;
}

}  // namespace mozzi::core::io::sql
