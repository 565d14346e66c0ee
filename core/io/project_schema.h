#pragma once
// The project file's schema as an ordered list of forward migrations: migration
// N (1-based) takes a file at user_version N-1 to user_version N. A released
// migration is never edited; a later schema change appends one.

#include <vector>

namespace mozzi::core::io {

// SQL text of each migration, in order. currentSchemaVersion() == size().
const std::vector<const char*>& projectMigrations();

// Tables a reader may count for a summary (everything except meta).
const std::vector<const char*>& projectDataTables();

}  // namespace mozzi::core::io
