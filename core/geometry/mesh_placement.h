#pragma once
// Where a mesh's nodes are in the global system: each node's coordinates are
// given in its definition coordinate system (UFF 15/2411 field 2), which may be
// cartesian (x, y, z), cylindrical (r, theta [deg], z) or spherical
// (r, theta [deg], phi [deg]) and is placed by an origin and a rotation.

#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/io/project_records.h"

namespace mozzi::core::geometry {

// Global positions [m], in the order of mesh.nodes. A node whose definition
// system is not in the mesh is an error naming the node and the system.
Result<std::vector<Vector3>> globalNodePositions(const io::StoredMesh& mesh);

}  // namespace mozzi::core::geometry
