#include "core/stability/root_finding.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/stability/mode_tracking.h"

namespace mozzi::core::stability {
namespace {

TEST(Brent, FindsAnalyticRoots) {
  auto r = brentRoot([](double x) { return x * x - 2.0; }, 0.0, 2.0, 1e-15, "sqrt2");
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(*r, std::sqrt(2.0), 4e-16);
  auto c = brentRoot([](double x) { return std::cos(x); }, 1.0, 2.0, 1e-15, "pi/2");
  ASSERT_TRUE(c.ok());
  EXPECT_NEAR(*c, M_PI / 2.0, 4e-16);
}

TEST(Brent, RejectsABracketWithoutSignChange) {
  auto r = brentRoot([](double x) { return x * x + 1.0; }, -1.0, 1.0, 1e-12, "no root");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "no root");
  EXPECT_FALSE(brentRoot([](double) { return std::nan(""); }, 0.0, 1.0, 1e-12, "nan").ok());
}

TEST(SpeedGrid, InclusiveAndValidated) {
  auto g = speedGrid(0.0, 10.0, 0.1);
  ASSERT_TRUE(g.ok());
  EXPECT_EQ(g->size(), 101u);
  EXPECT_NEAR(g->back(), 10.0, 1e-12);
  EXPECT_FALSE(speedGrid(0.0, 10.0, 0.0).ok());
  EXPECT_FALSE(speedGrid(5.0, 1.0, 1.0).ok());
  EXPECT_FALSE(speedGrid(0.0, std::nan(""), 1.0).ok());
}

TEST(ModeTracking, SingleDegreeOfFreedomOscillator) {
  // m x'' + (c0 - v c1) x' + k x = 0: negative damping grows with v, so the
  // mode destabilises exactly at v = c0 / c1 = 2.5 with frequency sqrt(k/m) = 40 rad/s (a steer oscillation above 30
  // rad/s is named wobble).
  StabilitySystem s;
  s.stateMatrix = [](double v) -> Result<Matrix> {
    Matrix A(2, 2);
    A << 0.0, 1.0, -1600.0, -(1.0 - 0.4 * v);
    return A;
  };
  s.shapeNames = {"steer"};
  s.shapeRows = {0};
  s.shapeIsRate = {false};
  s.kind = VehicleKind::Motorcycle;
  auto sweep = sweepSpeeds(s, {0.0, 1.0, 2.0, 3.0, 4.0});
  ASSERT_TRUE(sweep.ok());
  const auto e = sweep->firstEvent("wobble", "destabilises");
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(e->v, 2.5, 1e-14);
  EXPECT_NEAR(e->frequency, 40.0, 1e-12);
  EXPECT_FALSE(sweepSpeeds(s, {1.0, 1.0}).ok());
  EXPECT_FALSE(sweepSpeeds(s, {}).ok());
}

}  // namespace
}  // namespace mozzi::core::stability
