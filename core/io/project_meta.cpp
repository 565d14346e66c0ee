#include "core/io/project_meta.h"

#include <sqlite3.h>

#include <mutex>

#include "core/io/project_sql.h"

namespace mozzi::core::io {

Result<std::optional<std::string>> metaValue(const ProjectStore& store, const std::string& key) {
  const std::lock_guard<std::recursive_mutex> lock(store.mutex());
  const std::string where = store.path() + ", meta key '" + key + "'";
  sql::Statement stmt(store.connection(), "SELECT value FROM meta WHERE key = ?1");
  if (!stmt.ok()) return sql::sqliteError(store.connection(), "cannot read project metadata", where);
  MOZZI_TRY_ASSIGN(const bool found, stmt.bindAll(key).next("cannot read project metadata", where));
  if (!found) return std::optional<std::string>();
  return std::optional<std::string>(sql::columnText(stmt.get(), 0));
}

Result<void> setMetaValue(ProjectStore& store, const std::string& key, const std::string& value) {
  const std::string where = store.path() + ", meta key '" + key + "'";
  if (key.empty()) return makeError(ErrorCode::InvalidArgument, "empty metadata key", store.path());
  if (key == "created_utc" || key == "mozzi_version")
    return makeError(ErrorCode::InvalidArgument, "the key is the store's own and cannot be set", where);
  if (store.isReadOnly())
    return makeError(ErrorCode::Locked, "the project is open read-only: " + store.readOnlyReason(), where);
  const std::lock_guard<std::recursive_mutex> lock(store.mutex());
  sql::Statement stmt(store.connection(),
                      "INSERT INTO meta(key, value) VALUES (?1, ?2) ON CONFLICT(key) DO UPDATE SET value = ?2");
  if (!stmt.ok()) return sql::sqliteError(store.connection(), "cannot write project metadata", where);
  return stmt.bindAll(key, value).run("cannot write project metadata", where);
}

}  // namespace mozzi::core::io
