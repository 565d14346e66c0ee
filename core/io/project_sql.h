#pragma once
// Private helpers of the project store: RAII statements and transactions over
// the SQLite C API. Not part of core's public face; include only from
// core/io/project_*.cpp.

#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/common/dof.h"
#include "core/common/result.h"
#include "core/io/project_records.h"

namespace mozzi::core::io::sql {

Error sqliteError(sqlite3* db, const std::string& what, const std::string& where);

Result<void> exec(sqlite3* db, const char* sql, const std::string& where);

Result<std::int64_t> queryInt(sqlite3* db, const char* sql, const std::string& where);

std::string nowUtc();

// "file:" URI of a path for sqlite3_open_v2 with SQLITE_OPEN_URI ('%', '?',
// '#' and non-ASCII bytes percent-encoded; a relative path stays relative).
std::string fileUri(const std::string& path);

// Text of a column; "" for NULL (a corrupt or hostile file may hold NULLs
// where the schema promises text).
std::string columnText(sqlite3_stmt* stmt, int column);

// A DOF from (node, signed UFF direction) columns; NULL or an invalid code is
// an error naming `where`.
Result<Dof> columnDof(sqlite3_stmt* stmt, int nodeColumn, int directionColumn, const std::string& where);
std::optional<Dof> columnOptionalDof(sqlite3_stmt* stmt, int nodeColumn, int directionColumn);

// A campaign row: every query selects these columns in this order.
inline constexpr const char* kCampaignColumns =
    "id, specimen_id, rig_setup_id, name, kind, notes, started_utc, settings_json";
StoredCampaign campaignFromRow(sqlite3_stmt* row);

// Inserts a campaign's schedule inside the caller's transaction (checks
// positions 0..n-1 and distinct DOFs); project_campaign.cpp.
Result<void> insertCampaignPoints(sqlite3* db, std::int64_t campaignId, const std::vector<StoredCampaignPoint>& points,
                                  const std::string& where);

// CRC-32 of the content of an empty mesh (project_data.cpp; docs/formats/project.md, "Checksums"), the
// value a new specimen starts with.
std::uint32_t emptyMeshChecksum();

// One row of a stepped statement, read by column index. Valid only inside
// the forEachRow() visit (or after next() returned true) that handed it out.
class Row {
 public:
  explicit Row(sqlite3_stmt* stmt) : stmt_(stmt) {}
  sqlite3_stmt* get() const { return stmt_; }
  int columnCount() const { return sqlite3_column_count(stmt_); }
  bool isNull(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
  std::int64_t int64(int column) const { return sqlite3_column_int64(stmt_, column); }
  int int32(int column) const { return sqlite3_column_int(stmt_, column); }
  double real(int column) const { return sqlite3_column_double(stmt_, column); }
  std::string text(int column) const { return columnText(stmt_, column); }
  // std::nullopt for NULL.
  std::optional<std::int64_t> optionalInt64(int column) const {
    return isNull(column) ? std::nullopt : std::optional<std::int64_t>(int64(column));
  }
  std::optional<int> optionalInt32(int column) const {
    return isNull(column) ? std::nullopt : std::optional<int>(int32(column));
  }
  std::optional<double> optionalReal(int column) const {
    return isNull(column) ? std::nullopt : std::optional<double>(real(column));
  }
  Result<Dof> dof(int nodeColumn, int directionColumn, const std::string& where) const {
    return columnDof(stmt_, nodeColumn, directionColumn, where);
  }
  std::optional<Dof> optionalDof(int nodeColumn, int directionColumn) const {
    return columnOptionalDof(stmt_, nodeColumn, directionColumn);
  }
  // Reads columns 0, 1, ... into `out` in order, by each one's type: integers,
  // double, std::string, std::optional<std::int64_t> or std::optional<int>
  // (NULL: empty). The mirror of Statement::bindAll for a record's header row.
  template <class... Out>
  void into(Out&... out) const {
    int column = 0;
    (readNext(column, out), ...);
  }

 private:
  template <class T>
  void readNext(int& column, T& out) const {
    if constexpr (std::is_same_v<T, std::string>) {
      out = text(column++);
    } else if constexpr (std::is_same_v<T, std::optional<std::int64_t>>) {
      out = optionalInt64(column++);
    } else if constexpr (std::is_same_v<T, std::optional<int>>) {
      out = optionalInt32(column++);
    } else if constexpr (std::is_floating_point_v<T>) {
      out = real(column++);
    } else {
      static_assert(std::is_integral_v<T>, "Row::into reads integers, doubles, strings and optional integers");
      out = static_cast<T>(int64(column++));
    }
  }

  sqlite3_stmt* stmt_;
};

// A blob parameter for Statement::bindAll (not copied: the caller keeps it
// alive until the statement has run).
struct Blob {
  const void* data;
  std::size_t size;
};

class Statement {
 public:
  Statement(sqlite3* db, const char* sql);
  Statement(sqlite3* db, const std::string& sql) : Statement(db, sql.c_str()) {}
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  bool ok() const { return stmt_ != nullptr; }
  sqlite3_stmt* get() const { return stmt_; }

  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, const std::string& value);
  Statement& bindBlob(int index, const void* data, std::size_t size);
  Statement& bindNull(int index);
  Statement& bind(int index, const std::optional<std::int64_t>& value);
  Statement& bind(int index, const std::optional<int>& value) { return value ? bind(index, *value) : bindNull(index); }
  Statement& bind(int index, const std::optional<double>& value) {
    return value ? bind(index, *value) : bindNull(index);
  }
  // Binds node and direction of an optional DOF to index and index + 1.
  Statement& bindDof(int index, const std::optional<Dof>& dof);

  // Binds ?1, ?2, ... to `values` in order: integers (bool as 0/1, unsigned
  // as int64), doubles, strings, optionals (NULL when empty), Blob; a Dof or
  // std::optional<Dof> takes two places (node, signed UFF direction).
  template <class... Values>
  Statement& bindAll(const Values&... values) {
    int index = 1;
    (bindNext(index, values), ...);
    return *this;
  }

  // sqlite3_step result (SQLITE_ROW, SQLITE_DONE or an error code).
  int step();
  void reset();

  // Steps a statement that returns no row (INSERT, UPDATE, DELETE). Anything
  // but SQLITE_DONE is an error "<what>: <SQLite's message>" at `where`, so
  // `what` names the statement ("cannot store the hit").
  Result<void> run(const std::string& what, const std::string& where);
  // run(), then the rowid of the row the INSERT made.
  Result<std::int64_t> insert(const std::string& what, const std::string& where);
  // reset(), bindAll(values...), then run() or insert(): one row of a
  // statement prepared once for many.
  template <class... Values>
  Result<void> runWith(const std::string& what, const std::string& where, const Values&... values) {
    reset();
    return bindAll(values...).run(what, where);
  }
  template <class... Values>
  Result<std::int64_t> insertWith(const std::string& what, const std::string& where, const Values&... values) {
    reset();
    return bindAll(values...).insert(what, where);
  }
  // Steps to the one row a lookup by key returns: NotFound "<absent>" when
  // there is none, an error naming `what` when SQLite fails.
  Result<void> single(const std::string& what, const std::string& absent, const std::string& where);
  // The header row of record `id` (a statement selecting "... WHERE id = ?1"):
  // binds ?1 and steps to it; "cannot read the <noun>" when SQLite fails,
  // NotFound "no such <noun>" when there is none.
  Result<void> lookup(std::int64_t id, const std::string& noun, const std::string& where) {
    return bindAll(id).single("cannot read the " + noun, "no such " + noun, where);
  }
  // Steps once: true at a row, false past the last one, an error naming
  // `what` when SQLite fails.
  Result<bool> next(const std::string& what, const std::string& where);
  // Calls visit(row) for every row. visit returns void, or Result<void>
  // whose error stops the loop and is returned; a failing step is an error
  // naming `what`.
  template <class Visit>
  Result<void> forEachRow(const std::string& what, const std::string& where, Visit&& visit) {
    for (;;) {
      MOZZI_TRY_ASSIGN(const bool atRow, next(what, where));
      if (!atRow) return {};
      if constexpr (std::is_void_v<std::invoke_result_t<Visit&, const Row&>>) {
        visit(Row(stmt_));
      } else {
        MOZZI_TRY(visit(Row(stmt_)));
      }
    }
  }

 private:
  template <class T>
  void bindNext(int& index, const T& value) {
    if constexpr (std::is_same_v<T, Dof> || std::is_same_v<T, std::optional<Dof>>) {
      bindDof(index, value);
      index += 2;
    } else if constexpr (std::is_same_v<T, Blob>) {
      bindBlob(index++, value.data, value.size);
    } else if constexpr (std::is_same_v<T, bool>) {
      bind(index++, value ? 1 : 0);
    } else if constexpr (std::is_integral_v<T> || std::is_enum_v<T>) {
      bind(index++, static_cast<std::int64_t>(value));
    } else {
      bind(index++, value);
    }
  }

  sqlite3* db_ = nullptr;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE on construction (taking the write lock up front, so a
// transaction never fails half-way for a lock), ROLLBACK on destruction unless
// commit() succeeded.
class Transaction {
 public:
  Transaction(sqlite3* db, std::string where);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  const Result<void>& begun() const { return begun_; }
  Result<void> commit();

 private:
  sqlite3* db_;
  std::string where_;
  Result<void> begun_;
  bool open_ = false;
};

// Runs body() inside one Transaction: its error (or a failed BEGIN) is
// returned and the transaction rolled back; otherwise COMMIT, then body's
// value. body returns a Result.
template <class Body>
auto inTransaction(sqlite3* db, const std::string& where, Body&& body) -> decltype(body()) {
  Transaction tx(db, where);
  MOZZI_TRY(tx.begun());
  auto result = body();
  if (!result) return result;
  MOZZI_TRY(tx.commit());
  return result;
}

}  // namespace mozzi::core::io::sql
