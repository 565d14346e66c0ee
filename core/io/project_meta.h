#pragma once
// Small settings a project keeps in its `meta` table (key/value text, schema
// 1; no schema change): the report template (core/report/report_template.h)
// and the like. The keys "created_utc" and "mozzi_version" belong to the store
// and are refused here.

#include <optional>
#include <string>

#include "core/common/result.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

// The value of `key`; nullopt when the project has none.
Result<std::optional<std::string>> metaValue(const ProjectStore& store, const std::string& key);
// Sets (or replaces) `key`. Errors: a read-only project, a key of the store's
// own, an empty key, a database error (each naming the project and the key).
Result<void> setMetaValue(ProjectStore& store, const std::string& key, const std::string& value);

}  // namespace mozzi::core::io
