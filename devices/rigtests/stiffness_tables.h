#pragma once
// The stiffness tables of a project (thesis Tables 3 to 5, 7, 9, 10, 13): one
// column per stored static stiffness-rig test (a specimen in one constraint),
// the rows k_lat, a_tw, k_tw, the bending and torsion arms and stiffnesses
// and the twist axis inclination, each with its stored uncertainty, and beside
// them the thesis's values for the virtual specimen the test stands for
// (devices/sim/specimen_catalogue: the one place the thesis's tables are
// typed in). The Stiffness page presents this; the numbers are the stored
// results as the sequences wrote them (stiffness_tests.cpp), nothing is
// recomputed here.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "devices/rigtests/stiffness_results.h"

namespace mozzi::devices::rigtests {

// A row of the tables: the stored result's key, its English label and its SI unit.
struct StiffnessRowSpec {
  const char* key;    // "k_lat", "a_tw", ...
  const char* label;  // "Lateral stiffness"
  const char* unit;   // SI, as stored: "N/m", "m", "N m/rad", "rad"
};
// In the thesis's order (Tables 7, 9, 10, 13): k_lat, a_tw, k_tw, a_bend,
// k_bend, a_tors, k_tors, axis_inclination.
const std::vector<StiffnessRowSpec>& stiffnessRows();

struct StiffnessColumn {
  std::int64_t testId = 0;
  std::int64_t specimenId = 0;
  std::string specimenName;  // the project's
  std::string testName;
  core::io::TestStatus status = core::io::TestStatus::Complete;
  std::string statusNote;
  // The virtual specimen the test stands for ("" when none): the simulated
  // rig's key, else the catalogue entry the specimen's name stands for.
  std::string catalogueKey;
  std::string constraint;  // "front-constrained", "steering head locked", ... ("" when not known)
  // Stored results by row key (absent rows are not in the map).
  std::map<std::string, StoredQuantity> measured;
  // The thesis's values by row key, SI (absent where the thesis prints none),
  // and where they are printed ("thesis Table 10"); empty without a match.
  std::map<std::string, double> thesis;
  std::string thesisSource;
};

// Every static stiffness-rig test of the project, in specimen then test order.
// A test whose results cannot be read is left out and named in `skipped`.
core::Result<std::vector<StiffnessColumn>> stiffnessColumns(const core::io::ProjectStore& store,
                                                            std::vector<std::string>* skipped = nullptr);

// Relative difference (measured - thesis) / |thesis|; none without both.
std::optional<double> thesisDeviation(const StiffnessColumn& column, const std::string& key);

}  // namespace mozzi::devices::rigtests
