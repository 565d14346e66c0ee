// Worked examples of issue 10 from the thesis (docs/gap.md "Worked examples
// from the thesis"): fork A's model 1 against the 22.3 Hz test (§4.2, Tables
// 10-12) and the carbon bicycle fork's two torsional stiffness estimates
// (§6.4, 1208 and 1253 Nm/rad) as a real-data control.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/gap/diagnosis.h"
#include "core/gap/fork/fork_problem.h"
#include "core/stiffness/fork_models.h"

namespace mozzi::core::gap {
namespace {

// Table 12 / §4.2 inputs: k_1 = 28 kNm/rad at L_1 = 0.670 m, dynamic axis
// L_2 = 0.846 m, wheel centre 0.670 - 0.405 = 0.265 m above the contact point,
// M = 8 + 3 kg, J_wheel = 0.278 kg m^2, measured 22.3 Hz (Table 11), zeta 2.4%.
stiffness::ForkLumpedInput forkA() {
  return {28e3, 0.670, 0.846, 0.265, 11.0, 0.278, 22.3, 0.024};
}

// Uncertainties. Frequency: GAP.md's floor, 0.2% of 22.3 Hz (Table 11 prints
// 3 figures, i.e. +-0.05 Hz rounding, of the same size). Static lateral
// stiffness 3%: Table 10's decomposition closes to 2% (15 kNm/rad at the 0.517 m
// twist arm gives 56.1 kN/m; bending and torsion in series give 57.2 kN/m).
// Torsion part of the static test: Table 10, arm 0.066 m, 3 kNm/rad.
ForkLumpedGapInput forkAGap(bool withStatic) {
  ForkLumpedGapInput in;
  in.fork = forkA();
  in.frequencySigmaHz = 0.002 * 22.3;
  in.withStatic = withStatic;
  in.staticLateralStiffness = 56.1e3;
  in.staticSigma = 0.03 * 56.1e3;
  in.torsionCompliance = 0.066 * 0.066 / 3e3;
  return in;
}

int indexOf(const GapProblem& p, const std::string& effect) {
  const auto c = p.candidates();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].effect == effect) return static_cast<int>(i);
  return -1;
}

TEST(GapThesisForkA, TheCandidatesReproduceModels1To3) {
  auto p = ForkLumpedGapProblem::create(forkAGap(true));
  ASSERT_TRUE(p) << p.error().describe();
  // Model 1: 18.4 Hz (§4.2). sqrt(28000 / 2.0823) / 2 pi = 18.455 Hz: the
  // thesis truncates (reference/notes.md reproduces Table 12), so 0.1 Hz.
  const auto base = (*p)->predict(nullptr, -1, nullptr);
  EXPECT_NEAR(base[0], 18.4, 0.1);
  // Static lateral stiffness of model 1 with the torsion part: 57.2 kN/m, 2% from 56.1.
  EXPECT_NEAR(base[1] / 56.1e3, 1.0, 0.03);
  // Model 2 (stiffness at the dynamic axis): 78.4 kNm/rad = 2.8 k_1 gives 22.3 Hz.
  const double s2 = 78.4 / 28.0;
  const auto m2 = (*p)->predict(nullptr, indexOf(**p, "stiffness_location"), &s2);
  EXPECT_NEAR(m2[0], 22.3, 0.05);
  // Its static lateral stiffness: bending alone k_2 / L_2^2 = 109.5 kN/m
  // (GAP.md), 94.5 kN/m with Table 10's torsion part in series: both far above 56.1.
  EXPECT_NEAR(78.4e3 / (0.846 * 0.846), 109.5e3, 0.1e3);
  EXPECT_NEAR(m2[1], 1.0 / (1.0 / 109.54e3 + 0.066 * 0.066 / 3e3), 0.2e3);
  // Model 3: pure moment -0.67 kg m^2 (J_3 = 1.426) gives 22.3 Hz, static unchanged.
  const double dJ = 1.426 - 2.085;
  const auto m3 = (*p)->predict(nullptr, indexOf(**p, "inertia"), &dJ);
  EXPECT_NEAR(m3[0], 22.3, 0.05);
  EXPECT_DOUBLE_EQ(m3[1], base[1]);
  // Residual compliance: 1 - (18.4/22.3)^2 = 32% of the static bending
  // compliance not in the mode gives 22.3 Hz, static unchanged.
  const double rho = 1.0 - std::pow(base[0] / 22.3, 2);
  const auto rc = (*p)->predict(nullptr, indexOf(**p, "residual_compliance"), &rho);
  EXPECT_NEAR(rc[0], 22.3, 1e-9);
  EXPECT_DOUBLE_EQ(rc[1], base[1]);
  std::printf("fork A: model 1 %.2f Hz, %.1f kN/m; model 2 %.2f Hz, %.1f kN/m; model 3 %.2f Hz; rho %.3f\n", base[0],
              base[1] / 1e3, m2[0], m2[1] / 1e3, m3[0], rho);
}

TEST(GapThesisCarbonFork, EstimatesComeFromTheTable19And20Frequencies) {
  // §6.4 via core/stiffness (validation/stiffness_forks_test): 19.3 Hz with the
  // wheel, 191.2 Hz alone; d = 0.060 m is that test's single assumed input.
  const stiffness::BicycleForkParameters carbon{0.393, 1.334, 0.350, 0.094, 0.004, 0.225, 0.060, 0.460};
  auto t = stiffness::bicycleForkTorsion(carbon, 19.3, 0.1004, 191.2);
  ASSERT_TRUE(t) << t.error().describe();
  EXPECT_NEAR(t->stiffnessWithWheel, 1208.0, 0.002 * 1208.0);
  EXPECT_NEAR(t->stiffnessAlone, 1253.0, 0.002 * 1253.0);
}

}  // namespace
}  // namespace mozzi::core::gap
