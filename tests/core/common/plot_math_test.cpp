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

// Min/max decimation: every pixel column of the decimated curve spans the
// same y interval as the full curve's samples in that column (what decides
// which pixels are lit), with at most 2 points per column plus the two edges.
TEST(PlotMath, MinMaxDecimationKeepsEveryColumnsExtremes) {
  const int n = 20000, columns = 700;
  Vector x(n), y(n);
  for (int k = 0; k < n; ++k) {
    x[k] = 1.0 + 0.05 * k;  // 1 .. 1000.95 Hz
    y[k] = std::sin(0.37 * k) * std::exp(-1e-4 * k) + 1e-3 * std::cos(3.1 * k);
  }
  for (bool logX : {false, true}) {
    const double lo = 100.0, hi = 800.0;
    const DecimatedCurve d = decimateMinMax(x, y, lo, hi, columns, logX);
    ASSERT_LE(d.x.size(), 2 * columns + 2);
    ASSERT_LT(d.x.size(), n / 10);
    ASSERT_EQ(d.x.size(), static_cast<Eigen::Index>(d.index.size()));
    // Edges: the samples just outside the range are kept.
    EXPECT_LT(d.x[0], lo);
    EXPECT_GT(d.x[d.x.size() - 1], hi);
    for (Eigen::Index q = 1; q < d.x.size(); ++q) ASSERT_LT(d.index[q - 1], d.index[q]);  // original order
    // Column of a sample from the column starts (checked against the edges below).
    const auto starts = pixelColumnStarts(x, lo, hi, columns, logX);
    ASSERT_EQ(starts.size(), static_cast<std::size_t>(columns) + 1);
    for (int c = 0; c < columns; ++c) {
      const double t0 = logX ? std::log10(lo) : lo, t1 = logX ? std::log10(hi) : hi;
      const double edge = logX ? std::pow(10.0, t0 + (t1 - t0) * c / columns) : t0 + (t1 - t0) * c / columns;
      const Eigen::Index s0 = starts[static_cast<std::size_t>(c)];
      ASSERT_GE(x[s0], edge * (1 - 1e-12)) << c;
      if (s0 > 0) {
        ASSERT_LT(x[s0 - 1], edge * (1 + 1e-12)) << c;
      }
    }
    auto col = [&](double v) {
      int c = 0;
      while (c + 1 < columns && v >= x[starts[static_cast<std::size_t>(c) + 1]]) ++c;
      return c;
    };
    std::vector<double> fullMin(columns, 1e300), fullMax(columns, -1e300), decMin = fullMin, decMax = fullMax;
    for (int k = 0; k < n; ++k) {
      if (x[k] < lo || x[k] > hi) continue;
      fullMin[col(x[k])] = std::min(fullMin[col(x[k])], y[k]);
      fullMax[col(x[k])] = std::max(fullMax[col(x[k])], y[k]);
    }
    for (Eigen::Index q = 0; q < d.x.size(); ++q) {
      if (d.x[q] < lo || d.x[q] > hi) continue;
      EXPECT_EQ(d.y[q], y[d.index[q]]);
      decMin[col(d.x[q])] = std::min(decMin[col(d.x[q])], d.y[q]);
      decMax[col(d.x[q])] = std::max(decMax[col(d.x[q])], d.y[q]);
    }
    for (int c = 0; c < columns; ++c) {
      ASSERT_EQ(decMin[c], fullMin[c]) << "column " << c << (logX ? " log" : " lin");
      ASSERT_EQ(decMax[c], fullMax[c]) << "column " << c << (logX ? " log" : " lin");
    }
  }
}

TEST(PlotMath, MinMaxDecimationOfShortCurvesAndNaN) {
  Vector x(5), y(5);
  x << 0, 1, 2, 3, 4;
  y << 1, std::nan(""), 3, 4, 5;
  const DecimatedCurve d = decimateMinMax(x, y, 0.0, 4.0, 100);
  ASSERT_EQ(d.x.size(), 4);  // unchanged, the NaN dropped
  EXPECT_EQ(d.y[1], 3.0);
  // A range inside the data keeps one sample either side.
  const DecimatedCurve inner = decimateMinMax(x, y, 2.5, 3.5, 10);
  ASSERT_EQ(inner.x.size(), 3);
  EXPECT_EQ(inner.x[0], 2.0);
  EXPECT_EQ(inner.x[2], 4.0);
  EXPECT_EQ(decimateMinMax(Vector(), Vector(), 0, 1, 10).x.size(), 0);
}

TEST(PlotMath, NearestSampleAndDataRange) {
  Vector x(4), y(4);
  x << 1, 2, 4, 8;
  y << -1, 10, 0.5, 3;
  EXPECT_EQ(nearestSample(x, -5), 0);
  EXPECT_EQ(nearestSample(x, 2.9), 1);
  EXPECT_EQ(nearestSample(x, 3.1), 2);
  EXPECT_EQ(nearestSample(x, 100), 3);
  EXPECT_EQ(nearestSample(Vector(), 1), -1);
  const AxisRange lin = dataRange(x, y, 2, 8, false, 0.0);
  EXPECT_DOUBLE_EQ(lin.lower, 0.5);
  EXPECT_DOUBLE_EQ(lin.upper, 10.0);
  const AxisRange lg = dataRange(x, y, 0, 10, true, 0.0);  // -1 does not count on a log axis
  EXPECT_DOUBLE_EQ(lg.lower, 0.5);
  EXPECT_DOUBLE_EQ(lg.upper, 10.0);
  const AxisRange none = dataRange(x, y, 20, 30, false);
  EXPECT_EQ(none.lower, 0.0);
  EXPECT_EQ(none.upper, 1.0);
  // A magnitude in dB with a zero line (its floor): the axis spans the data.
  ComplexVector h(4);
  h << Complex(0.0, 0.0), Complex(0.1, 0.0), Complex(1.0, 0.0), Complex(10.0, 0.0);
  const AxisRange db = dataRange(x, magnitudeDb(h), 0, 10, false, 0.0, kMagnitudeFloorDb);
  EXPECT_DOUBLE_EQ(db.lower, -20.0);
  EXPECT_DOUBLE_EQ(db.upper, 20.0);
}

TEST(PlotMath, HeatColourEndsAndDarkness) {
  EXPECT_EQ(heatColour(0.0).r, 255);
  EXPECT_EQ(heatColour(0.0).b, 255);
  EXPECT_EQ(heatColour(1.0).r, 150);
  EXPECT_EQ(heatColour(1.0).g, 0);
  EXPECT_EQ(heatColour(2.0).r, 150);  // clamped
  EXPECT_EQ(heatColour(std::nan("")).g, 255);
  EXPECT_FALSE(heatColourIsDark(0.0));
  EXPECT_TRUE(heatColourIsDark(1.0));
}

// A 2 x 1 region on a square drawing grows to 2 x 2 about its centre; a
// unit square on 200 x 100 pixels becomes 2 x 1.
TEST(PlotMath, EqualAspectGrowsTheShortSide) {
  AxisRange x{0.0, 2.0}, y{0.0, 1.0};
  ASSERT_TRUE(equalAspectRanges(x, y, 100, 100));
  EXPECT_NEAR(x.lower, 0.0, 1e-15);
  EXPECT_NEAR(x.upper, 2.0, 1e-15);
  EXPECT_NEAR(y.lower, -0.5, 1e-15);
  EXPECT_NEAR(y.upper, 1.5, 1e-15);
  AxisRange u{0.0, 1.0}, v{0.0, 1.0};
  ASSERT_TRUE(equalAspectRanges(u, v, 200, 100));
  EXPECT_NEAR(u.upper - u.lower, 2.0, 1e-15);
  EXPECT_NEAR(u.lower, -0.5, 1e-15);
  EXPECT_NEAR(v.upper - v.lower, 1.0, 1e-15);
  AxisRange bad{1.0, 0.0};
  EXPECT_FALSE(equalAspectRanges(bad, v, 100, 100));
  EXPECT_FALSE(equalAspectRanges(u, v, 0, 100));
}

}  // namespace
}  // namespace mozzi::core
