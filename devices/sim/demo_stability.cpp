#include "devices/sim/demo_stability.h"

#include "core/io/project_store.h"
#include "core/stability/stability_record.h"

namespace mozzi::devices::sim {

namespace st = core::stability;

core::Result<void> addDemoStability(core::io::ProjectStore& store) {
  struct Sweep {
    const char* name;
    const char* specimen;  // the fork the sweep is about (virtual_specimens.cpp)
    st::StabilityRequest request;
  };
  // Bicycle 0-10 m/s every 0.05 m/s (Meijaard et al. 2007 Figure 3, thesis
  // Figure 51); motorcycle 1-60 m/s every 0.25 m/s (thesis Figure 33).
  const Sweep sweeps[] = {
      {"Benchmark bicycle, rigid fork",
       "Steel bicycle fork",
       {"bicycle", "rigid", std::nullopt, "", 0.0, 10.0, 0.05, false}},
      {"Benchmark bicycle, steel fork in bending against the rigid fork",
       "Steel bicycle fork",
       {"bicycle", "bending", std::nullopt, "", 0.0, 10.0, 0.05, true}},
      {"Sharp 1971 motorcycle, lumped fork model 1 against the rigid fork",
       "Fork A (enduro) with wheel",
       {"motorcycle", "model 1", std::nullopt, "", 1.0, 60.0, 0.25, true}},
  };
  for (const Sweep& s : sweeps) {
    auto record = st::computeStabilityRecord(s.request);
    if (!record) return record.error();
    auto specimen = st::specimenNamed(store, s.specimen);
    if (!specimen) return specimen.error();
    auto id = st::storeStabilityRecord(store, *specimen, s.name, *record);
    if (!id) return id.error();
  }
  return {};
}

}  // namespace mozzi::devices::sim
