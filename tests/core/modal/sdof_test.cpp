#include "core/modal/sdof.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::modal {
namespace {

// One well-separated mode from an exact modal model (f = 150 Hz, zeta 0.5%,
// and a second mode at 300 Hz to give the realistic off-band background).
FrfMatrix singleModeFrf(FrfType type) {
  ModalModel m;
  m.responses = {Dof{1, Direction::Z}, Dof{2, Direction::Z}};
  m.references = {m.responses[0]};
  for (auto [f, z, a1, a2] :
       {std::tuple<double, double, double, double>{150.0, 0.005, 1.0, -0.6}, {300.0, 0.01, 0.8, 0.9}}) {
    Mode md;
    md.pole = poleFromFrequencyDamping(f, z);
    md.residue.resize(2, 1);
    // Real mode with unit modal mass phi = (a1, a2): R = phi phi_1 / (2 i wd).
    md.residue << a1 * a1 / Complex(0, 2 * md.pole.imag()), a2 * a1 / Complex(0, 2 * md.pole.imag());
    m.modes.push_back(md);
  }
  return synthesizeFrf(m, Vector::LinSpaced(2001, 100.0, 200.0), type).value();
}

// Peak picking on a lightly damped, well-separated mode: the half-power
// estimate is exact to O(zeta^2) plus line spacing (0.05 Hz): frequency within
// 0.01%, zeta within 3%.
TEST(Sdof, PeakPickingHalfPower) {
  const FrfMatrix frf = singleModeFrf(FrfType::Receptance);
  auto est = peakPicking(frf, 0, 140.0, 160.0);
  ASSERT_TRUE(est.ok()) << est.error().describe();
  EXPECT_NEAR(est->frequencyHz, 150.0, 0.015);
  EXPECT_NEAR(est->zeta, 0.005, 0.03 * 0.005);
  // Residue ratio gives the shape (-0.6 / 1) within 3% (background of the 300 Hz mode).
  EXPECT_NEAR((est->residue[1] / est->residue[0]).real(), -0.6, 0.03 * 0.6);
  // Errors: the band holds no peak (monotonic flank) and too few lines.
  EXPECT_FALSE(peakPicking(frf, 0, 160.0, 190.0).ok());
  EXPECT_FALSE(peakPicking(frf, 0, 150.0, 150.1).ok());
}

// Circle fit in mobility (works from any type): frequency within 0.01%, zeta
// within 3%, modal constant of the driving point (1.0) within 5%.
TEST(Sdof, CircleFitKennedyPancu) {
  const FrfMatrix frf = singleModeFrf(FrfType::Accelerance);
  auto est = circleFit(frf, 0, 147.0, 153.0);
  ASSERT_TRUE(est.ok()) << est.error().describe();
  EXPECT_NEAR(est->frequencyHz, 150.0, 0.015);
  EXPECT_NEAR(est->zeta, 0.005, 0.03 * 0.005);
  const double wd = 2 * M_PI * 150.0 * std::sqrt(1 - 0.005 * 0.005);
  const Complex a = est->residue[0] * Complex(0, 2 * wd);  // modal constant
  EXPECT_NEAR(a.real(), 1.0, 0.05);
  EXPECT_NEAR(a.imag(), 0.0, 0.05);
  EXPECT_FALSE(circleFit(frf, 0, 150.0, 150.1).ok());
}

}  // namespace
}  // namespace mozzi::core::modal
