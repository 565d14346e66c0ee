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
  const auto base = (*p)->predict({nullptr, -1, nullptr});
  EXPECT_NEAR(base[0], 18.4, 0.1);
  // Static lateral stiffness of model 1 with the torsion part: 57.2 kN/m, 2% from 56.1.
  EXPECT_NEAR(base[1] / 56.1e3, 1.0, 0.03);
  // Model 2 (stiffness at the dynamic axis): 78.4 kNm/rad = 2.8 k_1 gives 22.3 Hz.
  const double s2 = 78.4 / 28.0;
  const auto m2 = (*p)->predict({nullptr, indexOf(**p, "stiffness_location"), &s2});
  EXPECT_NEAR(m2[0], 22.3, 0.05);
  // Its static lateral stiffness: bending alone k_2 / L_2^2 = 109.5 kN/m
  // (GAP.md), 94.5 kN/m with Table 10's torsion part in series: both far above 56.1.
  EXPECT_NEAR(78.4e3 / (0.846 * 0.846), 109.5e3, 0.1e3);
  EXPECT_NEAR(m2[1], 1.0 / (1.0 / 109.54e3 + 0.066 * 0.066 / 3e3), 0.2e3);
  // Model 3: pure moment -0.67 kg m^2 (J_3 = 1.426) gives 22.3 Hz, static unchanged.
  const double dJ = 1.426 - 2.085;
  const auto m3 = (*p)->predict({nullptr, indexOf(**p, "inertia"), &dJ});
  EXPECT_NEAR(m3[0], 22.3, 0.05);
  EXPECT_DOUBLE_EQ(m3[1], base[1]);
  // Residual compliance: 1 - (18.4/22.3)^2 = 32% of the static bending
  // compliance not in the mode gives 22.3 Hz, static unchanged.
  const double rho = 1.0 - std::pow(base[0] / 22.3, 2);
  const auto rc = (*p)->predict({nullptr, indexOf(**p, "residual_compliance"), &rho});
  EXPECT_NEAR(rc[0], 22.3, 1e-9);
  EXPECT_DOUBLE_EQ(rc[1], base[1]);
  std::printf("fork A: model 1 %.2f Hz, %.1f kN/m; model 2 %.2f Hz, %.1f kN/m; model 3 %.2f Hz; rho %.3f\n", base[0],
              base[1] / 1e3, m2[0], m2[1] / 1e3, m3[0], rho);
}

DiagnosisOptions options() {
  DiagnosisOptions o;
  o.bootstrapSamples = 200;  // the threshold's 0.95 quantile from 200 draws: +-1.5% in probability
  o.multistarts = 5;
  o.seed = 42;
  return o;
}

const RankedEffect* find(const Diagnosis& d, const std::string& effect) {
  for (const auto& r : d.ranking)
    if (r.candidate.effect == effect) return &r;
  return nullptr;
}

bool inVerdictSet(const Diagnosis& d, const std::string& effect) {
  for (int i : d.verdictSet)
    if (d.ranking[static_cast<std::size_t>(i)].candidate.effect == effect) return true;
  return false;
}

void printDiagnosis(const char* title, const Diagnosis& d) {
  std::printf("%s: verdict %s (threshold %.2f, baseline chi2 %.1f)\n", title, verdictName(d.verdict), d.threshold,
              d.chiSquare);
  std::printf("  %-20s %-24s %10s %10s %10s %9s %8s %s\n", "effect", "location", "size", "std.err", "LR", "chi2 after",
              "shrink%", "in verdict");
  for (const auto& r : d.ranking)
    std::printf("  %-20s %-24s %10.4g %10.3g %10.2f %9.2f %8.1f %s\n", r.candidate.effect.c_str(),
                r.candidate.location.empty() ? "-" : r.candidate.location[0].c_str(),
                r.parameters.empty() ? 0.0 : r.parameters[0], r.stdErrors.empty() ? 0.0 : r.stdErrors[0],
                r.likelihoodRatio, r.chiSquare, r.shrinkPct, inVerdictSet(d, r.candidate.effect) ? "yes" : "");
}

// GAP.md worked case: with the frequency alone, stiffness location (model 2),
// inertia (model 3), a stiffer spring and a residual compliance of the static
// test all close the gap exactly: one datum, one parameter each.
TEST(GapThesisForkA, FrequencyAloneCannotTellTheExplanationsApart) {
  auto p = ForkLumpedGapProblem::create(forkAGap(false));
  ASSERT_TRUE(p) << p.error().describe();
  const auto d = diagnose(**p, options());
  ASSERT_TRUE(d) << d.error().describe();
  printDiagnosis("fork A, 22.3 Hz only", *d);
  EXPECT_EQ(d->verdict, Verdict::Ambiguous) << d->explanation;
  ASSERT_EQ(d->ranking.size(), 4u);
  for (const auto& r : d->ranking) {
    // Every explanation fits the single frequency exactly (chi2 after ~ 0,
    // against a baseline chi2 of (18.46 - 22.3)^2 / 0.045^2 ~ 7e3).
    EXPECT_TRUE(r.fitted) << r.candidate.effect;
    EXPECT_LT(r.chiSquare, 0.01) << r.candidate.effect;
    EXPECT_GT(r.likelihoodRatio, d->threshold) << r.candidate.effect;
  }
  // The fitted sizes are the thesis's models: 78.4 / 28 = 2.8 at the dynamic
  // axis (model 2) and a pure moment 1.426 - 2.085 = -0.66 kg m^2 (model 3),
  // within 4 standard errors (the prior on the unsprung mass sets them).
  const auto* m2 = find(*d, "stiffness_location");
  const auto* m3 = find(*d, "inertia");
  ASSERT_TRUE(m2 && m3 && !m2->stdErrors.empty() && !m3->stdErrors.empty());
  EXPECT_NEAR(m2->parameters[0], 2.8, 4 * m2->stdErrors[0]);
  EXPECT_NEAR(m3->parameters[0], -0.66, 4 * m3->stdErrors[0]);
}

// Adding Table 10's static lateral stiffness (56.1 kN/m): a spring at the
// dynamic axis stiff enough for 22.3 Hz implies 109.5 kN/m from bending alone
// (94.5 kN/m with the torsion part), so model 2's location is rejected, and so
// is a stiffer spring at the static axis; inertia and a residual compliance of
// the static test remain (both leave the static stiffness untouched).
TEST(GapThesisForkA, StaticStiffnessRejectsModel2) {
  auto freq = ForkLumpedGapProblem::create(forkAGap(false));
  auto both = ForkLumpedGapProblem::create(forkAGap(true));
  ASSERT_TRUE(freq && both);
  const auto before = diagnose(**freq, options());
  const auto after = diagnose(**both, options());
  ASSERT_TRUE(before && after);
  printDiagnosis("fork A, 22.3 Hz + 56.1 kN/m", *after);
  // Before: model 2's location fits the frequency exactly (one of four exact fits).
  EXPECT_EQ(before->verdict, Verdict::Ambiguous);
  const auto* m2before = find(*before, "stiffness_location");
  ASSERT_TRUE(m2before);
  EXPECT_LT(m2before->chiSquare, 0.01);
  EXPECT_EQ(after->verdict, Verdict::Ambiguous) << after->explanation;
  EXPECT_FALSE(inVerdictSet(*after, "stiffness_location"));
  EXPECT_FALSE(inVerdictSet(*after, "bending_stiffness"));
  EXPECT_TRUE(inVerdictSet(*after, "inertia"));
  EXPECT_TRUE(inVerdictSet(*after, "residual_compliance"));
  const auto* m2 = find(*after, "stiffness_location");
  ASSERT_TRUE(m2);
  // Rejected by goodness of fit: one degree of freedom left, chi2 far beyond
  // any noise (p < 1e-6; measured chi2 about 265).
  EXPECT_LT(m2->fitPValue, 1e-6);
  const auto* m3 = find(*after, "inertia");
  ASSERT_TRUE(m3);
  EXPECT_GT(m3->fitPValue, 0.05);  // the static stiffness is model 1's own, 2% from 56.1
}

// §6.4: 1208 Nm/rad with the wheel, 1253 Nm/rad alone. Realistic uncertainty:
// 5% per estimate, dominated by the inertia model (fork mass lumped as two
// sixths at the tips, wheel as a thin ring, fake hub as a cylinder, the tip
// distance d assumed), with 0.4% from the 0.2% frequency floor. The two agree:
// no effect. With the frequency floor alone (0.4% per estimate) the 3.7%
// difference would be blamed on an inertia error of one configuration or the
// other, which is why the uncertainty must be the realistic one.
TEST(GapThesisCarbonFork, TwoTorsionEstimatesAreAControlWithNoEffect) {
  auto realistic = StiffnessEstimatesGapProblem::create(
      {{"with wheel", 1208.0, 0.05 * 1208.0}, {"fork alone", 1253.0, 0.05 * 1253.0}}, "N m/rad");
  ASSERT_TRUE(realistic);
  const auto d = diagnose(**realistic, options());
  ASSERT_TRUE(d) << d.error().describe();
  printDiagnosis("carbon fork torsion, 5%", *d);
  EXPECT_EQ(d->verdict, Verdict::None) << d->explanation;
  EXPECT_GT(d->fitPValue, 0.05);  // chi2 0.27 on 1 dof
  // A clamp compliance acts the same in both configurations: it cannot be
  // separated from the stiffness itself, and the screen says so.
  const auto* clamp = find(*d, "boundary_stiffness");
  ASSERT_TRUE(clamp);
  EXPECT_FALSE(clamp->identifiable);

  auto floorOnly = StiffnessEstimatesGapProblem::create(
      {{"with wheel", 1208.0, 0.004 * 1208.0}, {"fork alone", 1253.0, 0.004 * 1253.0}}, "N m/rad");
  ASSERT_TRUE(floorOnly);
  const auto f = diagnose(**floorOnly, options());
  ASSERT_TRUE(f);
  printDiagnosis("carbon fork torsion, 0.4%", *f);
  EXPECT_NE(f->verdict, Verdict::None) << f->explanation;
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
