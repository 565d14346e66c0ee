#pragma once
// Private helpers of the project store: RAII statements and transactions over
// the SQLite C API. Not part of core's public face; include only from
// core/io/project_*.cpp.

#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <string>
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

class Statement {
 public:
  Statement(sqlite3* db, const char* sql);
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
  // Binds node and direction of an optional DOF to index and index + 1.
  Statement& bindDof(int index, const std::optional<Dof>& dof);

  // sqlite3_step result (SQLITE_ROW, SQLITE_DONE or an error code).
  int step();
  void reset();

  // Steps a statement that returns no row (INSERT, UPDATE, DELETE). Anything
  // but SQLITE_DONE is an error "<what>: <SQLite's message>" at `where`, so
  // `what` names the statement ("cannot store the hit").
  Result<void> run(const std::string& what, const std::string& where);
  // run(), then the rowid of the row the INSERT made.
  Result<std::int64_t> insert(const std::string& what, const std::string& where);
  // Steps to the one row a lookup by key returns: NotFound "<absent>" when
  // there is none, an error naming `what` when SQLite fails.
  Result<void> single(const std::string& what, const std::string& absent, const std::string& where);

 private:
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

}  // namespace mozzi::core::io::sql
