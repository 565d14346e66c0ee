// Worked example of issue 10 from the thesis (docs/gap.md "Worked examples
// from the thesis"): the first-order relaxation length (§5.4, eq. 48-50) falls
// short of the measured one, blamed on unmodelled belt modes. Fig. 43's
// numbers are not printed; docs/gap/tyre-*-sigma.csv reconstruct the measured
// values from the sentences of §5.4 (see the files' headers). The check is on
// held-out pressures: fit each explanation on some pressures, predict the others.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/gap/diagnosis.h"
#include "core/gap/tire/tire_problem.h"

namespace mozzi::core::gap {
namespace {

const std::string kDocs = std::string(MOZZI_SOURCE_DIR) + "/docs/gap/";

struct Files {
  TireGapModel model;
  std::vector<ConditionPoint> points;
};

Files load(const std::string& stem) {
  auto json = readTextFile(kDocs + stem + ".json");
  auto csv = readTextFile(kDocs + stem + "-sigma.csv");
  EXPECT_TRUE(json && csv);
  auto model = parseTireGapModel(*json, stem);
  auto points = parseRelaxationCsv(*csv, stem);
  EXPECT_TRUE(model && points);
  return {*model, *points};
}

std::unique_ptr<TireGapProblem> subset(const Files& f, double loBar, double hiBar) {
  std::vector<ConditionPoint> pts;
  for (const auto& p : f.points)
    if (p.x >= loBar && p.x <= hiBar) pts.push_back(p);
  auto p = TireGapProblem::create(f.model, pts);
  EXPECT_TRUE(p) << p.error().describe();
  return std::move(*p);
}

DiagnosisOptions options() {
  DiagnosisOptions o;
  o.bootstrapSamples = 200;
  o.multistarts = 5;
  o.seed = 7;
  return o;
}

const RankedEffect* find(const Diagnosis& d, const std::string& effect) {
  for (const auto& r : d.ranking)
    if (r.candidate.effect == effect) return &r;
  return nullptr;
}

// Relative errors [%] on the held-out problem at the baseline (theta = 1) and
// after an effect fitted on the training pressures (its jointly refitted theta).
struct HeldOut {
  std::vector<double> before, after;
  double rmsBefore = 0, rmsAfter = 0;
};
HeldOut heldOut(const TireGapProblem& test, const Diagnosis& train, const std::string& effect) {
  HeldOut h;
  const auto* r = find(train, effect);
  EXPECT_TRUE(r && r->fitted) << effect;
  if (!r || !r->fitted) return h;
  const auto b = test.metrics({train.calibrated.data(), -1, nullptr});
  const auto a = test.metrics({r->theta.data(), r->candidateIndex, r->parameters.data()});
  for (const auto& e : b.entries) h.before.push_back(e.value);
  for (const auto& e : a.entries) h.after.push_back(e.value);
  h.rmsBefore = b.overall;
  h.rmsAfter = a.overall;
  return h;
}

void printHeldOut(const char* title, const TireGapProblem& test, const Diagnosis& train,
                  const std::vector<std::string>& effects) {
  std::printf("%s (fit on the other pressures; relative error of the prediction [%%])\n  %-26s", title, "effect");
  for (const auto& p : test.points()) std::printf(" %9s", p.label.c_str());
  std::printf("   RMS   shrink%%\n");
  for (const auto& name : effects) {
    const auto h = heldOut(test, train, name);
    if (h.after.empty()) continue;
    if (&name == &effects.front()) {
      std::printf("  %-26s", "baseline (calibrated)");
      for (double v : h.before) std::printf(" %9.1f", v);
      std::printf(" %6.1f\n", 100 * h.rmsBefore);
    }
    std::printf("  %-26s", name.c_str());
    for (double v : h.after) std::printf(" %9.1f", v);
    std::printf(" %6.1f %8.1f\n", 100 * h.rmsAfter, 100 * (1 - h.rmsAfter / h.rmsBefore));
  }
}

const std::vector<std::string> kEffects = {"belt_modes", "contact_patch_fraction", "ring_pressure_stiffening"};

// Radial tyre near nominal pressure: "about 20%". Fitted on 1.5 and 3 bar, the
// belt modes predict 2 bar; so does a larger contact-patch fraction: over
// 1.5-3 bar a(p) changes by 11% only, so the two signatures are nearly parallel.
TEST(GapThesisTyre, RadialTyreBeltModesPredictTheHeldOutNominalPressure) {
  const auto f = load("tyre-120-70-R17");
  auto train = TireGapProblem::create(f.model, {f.points[0], f.points[2]});  // 1.5 and 3 bar
  auto test = TireGapProblem::create(f.model, {f.points[1]});                // 2 bar
  ASSERT_TRUE(train && test);
  const auto d = diagnose(**train, options());
  ASSERT_TRUE(d) << d.error().describe();
  printHeldOut("120/70 R17, held out 2 bar", **test, *d, kEffects);
  const auto belt = heldOut(**test, *d, "belt_modes");
  ASSERT_EQ(belt.after.size(), 1u);
  // Before: 1/1.2 - 1 = -16.7% at the uncalibrated baseline; calibrating the
  // cornering stiffness (5% prior, docs/gap/tyre-*.json) takes a third of it
  // (measured -11.2%). After: within one 4% standard uncertainty of the
  // reconstructed value. With a 10% prior the calibration absorbs most of the
  // gap and the three pressures no longer show an effect (docs/gap.md).
  EXPECT_LT(belt.before[0], -8.0);
  EXPECT_LT(std::abs(belt.after[0]), 4.0);
  const auto patch = heldOut(**test, *d, "contact_patch_fraction");
  ASSERT_EQ(patch.after.size(), 1u);
  EXPECT_LT(std::abs(patch.after[0]), 4.0);

  // All three pressures: belt modes and contact-patch fraction explain the gap
  // equally (likelihood ratios within 10% of each other); the pressure range is
  // too narrow to separate them. Their fitted sizes: rho ~ 0.37 (a compliance
  // 37% of the identified modes' in series), patch scale ~ 1.43.
  const auto all = diagnose(*subset(f, 0, 10), options());
  ASSERT_TRUE(all) << all.error().describe();
  std::printf("120/70 R17, 1.5-3 bar: verdict %s, threshold %.2f\n  %s\n", verdictName(all->verdict), all->threshold,
              all->explanation.c_str());
  const auto* b = find(*all, "belt_modes");
  const auto* c = find(*all, "contact_patch_fraction");
  ASSERT_TRUE(b && c);
  EXPECT_NEAR(b->likelihoodRatio / c->likelihoodRatio, 1.0, 0.1);
  // The damping of the carcass moves sigma by under 0.3 noise standard deviations
  // at any size in its box (ring_model validation: -0.03% at 3%): not identifiable.
  const auto* damping = find(*all, "carcass_damping");
  ASSERT_TRUE(damping);
  EXPECT_FALSE(damping->identifiable);
}

// Diagonal scooter tyre, 0.5-4 bar: the gap grows from 30% at 4 bar to 50% at
// 0.5 bar (§5.4). A constant belt-mode compliance adds the same length at
// every pressure, i.e. a smaller fraction where the prediction is larger (low
// pressure): it cannot follow the trend. Fitted on 1.5-4 bar, it falls short
// at the held-out low pressures; a term that grows as the pressure drops
// (contact-patch fraction, scaling with a(p)) predicts them.
TEST(GapThesisTyre, ScooterTyreLowPressuresHeldOut) {
  const auto f = load("tyre-110-70-16");
  auto train = subset(f, 1.5, 4.0);
  auto test = subset(f, 0.0, 1.0);
  const auto d = diagnose(*train, options());
  ASSERT_TRUE(d) << d.error().describe();
  printHeldOut("110/70-16, held out 0.5-1 bar", *test, *d, kEffects);
  const auto belt = heldOut(*test, *d, "belt_modes");
  const auto patch = heldOut(*test, *d, "contact_patch_fraction");
  ASSERT_EQ(belt.after.size(), 3u);
  ASSERT_EQ(patch.after.size(), 3u);
  // Belt modes close part of the gap but leave the 0.5 bar value more than two
  // 4% uncertainties short; the contact-patch term stays within two.
  EXPECT_LT(belt.after[0], -8.0);
  EXPECT_LT(std::abs(patch.after[0]), 8.0);
  EXPECT_LT(patch.rmsAfter, belt.rmsAfter);
  EXPECT_GT(1 - belt.rmsAfter / belt.rmsBefore, 0.3);  // the belt modes still shrink the held-out gap

  // All seven pressures: an effect is needed (the baseline chi2 is far beyond
  // noise) and the constant compliance fits worse than the a(p)-scaled term.
  const auto all = diagnose(*subset(f, 0, 10), options());
  ASSERT_TRUE(all) << all.error().describe();
  std::printf("110/70-16, 0.5-4 bar: verdict %s, threshold %.2f\n  %s\n", verdictName(all->verdict), all->threshold,
              all->explanation.c_str());
  EXPECT_NE(all->verdict, Verdict::None);
  ASSERT_FALSE(all->ranking.empty());
  EXPECT_EQ(all->ranking[0].candidate.effect, "contact_patch_fraction");
  const auto* b = find(*all, "belt_modes");
  ASSERT_TRUE(b);
  EXPECT_LT(b->fitPValue, 0.01);  // a significant residual is left by the constant compliance
}

}  // namespace
}  // namespace mozzi::core::gap
