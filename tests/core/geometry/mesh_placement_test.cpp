#include "core/geometry/mesh_placement.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::geometry {
namespace {

io::StoredNode node(int label, int cs, Vector3 p) {
  io::StoredNode n;
  n.label = label;
  n.definitionCs = cs;
  n.position = p;
  return n;
}

// Hand-computed placements: a cartesian system turned 90 deg about z and moved,
// a cylindrical and a spherical system at the origin.
TEST(MeshPlacement, NodesInLocalSystemsLandWhereGeometrySaysTheyShould) {
  io::StoredMesh mesh;
  io::StoredCoordinateSystem turned;
  turned.label = 1;
  turned.origin = Vector3(1.0, 2.0, 3.0);
  turned.rotation << 0, -1, 0,  //
      1, 0, 0,                  //
      0, 0, 1;                  // local x along global y
  io::StoredCoordinateSystem cylinder;
  cylinder.label = 2;
  cylinder.kind = io::StoredCoordinateSystem::Kind::Cylindrical;
  io::StoredCoordinateSystem sphere;
  sphere.label = 3;
  sphere.kind = io::StoredCoordinateSystem::Kind::Spherical;
  mesh.coordinateSystems = {turned, cylinder, sphere};
  mesh.nodes = {node(10, 0, {0.5, 0.0, -1.0}), node(11, 1, {1.0, 0.0, 0.0}), node(12, 2, {2.0, 90.0, 0.3}),
                node(13, 3, {1.0, 90.0, 180.0})};
  auto global = globalNodePositions(mesh);
  ASSERT_TRUE(global.ok()) << global.error().describe();
  const std::vector<Vector3> expected = {{0.5, 0.0, -1.0}, {1.0, 3.0, 3.0}, {0.0, 2.0, 0.3}, {-1.0, 0.0, 0.0}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_LT(((*global)[i] - expected[i]).norm(), 1e-12) << "node " << mesh.nodes[i].label;
  }
}

TEST(MeshPlacement, UnknownDefinitionSystemIsNamed) {
  io::StoredMesh mesh;
  mesh.nodes = {node(7, 4, {0, 0, 0})};
  auto global = globalNodePositions(mesh);
  ASSERT_FALSE(global.ok());
  EXPECT_NE(global.error().message.find("node 7"), std::string::npos);
  EXPECT_NE(global.error().message.find("coordinate system 4"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::geometry
