// The hand-written derivatives of the variable-projection refinement
// (core/modal/varpro.h) against numeric differences (Ceres' GradientChecker),
// and the normal-equation shortcuts against the dense Jacobians they avoid.
#include "core/modal/varpro.h"

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/modal/synthetic_system.h"

namespace mozzi::core::modal {
namespace {

using testing::sixModeSystem;

// Accelerances of the six-mode system (references DOF 3 and 5), 30-330 Hz at
// 0.5 Hz, with 1% complex noise: the residual at the probe point is misfit
// plus noise, so the Golub-Pereyra term of the Jacobian is not negligible.
FrfMatrix data() {
  const auto sys = sixModeSystem();
  return testing::accelerances(sys, {2, 4}, 30.0, 330.0, 0.5, 0.01, 7);
}

// Probe point: every mode 0.3% off in frequency and 20% off in damping.
Vector probe() {
  const auto sys = sixModeSystem();
  Vector theta(12);
  for (int r = 0; r < 6; ++r) {
    theta[2 * r] = sys.fn[r] * (r % 2 ? 1.003 : 0.997);
    theta[2 * r + 1] = sys.zeta[r] * 1.2;
  }
  return theta;
}

// The projected residual with one parameter block per frequency and per
// damping ratio (numeric differences scale their step with the block's
// magnitude, so f [Hz] and zeta must not share one); the Jacobian is
// Golub-Pereyra's (exact) or Kaufman's (approximate).
class ProjectedResidual : public ceres::CostFunction {
 public:
  ProjectedResidual(ModalVarpro* vp, bool kaufman) : vp_(vp), kaufman_(kaufman) {
    set_num_residuals(static_cast<int>(2 * vp->lineCount() * vp->frfCount()));
    for (int j = 0; j < 2 * vp->modeCount(); ++j) mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const int nm = vp_->modeCount();
    Vector theta(2 * nm);
    for (int j = 0; j < 2 * nm; ++j) theta[j] = p[j][0];
    Vector res;
    Matrix jgp, jk;
    vp_->denseResidual(theta, res, jacobians ? &jgp : nullptr, jacobians ? &jk : nullptr);
    if (!res.allFinite()) return false;
    Eigen::Map<Vector>(residuals, res.size()) = res;
    if (!jacobians) return true;
    const Matrix& j = kaufman_ ? jk : jgp;
    for (int q = 0; q < 2 * nm; ++q) {
      if (jacobians[q]) Eigen::Map<Vector>(jacobians[q], j.rows()) = j.col(q);
    }
    return true;
  }

 private:
  ModalVarpro* vp_;
  bool kaufman_;
};

ModalVarpro makeVarpro(const FrfMatrix& frf) {
  auto vp = ModalVarpro::create(frf, {LineSegment{0, frf.lineCount()}}, 6, true, true);
  EXPECT_TRUE(vp.ok()) << vp.error().describe();
  return std::move(vp).value();
}

// Largest |analytic - numeric| of a Jacobian column over the column's largest
// entry, over all blocks.
double columnScaledError(const ceres::GradientChecker::ProbeResults& r) {
  double worst = 0.0;
  for (std::size_t b = 0; b < r.jacobians.size(); ++b) {
    const double scale = r.numeric_jacobians[b].cwiseAbs().maxCoeff();
    worst = std::max(worst, (r.jacobians[b] - r.numeric_jacobians[b]).cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

// Numeric differences (Ridders' extrapolation) agree with the analytic
// Golub-Pereyra Jacobian: within 1e-9 of each column's largest entry (the
// measured agreement is about 1e-12), and entry by entry within 1e-4 relative
// (Ceres' measure, max |a - b| / max(|a|, |b|) per entry: entries 1e-8 of
// their column's largest carry the absolute rounding of about 1e-12 of it,
// which shows as up to 1e-5 relative). Kaufman's Jacobian, which drops the
// term Q T^-T D^T R, fails both at this point, where the residual is large:
// the check can tell the two apart.
TEST(Varpro, GolubPereyraJacobianMatchesNumericDifferences) {
  const FrfMatrix frf = data();
  ModalVarpro vp = makeVarpro(frf);
  Vector theta = probe();
  std::vector<double*> blocks;
  for (int j = 0; j < 12; ++j) blocks.push_back(theta.data() + j);
  ceres::NumericDiffOptions nd;
  // Ridders' method (the checker's) starts from max(this, this x |x|) and
  // samples up to 2^5 times that: 1e-5 keeps every zeta (>= 0.006) positive.
  nd.ridders_relative_initial_step_size = 1e-5;

  ProjectedResidual exact(&vp, false);
  ceres::GradientChecker checker(&exact, static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), nd);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(blocks.data(), 1e-4, &results)) << results.error_log.substr(0, 2000);
  const double scaled = columnScaledError(results);
  EXPECT_LT(scaled, 1e-9);
  std::printf("Golub-Pereyra: max relative error %.3g, column-scaled %.3g\n", results.maximum_relative_error, scaled);

  ProjectedResidual approx(&vp, true);
  ceres::GradientChecker checkerK(&approx, static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), nd);
  ceres::GradientChecker::ProbeResults resultsK;
  EXPECT_FALSE(checkerK.Probe(blocks.data(), 1e-4, &resultsK));
  EXPECT_GT(columnScaledError(resultsK), 1e-4);
  std::printf("Kaufman: max relative error %.3g, column-scaled %.3g\n", resultsK.maximum_relative_error,
              columnScaledError(resultsK));
}

// gradient(), gaussNewton() and kaufman() are J^T r, J_GP^T J_GP and
// J_K^T J_K of the dense Jacobians (same arithmetic reordered: agreement to
// 1e-9 of the largest entry).
TEST(Varpro, NormalEquationsWithoutTheJacobianMatchDense) {
  const FrfMatrix frf = data();
  ModalVarpro vp = makeVarpro(frf);
  const Vector theta = probe();
  Vector r;
  Matrix jgp, jk;
  vp.denseResidual(theta, r, &jgp, &jk);
  ASSERT_TRUE(r.allFinite());
  ASSERT_TRUE(vp.evaluate(theta, true));
  const Vector g = jgp.transpose() * r;
  const Matrix hgp = jgp.transpose() * jgp, hk = jk.transpose() * jk;
  EXPECT_LT((vp.gradient() - g).cwiseAbs().maxCoeff(), 1e-9 * g.cwiseAbs().maxCoeff());
  EXPECT_LT((vp.gaussNewton() - hgp).cwiseAbs().maxCoeff(), 1e-9 * hgp.cwiseAbs().maxCoeff());
  EXPECT_LT((vp.kaufman() - hk).cwiseAbs().maxCoeff(), 1e-9 * hk.cwiseAbs().maxCoeff());
  EXPECT_NEAR(vp.ssr(), r.squaredNorm(), 1e-9 * r.squaredNorm());
  EXPECT_NEAR(vp.explicitSsr(), r.squaredNorm(), 1e-12 * r.squaredNorm());
  // Kaufman differs from Golub-Pereyra here (the check above is not vacuous).
  EXPECT_GT((hgp - hk).cwiseAbs().maxCoeff(), 1e-6 * hgp.cwiseAbs().maxCoeff());
}

// The refinement's evaluations (refine.h): Derivatives::Kaufman gives the
// same gradient as the full one (from Y X^T on the modes' rows instead of
// E^T Y) and the same J_K^T J_K, Derivatives::Covariance the same J_K^T J_K,
// SSR and X; over two segments and two references (the row and column
// indexing of the second pass).
TEST(Varpro, KaufmanAndCovarianceEvaluationsMatchTheFullOne) {
  const FrfMatrix frf = data();
  const Eigen::Index half = frf.lineCount() / 2;
  auto made =
      ModalVarpro::create(frf, {LineSegment{0, half - 40}, LineSegment{half, frf.lineCount() - half}}, 6, true, true);
  ASSERT_TRUE(made.ok()) << made.error().describe();
  ModalVarpro vp = std::move(made).value();
  const Vector theta = probe();
  ASSERT_TRUE(vp.evaluate(theta, ModalVarpro::Derivatives::Full));
  const Vector g = vp.gradient();
  const Matrix hk = vp.kaufman(), x = vp.linear();
  const double ssr = vp.ssr();
  ASSERT_TRUE(vp.evaluate(theta, ModalVarpro::Derivatives::Kaufman));
  EXPECT_LT((vp.gradient() - g).cwiseAbs().maxCoeff(), 1e-9 * g.cwiseAbs().maxCoeff());
  EXPECT_LT((vp.kaufman() - hk).cwiseAbs().maxCoeff(), 1e-12 * hk.cwiseAbs().maxCoeff());
  ASSERT_TRUE(vp.evaluate(theta, ModalVarpro::Derivatives::Covariance));
  EXPECT_LT((vp.kaufman() - hk).cwiseAbs().maxCoeff(), 1e-12 * hk.cwiseAbs().maxCoeff());
  EXPECT_LT((vp.linear() - x).cwiseAbs().maxCoeff(), 1e-12 * x.cwiseAbs().maxCoeff());
  EXPECT_NEAR(vp.ssr(), ssr, 1e-12 * ssr);
  // Without the derivative workspace neither is possible.
  auto lsfdOnly = ModalVarpro::create(frf, {LineSegment{0, frf.lineCount()}}, 6, true, true, false);
  ASSERT_TRUE(lsfdOnly.ok());
  EXPECT_FALSE(lsfdOnly->evaluate(theta, ModalVarpro::Derivatives::Kaufman));
  EXPECT_FALSE(lsfdOnly->evaluate(theta, ModalVarpro::Derivatives::Covariance));
}

// The residual per FRF (blocks of lines, the product subtracted in place)
// equals |R_c|^2 of the dense residual, and sums to explicitSsr(); one FRF's
// model values are that FRF's column of modelValues(). Two references, so
// that the column index i no + o is exercised; a segment split, so that
// blocks do not cross segments.
TEST(Varpro, ResidualPerFrfAndOneFrfsModelMatchDense) {
  const FrfMatrix frf = data();
  ModalVarpro vp = makeVarpro(frf);
  const Vector theta = probe();
  Vector r;
  vp.denseResidual(theta, r, nullptr, nullptr);
  ASSERT_TRUE(r.allFinite());
  ASSERT_TRUE(vp.evaluate(theta, false));
  Vector perFrf;
  vp.explicitSsrPerFrf(perFrf);
  ASSERT_EQ(perFrf.size(), vp.frfCount());
  const Eigen::Index rows = 2 * vp.lineCount();
  for (Eigen::Index c = 0; c < vp.frfCount(); ++c) {
    const double expected = r.segment(c * rows, rows).squaredNorm();
    EXPECT_NEAR(perFrf[c], expected, 1e-12 * expected) << "FRF " << c;
  }
  EXPECT_NEAR(vp.explicitSsr(), perFrf.sum(), 1e-14 * perFrf.sum());
  std::vector<ComplexMatrix> all;
  vp.modelValues(all);
  ASSERT_EQ(all.size(), 2u);
  for (Eigen::Index i = 0; i < 2; ++i) {
    for (Eigen::Index o = 0; o < frf.responseCount(); o += 3) {
      ComplexVector one;
      vp.modelValues(o, i, one);
      const ComplexVector& col = all[static_cast<std::size_t>(i)].col(o);
      EXPECT_LE((one - col).cwiseAbs().maxCoeff(), 1e-13 * col.cwiseAbs().maxCoeff()) << o << ", " << i;
    }
  }

  auto split = ModalVarpro::create(frf, {LineSegment{10, 200}, LineSegment{300, 250}}, 6, true, true, false);
  ASSERT_TRUE(split.ok());
  ASSERT_TRUE(split->evaluate(theta, false));
  Vector splitPerFrf;
  split->explicitSsrPerFrf(splitPerFrf);
  std::vector<ComplexMatrix> model;
  split->modelValues(model);
  for (Eigen::Index i = 0; i < 2; ++i) {
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      double expected = 0.0;
      Eigen::Index k = 0;
      for (const LineSegment& seg : split->segments()) {
        for (Eigen::Index q = 0; q < seg.count; ++q, ++k)
          expected += std::norm(frf.h[static_cast<std::size_t>(i)](seg.first + q, o) -
                                model[static_cast<std::size_t>(i)](k, o));
      }
      EXPECT_NEAR(splitPerFrf[i * frf.responseCount() + o], expected, 1e-10 * expected) << o << ", " << i;
    }
  }
}

// Segments: the projected residual on two pieces of the band equals the one
// of a FrfMatrix cut to those lines.
TEST(Varpro, SegmentsEqualTheLinesTheyName) {
  const FrfMatrix frf = data();
  auto split = ModalVarpro::create(frf, {LineSegment{10, 200}, LineSegment{300, 250}}, 6, true, true);
  ASSERT_TRUE(split.ok());
  FrfMatrix cut = frf;
  cut.frequencyHz.resize(450);
  cut.frequencyHz << frf.frequencyHz.segment(10, 200), frf.frequencyHz.segment(300, 250);
  for (std::size_t i = 0; i < frf.h.size(); ++i) {
    cut.h[i].resize(450, frf.responseCount());
    cut.h[i] << frf.h[i].middleRows(10, 200), frf.h[i].middleRows(300, 250);
  }
  auto whole = ModalVarpro::create(cut, {LineSegment{0, 450}}, 6, true, true);
  ASSERT_TRUE(whole.ok());
  const Vector theta = probe();
  ASSERT_TRUE(split->evaluate(theta, true));
  ASSERT_TRUE(whole->evaluate(theta, true));
  EXPECT_NEAR(split->ssr(), whole->ssr(), 1e-10 * whole->ssr());
  EXPECT_LT((split->gaussNewton() - whole->gaussNewton()).norm(), 1e-10 * whole->gaussNewton().norm());
}

TEST(Varpro, RefusesInadmissiblePolesAndTooFewLines) {
  const FrfMatrix frf = data();
  ModalVarpro vp = makeVarpro(frf);
  Vector theta = probe();
  theta[1] = 1.2;  // zeta >= 1
  EXPECT_FALSE(vp.evaluate(theta, false));
  theta = probe();
  theta[4] = theta[2];  // modes 2 and 3 equal: basis rank deficient
  theta[5] = theta[3];
  EXPECT_FALSE(vp.evaluate(theta, false));
  auto few = ModalVarpro::create(frf, {LineSegment{0, 10}}, 6, true, true);
  ASSERT_FALSE(few.ok());
  EXPECT_EQ(few.error().code, ErrorCode::InvalidArgument);
}

}  // namespace
}  // namespace mozzi::core::modal
