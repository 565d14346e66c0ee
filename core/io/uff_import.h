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
// A coordinate-system name "NONE" (the format's placeholder for no name)
// becomes an empty name.
Result<StoredMesh> meshFromUff(const uff::UffFile& file);

// The inverse of meshFromUff, for exporting a mesh: 164 (SI, length factor 1),
// coordinate systems as 2420 (or 18), nodes as 2411 (or 15), the line
// segments as 82 trace lines (consecutive segments sharing a node form one
// chain, node 0 lifts the pen between chains; at most 250 nodes per trace
// line, as the format says). Faces have no dataset among these and are left
// out (MeshUffExport::facesLeftOut says how many); the mesh CSV keeps them.
// With doublePrecision (2411/2420, 17 significant digits) the file reads back
// to the same doubles; 15/18 keep 6 significant digits (E13.5).
struct MeshUffOptions {
  bool doublePrecision = true;
  std::string description;  // 151 model name; no 151 header when empty
};
struct MeshUffExport {
  uff::UffFile file;
  int facesLeftOut = 0;
};
// Names that the text records cannot hold (longer than 80 characters for 2420,
// 40 for 18, line breaks, trailing blanks) are an error naming the system.
Result<MeshUffExport> meshToUff(const StoredMesh& mesh, const MeshUffOptions& options = {});
Result<MeshUffExport> exportMeshUff(const StoredMesh& mesh, const std::string& path,
                                    const MeshUffOptions& options = {});
// Reads the geometry datasets of a file (anything else in it is ignored).
Result<StoredMesh> importMeshUff(const std::string& path);

// Imports `uffPath` into `specimenId`. A specimen that already has a mesh keeps
// it (the report says so); FRFs and modes are always added as new results.
Result<UffImportReport> importUff(ProjectStore& store, const std::string& uffPath, std::int64_t specimenId);

}  // namespace mozzi::core::io
