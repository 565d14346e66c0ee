// The measurement-mesh templates of the thesis set-ups: the point counts the
// thesis gives (§1.2-1.4 plate 3 or 4 sensors; §2.1 frames 20 and 26 points;
// §2.2 frame C 22 + 10 on the engine; §3.1, §3.2 swing-arms 6 and 18; chapter
// 4 forks 10 + 8 on the wheel; §5.2 tyre 6 points on the belt; §6.1 bicycle 9
// frame + 12 fork; chapter 6 bicycle fork 9 + 8 on the wheel), and the
// integrity of each mesh: every line, face, group and DOF names an existing
// node, labels and DOFs are unique, DOF directions are unit translations.
#include "core/geometry/mesh_templates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/geometry/mesh_placement.h"

namespace mozzi::core::geometry {
namespace {

struct Expected {
  const char* key;
  std::size_t nodes;
  std::size_t dofsPerNode;
  const char* countedGroup;  // a group whose size the thesis gives ("" for none)
  std::size_t groupSize;
};

const Expected kExpected[] = {
    {"stiffness-plate-3", 3, 1, "sensors", 3},               // eq. 3: L1, L2, L3
    {"stiffness-plate-4", 4, 1, "sensors", 4},               // §1.2: the fourth laser
    {"motorcycle-frame-20", 20, 3, "", 0},                   // §2.1 frame A
    {"motorcycle-frame-26", 26, 3, "", 0},                   // §2.1 frame B
    {"motorcycle-frame-22", 22, 3, "", 0},                   // §2.2 frame C
    {"motorcycle-frame-22-engine-10", 32, 3, "engine", 10},  // §2.2: 10 points on the engine
    {"swing-arm-6", 6, 3, "", 0},                            // §3.1
    {"swing-arm-18", 18, 3, "", 0},                          // §3.2
    {"motorcycle-fork-10", 10, 3, "", 0},                    // chapter 4
    {"motorcycle-fork-10-wheel-8", 18, 3, "wheel", 8},       // chapter 4: 8 on the wheel
    {"tyre-6", 6, 1, "belt", 6},                             // §5.2
    {"bicycle-9-12", 21, 3, "fork", 12},                     // §6.1: 9 frame + 12 fork
    {"bicycle-fork-9", 9, 3, "", 0},                         // chapter 6
    {"bicycle-fork-9-wheel-8", 17, 3, "wheel", 8},           // chapter 6: 8 on the wheel
};

TEST(MeshTemplates, EveryTemplateOfTheIssueWithTheThesisPointCounts) {
  EXPECT_EQ(meshTemplates().size(), std::size(kExpected));
  for (const auto& ex : kExpected) {
    const MeshTemplate* t = findMeshTemplate(ex.key);
    ASSERT_NE(t, nullptr) << ex.key;
    EXPECT_EQ(t->key, ex.key);
    EXPECT_EQ(t->mesh.nodes.size(), ex.nodes) << ex.key;
    EXPECT_EQ(t->measurementDofs.size(), ex.nodes * ex.dofsPerNode) << ex.key;
    if (*ex.countedGroup) {
      const NodeGroup* g = t->group(ex.countedGroup);
      ASSERT_NE(g, nullptr) << ex.key << " group " << ex.countedGroup;
      EXPECT_EQ(g->nodes.size(), ex.groupSize) << ex.key << " group " << ex.countedGroup;
    }
    EXPECT_FALSE(t->name.empty());
    EXPECT_NE(t->source.find("thesis"), std::string::npos) << ex.key;
    EXPECT_TRUE(t->approximateCoordinates) << ex.key << ": the thesis prints no coordinates";
    EXPECT_NE(t->notes.find("Axes"), std::string::npos) << ex.key << ": the notes state the axes";
    EXPECT_NE(t->notes.find("approximate"), std::string::npos) << ex.key << ": the notes say what is approximate";
  }
  EXPECT_EQ(findMeshTemplate("no-such-template"), nullptr);
  // The bicycle: 9 frame points, the rear hub is point 100 (§6.1).
  const MeshTemplate* bike = findMeshTemplate("bicycle-9-12");
  ASSERT_NE(bike->group("frame"), nullptr);
  EXPECT_EQ(bike->group("frame")->nodes.size(), 9u);
  EXPECT_NE(bike->node(100), nullptr);
  // The tyre: the accelerometer point 100 is the lowest of the belt (§5.2).
  EXPECT_NE(findMeshTemplate("tyre-6")->node(100), nullptr);
}

TEST(MeshTemplates, LinesFacesGroupsAndDofsNameExistingNodes) {
  for (const auto& t : meshTemplates()) {
    SCOPED_TRACE(t.key);
    std::set<int> labels;
    for (const auto& n : t.mesh.nodes) {
      EXPECT_TRUE(labels.insert(n.label).second) << "duplicate node " << n.label;
      EXPECT_GT(n.label, 0);
      EXPECT_EQ(n.definitionCs, 0);
      EXPECT_EQ(n.displacementCs, 0);
      EXPECT_TRUE(n.position.allFinite());
      EXPECT_LT(n.position.norm(), 2.0) << "node " << n.label << " [m]";
    }
    EXPECT_FALSE(t.mesh.lines.empty()) << "a mesh reads as the component through its trace lines";
    std::set<std::pair<int, int>> lines;
    std::set<int> traced;
    for (const auto& l : t.mesh.lines) {
      EXPECT_TRUE(labels.count(l.nodeA)) << "line to missing node " << l.nodeA;
      EXPECT_TRUE(labels.count(l.nodeB)) << "line to missing node " << l.nodeB;
      EXPECT_NE(l.nodeA, l.nodeB);
      EXPECT_TRUE(lines.insert({std::min(l.nodeA, l.nodeB), std::max(l.nodeA, l.nodeB)}).second)
          << "duplicate line " << l.nodeA << "-" << l.nodeB;
      traced.insert(l.nodeA);
      traced.insert(l.nodeB);
    }
    EXPECT_EQ(traced.size(), labels.size()) << "every node is on a trace line";
    for (const auto& f : t.mesh.faces) {
      for (int n : {f.nodeA, f.nodeB, f.nodeC}) EXPECT_TRUE(labels.count(n)) << "face with missing node " << n;
      if (f.nodeD != 0) {
        EXPECT_TRUE(labels.count(f.nodeD));
      }
    }
    for (const auto& g : t.groups)
      for (int n : g.nodes) EXPECT_TRUE(labels.count(n)) << "group " << g.name << " names missing node " << n;
    std::set<Dof> dofs;
    for (const auto& d : t.measurementDofs) {
      EXPECT_TRUE(labels.count(d.node)) << formatDof(d);
      EXPECT_TRUE(dofs.insert(d).second) << "duplicate DOF " << formatDof(d);
      // Unit translation along a global axis (no displacement system): the
      // accelerometers of the thesis are translational.
      ASSERT_FALSE(d.isRotation()) << formatDof(d);
      const Vector3 dir = (d.negative ? -1.0 : 1.0) * Vector3::Unit(static_cast<int>(d.direction) - 1);
      EXPECT_DOUBLE_EQ(dir.norm(), 1.0);
      EXPECT_EQ(parseDof(formatDof(d)).value(), d);
    }
    auto placed = globalNodePositions(t.mesh);
    ASSERT_TRUE(placed.ok()) << placed.error().describe();
    EXPECT_EQ(placed->size(), t.mesh.nodes.size());
  }
}

// The lateral axis is z (y on the plate): left and right halves mirror each
// other about z = 0 where the thesis's components are symmetric.
TEST(MeshTemplates, SymmetricComponentsMirrorAboutTheLateralAxis) {
  const std::pair<const char*, std::pair<const char*, const char*>> pairs[] = {
      {"swing-arm-6", {"left stem", "right stem"}},      {"swing-arm-18", {"left stem", "right stem"}},
      {"motorcycle-fork-10", {"left leg", "right leg"}}, {"bicycle-9-12", {"left blade", "right blade"}},
      {"bicycle-fork-9", {"left blade", "right blade"}},
  };
  for (const auto& [key, sides] : pairs) {
    const MeshTemplate* t = findMeshTemplate(key);
    ASSERT_NE(t, nullptr);
    const NodeGroup* a = t->group(sides.first);
    const NodeGroup* b = t->group(sides.second);
    ASSERT_TRUE(a && b) << key;
    ASSERT_EQ(a->nodes.size(), b->nodes.size());
    for (std::size_t i = 0; i < a->nodes.size(); ++i) {
      const Vector3 pa = t->node(a->nodes[i])->position, pb = t->node(b->nodes[i])->position;
      EXPECT_NEAR(pa.x(), pb.x(), 1e-12) << key;
      EXPECT_NEAR(pa.y(), pb.y(), 1e-12) << key;
      EXPECT_NEAR(pa.z(), -pb.z(), 1e-12) << key;
      EXPECT_GT(std::abs(pa.z()), 0.02) << key << ": the two sides are apart";
    }
  }
}

// Templates "with wheel" / "with engine" extend the plain ones: the shared
// nodes keep their labels and positions, so one stored mesh serves both.
TEST(MeshTemplates, ExtendedTemplatesKeepTheSharedNodes) {
  const std::pair<const char*, const char*> ext[] = {
      {"motorcycle-fork-10", "motorcycle-fork-10-wheel-8"},
      {"bicycle-fork-9", "bicycle-fork-9-wheel-8"},
      {"motorcycle-frame-22", "motorcycle-frame-22-engine-10"},
      {"motorcycle-frame-20", "motorcycle-frame-26"},
  };
  for (const auto& [small, big] : ext) {
    const MeshTemplate* s = findMeshTemplate(small);
    const MeshTemplate* b = findMeshTemplate(big);
    for (const auto& n : s->mesh.nodes) {
      const auto* m = b->node(n.label);
      ASSERT_NE(m, nullptr) << big << " lacks node " << n.label;
      EXPECT_EQ(m->position, n.position) << big << " node " << n.label;
    }
  }
}

// Geometry the thesis states: the tyre's points are equidistant on the belt
// (§5.2), the wheels' points equidistant on the rim (chapter 4, chapter 6;
// bicycle wheel radius 0.35 m, Table 21), the 3-point plate has the layout of
// eq. 3 (L3 at the origin, L2 below it, L1 beside L2, all in y = 0).
TEST(MeshTemplates, RingsAreEquidistantAndThePlateFollowsEquation3) {
  auto ring = [](const MeshTemplate& t, const std::vector<int>& nodes, double radius) {
    const double step = 2.0 * 3.14159265358979323846 / static_cast<double>(nodes.size());
    const double chord = 2.0 * radius * std::sin(step / 2.0);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Vector3 p = t.node(nodes[i])->position, q = t.node(nodes[(i + 1) % nodes.size()])->position;
      EXPECT_NEAR(p.norm(), radius, 1e-12) << t.key << " node " << nodes[i];
      EXPECT_NEAR((q - p).norm(), chord, 1e-12) << t.key;
      EXPECT_NEAR(p.z(), 0.0, 1e-12) << t.key << ": in the wheel plane";
    }
    // The first is the lowest point.
    EXPECT_NEAR(t.node(nodes.front())->position.x(), -radius, 1e-12) << t.key;
  };
  const MeshTemplate* tyre = findMeshTemplate("tyre-6");
  ring(*tyre, tyre->group("belt")->nodes, 0.30);
  const MeshTemplate* fork = findMeshTemplate("motorcycle-fork-10-wheel-8");
  ring(*fork, fork->group("wheel")->nodes, 0.34);
  const MeshTemplate* bfork = findMeshTemplate("bicycle-fork-9-wheel-8");
  ring(*bfork, bfork->group("wheel")->nodes, 0.35);

  const MeshTemplate* plate = findMeshTemplate("stiffness-plate-3");
  const Vector3 l1 = plate->node(1)->position, l2 = plate->node(2)->position, l3 = plate->node(3)->position;
  EXPECT_EQ(l3, Vector3::Zero());
  EXPECT_EQ(l2.x(), 0.0);
  EXPECT_LT(l2.z(), 0.0);
  EXPECT_GT(l1.x(), 0.0);
  EXPECT_EQ(l1.z(), l2.z());
  for (const auto& d : plate->measurementDofs) EXPECT_EQ(d.direction, Direction::Y) << "the plate normal";
}

}  // namespace
}  // namespace mozzi::core::geometry
