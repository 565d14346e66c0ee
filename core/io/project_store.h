#pragma once
// The project file: one SQLite database per project (.mozzi), WAL mode, foreign
// keys on, application_id 'MOZZ' and user_version = schema version. Opening
// checks that the file is a Mozzi project and passes PRAGMA quick_check; a file
// another instance holds open for writing opens read-only.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/common/result.h"

struct sqlite3;

namespace mozzi::core::io {

inline constexpr std::int32_t kProjectApplicationId = 0x4D4F5A5A;  // "MOZZ"

struct ProjectSummary {
  int schemaVersion = 0;
  std::string createdUtc;
  std::string mozziVersion;  // version of Mozzi that created the file
  struct Specimen {
    std::int64_t id = 0;
    std::string name;
    std::string kind;         // "frame", "swing-arm", "fork", "tyre", "bicycle", ...
    std::string description;  // what it is and where its parameters come from
  };
  std::vector<Specimen> specimens;
  struct TableCount {
    std::string table;
    std::int64_t rows = 0;
  };
  std::vector<TableCount> counts;  // rows per data table, for the project tree
};

class ProjectStore {
 public:
  enum class OpenMode { ReadWrite, ReadOnly };

  // Creates a new, empty project; fails if the file exists.
  static Result<ProjectStore> create(const std::string& path, const std::string& mozziVersion);
  // Opens an existing project. ReadWrite falls back to read-only when another
  // process holds the project; readOnlyReason() then says why.
  static Result<ProjectStore> open(const std::string& path, OpenMode mode = OpenMode::ReadWrite);

  ProjectStore(ProjectStore&&) noexcept;
  ProjectStore& operator=(ProjectStore&&) noexcept;
  ~ProjectStore();

  const std::string& path() const { return path_; }
  bool isReadOnly() const { return readOnly_; }
  const std::string& readOnlyReason() const { return readOnlyReason_; }
  int schemaVersion() const;

  Result<ProjectSummary> summary() const;
  Result<std::int64_t> addSpecimen(const std::string& name, const std::string& kind, const std::string& description);

  // Writes a consistent copy of the whole project to `path` (SQLite online
  // backup), leaving this store open on its own file.
  Result<void> saveAs(const std::string& path) const;

  // The raw connection for the io layer's own tables; never exposed past core.
  sqlite3* connection() const { return db_; }

  static int currentSchemaVersion();

 private:
  ProjectStore() = default;
  void close();

  sqlite3* db_ = nullptr;
  std::string path_;
  bool readOnly_ = false;
  std::string readOnlyReason_;
  // flock() on the database file for the life of a read-write session, so a
  // second instance sees it and opens read-only; the kernel drops it if we crash.
  int lockFd_ = -1;
};

}  // namespace mozzi::core::io
