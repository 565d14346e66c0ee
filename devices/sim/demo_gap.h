#pragma once
// The demo project's model and gap diagnosis (issue 23): the design model of
// fork A with wheel keeps only its three catalogued modes (thesis Table 11);
// the simulated specimen the demo campaign measured also has the
// out-of-band completion modes above them. The diagnosis of that model
// against the campaign's FRF set, kept in the project as a model and an
// analysis record, gives the Model vs Test story and the report's gap
// section something true to show: the gap is the missing residual of the
// out-of-band modes.

#include "core/common/result.h"
#include "core/io/project_store.h"

namespace mozzi::devices::sim {

// Needs the demo's fork A with wheel, its finished campaign's FRF set and the
// modal result identified from it (the steps before). Errors name the step.
core::Result<void> addDemoGapDiagnosis(core::io::ProjectStore& store);

}  // namespace mozzi::devices::sim
