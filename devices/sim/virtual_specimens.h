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
  // The catalogue specimens (specimen_catalogue.h) this component is tested
  // as, one per constraint or configuration: {"frame-a-front-constrained",
  // "frame-a-rear-constrained"}; empty for the wheelchair tyres (no modal or
  // static catalogue entry).
  std::vector<std::string> catalogueKeys;
  // The measurement mesh stored with it (core/geometry/mesh_templates.h); for
  // components tested with and without a wheel, the larger mesh (the fork's
  // nodes keep their labels in both). Empty: no mesh.
  std::string meshTemplate;
};

const std::vector<VirtualSpecimen>& virtualSpecimens();

// Creates the demo project at `path` (fails if the file exists): every virtual
// specimen with its measurement mesh, ready for the simulated rigs. The
// project is built by a list of steps (virtual_specimens.cpp, kDemoSteps),
// each a function of the open store and of what the earlier steps made; a
// new part of the demo (campaigns, rig tests, models) is one more step.
core::Result<void> createDemoProject(const std::string& path, const std::string& mozziVersion);

}  // namespace mozzi::devices::sim
