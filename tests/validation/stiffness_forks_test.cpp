// Thesis fork numbers reproduced through core/stiffness: Table 12 (lumped
// models of the enduro fork, §4.2) and the bicycle forks of §6.4 and §6.5
// (Tables 19, 20, 21). Inconsistencies are stated here and in
// docs/validation/stiffness.md.
#include <gtest/gtest.h>

#include <cmath>

#include "core/stiffness/fork_models.h"

namespace mozzi::core::stiffness {
namespace {

// Table 12 inputs (§4.2): k = 28 kNm/rad (Table 10) at L1 = 0.670 m, dynamic
// axis at L2 = 0.846 m, wheel 8 kg + unsprung 3 kg at 0.405 m below L1 (wheel
// centre 0.265 m above the contact point), wheel diametrical inertia 0.278
// kgm^2, measured lateral mode 22.3 Hz with zeta = 2.4 % (Table 11).
ForkLumpedInput table12Input() {
  return {28e3, 0.670, 0.846, 0.670 - 0.405, 11.0, 0.278, 22.3, 0.024};
}

TEST(ThesisTable12, LumpedForkModels) {
  const auto m = forkLumpedModels(table12Input());
  ASSERT_TRUE(m.ok()) << m.error().describe();
  // Model 1: J1 = 0.278 + 11 x 0.405^2 = 2.0823 kgm^2; the thesis prints 2.085
  // (0.13 % higher, a rounding in the thesis). Tolerance 0.2 %.
  EXPECT_NEAR(m->model1.inertia, 2.085, 0.002 * 2.085);
  // f_n1 = sqrt(28000 / 2.0823) / 2 pi = 18.46 Hz; with the thesis's 2.085 it is
  // 18.44, printed 18.4. Tolerance 0.5 % covers the inertia rounding and the
  // printed figure.
  EXPECT_NEAR(m->model1.frequencyHz, 18.4, 0.005 * 18.4);
  EXPECT_NEAR(m->model1.damping, 11.6, 0.05);  // printed to 0.1 Nms/rad; measured 11.59
  // Model 2: J2 = 0.278 + 11 (0.405 + 0.846 - 0.670)^2 = 3.9914 (printed 3.995,
  // 0.09 %), k2 = (2 pi 22.3)^2 J2 = 78.36 kNm/rad (printed 78.4), c2 = 26.84
  // (printed 26.9). Tolerances: 0.2 % on J and k, 0.1 Nms/rad on c (the printed
  // J2 gives 26.86; both round the same inputs).
  EXPECT_NEAR(m->model2.inertia, 3.995, 0.002 * 3.995);
  EXPECT_NEAR(m->model2.stiffness, 78.4e3, 0.002 * 78.4e3);
  EXPECT_NEAR(m->model2.damping, 26.9, 0.1);
  EXPECT_NEAR(m->model2.frequencyHz, 22.3, 1e-9);
  // Model 3: J3 = 28000 / (2 pi 22.3)^2 = 1.4262 (printed 1.426), c3 = 9.59 (9.6).
  EXPECT_NEAR(m->model3.inertia, 1.426, 0.0005);
  EXPECT_NEAR(m->model3.damping, 9.6, 0.05);
  EXPECT_NEAR(m->model3.frequencyHz, 22.3, 1e-9);
  // The text's "pure moment of -0.67 kgm^2" is J3 - J1 = 1.426 - 2.085 = -0.659
  // (or -0.656 with J1 = 2.0823): the printed -0.67 is 2 % off, a rounding in the text.
  EXPECT_NEAR(m->model3.pureMoment, -0.656, 0.001);
}

// Table 21 (masses, hub, wheel radius). The blade-tip distance d of eq. 52 is
// not printed; d = 0.060 m (a round value) is the single assumed input, and with
// it all four torsional stiffnesses below are reproduced.
BicycleForkParameters carbon() {
  return {0.393, 1.334, 0.350, 0.094, 0.004, 0.225, 0.060, 0.460};
}
BicycleForkParameters steel() {
  auto p = carbon();
  p.forkMass = 1.336;
  return p;
}

// §6.4. Carbon fork: with wheel 19.3 Hz (Table 20, eta 10.04 %), alone 191.2 Hz
// (Table 19) -> 1208 and 1253 Nm/rad, damping 1.0 Nm/(rad/s). Steel fork: with
// wheel 29.7 Hz (eta 2.22 %), alone two torsion modes 214.1 and 230.1 Hz in
// series (eq. 54) -> 2901 and 1938 Nm/rad, damping 0.3. Measured: 1208.5,
// 1253.5, 2901.2, 1939.9 Nm/rad, damping 1.000 and 0.345. Tolerance 0.2 % on
// stiffness (4-figure frequencies and 3-figure masses); damping is printed to
// 0.1, so +-0.05.
TEST(ThesisSection64, BicycleForkTorsion) {
  const auto c = bicycleForkTorsion(carbon(), 19.3, 0.1004, 191.2);
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_NEAR(c->stiffnessWithWheel, 1208.0, 0.002 * 1208.0);
  EXPECT_NEAR(c->stiffnessAlone, 1253.0, 0.002 * 1253.0);
  EXPECT_NEAR(c->damping, 1.0, 0.05);
  const auto s = bicycleForkTorsion(steel(), 29.7, 0.0222, 214.1, 230.1);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_NEAR(s->stiffnessWithWheel, 2901.0, 0.002 * 2901.0);
  EXPECT_NEAR(s->stiffnessAlone, 1938.0, 0.002 * 1938.0);
  EXPECT_NEAR(s->damping, 0.3, 0.05);
  // Eq. 52 as printed (wheel term m_F r_F^2, the ring about its spin axis)
  // would double the wheel inertia and give about 2410 Nm/rad for the carbon
  // fork, not 1208: the thesis's numbers use the diametrical m_F r_F^2 / 2.
  const double literal = modalStiffness(19.3, 2 * (0.393 / 6) * 0.0036 + 1.334 * 0.35 * 0.35);
  EXPECT_GT(literal / 1208.0, 1.9);
}

// §6.5 carbon fork: lateral mode 21.3 Hz with the wheel (eta 4.24 %), 64 Hz
// alone. The thesis finds h_W = 0.383 m and 5326 Nm/rad. The two curves meet
// at a shallow angle, so the result is sensitive to the printed (rounded)
// frequencies: with 21.3 and 64 Hz as printed the equations give h_W = 0.371 m
// and 5083 Nm/rad (-4.6 %). "64" has two significant figures; across the
// rounding box 21.25..21.35 Hz x 63.5..64.5 Hz the result spans the thesis
// values, so the test asserts that the thesis values lie inside the range
// reachable from the printed inputs, and the damping 1.6 Nm/(rad/s).
TEST(ThesisSection65, CarbonForkBendingWithinInputRounding) {
  const auto nominal = bicycleForkBending(carbon(), 21.3, 0.0424, 64.0);
  ASSERT_TRUE(nominal.ok()) << nominal.error().describe();
  EXPECT_NEAR(nominal->bendArm, 0.3714, 0.0005);
  EXPECT_NEAR(nominal->stiffness, 5083.0, 0.002 * 5083.0);
  EXPECT_NEAR(nominal->damping, 1.6, 0.05);  // measured 1.61
  double hMin = 1e9, hMax = -1e9, kMin = 1e9, kMax = -1e9;
  for (double fw : {21.25, 21.35}) {
    for (double fa : {63.5, 64.5}) {
      const auto b = bicycleForkBending(carbon(), fw, 0.0424, fa);
      ASSERT_TRUE(b.ok());
      hMin = std::min(hMin, b->bendArm);
      hMax = std::max(hMax, b->bendArm);
      kMin = std::min(kMin, b->stiffness);
      kMax = std::max(kMax, b->stiffness);
    }
  }
  EXPECT_LE(hMin, 0.383);
  EXPECT_GE(hMax, 0.383);
  EXPECT_LE(kMin, 5326.0);
  EXPECT_GE(kMax, 5326.0);
}

// §6.5 steel fork: lateral 30.5 Hz with wheel (eta 2.79 %), 84.7 Hz alone
// (Tables 19, 20). The printed equations give h_W = 0.182 m and 5160 Nm/rad;
// the thesis prints 5635 Nm/rad (+9 %), which no rounding of the 3- and
// 4-figure inputs reaches (the rounding box spans 5155..5165 Nm/rad; even the
// longitudinal 83.4 Hz gives 5284): an inconsistency of the thesis, recorded
// in docs/validation/stiffness.md. The asserted figure is the value of eq. 57
// to 59 checked against a brute-force scan of the two curves; the damping
// 0.75 rounds to the printed 0.8.
TEST(ThesisSection65, SteelForkBendingFromThePrintedEquations) {
  const auto b = bicycleForkBending(steel(), 30.5, 0.0279, 84.7);
  ASSERT_TRUE(b.ok()) << b.error().describe();
  double best = 1e18, hb = 0;
  for (int i = 0; i <= 46000; ++i) {
    const double h = i * 1e-5;
    const double dk = std::abs(modalStiffness(30.5, bendInertiaWithWheel(steel(), h)) -
                               modalStiffness(84.7, bendInertiaForkAlone(steel(), h)));
    if (dk < best) {
      best = dk;
      hb = h;
    }
  }
  EXPECT_NEAR(b->bendArm, hb, 2e-5);
  EXPECT_NEAR(b->bendArm, 0.1818, 0.0005);
  EXPECT_NEAR(b->stiffness, 5160.0, 0.002 * 5160.0);
  EXPECT_NEAR(b->damping, 0.8, 0.05);                 // measured 0.751
  EXPECT_GT((5635.0 - b->stiffness) / 5635.0, 0.05);  // the documented gap
}

}  // namespace
}  // namespace mozzi::core::stiffness
