#pragma once
// The virtual specimens behind the simulated rigs and the demo project: the
// components the thesis measured, each with where its parameters come from.

#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::devices::sim {

struct VirtualSpecimen {
  std::string name;    // e.g. "Fork A (enduro), without wheel"
  std::string kind;    // frame, swing-arm, fork, tyre, bicycle, bicycle-fork, wheelchair-tyre
  std::string source;  // thesis section and tables the parameters come from
};

const std::vector<VirtualSpecimen>& virtualSpecimens();

// Creates the demo project at `path` (fails if the file exists): every virtual
// specimen, ready for the simulated rigs.
core::Result<void> createDemoProject(const std::string& path, const std::string& mozziVersion);

}  // namespace mozzi::devices::sim
