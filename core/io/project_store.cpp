#include "core/io/project_store.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <utility>

namespace mozzi::core::io {
namespace {

// Schema versions in order; migration N takes a version N-1 file to version N.
// Version 1 is the foundation: metadata and specimens. Later issues append.
const char* const kMigrations[] = {
    // 1
    R"sql(
CREATE TABLE meta (
  key   TEXT PRIMARY KEY NOT NULL,
  value TEXT NOT NULL
) STRICT;
CREATE TABLE specimen (
  id          INTEGER PRIMARY KEY,
  name        TEXT NOT NULL UNIQUE,
  kind        TEXT NOT NULL,
  description TEXT NOT NULL DEFAULT ''
) STRICT;
)sql",
};
constexpr int kSchemaVersion = static_cast<int>(sizeof(kMigrations) / sizeof(kMigrations[0]));

Error sqliteError(sqlite3* db, const std::string& what, const std::string& where) {
  const int code = db ? sqlite3_errcode(db) : SQLITE_ERROR;
  ErrorCode kind = ErrorCode::IoError;
  if (code == SQLITE_NOTADB || code == SQLITE_CORRUPT) kind = ErrorCode::Corrupt;
  if (code == SQLITE_BUSY || code == SQLITE_LOCKED) kind = ErrorCode::Locked;
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
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db, sql, -1, &stmt, nullptr) != SQLITE_OK) return sqliteError(db, sql, where);
  std::int64_t value = 0;
  const int rc = sqlite3_step(stmt);
  if (rc == SQLITE_ROW) value = sqlite3_column_int64(stmt, 0);
  sqlite3_finalize(stmt);
  if (rc != SQLITE_ROW && rc != SQLITE_DONE) return sqliteError(db, sql, where);
  return value;
}

std::string nowUtc() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

// Applies migrations from the file's version to kSchemaVersion, each in its own
// transaction with user_version bumped inside it.
Result<void> migrate(sqlite3* db, int fromVersion, const std::string& path) {
  for (int v = fromVersion + 1; v <= kSchemaVersion; ++v) {
    const std::string where = path + ", migration to schema " + std::to_string(v);
    if (auto r = exec(db, "BEGIN IMMEDIATE", where); !r) return r;
    auto r = exec(db, kMigrations[v - 1], where);
    if (r) r = exec(db, ("PRAGMA user_version = " + std::to_string(v)).c_str(), where);
    if (r) r = exec(db, "COMMIT", where);
    if (!r) {
      (void)exec(db, "ROLLBACK", where);
      return r;
    }
  }
  return {};
}

}  // namespace

int ProjectStore::currentSchemaVersion() { return kSchemaVersion; }

ProjectStore::ProjectStore(ProjectStore&& other) noexcept { *this = std::move(other); }

ProjectStore& ProjectStore::operator=(ProjectStore&& other) noexcept {
  if (this != &other) {
    close();
    db_ = std::exchange(other.db_, nullptr);
    path_ = std::move(other.path_);
    readOnly_ = other.readOnly_;
    readOnlyReason_ = std::move(other.readOnlyReason_);
    lockFd_ = std::exchange(other.lockFd_, -1);
  }
  return *this;
}

ProjectStore::~ProjectStore() { close(); }

void ProjectStore::close() {
  if (db_) sqlite3_close_v2(db_);
  db_ = nullptr;
  if (lockFd_ >= 0) ::close(lockFd_);  // releases the flock
  lockFd_ = -1;
}

Result<ProjectStore> ProjectStore::create(const std::string& path, const std::string& mozziVersion) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    return makeError(ErrorCode::InvalidArgument, "a file of that name exists already; choose another name", path);
  }
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    Error e = sqliteError(db, "cannot create the project file", path);
    sqlite3_close_v2(db);
    return e;
  }
  auto r = exec(db,
                ("PRAGMA application_id = " + std::to_string(kProjectApplicationId) +
                 "; PRAGMA journal_mode = WAL; PRAGMA foreign_keys = ON;")
                    .c_str(),
                path);
  if (r) r = migrate(db, 0, path);
  if (r) {
    sqlite3_stmt* stmt = nullptr;
    sqlite3_prepare_v2(db, "INSERT INTO meta(key, value) VALUES ('created_utc', ?1), ('mozzi_version', ?2)", -1,
                       &stmt, nullptr);
    const std::string created = nowUtc();
    sqlite3_bind_text(stmt, 1, created.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(stmt, 2, mozziVersion.c_str(), -1, SQLITE_TRANSIENT);
    if (sqlite3_step(stmt) != SQLITE_DONE) r = sqliteError(db, "cannot write project metadata", path);
    sqlite3_finalize(stmt);
  }
  sqlite3_close_v2(db);
  if (!r) {
    std::filesystem::remove(path, ec);
    return r.error();
  }
  return open(path, OpenMode::ReadWrite);
}

Result<ProjectStore> ProjectStore::open(const std::string& path, OpenMode mode) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    return makeError(ErrorCode::NotFound, "the project file does not exist", path);
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    return makeError(ErrorCode::InvalidArgument, "not a regular file", path);
  }
  {
    // Reject anything that is not SQLite before SQLite touches it (it would
    // otherwise try to create -wal files next to a random file).
    std::ifstream in(path, std::ios::binary);
    char header[16] = {};
    in.read(header, sizeof header);
    if (in.gcount() != 16 || std::string(header, 15) != "SQLite format 3") {
      return makeError(ErrorCode::Corrupt, "not a Mozzi project: the file is not an SQLite database", path);
    }
  }

  ProjectStore store;
  store.path_ = path;
  store.readOnly_ = mode == OpenMode::ReadOnly;
  if (!store.readOnly_) {
    store.lockFd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (store.lockFd_ < 0) {
      store.readOnly_ = true;
      store.readOnlyReason_ = "the file is not writable";
    } else if (::flock(store.lockFd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(store.lockFd_);
      store.lockFd_ = -1;
      store.readOnly_ = true;
      store.readOnlyReason_ = "another Mozzi instance has this project open";
    }
  }
  const int flags = store.readOnly_ ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
  if (sqlite3_open_v2(path.c_str(), &store.db_, flags, nullptr) != SQLITE_OK) {
    return sqliteError(store.db_, "cannot open the project", path);
  }
  sqlite3_busy_timeout(store.db_, 2000);

  auto appId = queryInt(store.db_, "PRAGMA application_id", path);
  if (!appId) return appId.error();
  if (*appId != kProjectApplicationId) {
    return makeError(ErrorCode::Corrupt, "not a Mozzi project: SQLite database of another application", path);
  }
  auto check = queryInt(store.db_, "SELECT quick_check = 'ok' FROM pragma_quick_check", path);
  if (!check) return check.error();
  if (*check != 1) return makeError(ErrorCode::Corrupt, "the project fails SQLite's integrity check", path);

  auto version = queryInt(store.db_, "PRAGMA user_version", path);
  if (!version) return version.error();
  if (*version > kSchemaVersion) {
    return makeError(ErrorCode::Unsupported,
                     "the project was written by a newer Mozzi (schema " + std::to_string(*version) +
                         ", this version reads up to " + std::to_string(kSchemaVersion) + ")",
                     path);
  }
  if (!store.readOnly_) {
    if (auto r = exec(store.db_, "PRAGMA journal_mode = WAL; PRAGMA foreign_keys = ON;", path); !r) return r.error();
    if (*version < kSchemaVersion) {
      if (auto r = migrate(store.db_, static_cast<int>(*version), path); !r) return r.error();
    }
  } else if (*version < kSchemaVersion) {
    store.readOnlyReason_ += store.readOnlyReason_.empty() ? "" : "; ";
    store.readOnlyReason_ += "older schema, opened read-only without migration";
  }
  return store;
}

int ProjectStore::schemaVersion() const {
  auto v = queryInt(db_, "PRAGMA user_version", path_);
  return v ? static_cast<int>(*v) : 0;
}

Result<ProjectSummary> ProjectStore::summary() const {
  ProjectSummary s;
  s.schemaVersion = schemaVersion();
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db_, "SELECT key, value FROM meta", -1, &stmt, nullptr) != SQLITE_OK) {
    return sqliteError(db_, "cannot read project metadata", path_);
  }
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    const std::string key = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0));
    const std::string value = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 1));
    if (key == "created_utc") s.createdUtc = value;
    if (key == "mozzi_version") s.mozziVersion = value;
  }
  sqlite3_finalize(stmt);

  if (sqlite3_prepare_v2(db_, "SELECT id, name, kind, description FROM specimen ORDER BY id", -1, &stmt, nullptr) !=
      SQLITE_OK) {
    return sqliteError(db_, "cannot read specimens", path_);
  }
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    ProjectSummary::Specimen sp;
    sp.id = sqlite3_column_int64(stmt, 0);
    sp.name = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 1));
    sp.kind = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 2));
    sp.description = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 3));
    s.specimens.push_back(std::move(sp));
  }
  sqlite3_finalize(stmt);

  if (sqlite3_prepare_v2(db_, "SELECT name FROM sqlite_schema WHERE type = 'table' AND name NOT LIKE 'sqlite_%' "
                              "AND name <> 'meta' ORDER BY name",
                         -1, &stmt, nullptr) != SQLITE_OK) {
    return sqliteError(db_, "cannot list tables", path_);
  }
  std::vector<std::string> tables;
  while (sqlite3_step(stmt) == SQLITE_ROW) tables.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0)));
  sqlite3_finalize(stmt);
  for (const auto& table : tables) {
    auto n = queryInt(db_, ("SELECT count(*) FROM \"" + table + "\"").c_str(), path_);
    if (!n) return n.error();
    s.counts.push_back({table, *n});
  }
  return s;
}

Result<std::int64_t> ProjectStore::addSpecimen(const std::string& name, const std::string& kind,
                                               const std::string& description) {
  if (readOnly_) return makeError(ErrorCode::Locked, "the project is open read-only: " + readOnlyReason_, path_);
  if (name.empty()) return makeError(ErrorCode::InvalidArgument, "a specimen needs a name", path_);
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db_, "INSERT INTO specimen(name, kind, description) VALUES (?1, ?2, ?3)", -1, &stmt,
                         nullptr) != SQLITE_OK) {
    return sqliteError(db_, "cannot add specimen", path_);
  }
  sqlite3_bind_text(stmt, 1, name.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(stmt, 2, kind.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(stmt, 3, description.c_str(), -1, SQLITE_TRANSIENT);
  const int rc = sqlite3_step(stmt);
  sqlite3_finalize(stmt);
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot add specimen '" + name + "'", path_);
  return sqlite3_last_insert_rowid(db_);
}

Result<void> ProjectStore::saveAs(const std::string& path) const {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && std::filesystem::equivalent(path, path_, ec)) {
    return makeError(ErrorCode::InvalidArgument, "cannot save a project onto itself", path);
  }
  // Write to a temporary name, then rename: a crash never leaves a half copy
  // under the user's chosen name.
  const std::string temp = path + ".part";
  std::filesystem::remove(temp, ec);
  sqlite3* target = nullptr;
  if (sqlite3_open_v2(temp.c_str(), &target, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    Error e = sqliteError(target, "cannot create the copy", path);
    sqlite3_close_v2(target);
    return e;
  }
  sqlite3_backup* backup = sqlite3_backup_init(target, "main", db_, "main");
  int rc = backup ? sqlite3_backup_step(backup, -1) : SQLITE_ERROR;
  if (backup) sqlite3_backup_finish(backup);
  Result<void> result;
  if (rc != SQLITE_DONE) result = sqliteError(target, "cannot copy the project", path);
  if (result) result = exec(target, "PRAGMA journal_mode = WAL", path);
  sqlite3_close_v2(target);
  if (!result) {
    std::filesystem::remove(temp, ec);
    return result;
  }
  std::filesystem::rename(temp, path, ec);
  if (ec) return makeError(ErrorCode::IoError, "cannot move the copy into place: " + ec.message(), path);
  return {};
}

}  // namespace mozzi::core::io
