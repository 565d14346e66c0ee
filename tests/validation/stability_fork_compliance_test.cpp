// The thesis's improved bicycle model (appendix 3, eq. 61-65) with the steel
// fork of §6.4-§6.6, against the benchmark limit and the figures of §6.6.
#include <gtest/gtest.h>

#include <cmath>

#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/mode_tracking.h"

namespace mozzi::core::stability {
namespace {

// The four benchmark eigenvalues must be among the six of the stiff 3x3 model.
double slowModeError(const BicycleModel& stiff, const BicycleModel& bench, double v) {
  auto a = stiff.eigenvalues(v);
  auto b = bench.eigenvalues(v);
  EXPECT_TRUE(a.ok() && b.ok());
  double worst = 0.0;
  for (int i = 0; i < b->size(); ++i) {
    double best = 1e300;
    for (int j = 0; j < a->size(); ++j) best = std::min(best, std::abs((*a)(j) - (*b)(i)));
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(ForkCompliance, BothJointsReduceToTheBenchmarkWhenRigid) {
  const auto p = meijaard2007Parameters();
  const auto bench = benchmarkModel(p);
  ASSERT_TRUE(bench.ok());
  // With beta = 0 the roll and steer equations are the benchmark's: the 2x2
  // blocks equal Appendix A to rounding.
  for (auto m : {forkBendingModel(p, {1e3, 1.0, 0.21}), forkTorsionModel(p, {1e3, 1.0, 0.0})}) {
    ASSERT_TRUE(m.ok()) << m.error().describe();
    EXPECT_LT((m->M.topLeftCorner(2, 2) - bench->M).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((m->C1.topLeftCorner(2, 2) - bench->C1).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((m->K0.topLeftCorner(2, 2) - bench->K0).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((m->K2.topLeftCorner(2, 2) - bench->K2).cwiseAbs().maxCoeff(), 1e-12);
  }
  // Eigenvalues: the joint's effect on the slow modes falls like 1/k (bending,
  // v = 10 m/s: 3.4e-6 at k = 1e10, 3.4e-8 at 1e12, 3.4e-10 at 1e14 N m/rad)
  // while round-off grows like eps sqrt(k/J) even with the balanced solver; the
  // torsion joint's reduced inertia is ~30x smaller, so its round-off floor is
  // reached earlier (2e-10 at 1e12, 4e-9 at 1e14). At k = 1e14 (bending) and
  // 1e12 (torsion) both stay below the 1e-9 at 0..10 m/s.
  const auto bend = forkBendingModel(p, {1e14, 1.0, 0.21});
  const auto tors = forkTorsionModel(p, {1e12, 1.0, 0.0});
  ASSERT_TRUE(bend.ok() && tors.ok());
  for (double v : {0.0, 1.0, 3.0, 4.5, 6.0, 8.0, 10.0}) {
    EXPECT_LT(slowModeError(*bend, *bench, v), 1e-9) << "bending, v = " << v;
    EXPECT_LT(slowModeError(*tors, *bench, v), 1e-9) << "torsion, v = " << v;
  }
  // And the convergence is genuine: 100x stiffer, ~100x closer (at k = 1e6).
  const auto soft = forkBendingModel(p, {1e6, 1.0, 0.21});
  const auto softer = forkBendingModel(p, {1e4, 1.0, 0.21});
  ASSERT_TRUE(soft.ok() && softer.ok());
  const double e6 = slowModeError(*soft, *bench, 5.0), e4 = slowModeError(*softer, *bench, 5.0);
  EXPECT_GT(e4 / e6, 30.0);
  EXPECT_LT(e4 / e6, 300.0);
}

TEST(ForkCompliance, TorsionModeAtFiveMetresPerSecondAgainstThesis) {
  // §6.6: with k_gamma = 1938 N m/rad and c_gamma from the steel fork the torsion
  // eigenvalue at 5 m/s is -56 +/- 455i. The imaginary part follows from k and the
  // inertias alone; we agree within 1% (0.7%). The real part depends on c_gamma,
  // which the thesis does not state for this figure: with c = 0.3 N m s/rad
  // (§6.4, steel) we get about -16 (see docs/validation/stability.md).
  const auto p = meijaard2007Parameters();
  const auto m = forkTorsionModel(p, thesisSteelForkTorsion());
  ASSERT_TRUE(m.ok());
  auto sweep = sweepSpeeds(bicycleSystem(*m), {4.9, 5.0});
  ASSERT_TRUE(sweep.ok());
  const Root* torsion = nullptr;
  for (const Root& r : sweep->points[1].roots)
    if (r.name == "fork torsion") torsion = &r;
  ASSERT_NE(torsion, nullptr);
  EXPECT_NEAR(torsion->lambda.imag(), 455.0, 0.01 * 455.0);
  // Nearly decoupled 1-DOF oscillator: Re = -c / (2 J) with J = k / |lambda|^2.
  const double J = 1938.0 / std::norm(torsion->lambda);
  EXPECT_NEAR(torsion->lambda.real(), -0.3 / (2.0 * J), 0.05 * 0.3 / (2.0 * J));
  // "The other modes are similar to the ones of the CWBM": critical speeds
  // within 1e-3 m/s of the benchmark's 4.2924 and 6.0243 m/s.
  auto wide = sweepSpeeds(bicycleSystem(*m), *speedGrid(0.0, 10.0, 0.1));
  ASSERT_TRUE(wide.ok());
  ASSERT_TRUE(wide->criticalSpeed("weave").has_value());
  ASSERT_TRUE(wide->criticalSpeed("capsize").has_value());
  EXPECT_NEAR(*wide->criticalSpeed("weave"), 4.29238253634110, 1e-3);
  EXPECT_NEAR(*wide->criticalSpeed("capsize"), 6.02426201538836, 1e-3);
}

TEST(ForkCompliance, BendingWithSteelForkAgainstThesisFigure51) {
  const auto p = meijaard2007Parameters();
  const auto m = forkBendingModel(p, thesisSteelForkBending());
  ASSERT_TRUE(m.ok());
  auto sweep = sweepSpeeds(bicycleSystem(*m), *speedGrid(0.0, 30.0, 0.25));
  ASSERT_TRUE(sweep.ok());
  // "The self-stability range extends from 4.4 to 6 m/s": weave stabilises and
  // capsize destabilises at these speeds to the digits the thesis prints.
  const auto weave = sweep->firstEvent("weave", "stabilises");
  const auto capsize = sweep->firstEvent("capsize", "destabilises");
  ASSERT_TRUE(weave.has_value() && capsize.has_value());
  EXPECT_NEAR(weave->v, 4.4, 0.05);
  EXPECT_NEAR(capsize->v, 6.0, 0.5);
  // "A new complex mode dominated by steer rotation and front fork bending ...
  // imaginary part always larger than 27 rad/s."
  int seen = 0;
  for (const SpeedPoint& pt : sweep->points)
    for (const Root& r : pt.roots)
      if (r.name == "fork bending") {
        ++seen;
        EXPECT_GT(r.lambda.imag(), 27.0) << "v = " << pt.v;
      }
  EXPECT_EQ(seen, static_cast<int>(sweep->points.size()));
}

TEST(ForkCompliance, RejectsBadJointParameters) {
  const auto p = meijaard2007Parameters();
  const auto a = forkBendingModel(p, {0.0, 1.0, 0.2});
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().where.find("fork bending k"), std::string::npos);
  EXPECT_FALSE(forkTorsionModel(p, {100.0, -1.0, 0.0}).ok());
  EXPECT_FALSE(forkBendingModel(p, {100.0, 1.0, std::nan("")}).ok());
}

}  // namespace
}  // namespace mozzi::core::stability
