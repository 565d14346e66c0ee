#include "core/geometry/mesh_placement.h"

#include <cmath>
#include <map>
#include <string>

namespace mozzi::core::geometry {

Result<std::vector<Vector3>> globalNodePositions(const io::StoredMesh& mesh) {
  std::map<int, const io::StoredCoordinateSystem*> systems;
  for (const auto& cs : mesh.coordinateSystems) systems[cs.label] = &cs;
  std::vector<Vector3> out;
  out.reserve(mesh.nodes.size());
  constexpr double kDeg = M_PI / 180.0;
  for (const auto& node : mesh.nodes) {
    if (node.definitionCs == 0) {  // 0 is the global system
      out.push_back(node.position);
      continue;
    }
    const auto it = systems.find(node.definitionCs);
    if (it == systems.end()) {
      return makeError(ErrorCode::NotFound,
                       "node " + std::to_string(node.label) + " is defined in coordinate system " +
                           std::to_string(node.definitionCs) + ", which the mesh does not have",
                       "mesh node " + std::to_string(node.label));
    }
    const io::StoredCoordinateSystem& cs = *it->second;
    const Vector3& p = node.position;
    Vector3 local = p;
    switch (cs.kind) {
      case io::StoredCoordinateSystem::Kind::Cartesian: break;
      case io::StoredCoordinateSystem::Kind::Cylindrical:  // (r, theta, z)
        local = Vector3(p[0] * std::cos(p[1] * kDeg), p[0] * std::sin(p[1] * kDeg), p[2]);
        break;
      case io::StoredCoordinateSystem::Kind::Spherical:  // (r, theta from +z, phi from +x)
        local = Vector3(p[0] * std::sin(p[1] * kDeg) * std::cos(p[2] * kDeg),
                        p[0] * std::sin(p[1] * kDeg) * std::sin(p[2] * kDeg), p[0] * std::cos(p[1] * kDeg));
        break;
    }
    out.push_back(cs.origin + cs.rotation * local);  // rotation columns are the local axes in global
  }
  return out;
}

}  // namespace mozzi::core::geometry
