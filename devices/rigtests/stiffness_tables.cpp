#include "devices/rigtests/stiffness_tables.h"

#include <cmath>

#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::rigtests {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The constraint a catalogue entry names: the words after its comma ("Frame
// A, front-constrained"); forks were tested with the steering head locked to
// the rig's column (thesis chapter 4).
std::string constraintOf(const sim::SpecimenEntry& e) {
  const auto comma = e.name.find(", ");
  if (comma != std::string::npos) return e.name.substr(comma + 2);
  if (e.kind == "fork") return "steering head locked";
  return {};
}

// The thesis's printed values of a catalogue entry, by row key (SI).
std::map<std::string, double> thesisValues(const sim::StaticProperties& p) {
  std::map<std::string, double> t{{"k_lat", p.lateralStiffness}, {"k_tw", p.twistStiffness}};
  // Table 5 (frame C) prints the stiffnesses but no arm: the catalogue derives
  // its a_tw = sqrt(k_tw / k_lat) for the rig model; that is not the thesis's.
  if (p.bendArm > 0 || p.torsArm > 0) t["a_tw"] = p.twistArm;
  if (p.bendStiffness > 0) t["k_bend"] = p.bendStiffness;
  if (p.torsStiffness > 0) t["k_tors"] = p.torsStiffness;
  if (p.bendArm > 0) t["a_bend"] = p.bendArm;
  if (p.torsArm > 0) t["a_tors"] = p.torsArm;
  if (p.inclinationTabulated) t["axis_inclination"] = p.inclinationDeg * kDegree;
  return t;
}

}  // namespace

const std::vector<StiffnessRowSpec>& stiffnessRows() {
  static const std::vector<StiffnessRowSpec> rows = {
      {"k_lat", "Lateral stiffness", "N/m"},      {"a_tw", "Twist arm", "m"},
      {"k_tw", "Twist stiffness", "N m/rad"},     {"a_bend", "Bending arm", "m"},
      {"k_bend", "Bending stiffness", "N m/rad"}, {"a_tors", "Torsion arm", "m"},
      {"k_tors", "Torsion stiffness", "N m/rad"}, {"axis_inclination", "Inclination of the twist axis", "rad"},
  };
  return rows;
}

core::Result<std::vector<StiffnessColumn>> stiffnessColumns(const core::io::ProjectStore& store,
                                                            std::vector<std::string>* skipped) {
  auto tests = store.rigTests();
  if (!tests) return tests.error();
  auto summary = store.summary();
  if (!summary) return summary.error();
  std::vector<StiffnessColumn> out;
  for (const auto& specimen : summary->specimens) {
    for (const auto& info : *tests) {
      if (info.specimenId != specimen.id || info.kind != "static") continue;
      auto view = readStiffnessTest(store, info.id);
      if (!view) {
        if (skipped) skipped->push_back(info.specimenName + " / " + info.name + ": " + view.error().message);
        continue;
      }
      StiffnessColumn c;
      c.testId = info.id;
      c.specimenId = info.specimenId;
      c.specimenName = info.specimenName;
      c.testName = info.name;
      c.status = info.status;
      c.statusNote = info.statusNote;
      for (const auto& row : stiffnessRows()) {
        if (const auto* q = view->result(row.key)) c.measured[row.key] = *q;
      }
      const sim::SpecimenEntry* entry =
          view->specimenKey.empty() ? catalogueEntryForName(specimen.name) : sim::findSpecimen(view->specimenKey);
      if (entry) {
        c.catalogueKey = entry->key;
        c.constraint = constraintOf(*entry);
        if (entry->statics) {
          c.thesis = thesisValues(*entry->statics);
          c.thesisSource = entry->staticSource;
        }
      }
      out.push_back(std::move(c));
    }
  }
  return out;
}

std::optional<double> thesisDeviation(const StiffnessColumn& column, const std::string& key) {
  const auto m = column.measured.find(key);
  const auto t = column.thesis.find(key);
  if (m == column.measured.end() || t == column.thesis.end() || !(std::abs(t->second) > 0)) return std::nullopt;
  return (m->second.value - t->second) / std::abs(t->second);
}

}  // namespace mozzi::devices::rigtests
