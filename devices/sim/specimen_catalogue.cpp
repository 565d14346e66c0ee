#include "devices/sim/specimen_catalogue.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/tire/ring_model.h"
#include "core/tire/thesis_tyres.h"

namespace mozzi::devices::sim {

const char* dampingMeasureName(DampingMeasure m) {
  switch (m) {
    case DampingMeasure::Viscous: return "viscous zeta";
    case DampingMeasure::Hysteretic: return "hysteretic eta";
    case DampingMeasure::Assumed: return "assumed zeta";
  }
  return "?";
}

double SpecimenEntry::zeta(std::size_t mode) const {
  const double d = modes.at(mode).damping;
  return damping == DampingMeasure::Hysteretic ? 0.5 * d : d;
}

namespace {

// Frames: damping is not tabulated (§2.1, §2.2 give the frequencies in the text).
constexpr double kAssumedFrameZeta = 0.02;

StaticProperties statics(double kLat, double arm, double kTw, double bendArm, double kBend, double torsArm,
                         double kTors, double forceN = 300.0) {
  StaticProperties s;
  s.lateralStiffness = kLat;
  s.twistArm = arm;
  s.twistStiffness = kTw;
  s.bendArm = bendArm;
  s.bendStiffness = kBend;
  s.torsArm = torsArm;
  s.torsStiffness = kTors;
  s.testForceN = forceN;
  return s;
}

StaticProperties forkStatics(double kLat, double arm, double kTw, double bendArm, double kBend, double torsArm,
                             double kTors, double inclinationDeg, double forceN) {
  StaticProperties s = statics(kLat, arm, kTw, bendArm, kBend, torsArm, kTors, forceN);
  s.inclinationDeg = inclinationDeg;
  s.inclinationTabulated = true;
  return s;
}

SpecimenEntry frame(const char* key, const char* name, const char* modalSource, std::vector<double> f,
                    const char* staticSource, StaticProperties st) {
  SpecimenEntry e{key, name, "frame", modalSource, DampingMeasure::Assumed, {}, staticSource, st, {}};
  const char* shapes[] = {"Lateral", "Longitudinal", "Torsional"};
  for (std::size_t i = 0; i < f.size(); ++i)
    e.modes.push_back({f[i], kAssumedFrameZeta, f.size() == 2 && i == 1 ? "Torsional" : shapes[i]});
  return e;
}

// Forks without the wheel have no static test to fix their modal masses: a
// quarter of the fork's mass per mode (fork A 12.1 kg, fork B 14.3 kg,
// chapter 4), the modal mass of a uniform cantilever's first mode with the
// shape normalised to 1 at the tip (assumed).
std::vector<double> forkModalMass(double forkMassKg) {
  return std::vector<double>(3, 0.25 * forkMassKg);
}

std::string tyreKey(const std::string& size) {
  std::string k = "tyre-";
  for (char c : size) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (k.back() != '-')
      k += '-';
  }
  return k;  // "120/70 R17" -> "tyre-120-70-r17"
}

// The ring modes of Table 16 (k = 1 camber, 0 lateral, 2 C-shaped, 3 S-shaped)
// through eq. 45-46 with the assumed tyre mass: f_k = sqrt(C_k / m_k) / 2 pi.
SpecimenEntry tyre(const core::tire::ThesisTyre& t) {
  SpecimenEntry e;
  e.key = tyreKey(t.size);
  e.name = "Tyre " + t.size + " (" + t.use + ")";
  e.kind = "tyre";
  e.modalSource =
      "thesis Table 16 (C_k at 2 bar) with the assumed tyre mass of core/tire/thesis_tyres.h, eq. 45-46; damping 3% "
      "assumed";
  e.damping = DampingMeasure::Assumed;
  const double c[] = {t.lateralStiffness, t.camberStiffness, t.cShapedStiffness, t.sShapedStiffness};
  std::vector<core::tire::RingStiffnessInput> in;
  for (int k = 0; k < 4; ++k) in.push_back({k, c[k], core::tire::kAssumedDampingRatio});
  auto ring = core::tire::ringModelFromStiffness(in, core::tire::RingModelSettings{t.tyreMass, 0.8, t.outerRadius});
  if (ring) {
    for (const auto& m : ring->modes) {
      e.modes.push_back({m.naturalFrequencyHz, m.dampingRatio, m.name});
      e.modalMass.push_back(m.modalMass);
    }
  }
  return e;
}

std::vector<SpecimenEntry> buildCatalogue() {
  using D = DampingMeasure;
  std::vector<SpecimenEntry> c;
  // ---- frames (chapter 2): modes from the text, statics from Tables 3, 4, 5.
  c.push_back(frame("frame-a-front-constrained", "Frame A, front-constrained", "thesis §2.1 (text; damping 2% assumed)",
                    {26.5, 56.8, 77.0}, "thesis Tables 3 and 4",
                    statics(167e3, 0.551, 50.8e3, 0.556, 52.1e3, 0.032, 22.0e3)));
  c.push_back(frame("frame-a-rear-constrained", "Frame A, rear-constrained", "thesis §2.1 (text; damping 2% assumed)",
                    {43.0, 109.8}, "thesis Tables 3 and 4",
                    statics(253e3, 0.475, 57.0e3, 0.458, 53.5e3, 0.026, 19.6e3)));
  c.push_back(frame("frame-b-front-constrained", "Frame B, front-constrained", "thesis §2.1 (text; damping 2% assumed)",
                    {35.0, 42.0}, "thesis Tables 3 and 4",
                    statics(272e3, 0.689, 129e3, 0.553, 138.3e3, 0.298, 60.4e3)));
  c.push_back(frame("frame-b-rear-constrained", "Frame B, rear-constrained", "thesis §2.1 (text; damping 2% assumed)",
                    {36.2, 116.0}, "thesis Tables 3 and 4",
                    statics(238e3, 0.498, 59.1e3, 0.510, 64.3e3, 0.097, 60.2e3)));
  // Table 5 prints k_lat and k_tw but no arms: a_tw = sqrt(k_tw / k_lat) (eq. 30).
  c.push_back(frame("frame-c-without-engine", "Frame C without engine", "thesis §2.2 (text; damping 2% assumed)",
                    {42.2, 109.2}, "thesis Table 5",
                    statics(361e3, std::sqrt(260.2e3 / 361e3), 260.2e3, 0.0, 358.6e3, 0.0, 58.4e3)));
  c.push_back(frame("frame-c-with-engine", "Frame C with engine", "thesis §2.2 (text; damping 2% assumed)",
                    {17.6, 68.7}, "thesis Table 5",
                    statics(539e3, std::sqrt(414.6e3 / 539e3), 414.6e3, 0.0, 522.9e3, 0.0, 104e3)));
  // ---- swing-arms (chapter 3). Load on the wheel hub; the thesis gives no
  // force range for them: 1000 N assumed (stiffer than the frames).
  c.push_back({"swing-arm-a",
               "Swing-arm A",
               "swing-arm",
               "thesis Table 6",
               D::Hysteretic,
               {{115.0, 0.0173, "Bending"}, {184.0, 0.0102, "Torsional"}},
               "thesis Table 7",
               statics(623e3, 0.375, 87.6e3, 0.388, 94.2e3, 0.025, 98.8e3, 1000.0),
               {}});
  // Table 9 prints 1083 N/m: it is kN/m (1083e3 x 0.477^2 = 246.4 kNm/rad, reference/notes.md).
  c.push_back({"swing-arm-b",
               "Swing-arm B",
               "swing-arm",
               "thesis Table 8",
               D::Hysteretic,
               {{134.0, 0.0074, "Bending"}, {208.0, 0.0097, "Torsional"}},
               "thesis Table 9",
               statics(1083e3, 0.477, 246.4e3, 0.451, 222.4e3, 0.026, 77.4e3, 1000.0),
               {}});
  // ---- forks (chapter 4). The static tests loaded the lowest point of the
  // wheel, so the static data belong to the "with wheel" specimens. Simple-
  // method arms and stiffnesses (Table 10 left column; 13).
  c.push_back({"fork-a-without-wheel",
               "Fork A (enduro) without wheel",
               "fork",
               "thesis Table 11 (left)",
               D::Viscous,
               {{38.6, 0.022, "Lateral"}, {41.2, 0.018, "Longitudinal"}, {67.1, 0.036, "Torsional"}},
               "",
               std::nullopt,
               forkModalMass(12.1)});
  c.push_back({"fork-a-with-wheel",
               "Fork A (enduro) with wheel",
               "fork",
               "thesis Table 11 (right)",
               D::Viscous,
               {{22.3, 0.024, "Lateral"}, {23.5, 0.014, "Longitudinal"}, {67.2, 0.059, "Wheel"}},
               "thesis Table 10",
               forkStatics(56.1e3, 0.517, 15e3, 0.67, 28e3, 0.066, 3e3, 45.5, 300.0),
               {}});
  c.push_back({"fork-b-without-wheel",
               "Fork B (super sport) without wheel",
               "fork",
               "thesis Table 14 (left)",
               D::Viscous,
               {{42.0, 0.020, "Lateral"}, {49.4, 0.075, "Longitudinal"}, {63.4, 0.076, "Torsional"}},
               "",
               std::nullopt,
               forkModalMass(14.3)});
  // Table 13 prints "22 kNm 7 rad": 22 kNm/rad.
  c.push_back({"fork-b-with-wheel",
               "Fork B (super sport) with wheel",
               "fork",
               "thesis Table 14 (right)",
               D::Viscous,
               {{23.7, 0.030, "Lateral"}, {27.5, 0.023, "Longitudinal"}, {74.4, 0.047, "Wheel"}},
               "thesis Table 13",
               forkStatics(109.3e3, 0.452, 22e3, 0.528, 35e3, 0.083, 6e3, 41.2, 500.0),
               {}});
  // ---- tyres (chapter 5).
  for (const auto& t : core::tire::thesisTyres()) c.push_back(tyre(t));
  // ---- bicycles (§6.1, Table 18; eta). The banded carbon bicycle has no
  // seventh common mode.
  const char* bikeShapes[] = {"Tire dominated - Yaw", "Tire dominated - Roll", "Torsion",
                              "First bending",        "Fork lateral",          "Second bending",
                              "Seat tube, rear frame"};
  struct Bike {
    const char* key;
    const char* name;
    std::vector<double> f, eta;
  };
  const Bike bikes[] = {
      {"bicycle-steel", "Bicycle 1 (steel)", {11, 17, 24.1, 33.9, 41.6, 64.1, 66.5}, {8.5, 5.3, 5.7, 3.7, 1.7, 4, 2.7}},
      {"bicycle-ergal",
       "Bicycle 2 (ergal)",
       {12.8, 18.5, 25.7, 34.4, 43.2, 62.3, 71.0},
       {7.7, 4.4, 3.6, 4.1, 1.5, 1.5, 1.6}},
      {"bicycle-carbon-monocoque",
       "Bicycle 3 (carbon monocoque)",
       {11.5, 17.8, 23.7, 34.9, 43.5, 65.3, 72.8},
       {6, 5.5, 5.5, 3.9, 3.8, 3.6, 2.8}},
      {"bicycle-carbon-banded",
       "Bicycle 4 (carbon banded)",
       {11, 17, 24.1, 34.2, 45.8, 72.8},
       {8.5, 5.3, 5.7, 5.9, 1.3, 3.9}},
  };
  for (const auto& b : bikes) {
    SpecimenEntry e{b.key, b.name, "bicycle", "thesis Table 18", D::Hysteretic, {}, "", std::nullopt, {}};
    for (std::size_t i = 0; i < b.f.size(); ++i) e.modes.push_back({b.f[i], b.eta[i] / 100.0, bikeShapes[i]});
    // No static test on whole bicycles: modal mass 5 kg per mode (assumed,
    // a fraction of a 10-15 kg bicycle).
    e.modalMass.assign(e.modes.size(), 5.0);
    c.push_back(e);
  }
  // ---- bicycle forks (§6.2, §6.3, Tables 19, 20; eta). Modal mass 0.5 kg
  // per mode without the wheel, 1.5 kg with it (assumed).
  auto bikeFork = [&](const char* key, const char* name, const char* source, std::vector<CatalogueMode> modes,
                      double modalMass) {
    SpecimenEntry e{key, name, "bicycle-fork", source, D::Hysteretic, std::move(modes), "", std::nullopt, {}};
    e.modalMass.assign(e.modes.size(), modalMass);
    c.push_back(e);
  };
  bikeFork("bicycle-fork-carbon-without-wheel", "Carbon bicycle fork without wheel", "thesis Table 19",
           {{64.0, 0.025, "Lateral"}, {94.1, 0.0257, "Longitudinal"}, {191.2, 0.0757, "First torsional"}}, 0.5);
  bikeFork("bicycle-fork-steel-without-wheel", "Steel bicycle fork without wheel", "thesis Table 19",
           {{84.7, 0.0313, "Lateral"},
            {83.4, 0.0269, "Longitudinal"},
            {214.1, 0.0223, "First torsional"},
            {230.1, 0.0185, "Second torsional"}},
           0.5);
  bikeFork("bicycle-fork-carbon-with-wheel", "Carbon bicycle fork with wheel", "thesis Table 20",
           {{19.3, 0.1004, "Torsional"},
            {21.3, 0.0424, "Lateral"},
            {31.7, 0.0293, "Longitudinal"},
            {80.4, 0.0149, "Wheel diametrical"}},
           1.5);
  bikeFork("bicycle-fork-steel-with-wheel", "Steel bicycle fork with wheel", "thesis Table 20",
           {{29.7, 0.0222, "Torsional"},
            {30.5, 0.0279, "Lateral"},
            {35.1, 0.0242, "Longitudinal"},
            {80.2, 0.0167, "Wheel diametrical"}},
           1.5);
  return c;
}

}  // namespace

const std::vector<SpecimenEntry>& specimenCatalogue() {
  static const std::vector<SpecimenEntry> catalogue = buildCatalogue();
  return catalogue;
}

const SpecimenEntry* findSpecimen(const std::string& key) {
  for (const auto& e : specimenCatalogue())
    if (e.key == key) return &e;
  return nullptr;
}

std::vector<std::string> specimenKeys() {
  std::vector<std::string> keys;
  for (const auto& e : specimenCatalogue()) keys.push_back(e.key);
  return keys;
}

std::vector<std::string> staticSpecimenKeys() {
  std::vector<std::string> keys;
  for (const auto& e : specimenCatalogue())
    if (e.statics) keys.push_back(e.key);
  return keys;
}

std::vector<std::string> tyreSpecimenKeys() {
  std::vector<std::string> keys;
  for (const auto& e : specimenCatalogue())
    if (e.kind == "tyre") keys.push_back(e.key);
  return keys;
}

}  // namespace mozzi::devices::sim
