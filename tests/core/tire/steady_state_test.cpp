// Slopes at the origin by local regression (thesis appendix 2, §7.1).
#include "core/tire/steady_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mozzi::core::tire {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(SlopeAtOrigin, ExactForAPolynomialOfTheFittedDegree) {
  Vector x = Vector::LinSpaced(11, 0.0, 5 * kDeg);  // §7.1 wheelchair sweep 0..5 deg
  Vector y = (30.0 + 2300.0 * x.array() - 9000.0 * x.array().square()).matrix();
  auto s = slopeAtOrigin(x, y, 5 * kDeg, 2);
  ASSERT_TRUE(s) << s.error().describe();
  EXPECT_NEAR(s->slope, 2300.0, 1e-8);  // exact data: rounding only
  EXPECT_NEAR(s->intercept, 30.0, 1e-9);
  EXPECT_NEAR(s->slopeStdError, 0.0, 1e-6);
}

TEST(SlopeAtOrigin, StandardErrorCoversTheScatterUnderNoise) {
  // 300 seeded noisy sweeps of a tanh characteristic (slope 2300 N/rad):
  // the mean slope within 4 SE-of-mean of the local-regression bias-free
  // value, and the spread within 20% of the mean reported SE.
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 5.0);
  Vector x = Vector::LinSpaced(21, -5 * kDeg, 5 * kDeg);
  std::vector<double> est, se;
  for (int r = 0; r < 300; ++r) {
    Vector y(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) y[i] = 400.0 * std::tanh(2300.0 * x[i] / 400.0) + g(rng);
    auto s = slopeAtOrigin(x, y, 2 * kDeg, 1);  // tanh is odd: cubic bias only, 2 deg window
    ASSERT_TRUE(s);
    est.push_back(s->slope);
    se.push_back(s->slopeStdError);
  }
  double m = 0, mse = 0, v = 0;
  for (std::size_t i = 0; i < est.size(); ++i) m += est[i] / est.size(), mse += se[i] / se.size();
  for (double e : est) v += (e - m) * (e - m) / (est.size() - 1);
  EXPECT_NEAR(std::sqrt(v) / mse, 1.0, 0.2);
  // Bias of a linear fit to tanh over +-2 deg: slope (1 - (k/F)^2 <x^4>/<x^2>) ~ -2.4%: allow 4%.
  EXPECT_NEAR(m, 2300.0, 0.04 * 2300.0);
}

TEST(SlopeAtOrigin, RejectsNonMonotonicSweepsAndTooFewPoints) {
  Vector x(5);
  x << 0, 1 * kDeg, 2 * kDeg, 1.5 * kDeg, 3 * kDeg;
  Vector y = 100 * x;
  auto s = slopeAtOrigin(x, y, 5 * kDeg, 1);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("monotonic"), std::string::npos);
  EXPECT_NE(s.error().where.find("point 4"), std::string::npos);
  Vector x2 = Vector::LinSpaced(6, 0.0, 5 * kDeg);
  EXPECT_FALSE(slopeAtOrigin(x2, 100 * x2, 1.5 * kDeg, 2));  // 2 points in window
  Vector x3 = Vector::LinSpaced(6, 3 * kDeg, 8 * kDeg);
  auto far = slopeAtOrigin(x3, 100 * x3, 10 * kDeg, 1);
  ASSERT_FALSE(far);
  EXPECT_NE(far.error().message.find("zero angle"), std::string::npos);
}

TEST(CharacteriseSweep, NormalisesByTheVerticalLoad) {
  SteadyStateSweep s;
  s.angle = Vector::LinSpaced(11, 0.0, 10 * kDeg);  // camber sweep 0..10 deg (§7.1)
  s.force = 0.9 * 400.0 * s.angle;                  // camber stiffness 0.9 F_z /rad
  s.torque = -0.004 * 400.0 * s.angle;
  s.verticalLoad = 400.0;
  auto c = characteriseSweep(s, 3 * kDeg, 1);
  ASSERT_TRUE(c) << c.error().describe();
  EXPECT_NEAR(c->forceSlope.slope, 360.0, 1e-9);
  EXPECT_NEAR(c->torqueSlope.slope, -1.6, 1e-12);
  EXPECT_NEAR(c->normalisedForceSlope, 0.9, 1e-12);
  EXPECT_NEAR(c->normalisedForce[10], 0.9 * 10 * kDeg, 1e-12);
  s.verticalLoad = 0.0;
  EXPECT_FALSE(characteriseSweep(s));
}

}  // namespace
}  // namespace mozzi::core::tire
