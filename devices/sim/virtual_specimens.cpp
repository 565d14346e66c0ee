#include "devices/sim/virtual_specimens.h"

#include "core/io/project_store.h"
#include "devices/rigtests/virtual_rigs.h"

namespace mozzi::devices::sim {

const std::vector<VirtualSpecimen>& virtualSpecimens() {
  // Names and sources: thesis chapters 2 to 7.
  static const std::vector<VirtualSpecimen> kSpecimens = {
      {"Frame A", "frame", "thesis §2.1, Tables 3 and 4"},
      {"Frame B", "frame", "thesis §2.1, Tables 3 and 4"},
      {"Frame C without engine", "frame", "thesis §2.2, Table 5"},
      {"Frame C with engine", "frame", "thesis §2.2, Table 5"},
      {"Swing-arm A", "swing-arm", "thesis §3.1, Tables 6 and 7"},
      {"Swing-arm B", "swing-arm", "thesis §3.2, Tables 8 and 9"},
      {"Fork A (enduro) without wheel", "fork", "thesis §4.1, Tables 10 and 11"},
      {"Fork A (enduro) with wheel", "fork", "thesis §4.1, Tables 10, 11 and 12"},
      {"Fork B (super sport) without wheel", "fork", "thesis §4.3, Tables 13 and 14"},
      {"Fork B (super sport) with wheel", "fork", "thesis §4.3, Tables 13 and 14"},
      {"Tyre 120/70 R17 radial (front)", "tyre", "thesis ch. 5, Tables 15 to 17"},
      {"Tyre 180/55 R17 radial (rear)", "tyre", "thesis ch. 5, Tables 15 to 17"},
      {"Tyre 110/70-16 high-wheel scooter (front)", "tyre", "thesis ch. 5, Tables 15 to 17"},
      {"Tyre 140/70-14 high-wheel scooter (rear)", "tyre", "thesis ch. 5, Tables 15 to 17"},
      {"Tyre 120/70-12 scooter (front)", "tyre", "thesis ch. 5, Tables 15 to 17"},
      {"Tyre 130/70-12 scooter (rear)", "tyre", "thesis ch. 5, Tables 15 to 17"},
      {"Bicycle 1", "bicycle", "thesis §6.1, Table 18"},
      {"Bicycle 2", "bicycle", "thesis §6.1, Table 18"},
      {"Bicycle 3", "bicycle", "thesis §6.1, Table 18"},
      {"Bicycle 4", "bicycle", "thesis §6.1, Table 18"},
      {"Carbon bicycle fork", "bicycle-fork", "thesis §6.2, §6.4, §6.5, Tables 19 to 21"},
      {"Steel bicycle fork", "bicycle-fork", "thesis §6.3, §6.4, §6.5, Tables 19 to 21"},
      {"Wheelchair tyres", "wheelchair-tyre", "thesis ch. 7, appendix 2"},
  };
  return kSpecimens;
}

core::Result<void> createDemoProject(const std::string& path, const std::string& mozziVersion) {
  auto store = core::io::ProjectStore::create(path, mozziVersion);
  if (!store) return store.error();
  for (const auto& specimen : virtualSpecimens()) {
    auto id = store->addSpecimen(specimen.name, specimen.kind, "virtual specimen; parameters from " + specimen.source);
    if (!id) return id.error();
  }
  // Static and dynamic stiffness tests, relaxation and steady-state tyre tests.
  if (auto r = rigtests::addDemoRigTests(*store); !r) return r.error();
  return {};
}

}  // namespace mozzi::devices::sim
