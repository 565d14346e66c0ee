#include "core/io/project_store.h"

#include "core/io/project_schema.h"
#include "core/io/project_sql.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <random>
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
    MOZZI_TRY(sql::inTransaction(db, where, [&]() -> Result<void> {
      MOZZI_TRY(exec(db, migrations[static_cast<std::size_t>(v - 1)], where));
      if (v == 1) {
        MOZZI_TRY(exec(db, ("PRAGMA application_id = " + std::to_string(kProjectApplicationId)).c_str(), where));
        sql::Statement meta(db, "INSERT INTO meta(key, value) VALUES ('created_utc', ?1), ('mozzi_version', ?2)");
        MOZZI_TRY(meta.bindAll(sql::nowUtc(), mozziVersion).run("cannot write project metadata", where));
      }
      return exec(db, ("PRAGMA user_version = " + std::to_string(v)).c_str(), where);
    }));
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
    checksums_ = other.checksums_;
    modeUncertainty_ = other.modeUncertainty_;
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

namespace {

// Creates the schema in a new file at `path` (a temporary name chosen by
// createProjectAtomically) and closes it; `shownPath` names it in errors.
Result<void> createSchema(const std::string& path, const std::string& shownPath, const std::string& mozziVersion) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_EXCLUSIVE, nullptr) !=
      SQLITE_OK) {
    Error e = sqliteError(db, "cannot create the project file", shownPath);
    sqlite3_close_v2(db);
    return e;
  }
  // journal_mode cannot change inside a transaction; it writes no user data.
  auto r = exec(db, "PRAGMA journal_mode = WAL; PRAGMA synchronous = FULL; PRAGMA foreign_keys = ON;", shownPath);
  if (r) r = migrate(db, 0, shownPath, mozziVersion);
  if (sqlite3_close(db) != SQLITE_OK && r) r = makeError(ErrorCode::IoError, "cannot close the new project", shownPath);
  return r;
}

bool processGone(pid_t pid) {
  return pid > 0 && pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

// Removes ".NAME.creating-PID-*" files (and their -wal, -shm) left in `folder`
// by creations whose process no longer runs.
void removeStaleCreations(const std::filesystem::path& folder, const std::string& name) {
  const std::string prefix = "." + name + ".creating-";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.compare(0, prefix.size(), prefix) != 0) continue;
    const pid_t pid = static_cast<pid_t>(std::strtol(file.c_str() + prefix.size(), nullptr, 10));
    if (processGone(pid)) std::filesystem::remove(entry.path(), ec);
  }
}

void removeWithSidecars(const std::string& path) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) ::unlink((path + suffix).c_str());
}

}  // namespace

Result<void> createProjectAtomically(const std::string& path,
                                     const std::function<Result<void>(const std::string& tempPath)>& build) {
  namespace fs = std::filesystem;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    return makeError(ErrorCode::InvalidArgument, "a file of that name exists already; choose another name", path);
  }
  const fs::path target(path);
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return makeError(ErrorCode::NotFound, "the folder does not exist", path);
  if (::access(folder.c_str(), W_OK) != 0) {
    return makeError(ErrorCode::IoError, "cannot create a project in this folder: " + std::string(std::strerror(errno)),
                     path);
  }
  removeStaleCreations(folder, target.filename().string());
  std::mt19937_64 rng{std::random_device{}() ^ static_cast<std::uint64_t>(::getpid())};
  char token[24];
  std::snprintf(token, sizeof token, "%d-%08llx", static_cast<int>(::getpid()),
                static_cast<unsigned long long>(rng() & 0xffffffffULL));
  const std::string temp = (folder / ("." + target.filename().string() + ".creating-" + token)).string();
  if (auto r = build(temp); !r) {
    removeWithSidecars(temp);
    return r;
  }
  // The builder closed its connections, which checkpoints and removes the WAL;
  // make sure before the move (a WAL left beside the temporary name would not
  // follow the file).
  if (::access((temp + "-wal").c_str(), F_OK) == 0) {
    sqlite3* db = nullptr;
    Result<void> r;
    if (sqlite3_open_v2(temp.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
      r = sqliteError(db, "cannot finish the new project", path);
    } else {
      r = exec(db, "PRAGMA wal_checkpoint(TRUNCATE)", path);
    }
    sqlite3_close_v2(db);
    if (!r) {
      removeWithSidecars(temp);
      return r;
    }
  }
  const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int e = errno;
    if (fd >= 0) ::close(fd);
    removeWithSidecars(temp);
    return makeError(ErrorCode::IoError, "cannot write the new project: " + std::string(std::strerror(e)), path);
  }
  ::close(fd);
  // Move into place without ever replacing a file: renameat2(RENAME_NOREPLACE),
  // or link + unlink where the file system lacks it.
  int rc = ::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, path.c_str(), RENAME_NOREPLACE);
  if (rc != 0 && (errno == EINVAL || errno == ENOSYS)) {
    rc = ::link(temp.c_str(), path.c_str());
    if (rc == 0) ::unlink(temp.c_str());
  }
  if (rc != 0) {
    const int e = errno;
    removeWithSidecars(temp);
    if (e == EEXIST) {
      return makeError(ErrorCode::InvalidArgument,
                       "a file of that name exists already (another process created it meanwhile)", path);
    }
    return makeError(ErrorCode::IoError, "cannot move the new project into place: " + std::string(std::strerror(e)),
                     path);
  }
  removeWithSidecars(temp);  // -shm or -journal remnants of the temporary name, if any
  const int dfd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return {};
}

Result<ProjectStore> ProjectStore::create(const std::string& path, const std::string& mozziVersion) {
  // Inside createProjectAtomically's builder (the path is this process's own
  // temporary name) the file is created in place: it is already temporary.
  const std::string name = std::filesystem::path(path).filename().string();
  const std::string ownMark = ".creating-" + std::to_string(::getpid()) + "-";
  if (!name.empty() && name[0] == '.' && name.find(ownMark) != std::string::npos) {
    if (auto r = createSchema(path, path, mozziVersion); !r) {
      removeWithSidecars(path);
      return r.error();
    }
    return open(path, OpenMode::ReadWrite);
  }
  MOZZI_TRY(
      createProjectAtomically(path, [&](const std::string& temp) { return createSchema(temp, path, mozziVersion); }));
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
  const std::string folder = [&] {
    const auto parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
  }();
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
    } else if (::access(folder.c_str(), W_OK) != 0) {
      // WAL mode writes -wal and -shm beside the file: without a writable
      // folder (a colleague's share) the project can only be read.
      ::close(store.lockFd_);
      store.lockFd_ = -1;
      store.readOnly_ = true;
      store.readOnlyReason_ = "the project's folder is not writable";
    }
  }
  // Read-only: with no -wal file beside it the main file holds every committed
  // transaction. If no Mozzi writer holds the project (a shared flock, which a
  // writer's exclusive one excludes, held for this store's life) it is opened
  // immutable: SQLite then creates no -wal or -shm file, so reading works in a
  // folder the user cannot write and leaves nothing behind. With a -wal (a
  // writer is active, or one crashed before a checkpoint) it is opened as a
  // normal read-only WAL reader, which sees what the WAL holds.
  bool immutable = false;
  if (store.readOnly_ && ::access((path + "-wal").c_str(), F_OK) != 0) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0 && ::flock(fd, LOCK_SH | LOCK_NB) == 0 && ::access((path + "-wal").c_str(), F_OK) != 0) {
      store.lockFd_ = fd;
      immutable = true;
    } else if (fd >= 0) {
      ::close(fd);
    }
  }
  const int flags = (store.readOnly_ ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE) | SQLITE_OPEN_URI;
  const std::string uri = sql::fileUri(path) + (immutable ? "?immutable=1" : "");
  if (sqlite3_open_v2(uri.c_str(), &store.db_, flags, nullptr) != SQLITE_OK) {
    Error e = sqliteError(store.db_, "cannot open the project", path);
    if (store.readOnly_ && ::access(folder.c_str(), W_OK) != 0) {
      e.message +=
          " (the folder is not writable and a -wal file of an unfinished session is there: "
          "ask its owner to open and close the project once)";
    }
    return e;
  }
  sqlite3_busy_timeout(store.db_, 2000);

  MOZZI_TRY_ASSIGN(const std::int64_t appId, queryInt(store.db_, "PRAGMA application_id", path));
  if (appId != kProjectApplicationId) {
    return makeError(ErrorCode::Corrupt, "not a Mozzi project: SQLite database of another application", path);
  }
  MOZZI_TRY_ASSIGN(const std::int64_t check,
                   queryInt(store.db_, "SELECT quick_check = 'ok' FROM pragma_quick_check", path));
  if (check != 1) return makeError(ErrorCode::Corrupt, "the project fails SQLite's integrity check", path);

  MOZZI_TRY_ASSIGN(const std::int64_t version, queryInt(store.db_, "PRAGMA user_version", path));
  if (version > schemaVersionCount()) {
    return makeError(ErrorCode::Unsupported,
                     "the project was written by a newer Mozzi (schema " + std::to_string(version) +
                         ", this version reads up to " + std::to_string(schemaVersionCount()) + ")",
                     path);
  }
  if (version < 1) {
    return makeError(ErrorCode::Corrupt, "not a Mozzi project: the file has no schema (an interrupted creation?)",
                     path);
  }
  // synchronous = FULL: in WAL mode every COMMIT fsyncs the WAL, so a
  // committed hit survives a power cut as well as a process crash (measured
  // cost in docs/performance/project.md).
  MOZZI_TRY(exec(store.db_, "PRAGMA foreign_keys = ON; PRAGMA synchronous = FULL;", path));
  if (!store.readOnly_) {
    MOZZI_TRY(exec(store.db_, "PRAGMA journal_mode = WAL", path));
    if (version < schemaVersionCount()) MOZZI_TRY(migrate(store.db_, static_cast<int>(version), path, {}));
  } else if (version < schemaVersionCount()) {
    store.checksums_ = version >= 4;        // the checksum columns came with migration 4
    store.modeUncertainty_ = version >= 5;  // the modes' standard errors with migration 5
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
  sql::Statement meta(db_, "SELECT key, value FROM meta");
  MOZZI_TRY(meta.forEachRow("cannot read project metadata", path_, [&](const sql::Row& row) {
    const std::string key = row.text(0);
    if (key == "created_utc") s.createdUtc = row.text(1);
    if (key == "mozzi_version") s.mozziVersion = row.text(1);
  }));
  sql::Statement specimens(db_, "SELECT id, name, kind, description FROM specimen ORDER BY id");
  MOZZI_TRY(specimens.forEachRow("cannot read specimens", path_, [&](const sql::Row& row) {
    s.specimens.push_back({row.int64(0), row.text(1), row.text(2), row.text(3)});
  }));
  for (const char* table : projectDataTables()) {
    MOZZI_TRY_ASSIGN(const std::int64_t rows,
                     queryInt(db_, (std::string("SELECT count(*) FROM ") + table).c_str(), path_));
    s.counts.push_back({table, rows});
  }
  return s;
}

Result<void> ProjectStore::requireWritable() const {
  if (readOnly_) return makeError(ErrorCode::Locked, "the project is open read-only: " + readOnlyReason_, path_);
  return {};
}

Result<void> ProjectStore::writeInTransaction(const std::string& where, const std::function<Result<void>()>& body) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  return sql::inTransaction(db_, where, body);
}

Result<std::int64_t> ProjectStore::insertInTransaction(const std::string& where,
                                                       const std::function<Result<std::int64_t>()>& body) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  return sql::inTransaction(db_, where, body);
}

Result<std::int64_t> ProjectStore::addSpecimen(const std::string& name, const std::string& kind,
                                               const std::string& description) {
  return insertInTransaction(path_ + ", specimen '" + name + "'", [&]() -> Result<std::int64_t> {
    if (name.empty()) return makeError(ErrorCode::InvalidArgument, "a specimen needs a name", path_);
    // mesh_crc32: the checksum of the empty mesh (setMesh replaces it).
    sql::Statement stmt(db_, "INSERT INTO specimen(name, kind, description, mesh_crc32) VALUES (?1, ?2, ?3, ?4)");
    return stmt.bindAll(name, kind, description, sql::emptyMeshChecksum())
        .insert("cannot add specimen '" + name + "'", path_);
  });
}

Result<void> ProjectStore::checkpoint() {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  int logFrames = 0, checkpointed = 0;
  if (sqlite3_wal_checkpoint_v2(db_, nullptr, SQLITE_CHECKPOINT_PASSIVE, &logFrames, &checkpointed) != SQLITE_OK) {
    return sqliteError(db_, "cannot checkpoint the write-ahead log", path_);
  }
  return {};
}

Result<void> ProjectStore::deleteSpecimen(std::int64_t specimenId) {
  const std::string where = path_ + ", specimen " + std::to_string(specimenId);
  return writeInTransaction(where, [&]() -> Result<void> {
    sql::Statement stmt(db_, "DELETE FROM specimen WHERE id = ?1");
    MOZZI_TRY(stmt.bindAll(specimenId).run("cannot delete the specimen", where));
    if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such specimen", where);
    return {};
  });
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

Result<void> ProjectStore::setPowerLossDurable(bool durable) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  return exec(db_, durable ? "PRAGMA synchronous = FULL;" : "PRAGMA synchronous = NORMAL;", path_);
}

}  // namespace mozzi::core::io
