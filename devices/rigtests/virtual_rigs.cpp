#include "devices/rigtests/virtual_rigs.h"

#include "core/io/project_store.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/tyre_tests.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::rigtests {

const sim::SpecimenEntry* catalogueEntryForName(const std::string& name) {
  for (const auto& e : sim::specimenCatalogue())
    if (e.name == name) return &e;
  for (const auto& e : sim::specimenCatalogue())
    if (e.name.rfind(name + ",", 0) == 0) return &e;  // "Frame A" -> "Frame A, front-constrained"
  for (const auto& e : sim::specimenCatalogue()) {
    if (e.kind != "tyre") continue;
    // "Tyre 120/70 R17 (motorcycle front)": the size is the words between "Tyre " and " (".
    const auto open = e.name.find(" (");
    const std::string size = e.name.substr(5, open == std::string::npos ? std::string::npos : open - 5);
    if (name.find(size) != std::string::npos) return &e;
  }
  return nullptr;
}

core::Result<SpecimenChoice> resolveSpecimen(core::io::ProjectStore& store, const std::string& text) {
  auto summary = store.summary();
  if (!summary) return summary.error();
  SpecimenChoice c;
  if (const auto* e = sim::findSpecimen(text)) {
    c.catalogueKey = e->key;
    for (const auto& s : summary->specimens) {
      const auto* m = catalogueEntryForName(s.name);
      if (m && m->key == e->key) {
        c.specimenId = s.id;
        c.projectName = s.name;
        return c;
      }
    }
    auto id = store.addSpecimen(e->name, e->kind,
                                "virtual specimen " + e->key + "; parameters from " +
                                    (e->staticSource.empty() ? e->modalSource : e->staticSource));
    if (!id) return id.error();
    c.specimenId = *id;
    c.projectName = e->name;
    c.created = true;
    return c;
  }
  for (const auto& s : summary->specimens) {
    if (s.name != text) continue;
    const auto* m = catalogueEntryForName(s.name);
    if (!m)
      return core::makeError(core::ErrorCode::NotFound,
                             "the project specimen '" + text +
                                 "' stands for no virtual specimen the simulated rigs know (see mozzi-cli rig list)",
                             "--specimen");
    c.catalogueKey = m->key;
    c.specimenId = s.id;
    c.projectName = s.name;
    return c;
  }
  return core::makeError(core::ErrorCode::NotFound,
                         "'" + text +
                             "' is neither a virtual specimen key (mozzi-cli rig list) nor a specimen of the "
                             "project (mozzi-cli project info)",
                         "--specimen");
}

namespace {

// The demo's tests, into `store` (see addDemoRigTests).
core::Result<void> addDemoTests(core::io::ProjectStore& store) {
  auto stiffness = [&](const std::string& key, std::uint64_t seed,
                       const std::vector<double>& frequencies) -> core::Result<void> {
    auto who = resolveSpecimen(store, key);
    if (!who) return who.error();
    auto setup = simulatedStiffnessSetup(key, seed, false);
    if (!setup) return setup.error();
    auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
    if (!dev) return dev.error();
    StaticTestSettings st;
    st.peakForceN = sim::findSpecimen(key)->statics->testForceN;
    auto s = runStaticStiffnessTest(**dev, nullptr, *setup, st, StoreTarget{&store, who->specimenId, "static test"});
    if (!s) return s.error();
    DynamicTestSettings dy;
    dy.frequenciesHz = frequencies;
    dy.amplitudeN = st.peakForceN;
    auto d = runDynamicStiffnessTest(**dev, nullptr, *setup, dy, StoreTarget{&store, who->specimenId, "dynamic test"});
    if (!d) return d.error();
    return {};
  };
  // Fork A with wheel: the thesis swept 1 to 15 Hz (§4.1, Fig. 29); above,
  // its lateral mode at 22.3 Hz drives the lasers out of range at 300 N.
  if (auto r = stiffness("fork-a-with-wheel", 20, {1, 3, 5, 8, 10, 12, 15}); !r) return r;
  if (auto r = stiffness("frame-a-front-constrained", 21, {1, 5, 10, 15, 20}); !r) return r;

  const std::string tyre = "tyre-120-70-r17";
  auto who = resolveSpecimen(store, tyre);
  if (!who) return who.error();
  auto setup = simulatedTyreSetup(tyre, 2.0, 22, false);
  if (!setup) return setup.error();
  auto dev = sim::makeTyreTesterDriver()->create(DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"});
  if (!dev) return dev.error();
  auto rel = runRelaxationTest(**dev, *setup, RelaxationSettings{}, StoreTarget{&store, who->specimenId, "relaxation"});
  if (!rel) return rel.error();
  auto ss =
      runSteadyStateTest(**dev, *setup, SteadyStateSettings{}, StoreTarget{&store, who->specimenId, "steady state"});
  if (!ss) return ss.error();
  return {};
}

}  // namespace

core::Result<void> addDemoRigTests(core::io::ProjectStore& store) {
  // Generated data: no fsync per step (about 60 commits), full durability again after.
  if (auto r = store.setPowerLossDurable(false); !r) return r;
  auto tests = addDemoTests(store);
  if (auto r = store.setPowerLossDurable(true); !r) return r;
  return tests;
}

}  // namespace mozzi::devices::rigtests
