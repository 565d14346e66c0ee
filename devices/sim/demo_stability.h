#pragma once
// The demo project's stability results (issue 23): the benchmark bicycle with
// the rigid and the compliant (steel, bending) fork, and Sharp's (1971)
// motorcycle with lumped fork model 1 of thesis Table 12 against the rigid
// fork, kept as analyses of kind "stability" (core/stability/stability_record.h).
// Built-in parameters and fixed speed grids: the same numbers on every run.

#include "core/common/result.h"

namespace mozzi::core::io {
class ProjectStore;
}

namespace mozzi::devices::sim {

core::Result<void> addDemoStability(core::io::ProjectStore& store);

}  // namespace mozzi::devices::sim
