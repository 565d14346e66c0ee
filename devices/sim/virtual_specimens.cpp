#include "devices/sim/virtual_specimens.h"

#include "core/geometry/mesh_templates.h"
#include "core/io/project_store.h"
#include "devices/campaign/demo_campaigns.h"
#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/demo_gap.h"
#include "devices/sim/demo_stability.h"

namespace mozzi::devices::sim {

const std::vector<VirtualSpecimen>& virtualSpecimens() {
  // Names and sources: thesis chapters 2 to 7.
  static const std::vector<VirtualSpecimen> kSpecimens = {
      {"Frame A",
       "frame",
       "thesis §2.1, Tables 3 and 4",
       {"frame-a-front-constrained", "frame-a-rear-constrained"},
       "motorcycle-frame-20"},
      {"Frame B",
       "frame",
       "thesis §2.1, Tables 3 and 4",
       {"frame-b-front-constrained", "frame-b-rear-constrained"},
       "motorcycle-frame-26"},
      {"Frame C without engine", "frame", "thesis §2.2, Table 5", {"frame-c-without-engine"}, "motorcycle-frame-22"},
      {"Frame C with engine",
       "frame",
       "thesis §2.2, Table 5",
       {"frame-c-with-engine"},
       "motorcycle-frame-22-engine-10"},
      {"Swing-arm A", "swing-arm", "thesis §3.1, Tables 6 and 7", {"swing-arm-a"}, "swing-arm-6"},
      {"Swing-arm B", "swing-arm", "thesis §3.2, Tables 8 and 9", {"swing-arm-b"}, "swing-arm-18"},
      {"Fork A (enduro) without wheel",
       "fork",
       "thesis §4.1, Tables 10 and 11",
       {"fork-a-without-wheel"},
       "motorcycle-fork-10"},
      {"Fork A (enduro) with wheel",
       "fork",
       "thesis §4.1, Tables 10, 11 and 12",
       {"fork-a-with-wheel"},
       "motorcycle-fork-10-wheel-8"},
      {"Fork B (super sport) without wheel",
       "fork",
       "thesis §4.3, Tables 13 and 14",
       {"fork-b-without-wheel"},
       "motorcycle-fork-10"},
      {"Fork B (super sport) with wheel",
       "fork",
       "thesis §4.3, Tables 13 and 14",
       {"fork-b-with-wheel"},
       "motorcycle-fork-10-wheel-8"},
      {"Tyre 120/70 R17 radial (front)", "tyre", "thesis ch. 5, Tables 15 to 17", {"tyre-120-70-r17"}, "tyre-6"},
      {"Tyre 180/55 R17 radial (rear)", "tyre", "thesis ch. 5, Tables 15 to 17", {"tyre-180-55-r17"}, "tyre-6"},
      {"Tyre 110/70-16 high-wheel scooter (front)",
       "tyre",
       "thesis ch. 5, Tables 15 to 17",
       {"tyre-110-70-16"},
       "tyre-6"},
      {"Tyre 140/70-14 high-wheel scooter (rear)",
       "tyre",
       "thesis ch. 5, Tables 15 to 17",
       {"tyre-140-70-14"},
       "tyre-6"},
      {"Tyre 120/70-12 scooter (front)", "tyre", "thesis ch. 5, Tables 15 to 17", {"tyre-120-70-12"}, "tyre-6"},
      {"Tyre 130/70-12 scooter (rear)", "tyre", "thesis ch. 5, Tables 15 to 17", {"tyre-130-70-12"}, "tyre-6"},
      {"Bicycle 1", "bicycle", "thesis §6.1, Table 18", {"bicycle-steel"}, "bicycle-9-12"},
      {"Bicycle 2", "bicycle", "thesis §6.1, Table 18", {"bicycle-ergal"}, "bicycle-9-12"},
      {"Bicycle 3", "bicycle", "thesis §6.1, Table 18", {"bicycle-carbon-monocoque"}, "bicycle-9-12"},
      {"Bicycle 4", "bicycle", "thesis §6.1, Table 18", {"bicycle-carbon-banded"}, "bicycle-9-12"},
      {"Carbon bicycle fork",
       "bicycle-fork",
       "thesis §6.2, §6.4, §6.5, Tables 19 to 21",
       {"bicycle-fork-carbon-without-wheel", "bicycle-fork-carbon-with-wheel"},
       "bicycle-fork-9-wheel-8"},
      {"Steel bicycle fork",
       "bicycle-fork",
       "thesis §6.3, §6.4, §6.5, Tables 19 to 21",
       {"bicycle-fork-steel-without-wheel", "bicycle-fork-steel-with-wheel"},
       "bicycle-fork-9-wheel-8"},
      {"Wheelchair tyres", "wheelchair-tyre", "thesis ch. 7, appendix 2", {}, ""},
  };
  return kSpecimens;
}

namespace {

// What the steps of the demo share: the open store and the id of each
// virtual specimen (same order as virtualSpecimens()).
struct DemoContext {
  core::io::ProjectStore& store;
  std::vector<std::int64_t> specimenIds;
};

using DemoStep = core::Result<void> (*)(DemoContext&);

// Step 1: every virtual specimen, with its measurement mesh.
core::Result<void> addSpecimensWithMeshes(DemoContext& demo) {
  for (const auto& specimen : virtualSpecimens()) {
    auto id =
        demo.store.addSpecimen(specimen.name, specimen.kind, "virtual specimen; parameters from " + specimen.source);
    if (!id) return id.error();
    demo.specimenIds.push_back(*id);
    if (specimen.meshTemplate.empty()) continue;
    const auto* mesh = core::geometry::findMeshTemplate(specimen.meshTemplate);
    if (!mesh)
      return core::makeError(core::ErrorCode::NotFound, "no mesh template " + specimen.meshTemplate,
                             "demo specimen " + specimen.name);
    auto stored = demo.store.setMesh(*id, mesh->mesh);
    if (!stored) return stored.error();
  }
  return {};
}

// Step 2: static and dynamic stiffness tests, relaxation and steady-state tyre tests.
core::Result<void> addRigAndTyreTests(DemoContext& demo) {
  return rigtests::addDemoRigTests(demo.store);
}

// Step 3: finished hammer campaigns (hits and FRF sets) on fork A with wheel and frame A.
core::Result<void> addHammerCampaigns(DemoContext& demo) {
  return campaign::addDemoCampaigns(demo.store);
}

// Step 4: the modes of those campaigns' FRF sets, identified and kept.
core::Result<void> addIdentifiedModes(DemoContext& demo) {
  return campaign::identifyDemoCampaigns(demo.store);
}

// Step 5: stability of the benchmark bicycle and of Sharp's motorcycle (devices/sim/demo_stability.cpp).
core::Result<void> addStability(DemoContext& demo) {
  return addDemoStability(demo.store);
}

// Step 6: a design model of fork A with wheel and its gap diagnosis against the campaign's FRFs.
core::Result<void> addModelAndGapDiagnosis(DemoContext& demo) {
  return addDemoGapDiagnosis(demo.store);
}

// The demo, in order; append a step to extend it.
const DemoStep kDemoSteps[] = {addSpecimensWithMeshes, addRigAndTyreTests, addHammerCampaigns,
                               addIdentifiedModes,     addStability,       addModelAndGapDiagnosis};

}  // namespace

core::Result<void> createDemoProject(const std::string& path, const std::string& mozziVersion) {
  auto store = core::io::ProjectStore::create(path, mozziVersion);
  if (!store) return store.error();
  DemoContext demo{*store, {}};
  for (DemoStep step : kDemoSteps) {
    auto done = step(demo);
    if (!done) return done.error();
  }
  return {};
}

}  // namespace mozzi::devices::sim
