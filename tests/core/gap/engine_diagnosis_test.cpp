// End-to-end verdicts of the gap diagnosis on linear-Gaussian problems whose
// truth is known (tests/core/gap/engine_test_problems.h).
#include <gtest/gtest.h>

#include "core/gap/diagnosis.h"
#include "core/gap/diagnosis_json.h"
#include "core/gap/engine/statistics.h"
#include "engine_test_problems.h"

namespace mozzi::core::gap {
namespace {

using testing::bump;
using testing::LinearCandidate;
using testing::LinearGapProblem;
using testing::polynomialBasis;

constexpr int kN = 48;

// Three candidates at separated places plus a quadratic calibration basis.
std::vector<LinearCandidate> threeBumps() {
  return {{"mass_loading", bump(kN, 0.2, 0.05)},
          {"mass_loading", bump(kN, 0.5, 0.05)},
          {"element_stiffness", bump(kN, 0.8, 0.05)}};
}

DiagnosisOptions fastOptions() {
  DiagnosisOptions o;
  o.bootstrapSamples = 200;
  o.multistarts = 3;
  return o;
}

TEST(EngineDiagnosis, PlantedEffectIsFoundWithItsSize) {
  std::mt19937_64 rng(11);
  const Eigen::Vector3d theta(1.0, -0.5, 0.3);
  const Eigen::VectorXd phi = Eigen::VectorXd::Constant(1, 1.5);
  const auto problem = LinearGapProblem::generate(polynomialBasis(kN, 3), threeBumps(), theta, 1, phi,
                                                  Eigen::VectorXd::Zero(kN), 0.1, rng);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->verdict, Verdict::Effect) << d->explanation;
  ASSERT_FALSE(d->ranking.empty());
  EXPECT_EQ(d->ranking[0].candidateIndex, 1);
  ASSERT_EQ(d->ranking[0].stdErrors.size(), 1u);
  // Within 4 standard errors (a 6e-5 two-sided event for a Gaussian estimate).
  EXPECT_NEAR(d->ranking[0].parameters[0], 1.5, 4 * d->ranking[0].stdErrors[0]);
  EXPECT_GT(d->ranking[0].shrinkPct, 50.0);
  EXPECT_GT(d->ranking[0].heldOutImprovement, 0.0);
  const auto j = diagnosisToJson(*d);
  EXPECT_EQ(j["verdict"], "effect");
  EXPECT_EQ(j["best"]["effect"], "mass_loading");
  EXPECT_EQ(j["best"]["location"][0], "2+Z");
  std::cout << d->explanation << "\n" << j.dump(1).substr(0, 3000) << "\n";
}

TEST(EngineDiagnosis, ControlWithoutEffectSaysNone) {
  std::mt19937_64 rng(12);
  const Eigen::Vector3d theta(1.0, -0.5, 0.3);
  const auto problem = LinearGapProblem::generate(polynomialBasis(kN, 3), threeBumps(), theta, -1, Eigen::VectorXd(),
                                                  Eigen::VectorXd::Zero(kN), 0.1, rng);
  const auto d = diagnose(*problem, fastOptions());
  ASSERT_TRUE(d.ok()) << d.error().describe();
  std::cout << d->explanation << "\n";
  EXPECT_EQ(d->verdict, Verdict::None) << d->explanation;
}

}  // namespace
}  // namespace mozzi::core::gap
