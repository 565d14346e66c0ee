// End-to-end verdicts of the gap diagnosis on linear-Gaussian problems whose
// truth is known (tests/core/gap/engine_test_problems.h), counted over seeded
// trials and compared with binomial bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/gap/diagnosis.h"
#include "core/gap/diagnosis_json.h"
#include "engine_test_problems.h"

namespace mozzi::core::gap {
namespace {

using testing::bump;
using testing::LinearCandidate;
using testing::LinearGapProblem;
using testing::polynomialBasis;

constexpr int kN = 48;
constexpr double kSigma = 0.1;
const Eigen::Vector3d kTheta(1.0, -0.5, 0.3);

// Three candidates at separated places plus a quadratic calibration basis.
std::vector<LinearCandidate> threeBumps() {
  return {{"mass_loading", bump(kN, 0.2, 0.05)},
          {"mass_loading", bump(kN, 0.5, 0.05)},
          {"element_stiffness", bump(kN, 0.8, 0.05)}};
}

std::unique_ptr<LinearGapProblem> make(std::vector<LinearCandidate> cands, int k, double size, unsigned seed,
                                       const Eigen::VectorXd& extra = Eigen::VectorXd::Zero(kN)) {
  std::mt19937_64 rng(seed);
  return LinearGapProblem::generate(polynomialBasis(kN, 3), std::move(cands), kTheta, k,
                                    Eigen::VectorXd::Constant(1, size), extra, kSigma, rng);
}

DiagnosisOptions fastOptions() {
  DiagnosisOptions o;
  o.bootstrapSamples = 200;
  o.multistarts = 3;
  return o;
}

bool attributes(Verdict v) {
  return v == Verdict::Effect || v == Verdict::Ambiguous || v == Verdict::Partial;
}

TEST(EngineDiagnosis, PlantedEffectIsFoundWithItsSize) {
  const auto problem = make(threeBumps(), 1, 1.5, 11);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->verdict, Verdict::Effect) << d->explanation;
  ASSERT_FALSE(d->ranking.empty());
  EXPECT_EQ(d->ranking[0].candidateIndex, 1);
  ASSERT_EQ(d->ranking[0].stdErrors.size(), 1u);
  // Within 4 standard errors (a 6e-5 two-sided event for a Gaussian estimate).
  EXPECT_NEAR(d->ranking[0].parameters[0], 1.5, 4 * d->ranking[0].stdErrors[0]);
  // The planted bump is the whole systematic gap: after it only noise is left,
  // |noise| / |y| against |noise + bump| / |y| (here 0.017 against 0.072).
  // Linear model: the profile likelihood is exactly quadratic, so its 95%
  // interval is the Wald one, size +- 1.96 se (bisection to 1e-4 se).
  ASSERT_EQ(d->ranking[0].profileInterval.size(), 1u);
  const double se = d->ranking[0].stdErrors[0], size = d->ranking[0].parameters[0];
  EXPECT_NEAR(d->ranking[0].profileInterval[0].first, size - 1.959964 * se, 1e-3 * se);
  EXPECT_NEAR(d->ranking[0].profileInterval[0].second, size + 1.959964 * se, 1e-3 * se);
  EXPECT_GT(d->ranking[0].shrinkPct, 60.0);
  EXPECT_GT(d->ranking[0].heldOutImprovement, 0.5);
  EXPECT_LT(d->flipProbability, 0.1);
  // Block 2 and 3 (samples 16-31, t = 0.33-0.66) carry the bump at t = 0.5.
  ASSERT_FALSE(d->where.empty());
  EXPECT_TRUE(d->where[0].label == "block 2" || d->where[0].label == "block 3") << d->where[0].label;
}

// A model with nothing to calibrate (every parameter known): the screen has
// no calibration Jacobian to project out and the fits have only the effect's
// block; the planted bump must still be found with its size.
TEST(EngineDiagnosis, ModelWithoutCalibrationParameters) {
  std::mt19937_64 rng(5);
  const Eigen::MatrixXd none(kN, 0);
  const auto problem =
      LinearGapProblem::generate(none, threeBumps(), Eigen::VectorXd(0), 2, Eigen::VectorXd::Constant(1, 1.5),
                                 Eigen::VectorXd::Zero(kN), kSigma, rng);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_TRUE(d->calibrated.empty());
  EXPECT_EQ(d->verdict, Verdict::Effect) << d->explanation;
  ASSERT_FALSE(d->ranking.empty());
  EXPECT_EQ(d->ranking[0].candidateIndex, 2);
  ASSERT_EQ(d->ranking[0].stdErrors.size(), 1u);
  EXPECT_NEAR(d->ranking[0].parameters[0], 1.5, 4 * d->ranking[0].stdErrors[0]);
}

TEST(EngineDiagnosis, NonlinearEffectIsFoundWithItsSize) {
  // theta0 exp(-theta1 t) + theta0 (exp(phi b_k) - 1): a log-factor of 0.3 at
  // the middle bump is 35% more response there, far beyond sigma = 0.05.
  testing::NonlinearGapProblem model(40, {0.2, 0.5, 0.8}, 0.05);
  std::mt19937_64 rng(21);
  const double theta[] = {2.0, 1.5}, phi[] = {0.3};
  const auto problem = model.simulated({theta, 1, phi}, rng);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->verdict, Verdict::Effect) << d->explanation;
  EXPECT_EQ(d->ranking[0].candidateIndex, 1);
  ASSERT_EQ(d->ranking[0].stdErrors.size(), 1u);
  // 4 standard errors: the estimate is asymptotically Gaussian; at ~20 se from
  // zero the curvature of exp() biases it by far less than one se.
  EXPECT_NEAR(d->ranking[0].parameters[0], 0.3, 4 * d->ranking[0].stdErrors[0]);
  // exp() makes the profile asymmetric; it still brackets the estimate.
  ASSERT_EQ(d->ranking[0].profileInterval.size(), 1u);
  EXPECT_LT(d->ranking[0].profileInterval[0].first, d->ranking[0].parameters[0]);
  EXPECT_GT(d->ranking[0].profileInterval[0].second, d->ranking[0].parameters[0]);
  // The jointly refitted calibration near its truth: sd ~ sigma / sqrt(n) ~
  // 0.01 for the amplitude and a few times that for the decay; loose bounds
  // (the test is about the effect).
  EXPECT_NEAR(d->ranking[0].theta[0], 2.0, 0.1);
  EXPECT_NEAR(d->ranking[0].theta[1], 1.5, 0.2);
}

TEST(EngineDiagnosis, JsonFollowsTheIssueSchema) {
  const auto problem = make(threeBumps(), 1, 1.5, 11);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok());
  const auto j = diagnosisToJson(*d);
  EXPECT_EQ(j["verdict"], "effect");
  EXPECT_EQ(j["best"]["effect"], "mass_loading");
  EXPECT_EQ(j["best"]["location"], nlohmann::json::array({"2+Z"}));
  EXPECT_TRUE(j["gap_before"]["residual"].is_number());
  EXPECT_EQ(j["gap_before"]["bands"].size(), 6u);
  EXPECT_TRUE(j["where"]["bands"].is_array());
  ASSERT_EQ(j["ranking"].size(), 3u);
  const auto& r0 = j["ranking"][0];
  EXPECT_DOUBLE_EQ(r0["parameters"]["size0"].get<double>(), d->ranking[0].parameters[0]);
  EXPECT_DOUBLE_EQ(r0["std_errors"]["size0"].get<double>(), d->ranking[0].stdErrors[0]);
  EXPECT_NEAR(r0["interval_95"]["size0"][1].get<double>() - r0["interval_95"]["size0"][0].get<double>(),
              2 * 1.959964 * d->ranking[0].stdErrors[0], 1e-12);
  for (const char* key : {"likelihood_ratio", "threshold", "aicc", "held_out_improvement"}) {
    EXPECT_TRUE(r0["criterion"][key].is_number()) << key;
  }
  EXPECT_TRUE(r0["gap_after"]["residual"].is_number());
  EXPECT_DOUBLE_EQ(r0["shrink_pct"].get<double>(), d->ranking[0].shrinkPct);
  EXPECT_FALSE(j["explanation"].get<std::string>().empty());
}

TEST(EngineDiagnosis, ControlsWithoutEffectSayNoneAboutNinetyFivePercent) {
  const int trials = 100;
  int none = 0, attributed = 0;
  for (int t = 0; t < trials; ++t) {
    const auto problem = make(threeBumps(), -1, 0.0, 1000 + t);
    const auto d = diagnose(*problem, fastOptions());
    ASSERT_TRUE(d.ok()) << d.error().describe();
    none += d->verdict == Verdict::None;
    attributed += attributes(d->verdict);
  }
  std::printf("controls: %d of %d none, %d attributed an effect\n", none, trials, attributed);
  // alpha = 0.05: false attributions ~ Binomial(100, 0.05), sd 2.2, plus the
  // threshold's own sampling error with B = 200 (sd of P(max LR > T) is
  // sqrt(0.05 0.95 / 200) = 0.015, 1.5 trials): combined sd 2.7; 3 sd bound.
  EXPECT_LE(attributed, 5 + 8);
  // "none" misses the attributions and the ~1% whose goodness of fit fails at
  // fitAlpha = 0.01 (then "unexplained"): 94 expected, same 3 sd.
  EXPECT_GE(none, 94 - 8);
}

TEST(EngineDiagnosis, PlantedSizeLiesWithinItsStandardErrorAsTheoryPredicts) {
  const int trials = 100;
  int found = 0, within1 = 0, within2 = 0;
  for (int t = 0; t < trials; ++t) {
    const auto problem = make(threeBumps(), 1, 0.4, 2000 + t);
    DiagnosisOptions o = fastOptions();
    o.ambiguitySamples = 10;
    const auto d = diagnose(*problem, o);
    ASSERT_TRUE(d.ok()) << d.error().describe();
    if (d->verdict != Verdict::Effect || d->ranking[0].candidateIndex != 1) continue;
    ++found;
    const double err = std::abs(d->ranking[0].parameters[0] - 0.4) / d->ranking[0].stdErrors[0];
    within1 += err <= 1.0;
    within2 += err <= 2.0;
  }
  std::printf("planted: found %d of %d; within 1 se %d, within 2 se %d\n", found, trials, within1, within2);
  // Size 0.4 is 6.5 standard errors (se = sigma / |P s| = 0.062): found every
  // time but for the ~1% goodness-of-fit failures; GAP.md asks >= 90% top-1.
  EXPECT_GE(found, 95);
  // Gaussian estimate with exact covariance: P(|err| <= 1) = 0.683, sd over
  // 100 trials 4.7; P(<= 2) = 0.954, sd 2.1; 3 sd bounds.
  EXPECT_NEAR(within1, 0.683 * found, 3 * 4.7);
  EXPECT_NEAR(within2, 0.954 * found, 3 * 2.1);
}

TEST(EngineDiagnosis, CollinearCandidatesAreAmbiguous) {
  // Bumps 0.005 apart with width 0.05: projected signatures with |cos| ~ 0.997.
  auto cands = threeBumps();
  cands[0] = {"mass_loading", bump(kN, 0.505, 0.05)};
  const int trials = 20;
  int ambiguous = 0, wrongCommit = 0;
  for (int t = 0; t < trials; ++t) {
    const auto problem = make(cands, 1, 0.5, 3000 + t);
    const auto d = diagnose(*problem, fastOptions());
    ASSERT_TRUE(d.ok()) << d.error().describe();
    if (d->verdict == Verdict::Ambiguous) {
      ++ambiguous;
      ASSERT_EQ(d->verdictSet.size(), 2u);
      const int a = d->ranking[0].candidateIndex, b = d->ranking[1].candidateIndex;
      EXPECT_TRUE((a == 0 && b == 1) || (a == 1 && b == 0));
      EXPECT_FALSE(d->separatingMeasurement.empty());
    } else if (attributes(d->verdict) && d->ranking[0].candidateIndex != 1) {
      ++wrongCommit;
    }
  }
  std::printf("collinear: %d of %d ambiguous, %d committed to the wrong member\n", ambiguous, trials, wrongCommit);
  // GAP.md: ambiguous pairs committed to the wrong member at most 10%.
  EXPECT_LE(wrongCommit, 2);
  EXPECT_GE(ambiguous, 16);
}

TEST(EngineDiagnosis, SignatureAbsorbedByCalibrationIsNotIdentifiable) {
  // The effect's signature is t, a column of the calibration basis: whatever
  // its size, calibration absorbs it.
  Eigen::VectorXd t(kN);
  for (int i = 0; i < kN; ++i) t[i] = (i + 0.5) / kN;
  // Two parameters moving the residual only through their sum: rank 1.
  Eigen::MatrixXd twin(kN, 2);
  twin << bump(kN, 0.5, 0.05), bump(kN, 0.5, 0.05);
  const auto problem = make({{"boundary_stiffness", t}, {"mass_loading", twin}}, 0, 1.0, 17);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->verdict, Verdict::NotIdentifiable) << d->explanation;
  ASSERT_EQ(d->ranking.size(), 2u);
  for (const auto& e : d->ranking) {
    EXPECT_FALSE(e.identifiable);
    EXPECT_TRUE(e.stdErrors.empty());
    EXPECT_NE(e.note.find("singular values"), std::string::npos) << e.note;
  }
  EXPECT_NE(d->ranking[0].note.find("absorbs"), std::string::npos) << d->ranking[0].note;
  const auto j = diagnosisToJson(*d);
  EXPECT_EQ(j["verdict"], "not_identifiable");
  EXPECT_TRUE(j["best"].is_null());
  EXPECT_TRUE(j["ranking"][0]["std_errors"].is_null());
  EXPECT_FALSE(j["ranking"][0]["identifiable"].get<bool>());
}

TEST(EngineDiagnosis, OutOfCatalogueResidualIsNotACleanAttribution) {
  Eigen::VectorXd wave(kN);
  for (int i = 0; i < kN; ++i) wave[i] = std::sin(2 * M_PI * 6 * (i + 0.5) / kN);
  int clean = 0, partial = 0;
  for (int t = 0; t < 10; ++t) {
    // Only the wave: nothing in the catalogue has its shape.
    const auto alone = make(threeBumps(), -1, 0.0, 4000 + t, 0.4 * wave);
    const auto d = diagnose(*alone, fastOptions());
    ASSERT_TRUE(d.ok()) << d.error().describe();
    EXPECT_TRUE(d->verdict == Verdict::Unexplained || d->verdict == Verdict::Partial) << d->explanation;
    clean += d->verdict == Verdict::Effect;
    // A catalogue effect plus the wave: the effect is found, the rest remains.
    const auto mixed = make(threeBumps(), 1, 1.5, 5000 + t, 0.15 * wave);
    const auto m = diagnose(*mixed, fastOptions());
    ASSERT_TRUE(m.ok()) << m.error().describe();
    partial += m->verdict == Verdict::Partial && m->ranking[0].candidateIndex == 1;
  }
  EXPECT_EQ(clean, 0);
  // The wave leaves chi-square ~ 44 + 0.15^2 / 2 * 48 / 0.01 = 98 on 44 dof
  // (p ~ 1e-6) after the bump: "partial" every time.
  EXPECT_EQ(partial, 10);
}

TEST(EngineDiagnosis, DegenerateProblemsDoNotBreakIt) {
  // No calibration parameters: the effect alone is fitted.
  std::mt19937_64 rng(31);
  const auto bare =
      LinearGapProblem::generate(Eigen::MatrixXd(kN, 0), {{"mass_loading", bump(kN, 0.5, 0.05)}}, Eigen::VectorXd(0), 0,
                                 Eigen::VectorXd::Constant(1, 1.0), Eigen::VectorXd::Zero(kN), kSigma, rng);
  auto d = diagnose(*bare, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->verdict, Verdict::Effect) << d->explanation;
  EXPECT_NEAR(d->ranking[0].parameters[0], 1.0, 4 * d->ranking[0].stdErrors[0]);
  // No candidates: the verdict rests on the goodness of fit alone.
  const auto empty = make({}, -1, 0.0, 32);
  d = diagnose(*empty, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_TRUE(d->ranking.empty());
  EXPECT_EQ(d->verdict, d->fitPValue >= 0.01 ? Verdict::None : Verdict::Unexplained);
}

TEST(EngineDiagnosis, RejectsBadOptionsAndHonoursCancel) {
  const auto problem = make(threeBumps(), -1, 0.0, 1);
  DiagnosisOptions o = fastOptions();
  o.effects = {"no_such_effect"};
  auto d = diagnose(*problem, o);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(d.error().message.find("mass_loading"), std::string::npos);
  o.effects = {"element_stiffness"};
  d = diagnose(*problem, o);
  ASSERT_TRUE(d.ok());
  ASSERT_EQ(d->ranking.size(), 1u);
  EXPECT_EQ(d->ranking[0].candidateIndex, 2);
  o = fastOptions();
  o.progress = [](double f, const std::string&) { return f < 0.3; };
  d = diagnose(*problem, o);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error().code, ErrorCode::Cancelled);
}

}  // namespace
}  // namespace mozzi::core::gap
