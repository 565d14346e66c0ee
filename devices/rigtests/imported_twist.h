#pragma once
// A twist CSV of `mozzi-cli twist static|dynamic` (core/stiffness/plate_csv.h,
// docs/cli/stiffness.md) read into the view of a stored stiffness-rig test
// (stiffness_results.h), so the Twist Axes page draws an imported file as it
// draws the project's tests: the same result keys, units and axis convention
// (the foot of the axis from the load point, beta from the plate's v axis).

#include <string>

#include "core/common/result.h"
#include "core/stiffness/plate_csv.h"
#include "devices/rigtests/stiffness_results.h"

namespace mozzi::devices::rigtests {

// `twist static` (one load or a ramp): k_lat, a_tw, k_tw, the axis. Errors:
// those of core::stiffness::staticTwistFromCsv, naming the file.
core::Result<StiffnessTestView> staticViewFromCsv(const core::stiffness::PlateCsv& csv, const std::string& name);

// `twist dynamic`: one step per frequency with its axis (and k_lat, k_tw
// when the force columns are given) and the laser phasors. A frequency whose
// axis cannot be found keeps a step without an axis; its error is in `note`.
// Errors: the file's shape, no frequency with an axis.
core::Result<StiffnessTestView> dynamicViewFromCsv(const core::stiffness::PlateCsv& csv, const std::string& name,
                                                   std::string* note = nullptr);

// Keeps an imported static or dynamic view in the project as a rig test of
// `specimenId`, so the report, the Stiffness page and the CLI see it: a rig
// set-up (rig kind "imported-csv", driver "csv", the source file in its
// parameters) holding the plate geometry as readStiffnessTest reads it, and a
// complete test named after the view (made unique within the specimen)
// holding its results (whole-test for static, per step for dynamic: the
// frequency, the axis, a_tw, k_lat and k_tw where known, the laser phasors).
// Returns the test's id. Errors: those of the store.
core::Result<std::int64_t> storeImportedTest(core::io::ProjectStore& store, std::int64_t specimenId,
                                             const StiffnessTestView& view, const std::string& sourcePath);

}  // namespace mozzi::devices::rigtests
