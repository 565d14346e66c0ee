// The body-and-joint linearisation against the Appendix A formulas of Meijaard
// et al. (2007): two independent derivations of the same benchmark matrices.
#include "core/stability/multibody_linearizer.h"

#include <gtest/gtest.h>

#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"

namespace mozzi::core::stability {
namespace {

void expectNear(const Matrix& a, const Matrix& b, double tol, const char* what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  for (int i = 0; i < a.rows(); ++i)
    for (int j = 0; j < a.cols(); ++j) EXPECT_NEAR(a(i, j), b(i, j), tol) << what << "(" << i << "," << j << ")";
}

TEST(MultibodyLinearizer, ReproducesTheBenchmarkAppendixFormulas) {
  const auto p = meijaard2007Parameters();
  const auto formulas = benchmarkModel(p);
  const auto bodies = whippleFromBodies(p);
  ASSERT_TRUE(formulas.ok());
  ASSERT_TRUE(bodies.ok()) << bodies.error().describe();
  // Entries are O(1..100); both are sums of a few dozen double products, so
  // they may differ by rounding only: 1e-12 absolute.
  expectNear(bodies->M, formulas->M, 1e-12, "M");
  expectNear(bodies->C1, formulas->C1, 1e-12, "C1");
  expectNear(bodies->K0, formulas->K0, 1e-12, "K0");
  expectNear(bodies->K2, formulas->K2, 1e-12, "K2");
}

TEST(MultibodyLinearizer, FrontLoadIsTheStaticReaction) {
  // Moment balance about the rear contact: N_F w = g m_T x_T (benchmark: 294.3 N... computed here).
  const auto p = meijaard2007Parameters();
  auto t = bicycleTopology(p, ForkJoint::None, 0.0);
  ASSERT_TRUE(t.ok());
  auto lin = linearize(*t);
  ASSERT_TRUE(lin.ok());
  const double mTxT = p.xB * p.mB + p.xH * p.mH + p.w * p.mF;
  EXPECT_NEAR(std::fabs(lin->frontLoad), p.g * mTxT / p.w, 1e-10);
}

TEST(MultibodyLinearizer, RejectsBadTopology) {
  VehicleTopology t;
  EXPECT_FALSE(linearize(t).ok());
  auto good = bicycleTopology(meijaard2007Parameters(), ForkJoint::None, 0.0);
  ASSERT_TRUE(good.ok());
  VehicleTopology bad = *good;
  bad.joints[2].axis = Vector3(1.0, 0.0, 1.0);  // not a unit vector
  const auto r = linearize(bad);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().where.find("steer"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::stability
