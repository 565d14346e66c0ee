#include "core/common/plot_math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core {
namespace {

TEST(PlotMath, MagnitudeInDecibelsOfKnownValues) {
  ComplexVector h(4);
  h << Complex(1.0, 0.0), Complex(0.0, 10.0), Complex(3.0, 4.0), Complex(0.0, 0.0);
  const Vector db = magnitudeDb(h);
  EXPECT_DOUBLE_EQ(db[0], 0.0);
  EXPECT_NEAR(db[1], 20.0, 1e-12);
  EXPECT_NEAR(db[2], 20.0 * std::log10(5.0), 1e-12);
  EXPECT_EQ(db[3], kMagnitudeFloorDb);
  EXPECT_NEAR(magnitudeDb(h, 10.0)[1], 0.0, 1e-12);  // dB re 10
}

// SDOF receptance 1/(k - m w^2 + i c w): phase goes from 0 through -90 at
// resonance to -180; past a second pole it reaches -360, which only the
// unwrapped phase shows (the wrapped one jumps to +180).
TEST(PlotMath, PhaseOfTwoPolesUnwrapsPastMinus180) {
  const int n = 2000;
  ComplexVector h(n);
  for (int k = 0; k < n; ++k) {
    const double w = 0.01 + 4.0 * k / n;
    const Complex s(0.0, w);
    // Two poles in series (a 4th-order low-pass): phase falls to -360.
    h[k] = 1.0 / ((s * s + 0.02 * s + 1.0) * (s * s + 0.04 * s + 4.0));
  }
  const Vector wrapped = phaseDegrees(h, false);
  const Vector unwrapped = phaseDegrees(h, true);
  EXPECT_LE(wrapped.maxCoeff(), 180.0);
  EXPECT_GT(wrapped.minCoeff(), -180.0);
  EXPECT_NEAR(unwrapped[0], 0.0, 1.0);
  EXPECT_NEAR(unwrapped[n - 1], -360.0, 5.0);  // far above both poles: -4 x 90 deg
  for (int k = 1; k < n; ++k) ASSERT_LT(std::abs(unwrapped[k] - unwrapped[k - 1]), 180.0) << k;
  for (int k = 0; k < n; ++k) {
    const double diff = std::remainder(unwrapped[k] - wrapped[k], 360.0);
    ASSERT_NEAR(diff, 0.0, 1e-9) << k;  // same angle, different branch
  }
}

TEST(PlotMath, RoundedRangesEndOnRoundNumbers) {
  const AxisRange a = roundedRange(0.13, 9.7, false);
  EXPECT_DOUBLE_EQ(a.lower, 0.0);
  EXPECT_DOUBLE_EQ(a.upper, 10.0);
  const AxisRange b = roundedRange(-87.0, 12.0, false);
  EXPECT_DOUBLE_EQ(b.lower, -100.0);
  EXPECT_DOUBLE_EQ(b.upper, 20.0);
  const AxisRange c = roundedRange(3.2, 4700.0, true);
  EXPECT_DOUBLE_EQ(c.lower, 1.0);
  EXPECT_DOUBLE_EQ(c.upper, 10000.0);
  const AxisRange d = roundedRange(5.0, 5.0, false);
  EXPECT_DOUBLE_EQ(d.lower, 4.5);
  EXPECT_DOUBLE_EQ(d.upper, 5.5);
  const AxisRange e = roundedRange(NAN, 1.0, false);
  EXPECT_DOUBLE_EQ(e.upper - e.lower, 1.0);
  const AxisRange f = roundedRange(-1.0, 10.0, true);  // log axis needs positive values
  EXPECT_GT(f.lower, 0.0);
}

}  // namespace
}  // namespace mozzi::core
