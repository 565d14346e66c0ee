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
  std::vector<std::pair<std::int64_t, std::int64_t>> ids;
  MOZZI_TRY(stmt.forEachRow("cannot list records", where, [&](const sql::Row& r) {
    ids.emplace_back(r.int64(0), r.columnCount() > 1 ? r.int64(1) : 0);
  }));
  return ids;
}

}  // namespace

Result<IntegrityReport> ProjectStore::checkIntegrity() const {
  IntegrityReport report;
  auto problem = [&](const Error& e) { report.problems.push_back({e.where.empty() ? path_ : e.where, e.message}); };
  // Full structural check of the database file (b-trees, indexes, free list).
  sql::Statement integrity(db_, "PRAGMA integrity_check");
  if (auto r = integrity.forEachRow("SQLite integrity check could not run", path_,
                                    [&](const sql::Row& row) {
                                      if (row.text(0) != "ok")
                                        report.problems.push_back({path_, "SQLite integrity check: " + row.text(0)});
                                    });
      !r) {
    problem(r.error());
  }
  // Each kind: the query listing its records, and how to read one.
  struct Kind {
    const char* list;
    std::function<Result<void>(std::int64_t, std::int64_t)> read;
  };
  // A reader's value is dropped: that it could be read is what counts.
  auto byId = [this](auto reader) {
    return [this, reader](std::int64_t id, std::int64_t) -> Result<void> {
      MOZZI_TRY((this->*reader)(id));
      return {};
    };
  };
  const std::vector<Kind> kinds = {
      {"SELECT id FROM hit ORDER BY id", byId(&ProjectStore::hit)},
      {"SELECT rig_test_id, step FROM rig_test_record ORDER BY id",
       [this](std::int64_t id, std::int64_t step) -> Result<void> {
         MOZZI_TRY(rigTestRecord(id, static_cast<int>(step)));
         return {};
       }},
      {"SELECT id FROM frf_set ORDER BY id", byId(&ProjectStore::frfSet)},
      {"SELECT id FROM modal_result ORDER BY id", byId(&ProjectStore::modalResult)},
      {"SELECT id FROM specimen ORDER BY id", byId(&ProjectStore::mesh)},
      {"SELECT id FROM rig_test ORDER BY id", byId(&ProjectStore::rigTest)},
      {"SELECT id FROM tyre_test ORDER BY id", byId(&ProjectStore::tyreTest)},
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
