// The demo project: every virtual specimen with the measurement mesh of its
// thesis set-up, so the 3-D view shows it; each names the catalogue specimens
// (constraints, with/without wheel) the simulated rigs run it as.
#include "devices/sim/virtual_specimens.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "core/geometry/mesh_templates.h"
#include "core/io/project_store.h"
#include "devices/sim/specimen_catalogue.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::sim {
namespace {

TEST(VirtualSpecimens, EachNamesItsCatalogueEntriesAndMesh) {
  for (const auto& v : virtualSpecimens()) {
    SCOPED_TRACE(v.name);
    if (v.kind == "wheelchair-tyre") {
      EXPECT_TRUE(v.catalogueKeys.empty());
      EXPECT_TRUE(v.meshTemplate.empty());
      continue;
    }
    ASSERT_FALSE(v.catalogueKeys.empty());
    const auto* mesh = core::geometry::findMeshTemplate(v.meshTemplate);
    ASSERT_NE(mesh, nullptr) << v.meshTemplate;
    for (const auto& key : v.catalogueKeys) {
      const SpecimenEntry* e = findSpecimen(key);
      ASSERT_NE(e, nullptr) << key;
      EXPECT_EQ(e->kind, v.kind) << key;
      // The stored mesh holds every node of the mesh the specimen is
      // simulated on (with and without the wheel: the larger one).
      const auto* own = core::geometry::findMeshTemplate(meshTemplateKey(key));
      ASSERT_NE(own, nullptr) << key;
      for (const auto& n : own->mesh.nodes) {
        const auto* stored = mesh->node(n.label);
        ASSERT_NE(stored, nullptr) << key << " node " << n.label;
        EXPECT_EQ(stored->position, n.position);
      }
    }
  }
}

TEST(VirtualSpecimens, TheDemoProjectStoresEveryMeshQuickly) {
  const auto path = std::filesystem::temp_directory_path() / ("mozzi_demo_" + std::to_string(::getpid()) + ".mozzi");
  std::filesystem::remove(path);
  const auto start = std::chrono::steady_clock::now();
  auto created = createDemoProject(path.string(), "test");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(created.ok()) << created.error().describe();
  std::printf("demo project created in %.3f s\n", seconds);
  // Speed is measured, not asserted here: with the demo campaigns (228
  // simulated hits) it took 13.6 s wall on an idle 2-core machine
  // (`/usr/bin/time -v mozzi-cli project demo`, docs/performance/campaign.md).
  EXPECT_FALSE(createDemoProject(path.string(), "test").ok()) << "an existing file is not overwritten";

  auto store = core::io::ProjectStore::open(path.string(), core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto summary = store->summary();
  ASSERT_TRUE(summary.ok());
  ASSERT_EQ(summary->specimens.size(), virtualSpecimens().size());
  for (std::size_t i = 0; i < virtualSpecimens().size(); ++i) {
    const auto& v = virtualSpecimens()[i];
    const auto& s = summary->specimens[i];
    EXPECT_EQ(s.name, v.name);
    auto mesh = store->mesh(s.id);
    ASSERT_TRUE(mesh.ok()) << v.name;
    if (v.meshTemplate.empty()) {
      EXPECT_TRUE(mesh->nodes.empty()) << v.name;
      continue;
    }
    const auto* t = core::geometry::findMeshTemplate(v.meshTemplate);
    ASSERT_EQ(mesh->nodes.size(), t->mesh.nodes.size()) << v.name;
    EXPECT_EQ(mesh->lines.size(), t->mesh.lines.size()) << v.name;
    EXPECT_EQ(mesh->faces.size(), t->mesh.faces.size()) << v.name;
    for (const auto& n : mesh->nodes) {
      const auto* tn = t->node(n.label);
      ASSERT_NE(tn, nullptr) << v.name << " node " << n.label;
      EXPECT_TRUE(n.position.isApprox(tn->position, 1e-12)) << v.name << " node " << n.label;
    }
  }
  std::filesystem::remove(path);
  std::filesystem::remove(path.string() + "-wal");
  std::filesystem::remove(path.string() + "-shm");
}

}  // namespace
}  // namespace mozzi::devices::sim
