// The demo project: every virtual specimen with the measurement mesh of its
// thesis set-up, so the 3-D view shows it; each names the catalogue specimens
// (constraints, with/without wheel) the simulated rigs run it as.
#include "devices/sim/virtual_specimens.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/geometry/mesh_templates.h"
#include "core/io/project_store.h"
#include "devices/campaign/demo_campaigns.h"
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

  // The demo campaigns' modes, identified and kept (one modal result per
  // campaign): every catalogued mode of the specimen found within 1% in
  // frequency (the campaigns' noise and 2048 Hz sampling; the validation
  // test devices_campaign_identify finds them within 0.02%), each with a
  // positive damping once the exponential window's decay is removed.
  auto results = store->modalResults();
  ASSERT_TRUE(results.ok());
  ASSERT_EQ(results->size(), 2u);
  for (const auto& info : *results) {
    ASSERT_TRUE(info.frfSetId.has_value());
    std::string specimenName;
    for (const auto& s : summary->specimens)
      if (s.id == info.specimenId) specimenName = s.name;
    std::string key;  // the catalogue entry the demo campaign ran the specimen as
    for (const auto& c : campaign::demoCampaigns())
      if (c.specimenName == specimenName) key = c.specimenKey;
    const SpecimenEntry* entry = nullptr;
    for (const auto& e : specimenCatalogue())
      if (e.key == key) entry = &e;
    ASSERT_NE(entry, nullptr) << specimenName;
    auto modes = store->modalResult(info.id);
    ASSERT_TRUE(modes.ok());
    for (const auto& truth : entry->modes) {
      const core::io::StoredMode* nearest = nullptr;
      for (const auto& m : modes->modes)
        if (!nearest ||
            std::abs(m.frequencyHz - truth.frequencyHz) < std::abs(nearest->frequencyHz - truth.frequencyHz))
          nearest = &m;
      ASSERT_NE(nearest, nullptr) << specimenName;
      EXPECT_NEAR(nearest->frequencyHz, truth.frequencyHz, 0.01 * truth.frequencyHz) << specimenName;
      EXPECT_GT(nearest->dampingRatio, 0.0) << specimenName;
    }
  }

  // Step 6: the design model of fork A with wheel and its stored gap
  // diagnosis against the campaign's FRF set. The overlay's measured curve is
  // the stored FRF set read back here (|H| at the same lines, to the 1e-9
  // relative of the JSON's 17 digits), so the report draws what was measured.
  auto analyses = store->analyses();
  ASSERT_TRUE(analyses.ok());
  std::vector<core::io::StoredAnalysis> diagnoses;
  for (const auto& a : *analyses)
    if (a.kind == "gap-diagnosis") diagnoses.push_back(a);
  ASSERT_EQ(diagnoses.size(), 1u);
  const auto& gap = diagnoses.front();
  EXPECT_EQ(gap.kind, "gap-diagnosis");
  ASSERT_TRUE(gap.modelId && gap.frfSetId && gap.modalResultId);
  EXPECT_FALSE(gap.findings.empty());
  for (const auto& f : gap.findings) {
    EXPECT_GE(f.remainingGap, 0.0);
    EXPECT_LE(f.remainingGap, 1.0);
    EXPECT_LT(f.bandLowHz, f.bandHighHz);
  }
  const auto json = nlohmann::json::parse(gap.resultJson);
  ASSERT_TRUE(json.contains("verdict") && json["verdict"].is_string());
  ASSERT_TRUE(json["overlay"].is_array() && !json["overlay"].empty());
  auto frf = store->frfSet(*gap.frfSetId);
  ASSERT_TRUE(frf.ok());
  const auto& curve = json["overlay"][0];
  const auto x = curve["x"].get<std::vector<double>>();
  const auto measured = curve["measured"].get<std::vector<double>>();
  ASSERT_EQ(x.size(), measured.size());
  ASSERT_LE(x.size(), 401u);  // thinned to at most 400 points (+ the last)
  // The curve is one FRF "response / reference" of the set: find the column
  // whose |H| matches at the first line, then check every point.
  int matched = -1;
  for (std::size_t i = 0; i < frf->h.size() && matched < 0; ++i)
    for (Eigen::Index o = 0; o < frf->responseCount(); ++o) {
      bool all = true;
      for (std::size_t k = 0; k < x.size() && all; ++k) {
        Eigen::Index line = 0;
        while (line < frf->lineCount() && std::abs(frf->frequencyHz[line] - x[k]) > 1e-9 * (1 + x[k])) ++line;
        all = line < frf->lineCount() &&
              std::abs(std::abs(frf->h[i](line, o)) - measured[k]) <= 1e-9 * std::abs(measured[k]);
      }
      if (all) matched = static_cast<int>(o);
    }
  EXPECT_GE(matched, 0) << "the overlay's measured curve is not an FRF of the stored set";
  bool modelStored = false;
  for (const auto& s : summary->specimens)
    if (s.id == gap.specimenId) modelStored = s.name == "Fork A (enduro) with wheel";
  EXPECT_TRUE(modelStored);

  std::filesystem::remove(path);
  std::filesystem::remove(path.string() + "-wal");
  std::filesystem::remove(path.string() + "-shm");
}

}  // namespace
}  // namespace mozzi::devices::sim
