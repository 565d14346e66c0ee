// Mesh edits as data: each planned edit does what the editor promises, its
// inverse restores the document exactly, and refused edits name the item.
#include "core/geometry/mesh_edit.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace mozzi::core::geometry {
namespace {

using io::MeshDocument;

Dof dof(int node, Direction d, bool negative = false) {
  return Dof{node, d, negative};
}

// A unit square 1-2-3-4 in the xy plane (m), a diagonal node 5 in a
// cylindrical system, a trace line around, one face, DOFs and a slave rule.
MeshDocument square() {
  MeshDocument d;
  io::StoredCoordinateSystem cyl;
  cyl.label = 7;
  cyl.name = "hub";
  cyl.kind = io::StoredCoordinateSystem::Kind::Cylindrical;
  d.mesh.coordinateSystems = {cyl};
  auto node = [](int label, double x, double y, double z, int cs = 0) {
    io::StoredNode n;
    n.label = label;
    n.definitionCs = cs;
    n.position = Vector3(x, y, z);
    return n;
  };
  d.mesh.nodes = {node(1, 0, 0, 0), node(2, 1, 0, 0), node(3, 1, 1, 0), node(4, 0, 1, 0), node(5, 0.5, 45.0, 0.0, 7)};
  d.mesh.lines = {{1, 2}, {2, 3}, {3, 4}, {4, 1}};
  d.mesh.faces = {{1, 2, 3, 4}};
  d.measurementDofs = {dof(1, Direction::Z), dof(2, Direction::Z), dof(3, Direction::Z)};
  d.slaves = {{dof(4, Direction::Z), {{dof(1, Direction::Z), 0.5}, {dof(3, Direction::Z), 0.5}}}};
  return d;
}

void expectUndoRestores(const MeshDocument& before, const MeshEdit& edit) {
  MeshDocument d = before;
  ASSERT_TRUE(apply(d, edit).ok());
  ASSERT_TRUE(apply(d, inverse(edit)).ok());
  EXPECT_TRUE(io::sameDocument(d, before)) << edit.description;
}

TEST(MeshEdit, DeleteNodeTakesItsLinesFacesDofsAndSlavesAndUndoRestoresAll) {
  const MeshDocument before = square();
  auto edit = planDeleteNodes(before, {3});
  ASSERT_TRUE(edit.ok()) << edit.error().describe();
  MeshDocument d = before;
  ASSERT_TRUE(apply(d, *edit).ok());
  ASSERT_EQ(d.mesh.nodes.size(), 4u);
  EXPECT_FALSE(nodeIndex(d, 3));
  ASSERT_EQ(d.mesh.lines.size(), 2u);  // 2-3 and 3-4 gone
  EXPECT_EQ(d.mesh.lines[0].nodeA, 1);
  EXPECT_EQ(d.mesh.lines[1].nodeA, 4);
  EXPECT_TRUE(d.mesh.faces.empty());
  EXPECT_EQ(d.measurementDofs.size(), 2u);
  EXPECT_TRUE(d.slaves.empty());  // node 3 was a master
  EXPECT_TRUE(validate(d).ok());
  expectUndoRestores(before, *edit);
}

TEST(MeshEdit, RenumberFollowsEveryReference) {
  const MeshDocument before = square();
  auto edit = planRenumber(before, 1, 100);
  ASSERT_TRUE(edit.ok());
  MeshDocument d = before;
  ASSERT_TRUE(apply(d, *edit).ok());
  EXPECT_EQ(d.mesh.nodes[0].label, 100);
  EXPECT_EQ(d.mesh.lines[0].nodeA, 100);
  EXPECT_EQ(d.mesh.lines[3].nodeB, 100);
  EXPECT_EQ(d.mesh.faces[0].nodeA, 100);
  EXPECT_EQ(d.measurementDofs[0].node, 100);
  EXPECT_EQ(d.slaves[0].masters[0].first.node, 100);
  EXPECT_TRUE(validate(d).ok());
  expectUndoRestores(before, *edit);

  auto clash = planRenumber(before, 1, 2);
  ASSERT_FALSE(clash.ok());
  EXPECT_NE(clash.error().message.find("node 2 already exists"), std::string::npos);
  auto missing = planRenumber(before, 9, 10);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("no node 9"), std::string::npos);
}

TEST(MeshEdit, RenumberAllSwapsLabelsWithoutCollisions) {
  MeshDocument before = square();
  auto edit = planRenumberAll(before, 10, 10);
  ASSERT_TRUE(edit.ok());
  MeshDocument d = before;
  ASSERT_TRUE(apply(d, *edit).ok());
  for (std::size_t i = 0; i < d.mesh.nodes.size(); ++i) EXPECT_EQ(d.mesh.nodes[i].label, 10 * static_cast<int>(i + 1));
  EXPECT_EQ(d.mesh.lines[1].nodeA, 20);
  EXPECT_EQ(d.mesh.lines[1].nodeB, 30);
  EXPECT_TRUE(validate(d).ok());
  expectUndoRestores(before, *edit);
  // Reversing the order maps 1 -> 5 and 5 -> 1 in one edit.
  std::reverse(before.mesh.nodes.begin(), before.mesh.nodes.end());
  auto swap = planRenumberAll(before, 1, 1);
  ASSERT_TRUE(swap.ok());
  d = before;
  ASSERT_TRUE(apply(d, *swap).ok());
  EXPECT_TRUE(validate(d).ok());
}

TEST(MeshEdit, SnapRoundsCartesianCoordinatesAndKeepsAngles) {
  MeshDocument d = square();
  d.mesh.nodes[1].position = Vector3(1.0123, -0.0049, 0.2551);
  d.mesh.nodes[4].position = Vector3(0.5049, 45.3, 0.0149);  // r, theta [deg], z
  auto edit = planSnapToGrid(d, {2, 5}, 0.01);
  ASSERT_TRUE(edit.ok());
  const MeshDocument before = d;
  ASSERT_TRUE(apply(d, *edit).ok());
  const double tol = 1e-12;  // one rounding of round(v / g) * g
  EXPECT_NEAR(d.mesh.nodes[1].position.x(), 1.01, tol);
  EXPECT_NEAR(d.mesh.nodes[1].position.y(), 0.0, tol);
  EXPECT_NEAR(d.mesh.nodes[1].position.z(), 0.26, tol);
  EXPECT_NEAR(d.mesh.nodes[4].position.x(), 0.50, tol);
  EXPECT_EQ(d.mesh.nodes[4].position.y(), 45.3);  // angle untouched
  EXPECT_NEAR(d.mesh.nodes[4].position.z(), 0.01, tol);
  expectUndoRestores(before, *edit);
  EXPECT_FALSE(planSnapToGrid(d, {2}, 0.0).ok());
}

TEST(MeshEdit, AddAndMoveNodesAddLinesAndFaces) {
  const MeshDocument before = square();
  auto add = planAddNode(before, io::StoredNode{0, 0, 0, 0, Vector3(2, 0, 0)});
  ASSERT_TRUE(add.ok());
  MeshDocument d = before;
  ASSERT_TRUE(apply(d, *add).ok());
  EXPECT_EQ(d.mesh.nodes.back().label, 6);  // next free label
  auto line = planAddLine(d, 2, 6);
  ASSERT_TRUE(line.ok());
  ASSERT_TRUE(apply(d, *line).ok());
  EXPECT_FALSE(planAddLine(d, 6, 2).ok());  // already there, either way round
  EXPECT_FALSE(planAddLine(d, 6, 6).ok());
  auto face = planAddFace(d, {2, 6, 3, 0});
  ASSERT_TRUE(face.ok());
  ASSERT_TRUE(apply(d, *face).ok());
  EXPECT_FALSE(planAddFace(d, {2, 2, 3, 0}).ok());
  auto move = planMoveNodes(d, {6, 1}, Vector3(0, 0, 0.5));
  ASSERT_TRUE(move.ok());
  ASSERT_TRUE(apply(d, *move).ok());
  EXPECT_EQ(d.mesh.nodes.back().position, Vector3(2, 0, 0.5));
  EXPECT_EQ(d.mesh.nodes.front().position, Vector3(0, 0, 0.5));
  EXPECT_FALSE(planMoveNodes(d, {5}, Vector3(1, 0, 0)).ok());  // cylindrical: edit coordinates instead
  EXPECT_TRUE(validate(d).ok());
  auto dup = planAddNode(d, io::StoredNode{0, 2, 0, 0, Vector3::Zero()});
  ASSERT_FALSE(dup.ok());
  EXPECT_NE(dup.error().message.find("node 2 already exists"), std::string::npos);
  auto badCs = planAddNode(d, io::StoredNode{0, 0, 3, 0, Vector3::Zero()});
  ASSERT_FALSE(badCs.ok());
  EXPECT_NE(badCs.error().message.find("coordinate system 3"), std::string::npos);
}

TEST(MeshEdit, NodeDofsAndSlaveRules) {
  MeshDocument d = square();
  auto dofs = planSetNodeDofs(d, 2, {dof(2, Direction::X), dof(2, Direction::Z)});
  ASSERT_TRUE(dofs.ok());
  const MeshDocument before = d;
  ASSERT_TRUE(apply(d, *dofs).ok());
  EXPECT_EQ(d.measurementDofs,
            (std::vector<Dof>{dof(1, Direction::Z), dof(2, Direction::Z), dof(3, Direction::Z), dof(2, Direction::X)}));
  expectUndoRestores(before, *dofs);
  EXPECT_FALSE(planSetNodeDofs(d, 2, {dof(3, Direction::X)}).ok());
  EXPECT_FALSE(planSetNodeDofs(d, 2, {dof(2, Direction::X), dof(2, Direction::X, true)}).ok());
  EXPECT_FALSE(planSetNodeDofs(d, 4, {dof(4, Direction::Z)}).ok());  // slaved

  // A cycle 4 -> 5 -> 4 is refused and named.
  auto first = planSetSlave(d, {dof(5, Direction::Z), {{dof(4, Direction::Z), 1.0}}});
  ASSERT_TRUE(first.ok());
  ASSERT_TRUE(apply(d, *first).ok());
  auto cycle = planSetSlave(d, {dof(4, Direction::Z), {{dof(5, Direction::Z), 1.0}}});
  ASSERT_FALSE(cycle.ok());
  EXPECT_NE(cycle.error().message.find("cycle"), std::string::npos);
  EXPECT_FALSE(planSetSlave(d, {dof(1, Direction::Z), {{dof(2, Direction::Z), 1.0}}}).ok());  // measured
  auto removed = planRemoveSlave(d, dof(5, Direction::Z));
  ASSERT_TRUE(removed.ok());
  ASSERT_TRUE(apply(d, *removed).ok());
  EXPECT_EQ(d.slaves.size(), 1u);
}

TEST(MeshEdit, CoordinateSystemsInUseCannotBeDeleted) {
  MeshDocument d = square();
  auto refused = planDeleteCoordinateSystem(d, 7);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("node 5"), std::string::npos);
  auto added = planAddCoordinateSystem(d, io::StoredCoordinateSystem{});
  ASSERT_TRUE(added.ok());
  ASSERT_TRUE(apply(d, *added).ok());
  EXPECT_EQ(d.mesh.coordinateSystems.back().label, 8);
  auto gone = planDeleteCoordinateSystem(d, 8);
  ASSERT_TRUE(gone.ok());
  ASSERT_TRUE(apply(d, *gone).ok());
  EXPECT_EQ(d.mesh.coordinateSystems.size(), 1u);
}

TEST(MeshEdit, StaleEditIsRefusedAndLeavesTheDocument) {
  const MeshDocument original = square();
  auto edit = planDeleteNodes(original, {1});
  ASSERT_TRUE(edit.ok());
  MeshDocument changed = original;
  changed.mesh.nodes[0].position.x() = 0.25;  // someone moved node 1 meanwhile
  const MeshDocument snapshot = changed;
  auto r = apply(changed, *edit);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("changed since"), std::string::npos);
  EXPECT_TRUE(io::sameDocument(changed, snapshot));
}

TEST(MeshEdit, ReplaceAndUndoRestoreTheWholeDocument) {
  const MeshDocument before = square();
  MeshDocument other;
  other.mesh.nodes = {io::StoredNode{0, 40, 0, 0, Vector3(1, 2, 3)}};
  const MeshEdit edit = planReplace(before, other, "start from template");
  MeshDocument d = before;
  ASSERT_TRUE(apply(d, edit).ok());
  EXPECT_TRUE(io::sameDocument(d, other));
  expectUndoRestores(before, edit);
}

TEST(MeshEdit, OrphansNameTheDataAndTheirDofs) {
  const MeshDocument before = square();
  const std::vector<MeasuredData> data = {
      {"campaign 'Frame A roving hammer' hits", {dof(2, Direction::Z), dof(3, Direction::Z), dof(9, Direction::Z)}},
      {"modal result 1 'PolyMAX'", {dof(1, Direction::Z)}}};
  MeshDocument after = before;
  ASSERT_TRUE(apply(after, *planDeleteNodes(before, {2, 3})).ok());
  const auto orphans = orphanedBy(before, after, data);
  ASSERT_EQ(orphans.size(), 1u);
  EXPECT_EQ(orphans[0].name, "campaign 'Frame A roving hammer' hits");
  EXPECT_EQ(orphans[0].dofs, (std::vector<Dof>{dof(2, Direction::Z), dof(3, Direction::Z)}));  // 9 was never there
  EXPECT_EQ(describeOrphans(orphans), "campaign 'Frame A roving hammer' hits (2:+Z, 3:+Z)");
  // Moving a node orphans nothing; renumbering does.
  MeshDocument moved = before;
  ASSERT_TRUE(apply(moved, *planMoveNodes(before, {1}, Vector3(0, 0, 1))).ok());
  EXPECT_TRUE(orphanedBy(before, moved, data).empty());
  MeshDocument renumbered = before;
  ASSERT_TRUE(apply(renumbered, *planRenumber(before, 1, 11)).ok());
  ASSERT_EQ(orphanedBy(before, renumbered, data).size(), 1u);
  EXPECT_EQ(orphanedBy(before, renumbered, data)[0].name, "modal result 1 'PolyMAX'");
}

TEST(MeshEdit, TextFormsOfDofsAndRules) {
  auto dofs = parseNodeDofs(12, "+X, z -RY");
  ASSERT_TRUE(dofs.ok()) << dofs.error().describe();
  EXPECT_EQ(*dofs, (std::vector<Dof>{dof(12, Direction::X), dof(12, Direction::Z), dof(12, Direction::RY, true)}));
  EXPECT_EQ(formatNodeDofs(*dofs), "+X +Z -RY");
  EXPECT_TRUE(parseNodeDofs(12, "  ")->empty());
  auto bad = parseNodeDofs(12, "+X +W");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("'+W'"), std::string::npos);

  auto rule = parseSlaveRule("5:+Z = 0.5 4:+Z + 0.25*6:-Z - 7:+Z");
  ASSERT_TRUE(rule.ok()) << rule.error().describe();
  EXPECT_EQ(rule->slave, dof(5, Direction::Z));
  ASSERT_EQ(rule->masters.size(), 3u);
  EXPECT_EQ(rule->masters[0].second, 0.5);
  EXPECT_EQ(rule->masters[1].first, dof(6, Direction::Z, true));
  EXPECT_EQ(rule->masters[1].second, 0.25);
  EXPECT_EQ(rule->masters[2].second, -1.0);
  auto again = parseSlaveRule(formatSlaveRule(*rule));
  ASSERT_TRUE(again.ok()) << formatSlaveRule(*rule);
  EXPECT_EQ(*again, *rule);
  EXPECT_FALSE(parseSlaveRule("5:+Z 4:+Z").ok());
  EXPECT_FALSE(parseSlaveRule("5:+Z = 0.5").ok());
  EXPECT_FALSE(parseSlaveRule("5:+Z = 0.5 0.5 4:+Z").ok());
}

}  // namespace
}  // namespace mozzi::core::geometry
