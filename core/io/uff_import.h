#pragma once
// Bringing a Universal File into a project: geometry (nodes 15/2411,
// coordinate systems 18/2420, trace lines 82) becomes the specimen's mesh, FRF
// records (58, function type 4, with coherence 6) an FRF set, modal data (55) a
// modal result. Everything is converted before anything is written, so a file
// that cannot be read leaves the project untouched.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/io/uff/uff.h"

namespace mozzi::core::io {

class ProjectStore;

struct UffImportReport {
  std::int64_t specimenId = 0;
  int nodes = 0;
  int lines = 0;
  int coordinateSystems = 0;
  std::optional<std::int64_t> frfSetId;
  int frfPairs = 0;
  std::optional<std::int64_t> modalResultId;
  int modes = 0;
  // What was not imported and why, and the reader's warnings, in words.
  std::vector<std::string> notes;
};

// Mesh in SI units from the geometry datasets: lengths divided by the 164
// length factor (UFF: SI value = file value / factor); coordinate-system axes
// become rotation columns; each trace line gives one segment per pair of
// consecutive nodes, node 0 lifting the pen.
Result<StoredMesh> meshFromUff(const uff::UffFile& file);

// Imports `uffPath` into `specimenId`. A specimen that already has a mesh keeps
// it (the report says so); FRFs and modes are always added as new results.
Result<UffImportReport> importUff(ProjectStore& store, const std::string& uffPath, std::int64_t specimenId);

}  // namespace mozzi::core::io
