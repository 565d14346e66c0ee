// The linear screen against closed-form projections: P s computed by hand,
// principal-angle cosines, and the box-constrained linear likelihood ratio.
#include "core/gap/engine/screen.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine_test_problems.h"

namespace mozzi::core::gap {
namespace {

using engine::Model;
using engine::Scaled;
using testing::bump;
using testing::LinearCandidate;
using testing::LinearGapProblem;

constexpr int kN = 40;
constexpr double kSigma = 0.1;

struct Fixture {
  std::unique_ptr<LinearGapProblem> problem;
  std::vector<Scaled> theta;
  std::vector<std::pair<int, std::vector<Scaled>>> phi;
  Eigen::MatrixXd a;
};

Fixture make(std::vector<LinearCandidate> cands) {
  Fixture f;
  f.a = testing::polynomialBasis(kN, 2);
  std::mt19937_64 rng(1);
  f.problem = LinearGapProblem::generate(f.a, cands, Eigen::Vector2d(1, 1), -1, Eigen::VectorXd(),
                                         Eigen::VectorXd::Zero(kN), kSigma, rng);
  for (const auto& p : f.problem->calibrationParameters()) f.theta.push_back(*engine::scaleParameter(p, "t"));
  const auto cs = f.problem->candidates();
  for (std::size_t k = 0; k < cs.size(); ++k) {
    std::vector<Scaled> s;
    for (const auto& p : cs[k].parameters) s.push_back(*engine::scaleParameter(p, "t"));
    f.phi.emplace_back(static_cast<int>(k), s);
  }
  return f;
}

TEST(EngineScreen, ProjectedSignatureIsWhatCalibrationCannotAbsorb) {
  const Eigen::VectorXd s0 = bump(kN, 0.3, 0.08), s1 = bump(kN, 0.7, 0.08);
  Eigen::VectorXd line(kN);
  for (int i = 0; i < kN; ++i) line[i] = 0.5 - 2.0 * (i + 0.5) / kN;  // in the span of the calibration basis
  auto f = make({{"a", s0}, {"b", s1}, {"c", s0}, {"d", line}});
  Model base(*f.problem, f.theta, -1, {});
  const auto screen = engine::screenCandidates(base, Eigen::VectorXd::Zero(2), f.phi);
  ASSERT_TRUE(screen.ok()) << screen.error().describe();
  ASSERT_EQ(screen->candidates.size(), 4u);
  // Hand projection with the normal equations (fine at this size) in the
  // whitened, scaled coordinates: s in u units = s * span / sigma.
  const double span = 10.0;  // bounds [-5, 5]
  const Eigen::MatrixXd q = f.a.householderQr().householderQ() * Eigen::MatrixXd::Identity(kN, 2);
  auto projected = [&](const Eigen::VectorXd& s) { return Eigen::VectorXd(s - q * (q.transpose() * s)); };
  const Eigen::VectorXd b0 = projected(s0) * span / kSigma, b1 = projected(s1) * span / kSigma;
  // Signature step 1e-4 of the span on a linear model: exact to rounding; 1e-6 relative.
  EXPECT_NEAR(screen->candidates[0].projectedNorm[0], b0.norm(), 1e-6 * b0.norm());
  EXPECT_TRUE(screen->candidates[0].identifiable);
  // Confusability: |cos| of the projected signatures; a duplicate gives 1.
  const double cos01 = std::abs(b0.dot(b1)) / (b0.norm() * b1.norm());
  EXPECT_NEAR(screen->confusability(0, 1), cos01, 1e-9);
  EXPECT_NEAR(screen->confusability(0, 2), 1.0, 1e-12);
  // A signature inside the calibration span is absorbed: not identifiable.
  EXPECT_FALSE(screen->candidates[3].identifiable);
  EXPECT_NE(screen->candidates[3].reason.find("absorbs"), std::string::npos);
  EXPECT_TRUE(std::isnan(screen->confusability(0, 3)));
}

TEST(EngineScreen, LinearRatioIsTheBoxConstrainedProjection) {
  // Bounds [0, 5]: a one-sided effect (a mass cannot be negative).
  auto f = make({{"mass", bump(kN, 0.5, 0.08), 0.0, 5.0}});
  Model base(*f.problem, f.theta, -1, {});
  const auto screen = engine::screenCandidates(base, Eigen::VectorXd::Zero(2), f.phi);
  ASSERT_TRUE(screen.ok());
  const Eigen::VectorXd b = screen->candidates[0].projected.col(0);
  // r along +b: the improvement is (b'r)^2 / |b|^2 with step -b'r/|b|^2 < 0,
  // which the box clips to 0 (no improvement); along -b it is allowed.
  const Eigen::VectorXd r = 3.0 * b / b.norm();
  Eigen::VectorXd step;
  EXPECT_NEAR(screen->linearRatio(0, r, &step), 0.0, 1e-12);
  EXPECT_EQ(step[0], 0.0);
  EXPECT_NEAR(screen->linearRatio(0, -r, &step), 9.0, 1e-9);
  EXPECT_NEAR(step[0], 3.0 / b.norm(), 1e-12);
}

}  // namespace
}  // namespace mozzi::core::gap
