#pragma once
// CSV import and export of time records, FRFs and modal tables, with the unit
// of every column in its header (docs/formats/csv.md). Export writes SI units
// and 17 significant digits, so export-then-import returns the same doubles.
// Import accepts the common non-SI units of the lab (g, mm, mm/s, kN, ms, %,
// loss factor) and converts them to SI; anything it cannot interpret is a
// ParseError naming the line and column.

#include <iosfwd>
#include <string>
#include <string_view>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/io/mesh_document.h"
#include "core/io/project_records.h"
#include "core/io/time_table.h"

namespace mozzi::core::io::csv {

// Writers. `out` receives the whole file; errors are only those of invalid
// input (empty tables, NaN).
Result<void> writeTimeCsv(const TimeTable& table, std::ostream& out);
Result<void> writeFrfCsv(const FrfMatrix& frf, std::ostream& out);
Result<void> writeModalCsv(const ModalTable& table, std::ostream& out);

// Readers from text in memory; `source` names the file in error messages.
Result<TimeTable> readTimeCsv(std::string_view text, const std::string& source);
Result<FrfMatrix> readFrfCsv(std::string_view text, const std::string& source);
Result<ModalTable> readModalCsv(std::string_view text, const std::string& source);

// File helpers: read the file (at most 2 GiB) and parse, or write it.
Result<TimeTable> importTimeCsv(const std::string& path);
Result<FrfMatrix> importFrfCsv(const std::string& path);
Result<ModalTable> importModalCsv(const std::string& path);
Result<void> exportTimeCsv(const TimeTable& table, const std::string& path);
Result<void> exportFrfCsv(const FrfMatrix& frf, const std::string& path);
Result<void> exportModalCsv(const ModalTable& table, const std::string& path);

// Measurement meshes (docs/formats/csv.md, "Meshes"): sections
// coordinate-systems, nodes, lines, faces, dofs and slaves, each a table of
// numbers under its own header; a file with only a "node, x [mm], y [mm],
// z [mm]" table is a mesh of nodes. What writeMeshCsv writes reads back to the
// same document (same doubles, same order). The reader checks the format
// (numbers, whole labels, units, UFF direction codes); geometry::validate
// checks the mesh (labels unique, lines and faces on existing nodes).
Result<void> writeMeshCsv(const MeshDocument& document, std::ostream& out);
Result<MeshDocument> readMeshCsv(std::string_view text, const std::string& source);
Result<MeshDocument> importMeshCsv(const std::string& path);
Result<void> exportMeshCsv(const MeshDocument& document, const std::string& path);

// Scale factor to SI and the SI unit for a unit text ("g" -> 9.80665, "m/s^2").
// Exposed for the MATLAB importer's channel map. Unknown units are an error.
struct SiUnit {
  double factor = 1.0;   // value_SI = factor * value
  std::string unit;      // canonical SI unit
  std::string quantity;  // "force", "acceleration", "velocity", "displacement", "time", "frequency", ""
};
Result<SiUnit> siUnit(std::string_view unit);

}  // namespace mozzi::core::io::csv
