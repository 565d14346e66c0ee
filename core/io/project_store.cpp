#include "core/io/project_store.h"

#include "core/io/project_schema.h"
#include "core/io/project_sql.h"

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

using sql::exec;
using sql::queryInt;
using sql::sqliteError;

int schemaVersionCount() {
  return static_cast<int>(projectMigrations().size());
}

// Applies migrations from the file's version to the current one, each in its
// own transaction with user_version bumped inside it. The first migration also
// stamps the application id and the creation metadata, so a new project
// appears complete or not at all.
Result<void> migrate(sqlite3* db, int fromVersion, const std::string& path, const std::string& mozziVersion) {
  const auto& migrations = projectMigrations();
  for (int v = fromVersion + 1; v <= schemaVersionCount(); ++v) {
    const std::string where = path + ", migration to schema " + std::to_string(v);
    sql::Transaction tx(db, where);
    if (!tx.begun()) return tx.begun();
    if (auto r = exec(db, migrations[static_cast<std::size_t>(v - 1)], where); !r) return r;
    if (v == 1) {
      if (auto r = exec(db, ("PRAGMA application_id = " + std::to_string(kProjectApplicationId)).c_str(), where); !r) {
        return r;
      }
      sql::Statement meta(db, "INSERT INTO meta(key, value) VALUES ('created_utc', ?1), ('mozzi_version', ?2)");
      meta.bind(1, sql::nowUtc()).bind(2, mozziVersion);
      if (meta.step() != SQLITE_DONE) return sqliteError(db, "cannot write project metadata", where);
    }
    if (auto r = exec(db, ("PRAGMA user_version = " + std::to_string(v)).c_str(), where); !r) return r;
    if (auto r = tx.commit(); !r) return r;
  }
  return {};
}

}  // namespace

int ProjectStore::currentSchemaVersion() {
  return schemaVersionCount();
}

ProjectStore::ProjectStore(ProjectStore&& other) noexcept {
  *this = std::move(other);
}

ProjectStore& ProjectStore::operator=(ProjectStore&& other) noexcept {
  if (this != &other) {
    close();
    db_ = std::exchange(other.db_, nullptr);
    path_ = std::move(other.path_);
    readOnly_ = other.readOnly_;
    readOnlyReason_ = std::move(other.readOnlyReason_);
    lockFd_ = std::exchange(other.lockFd_, -1);
    hitEncoding_ = other.hitEncoding_;
  }
  return *this;
}

ProjectStore::~ProjectStore() {
  close();
}

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
  // journal_mode cannot change inside a transaction; it writes no user data.
  auto r = exec(db, "PRAGMA journal_mode = WAL; PRAGMA synchronous = FULL; PRAGMA foreign_keys = ON;", path);
  if (r) r = migrate(db, 0, path, mozziVersion);
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
  if (*version > schemaVersionCount()) {
    return makeError(ErrorCode::Unsupported,
                     "the project was written by a newer Mozzi (schema " + std::to_string(*version) +
                         ", this version reads up to " + std::to_string(schemaVersionCount()) + ")",
                     path);
  }
  if (*version < 1) {
    return makeError(ErrorCode::Corrupt, "not a Mozzi project: the file has no schema (an interrupted creation?)",
                     path);
  }
  // synchronous = FULL: in WAL mode every COMMIT fsyncs the WAL, so a
  // committed hit survives a power cut as well as a process crash (measured
  // cost in docs/performance/project.md).
  if (auto r = exec(store.db_, "PRAGMA foreign_keys = ON; PRAGMA synchronous = FULL;", path); !r) return r.error();
  if (!store.readOnly_) {
    if (auto r = exec(store.db_, "PRAGMA journal_mode = WAL", path); !r) return r.error();
    if (*version < schemaVersionCount()) {
      if (auto r = migrate(store.db_, static_cast<int>(*version), path, {}); !r) return r.error();
    }
  } else if (*version < schemaVersionCount()) {
    store.readOnlyReason_ += store.readOnlyReason_.empty() ? "" : "; ";
    store.readOnlyReason_ += "older schema, opened read-only without migration";
  }
  return store;
}

int ProjectStore::schemaVersion() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  auto v = queryInt(db_, "PRAGMA user_version", path_);
  return v ? static_cast<int>(*v) : 0;
}

Result<ProjectSummary> ProjectStore::summary() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  ProjectSummary s;
  s.schemaVersion = schemaVersion();
  {
    sql::Statement stmt(db_, "SELECT key, value FROM meta");
    if (!stmt.ok()) return sqliteError(db_, "cannot read project metadata", path_);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      const std::string key = sql::columnText(stmt.get(), 0);
      if (key == "created_utc") s.createdUtc = sql::columnText(stmt.get(), 1);
      if (key == "mozzi_version") s.mozziVersion = sql::columnText(stmt.get(), 1);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read project metadata", path_);
  }
  {
    sql::Statement stmt(db_, "SELECT id, name, kind, description FROM specimen ORDER BY id");
    if (!stmt.ok()) return sqliteError(db_, "cannot read specimens", path_);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      ProjectSummary::Specimen sp;
      sp.id = sqlite3_column_int64(stmt.get(), 0);
      sp.name = sql::columnText(stmt.get(), 1);
      sp.kind = sql::columnText(stmt.get(), 2);
      sp.description = sql::columnText(stmt.get(), 3);
      s.specimens.push_back(std::move(sp));
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read specimens", path_);
  }
  for (const char* table : projectDataTables()) {
    auto n = queryInt(db_, (std::string("SELECT count(*) FROM ") + table).c_str(), path_);
    if (!n) return n.error();
    s.counts.push_back({table, *n});
  }
  return s;
}

Result<void> ProjectStore::requireWritable() const {
  if (readOnly_) return makeError(ErrorCode::Locked, "the project is open read-only: " + readOnlyReason_, path_);
  return {};
}

Result<std::int64_t> ProjectStore::addSpecimen(const std::string& name, const std::string& kind,
                                               const std::string& description) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  if (name.empty()) return makeError(ErrorCode::InvalidArgument, "a specimen needs a name", path_);
  sql::Transaction tx(db_, path_ + ", specimen '" + name + "'");
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_, "INSERT INTO specimen(name, kind, description) VALUES (?1, ?2, ?3)");
  stmt.bind(1, name).bind(2, kind).bind(3, description);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot add specimen '" + name + "'", path_);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<void> ProjectStore::checkpoint() {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r;
  int logFrames = 0, checkpointed = 0;
  if (sqlite3_wal_checkpoint_v2(db_, nullptr, SQLITE_CHECKPOINT_PASSIVE, &logFrames, &checkpointed) != SQLITE_OK) {
    return sqliteError(db_, "cannot checkpoint the write-ahead log", path_);
  }
  return {};
}

Result<void> ProjectStore::setDurable(bool durable) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  return exec(db_, durable ? "PRAGMA synchronous = FULL" : "PRAGMA synchronous = OFF", path_);
}

Result<void> ProjectStore::deleteSpecimen(std::int64_t specimenId) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", specimen " + std::to_string(specimenId);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun();
  sql::Statement stmt(db_, "DELETE FROM specimen WHERE id = ?1");
  stmt.bind(1, specimenId);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot delete the specimen", where);
  if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such specimen", where);
  return tx.commit();
}

Result<void> ProjectStore::saveAs(const std::string& path) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
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
