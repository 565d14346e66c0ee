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

}  // namespace mozzi::devices::rigtests
