#pragma once
// The catalogue of virtual specimens the simulated rigs run on: every
// component of thesis chapters 2 to 6 with the numbers the thesis tabulates and
// where each comes from. One data table (specimen_catalogue.cpp) feeds the
// modal models of the hammer station, the static models of the stiffness rig
// and the tyres of the tyre tester.
//
// Modal data: Tables 6, 8 (swing-arms, hysteretic eta), 11, 14 (forks, viscous
// zeta), 18 (bicycles, eta), 19, 20 (bicycle forks, eta), the frame
// frequencies of §2.1 and §2.2 (text, damping not given: 2% assumed) and the
// tyre ring modes of Table 16 (C_k with the assumed tyre mass of
// core/tire/thesis_tyres.h, eq. 45-46, damping 3% assumed). Hysteretic eta
// enters the viscous models as zeta = eta / 2 (reference/notes.md, §6.4).
// Static data: Tables 3, 4 (frames A, B), 5 (frame C), 7, 9 (swing-arms),
// 10, 13 (forks).

#include <optional>
#include <string>
#include <vector>

namespace mozzi::devices::sim {

enum class DampingMeasure {
  Viscous,     // zeta as tabulated (Tables 11, 14)
  Hysteretic,  // eta as tabulated (Tables 6, 8, 18, 19, 20); zeta = eta / 2
  Assumed,     // not tabulated; zeta assumed (frames 2%, tyres 3%)
};
const char* dampingMeasureName(DampingMeasure m);

struct CatalogueMode {
  double frequencyHz = 0.0;
  double damping = 0.0;  // as tabulated: zeta, eta or the assumed zeta (fraction, not %)
  std::string shape;     // the table's description ("Lateral", "Torsional", ...)
};

struct StaticProperties {
  double lateralStiffness = 0.0;              // k_lat [N/m]
  double twistArm = 0.0;                      // a_tw [m] (Table 5: sqrt(k_tw / k_lat), the arm is not printed)
  double twistStiffness = 0.0;                // k_tw as printed [Nm/rad]
  double bendArm = 0.0, bendStiffness = 0.0;  // 0 where not tabulated
  double torsArm = 0.0, torsStiffness = 0.0;
  double inclinationDeg = 30.0;  // twist axis from the plate's v axis (forks: Tables 10, 13)
  bool inclinationTabulated = false;
  double testForceN = 300.0;  // peak of the thesis's static ramp (±300 N, fork B ±500 N)
};

struct SpecimenEntry {
  std::string key;   // "fork-a-without-wheel"
  std::string name;  // "Fork A (enduro) without wheel"
  std::string kind;  // frame, swing-arm, fork, tyre, bicycle, bicycle-fork
  std::string modalSource;
  DampingMeasure damping = DampingMeasure::Viscous;
  std::vector<CatalogueMode> modes;
  std::string staticSource;  // empty without static data
  std::optional<StaticProperties> statics;
  // Modal mass per mode [kg], shapes scaled to a largest component of 1, when
  // there is no static stiffness to fix it (tyres: ring m_k of eq. 45, the
  // largest component being point 100; forks without wheel a quarter of the
  // fork's mass; bicycles 5 kg, bicycle forks 0.5 or 1.5 kg, assumed); empty
  // with static data (then the modal model's static compliance is 1/k_lat).
  std::vector<double> modalMass;

  double zeta(std::size_t mode) const;  // viscous damping ratio of the model
};

// Every specimen, in thesis order (frames, swing-arms, forks, tyres, bicycles,
// bicycle forks).
const std::vector<SpecimenEntry>& specimenCatalogue();
const SpecimenEntry* findSpecimen(const std::string& key);
std::vector<std::string> specimenKeys();        // every key
std::vector<std::string> staticSpecimenKeys();  // keys with static data
std::vector<std::string> tyreSpecimenKeys();    // kind "tyre"

}  // namespace mozzi::devices::sim
