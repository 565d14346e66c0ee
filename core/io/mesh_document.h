#pragma once
// A measurement mesh as the editor and the exchange files see it: the stored
// geometry (coordinate systems, nodes, trace-line segments, faces) plus the
// measurement DOFs (where a campaign measures, node label and direction in the
// node's displacement system) and the slave rules that let an unmeasured DOF
// follow measured ones. The project schema stores the geometry only
// (StoredMesh); DOFs and slaves travel in the mesh CSV (docs/formats/csv.md).

#include <utility>
#include <vector>

#include "core/common/dof.h"
#include "core/io/project_records.h"

namespace mozzi::core::io {

// u(slave) = sum_k weight_k u(master_k), complex shape values; masters are
// measured DOFs or other slaves (no cycles).
struct SlavedDof {
  Dof slave;
  std::vector<std::pair<Dof, double>> masters;  // (master DOF, weight [1])

  friend bool operator==(const SlavedDof& a, const SlavedDof& b) {
    return a.slave == b.slave && a.masters == b.masters;
  }
};

struct MeshDocument {
  StoredMesh mesh;
  std::vector<Dof> measurementDofs;  // in the order the editor lists them
  std::vector<SlavedDof> slaves;
};

// Geometry equality as the exchange formats keep it: labels, kinds, names,
// coordinates (exact doubles), rotation, order. Database row ids are ignored.
inline bool sameCoordinateSystem(const StoredCoordinateSystem& a, const StoredCoordinateSystem& b) {
  return a.label == b.label && a.name == b.name && a.kind == b.kind && a.origin == b.origin && a.rotation == b.rotation;
}
inline bool sameNode(const StoredNode& a, const StoredNode& b) {
  return a.label == b.label && a.definitionCs == b.definitionCs && a.displacementCs == b.displacementCs &&
         a.position == b.position;
}
inline bool sameLine(const StoredLine& a, const StoredLine& b) {
  return a.nodeA == b.nodeA && a.nodeB == b.nodeB;
}
inline bool sameFace(const StoredFace& a, const StoredFace& b) {
  return a.nodeA == b.nodeA && a.nodeB == b.nodeB && a.nodeC == b.nodeC && a.nodeD == b.nodeD;
}
inline bool sameMesh(const StoredMesh& a, const StoredMesh& b) {
  auto same = [](const auto& x, const auto& y, auto eq) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!eq(x[i], y[i])) return false;
    return true;
  };
  return same(a.coordinateSystems, b.coordinateSystems, sameCoordinateSystem) && same(a.nodes, b.nodes, sameNode) &&
         same(a.lines, b.lines, sameLine) && same(a.faces, b.faces, sameFace);
}
inline bool sameDocument(const MeshDocument& a, const MeshDocument& b) {
  return sameMesh(a.mesh, b.mesh) && a.measurementDofs == b.measurementDofs && a.slaves == b.slaves;
}

}  // namespace mozzi::core::io
