// The engine's bounded least-squares fit against closed-form least squares:
// estimates, Ceres covariance, Gaussian priors, bounds, and rank deficiency
// reported instead of pseudo-inverted.
#include "core/gap/engine/fit.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "engine_test_problems.h"

namespace mozzi::core::gap {
namespace {

using engine::Model;
using engine::Scaled;
using testing::LinearGapProblem;

constexpr int kN = 30;
constexpr double kSigma = 0.2;

std::vector<Scaled> scaled(const std::vector<Parameter>& defs) {
  std::vector<Scaled> out;
  for (const auto& p : defs) out.push_back(*engine::scaleParameter(p, "test"));
  return out;
}

Eigen::MatrixXd design() {
  return testing::polynomialBasis(kN, 2);
}

std::unique_ptr<LinearGapProblem> data(const Eigen::MatrixXd& a, unsigned seed) {
  std::mt19937_64 rng(seed);
  return LinearGapProblem::generate(a, {}, Eigen::Vector2d(1.0, -2.0), -1, Eigen::VectorXd(), Eigen::VectorXd::Zero(kN),
                                    kSigma, rng);
}

engine::FitOptions withCovariance() {
  engine::FitOptions o;
  o.covariance = true;
  return o;
}

TEST(EngineFit, MatchesClosedFormLeastSquaresAndItsCovariance) {
  const Eigen::MatrixXd a = design();
  const auto problem = data(a, 1);
  Model model(*problem, scaled(problem->calibrationParameters()), -1, {});
  const auto fit = engine::fitModel(model, {Eigen::VectorXd::Zero(2)}, withCovariance());
  ASSERT_TRUE(fit.ok);
  // theta = (A'A)^-1 A'y, cov = sigma^2 (A'A)^-1 (Gauss-Markov).
  const Eigen::Vector2d expected = a.colPivHouseholderQr().solve(problem->measured());
  const Eigen::Matrix2d cov = kSigma * kSigma * (a.transpose() * a).inverse();
  const auto x = model.thetaX(fit.u);
  // Numerical Jacobian (step 1e-6 of the span 200) on a linear model is exact to
  // rounding; the solver stops at a relative cost change of 1e-10: 1e-6.
  EXPECT_NEAR(x[0], expected[0], 1e-6);
  EXPECT_NEAR(x[1], expected[1], 1e-6);
  ASSERT_EQ(fit.stdErrors.size(), 2u);
  EXPECT_NEAR(fit.stdErrors[0], std::sqrt(cov(0, 0)), 1e-6 * std::sqrt(cov(0, 0)) + 1e-9);
  EXPECT_NEAR(fit.stdErrors[1], std::sqrt(cov(1, 1)), 1e-6 * std::sqrt(cov(1, 1)) + 1e-9);
  EXPECT_FALSE(fit.rankDeficient);
  // NLL = 0.5 |r|^2 with whitened residuals.
  EXPECT_NEAR(fit.nll, 0.5 * fit.chiSquare, 1e-12);
  EXPECT_NEAR(fit.chiSquare, ((a * expected - problem->measured()) / kSigma).squaredNorm(), 1e-8);
}

TEST(EngineFit, GaussianPriorGivesThePosteriorMode) {
  const Eigen::MatrixXd a = design();
  auto problem = data(a, 2);
  const double tau = 0.5;
  problem->setPrior(tau);
  Model model(*problem, scaled(problem->calibrationParameters()), -1, {});
  EXPECT_EQ(model.priorCount(), 2);
  const auto fit = engine::fitModel(model, {Eigen::VectorXd::Zero(2)}, withCovariance());
  ASSERT_TRUE(fit.ok);
  // Ridge form: (A'A / s^2 + I / tau^2) theta = A'y / s^2; posterior covariance
  // is the inverse of that matrix.
  const Eigen::Matrix2d h = a.transpose() * a / (kSigma * kSigma) + Eigen::Matrix2d::Identity() / (tau * tau);
  const Eigen::Vector2d expected = h.ldlt().solve(a.transpose() * problem->measured() / (kSigma * kSigma));
  const auto x = model.thetaX(fit.u);
  EXPECT_NEAR(x[0], expected[0], 1e-6);
  EXPECT_NEAR(x[1], expected[1], 1e-6);
  const Eigen::Matrix2d cov = h.inverse();
  EXPECT_NEAR(fit.stdErrors[0], std::sqrt(cov(0, 0)), 1e-6);
  EXPECT_NEAR(fit.stdErrors[1], std::sqrt(cov(1, 1)), 1e-6);
  // NLL includes the prior block.
  EXPECT_NEAR(fit.nll, 0.5 * fit.chiSquare + 0.5 * (x[0] * x[0] + x[1] * x[1]) / (tau * tau), 1e-9);
}

TEST(EngineFit, RankDeficiencyIsReportedNotPseudoInverted) {
  Eigen::MatrixXd a(kN, 2);
  a.col(0) = design().col(1);
  a.col(1) = design().col(1);  // two parameters that only act through their sum
  const auto problem = data(a, 3);
  Model model(*problem, scaled(problem->calibrationParameters()), -1, {});
  const auto fit = engine::fitModel(model, {Eigen::VectorXd::Zero(2)}, withCovariance());
  ASSERT_TRUE(fit.ok);
  EXPECT_TRUE(fit.rankDeficient);
  EXPECT_TRUE(fit.stdErrors.empty());
  ASSERT_EQ(fit.singularValues.size(), 2);
  EXPECT_LT(fit.singularValues[1], 1e-8 * fit.singularValues[0]);
  // Null direction (1, -1) / sqrt 2 (same scales): moving one up and the other
  // down leaves the residuals unchanged.
  EXPECT_NEAR(std::abs(fit.nullDirection[0]), std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(fit.nullDirection[0], -fit.nullDirection[1], 1e-6);
}

TEST(EngineFit, BoundsHoldAndBadBoundsAreRejected) {
  // One effect with bounds [0, 5] on data generated with size -1: the fit
  // stops at the bound.
  testing::LinearCandidate cand{"mass_loading", testing::bump(kN, 0.5, 0.1), 0.0, 5.0};
  std::mt19937_64 rng(4);
  const auto problem =
      LinearGapProblem::generate(design(), {cand}, Eigen::Vector2d(1.0, -2.0), 0, Eigen::VectorXd::Constant(1, -1.0),
                                 Eigen::VectorXd::Zero(kN), kSigma, rng);
  Model model(*problem, scaled(problem->calibrationParameters()), 0, scaled(problem->candidates()[0].parameters));
  const auto fit = engine::fitModel(model, {Eigen::VectorXd::Zero(3), Eigen::Vector3d(0, 0, 0.5)}, {});
  ASSERT_TRUE(fit.ok);
  EXPECT_EQ(model.phiX(fit.u)[0], 0.0);
  EXPECT_EQ(fit.starts, 2);

  const auto bad = engine::scaleParameter({"k", "N/m", 5.0, 6.0, 10.0, 0.0}, "test");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(bad.error().where.find("'k'"), std::string::npos);
}

// A resonance the effect moves by many half-power bandwidths: one lightly
// damped SDOF |H|(f) = 1 / |1 - (f/fn)^2 + 2 i zeta f/fn| sampled on 200
// lines, measured with fn scaled by 1.8 and fitted with the scale as the
// effect's size (nominal 1, box [0.05, 20], no calibration parameter). The
// cost along the scale is flat away from the measured peak, so a local fit
// from nominal stops there; the grid's minima give a start in the right basin
// and the fit from it returns the true scale (noise-free: to 1e-6).
class MovedResonance final : public GapProblem {
 public:
  MovedResonance() {
    for (int k = 0; k < kLines; ++k) measured_[k] = magnitude(1.8, 1.0 + 0.02 * k);
  }
  std::string dataKind() const override { return "frf"; }
  std::vector<Parameter> calibrationParameters() const override { return {}; }
  std::vector<Candidate> candidates() const override {
    return {{"boundary_stiffness", {"1+X"}, {{"scale", "", 1.0, 0.05, 20.0, 0.0}}}};
  }
  int residualCount() const override { return kLines; }
  bool residuals(const ModelPoint& at, double* r) const override {
    const double scale = at.candidate >= 0 ? at.phi[0] : 1.0;
    for (int k = 0; k < kLines; ++k) r[k] = (magnitude(scale, 1.0 + 0.02 * k) - measured_[k]) / 0.01;
    return true;
  }
  std::unique_ptr<GapProblem> simulated(const ModelPoint&, std::mt19937_64&) const override { return nullptr; }
  GapMetrics metrics(const ModelPoint&) const override { return {}; }

 private:
  static constexpr int kLines = 200;
  static double magnitude(double stiffnessScale, double f) {
    const double fn = 2.0 * std::sqrt(stiffnessScale), x = f / fn, zeta = 0.01;
    return 1.0 / std::hypot(1.0 - x * x, 2.0 * zeta * x);
  }
  std::array<double, kLines> measured_{};
};

TEST(EngineFit, GridStartsStepOverALocalMinimumAtNominal) {
  MovedResonance problem;
  Model model(problem, {}, 0, scaled(problem.candidates()[0].parameters));
  const Eigen::VectorXd nominal = Eigen::VectorXd::Zero(1);
  const auto local = engine::fitModel(model, {nominal}, {});
  ASSERT_TRUE(local.ok);
  EXPECT_GT(std::abs(model.phiX(local.u)[0] - 1.8), 0.3) << "the local fit should stay near nominal";
  const auto grid = engine::gridStarts(model, 0, 1, nominal, 2);
  ASSERT_FALSE(grid.empty());
  const auto fit = engine::fitModel(model, grid, {});
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(model.phiX(fit.u)[0], 1.8, 1e-6);
  // Only minima below a given cost: none lies below the true optimum's.
  Eigen::VectorXd work;
  EXPECT_TRUE(engine::gridStarts(model, 0, 1, nominal, 2, engine::dataCost(model, fit.u, work)).empty());
}

}  // namespace
}  // namespace mozzi::core::gap
