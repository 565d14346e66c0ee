// ProjectStore::checkIntegrity: `mozzi-cli project check` and the GUI's
// integrity check. Every record is read through the same reader the program
// uses, so a record that passes here is one every command can read.

#include <functional>
#include <string>
#include <vector>

#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

// Ids (or id pairs) listed by a query; an unreadable list is itself a problem.
Result<std::vector<std::pair<std::int64_t, std::int64_t>>> listIds(sqlite3* db, const char* query,
                                                                   const std::string& where) {
  sql::Statement stmt(db, query);
  if (!stmt.ok()) return sql::sqliteError(db, "cannot list records", where);
  std::vector<std::pair<std::int64_t, std::int64_t>> ids;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    ids.emplace_back(sqlite3_column_int64(stmt.get(), 0),
                     sqlite3_column_count(stmt.get()) > 1 ? sqlite3_column_int64(stmt.get(), 1) : 0);
  }
  if (rc != SQLITE_DONE) return sql::sqliteError(db, "cannot list records", where);
  return ids;
}

}  // namespace

Result<IntegrityReport> ProjectStore::checkIntegrity() const {
  IntegrityReport report;
  auto problem = [&](const Error& e) { report.problems.push_back({e.where.empty() ? path_ : e.where, e.message}); };
  {
    // Full structural check of the database file (b-trees, indexes, free list).
    sql::Statement stmt(db_, "PRAGMA integrity_check");
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      const std::string line = sql::columnText(stmt.get(), 0);
      if (line != "ok") report.problems.push_back({path_, "SQLite integrity check: " + line});
    }
    if (rc != SQLITE_DONE) problem(sql::sqliteError(db_, "SQLite integrity check could not run", path_));
  }
  // Each kind: the query listing its records, and how to read one.
  struct Kind {
    const char* list;
    std::function<Result<void>(std::int64_t, std::int64_t)> read;
  };
  const std::vector<Kind> kinds = {
      {"SELECT id FROM hit ORDER BY id",
       [&](std::int64_t id, std::int64_t) -> Result<void> {
         auto r = hit(id);
         return r ? Result<void>() : r.error();
       }},
      {"SELECT rig_test_id, step FROM rig_test_record ORDER BY id",
       [&](std::int64_t id, std::int64_t step) -> Result<void> {
         auto r = rigTestRecord(id, static_cast<int>(step));
         return r ? Result<void>() : r.error();
       }},
      {"SELECT id FROM frf_set ORDER BY id",
       [&](std::int64_t id, std::int64_t) -> Result<void> {
         auto r = frfSet(id);
         return r ? Result<void>() : r.error();
       }},
      {"SELECT id FROM modal_result ORDER BY id",
       [&](std::int64_t id, std::int64_t) -> Result<void> {
         auto r = modalResult(id);
         return r ? Result<void>() : r.error();
       }},
      {"SELECT id FROM specimen ORDER BY id",
       [&](std::int64_t id, std::int64_t) -> Result<void> {
         auto r = mesh(id);
         return r ? Result<void>() : r.error();
       }},
      {"SELECT id FROM rig_test ORDER BY id",
       [&](std::int64_t id, std::int64_t) -> Result<void> {
         auto r = rigTest(id);
         return r ? Result<void>() : r.error();
       }},
      {"SELECT id FROM tyre_test ORDER BY id",
       [&](std::int64_t id, std::int64_t) -> Result<void> {
         auto r = tyreTest(id);
         return r ? Result<void>() : r.error();
       }},
  };
  for (const auto& kind : kinds) {
    auto ids = listIds(db_, kind.list, path_);
    if (!ids) {
      problem(ids.error());
      continue;
    }
    for (const auto& [id, second] : *ids) {
      ++report.recordsChecked;
      if (auto r = kind.read(id, second); !r) problem(r.error());
    }
  }
  // Records from before schema 4 (NULL checksum) were read but not verified.
  for (const auto& [table, column] : std::vector<std::pair<std::string, std::string>>{{"frf_set", "content_crc32"},
                                                                                      {"frf", "content_crc32"},
                                                                                      {"modal_result", "content_crc32"},
                                                                                      {"specimen", "mesh_crc32"},
                                                                                      {"rig_test", "content_crc32"},
                                                                                      {"tyre_test", "content_crc32"}}) {
    const std::string query =
        "SELECT count(*) FROM " + table + (checksums_ ? " WHERE " + column + " IS NULL" : std::string());
    auto n = sql::queryInt(db_, query.c_str(), path_);
    if (n) report.recordsWithoutChecksum += *n;
  }
  return report;
}

}  // namespace mozzi::core::io
