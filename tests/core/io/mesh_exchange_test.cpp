// Mesh export and import: what Mozzi writes (UFF 2411/2420/82, or 15/18, and
// the mesh CSV) reads back to the same mesh; vendor geometry files import as
// they did and survive an export-import round trip; bad CSV input is named by
// file, line and column.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "core/geometry/mesh_edit.h"
#include "core/io/csv/csv_exchange.h"
#include "core/io/uff_import.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;
const std::string kData = std::string(MOZZI_SHARED_DATA_DIR) + "/uff/";

Dof dof(int node, Direction d, bool negative = false) {
  return Dof{node, d, negative};
}

// A mesh with awkward doubles (random, irrational), a rotated cartesian and a
// cylindrical system, 300 nodes on a broken chain (so trace lines split at the
// 250-node limit and lift the pen), faces, DOFs and slaves.
MeshDocument awkwardMesh() {
  std::mt19937 rng(2411);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  MeshDocument d;
  StoredCoordinateSystem turned;
  turned.label = 3;
  turned.name = "fork leg, 12.5 deg";
  const double a = 12.5 * M_PI / 180.0;
  turned.rotation << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  turned.origin = Vector3(M_PI / 10, -std::sqrt(2.0) / 7, 1e-3 / 3);
  StoredCoordinateSystem cyl;
  cyl.label = 4;
  cyl.kind = StoredCoordinateSystem::Kind::Cylindrical;
  d.mesh.coordinateSystems = {turned, cyl};
  for (int i = 1; i <= 300; ++i) {
    StoredNode n;
    n.label = 1000 + 7 * i;
    n.definitionCs = i % 3 == 0 ? 3 : (i % 3 == 1 ? 0 : 4);
    n.displacementCs = i % 2 == 0 ? 3 : 0;
    n.position = Vector3(uni(rng), n.definitionCs == 4 ? 360.0 * uni(rng) : uni(rng), uni(rng) * 1e-3);
    d.mesh.nodes.push_back(n);
  }
  for (int i = 1; i < 300; ++i) {
    if (i % 97 == 0) continue;  // three breaks in the chain
    d.mesh.lines.push_back({d.mesh.nodes[i - 1].label, d.mesh.nodes[i].label});
  }
  d.mesh.lines.push_back({d.mesh.nodes[5].label, d.mesh.nodes[50].label});  // a stray segment
  d.mesh.faces = {{1007, 1014, 1021, 0}, {1028, 1035, 1042, 1049}};
  d.measurementDofs = {dof(1007, Direction::Z), dof(1014, Direction::X, true), dof(1021, Direction::RY)};
  d.slaves = {{dof(1028, Direction::Z), {{dof(1007, Direction::Z), 1.0 / 3.0}, {dof(1014, Direction::X), -0.7}}}};
  return d;
}

TEST(MeshUffExport, DoublePrecisionDatasetsReadBackToTheSameMesh) {
  const MeshDocument d = awkwardMesh();
  auto exported = meshToUff(d.mesh, {true, "awkward"});
  ASSERT_TRUE(exported.ok()) << exported.error().describe();
  EXPECT_EQ(exported->facesLeftOut, 2);
  int traces = 0;
  for (const auto* t : exported->file.all<uff::TraceLine82>()) {
    EXPECT_LE(t->nodes.size(), 250u);
    ++traces;
  }
  EXPECT_GE(traces, 2);
  auto bytes = uff::writeBytes(exported->file);
  ASSERT_TRUE(bytes.ok());
  auto file = uff::readBytes(*bytes);
  ASSERT_TRUE(file.ok()) << file.error().describe();
  EXPECT_TRUE(file->warnings.empty());
  auto back = meshFromUff(*file);
  ASSERT_TRUE(back.ok());
  StoredMesh expected = d.mesh;
  expected.faces.clear();  // no dataset for faces among 15/2411, 18/2420, 82
  EXPECT_TRUE(sameMesh(*back, expected));
  EXPECT_EQ(back->coordinateSystems[0].name, "fork leg, 12.5 deg");
}

TEST(MeshUffExport, SinglePrecisionDatasetsKeepSixDigits) {
  const MeshDocument d = awkwardMesh();
  auto exported = meshToUff(d.mesh, {false, ""});
  ASSERT_TRUE(exported.ok());
  auto bytes = uff::writeBytes(exported->file);
  ASSERT_TRUE(bytes.ok());
  ASSERT_NE(bytes->find("    15\n"), std::string::npos);
  ASSERT_NE(bytes->find("    18\n"), std::string::npos);
  auto back = meshFromUff(*uff::readBytes(*bytes));
  ASSERT_TRUE(back.ok());
  ASSERT_EQ(back->nodes.size(), d.mesh.nodes.size());
  for (std::size_t i = 0; i < d.mesh.nodes.size(); ++i) {
    // E13.5: 6 significant digits, relative error <= 5e-6 per coordinate.
    for (int k = 0; k < 3; ++k) {
      const double v = d.mesh.nodes[i].position[k];
      EXPECT_NEAR(back->nodes[i].position[k], v, 5e-6 * std::abs(v) + 1e-300);
    }
    EXPECT_EQ(back->nodes[i].label, d.mesh.nodes[i].label);
  }
  // Axes rebuilt from the 18 definition points: within the points' 6 digits.
  EXPECT_LT((back->coordinateSystems[0].rotation - d.mesh.coordinateSystems[0].rotation).norm(), 2e-5);
  EXPECT_EQ(back->lines.size(), d.mesh.lines.size());
}

TEST(MeshUffExport, NamesTheFormatCannotHoldAreRefused) {
  StoredMesh mesh;
  StoredCoordinateSystem cs;
  cs.label = 2;
  cs.name = std::string(41, 'x');
  mesh.coordinateSystems = {cs};
  EXPECT_TRUE(meshToUff(mesh, {true, ""}).ok());  // 2420 holds 80
  auto r = meshToUff(mesh, {false, ""});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "coordinate system 2");
}

// Every vendor file with nodes: the import gives the node count and first
// node of the reference reader (expected.json), and an export of that mesh
// reads back identically.
TEST(MeshUffExport, VendorGeometryImportsAsBeforeAndRoundTrips) {
  std::ifstream in(kData + "expected.json");
  const auto expected = nlohmann::json::parse(in);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kData)) {
    if (entry.path().extension() != ".uff") continue;
    auto mesh = importMeshUff(entry.path().string());
    ASSERT_TRUE(mesh.ok()) << entry.path() << ": " << mesh.error().describe();
    if (mesh->nodes.empty()) continue;
    ++files;
    const auto& info = expected.at(entry.path().filename().string());
    std::size_t nodeCount = 0;
    bool firstSeen = false;
    double lengthFactor = 1.0;  // 164: SI = file value / factor
    for (const auto& ds : info.at("sets"))
      if (ds.at("type") == 164) lengthFactor = ds.at("length").get<double>();
    for (const auto& ds : info.at("sets")) {
      if (ds.at("type") != 15 && ds.at("type") != 2411) continue;
      nodeCount += ds.at("num_nodes").get<std::size_t>();
      if (firstSeen) continue;
      firstSeen = true;
      // First node as the reference reader has it, in SI.
      EXPECT_EQ(mesh->nodes.front().label, ds.at("first_node").get<int>()) << entry.path();
      for (int k = 0; k < 3; ++k) {
        const double v = ds.at("first_xyz")[static_cast<std::size_t>(k)].get<double>() / lengthFactor;
        EXPECT_NEAR(mesh->nodes.front().position[k], v, 1e-12 * (1.0 + std::abs(v))) << entry.path();
      }
    }
    EXPECT_EQ(mesh->nodes.size(), nodeCount) << entry.path();
    auto exported = meshToUff(*mesh, {true, ""});
    ASSERT_TRUE(exported.ok()) << entry.path() << ": " << exported.error().describe();
    auto back = meshFromUff(*uff::readBytes(*uff::writeBytes(exported->file)));
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(sameMesh(*back, *mesh)) << entry.path();
  }
  EXPECT_GE(files, 3);
}

TEST(MeshCsv, WhatIsWrittenReadsBackIdentically) {
  const MeshDocument d = awkwardMesh();
  std::ostringstream out;
  ASSERT_TRUE(csv::writeMeshCsv(d, out).ok());
  auto back = csv::readMeshCsv(out.str(), "awkward.csv");
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_TRUE(sameDocument(*back, d));
  EXPECT_TRUE(geometry::validate(*back).ok());
}

TEST(MeshCsv, ForeignNodeTablesInMillimetres) {
  const std::string text =
      "\xEF\xBB\xBF# exported from a spreadsheet\r\n"
      "Node;X [mm];Y [mm];Z [mm]\r\n"
      "1;0;0;0\r\n"
      "2;250.5;0;-12\r\n";
  auto d = csv::readMeshCsv(text, "lab.csv");
  ASSERT_TRUE(d.ok()) << d.error().describe();
  ASSERT_EQ(d->mesh.nodes.size(), 2u);
  EXPECT_EQ(d->mesh.nodes[1].label, 2);
  EXPECT_NEAR(d->mesh.nodes[1].position.x(), 0.2505, 1e-15);
  EXPECT_NEAR(d->mesh.nodes[1].position.z(), -0.012, 1e-15);
}

TEST(MeshCsv, CylindricalAnglesAreNotScaledWithLengths) {
  const std::string text =
      "# mozzi-csv 1, mesh\n# section = coordinate-systems\n"
      "cs [1],type [1],origin x [mm],origin y [mm],origin z [mm],x axis x [1],x axis y [1],x axis z [1],"
      "y axis x [1],y axis y [1],y axis z [1],z axis x [1],z axis y [1],z axis z [1]\n"
      "5,1,0,0,0,1,0,0,0,1,0,0,0,1\n"
      "# section = nodes\nnode [1],cs [1],x [mm],y [mm],z [mm]\n7,5,300,45,20\n";
  auto d = csv::readMeshCsv(text, "cyl.csv");
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->mesh.nodes[0].position, Vector3(0.3, 45.0, 0.02));
}

TEST(MeshCsv, ErrorsNameFileLineAndColumn) {
  auto noUnit = csv::readMeshCsv("node,x,y [m],z [m]\n1,0,0,0\n", "a.csv");
  ASSERT_FALSE(noUnit.ok());
  EXPECT_EQ(noUnit.error().where, "a.csv:1, column 2");
  auto fraction = csv::readMeshCsv("node,x [m],y [m],z [m]\n1.5,0,0,0\n", "b.csv");
  ASSERT_FALSE(fraction.ok());
  EXPECT_EQ(fraction.error().where, "b.csv:2, column 1");
  auto section = csv::readMeshCsv("# section = elements\nnode a [1]\n1\n", "c.csv");
  ASSERT_FALSE(section.ok());
  EXPECT_EQ(section.error().where, "c.csv:1");
  auto kind = csv::readMeshCsv("# mozzi-csv 1, frf\nnode,x [m],y [m],z [m]\n1,0,0,0\n", "d.csv");
  ASSERT_FALSE(kind.ok());
  EXPECT_NE(kind.error().message.find("not a mesh"), std::string::npos);
  const std::string badDof =
      "# section = nodes\nnode,x [m],y [m],z [m]\n1,0,0,0\n# section = dofs\n"
      "node [1],direction [1]\n1,7\n";
  auto dofCode = csv::readMeshCsv(badDof, "e.csv");
  ASSERT_FALSE(dofCode.ok());
  EXPECT_EQ(dofCode.error().where, "e.csv:6, column 2");
  EXPECT_FALSE(csv::readMeshCsv("# only a comment\n", "f.csv").ok());
}

}  // namespace
}  // namespace mozzi::core::io
