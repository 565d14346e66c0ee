// Animation numerics: the phase from elapsed time, the deformed points at a
// phase against x0 + A Im(u e^{i theta}) computed with complex arithmetic,
// the automatic amplitude, the colour range and frame names.
#include "core/geometry/animation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace mozzi::core::geometry {
namespace {

TEST(Animation, PhaseComesFromElapsedTimeAndWraps) {
  EXPECT_NEAR(animationPhase(0.25, 1.0), M_PI / 2, 1e-15);
  EXPECT_NEAR(animationPhase(1.75, 0.5), 7 * M_PI / 4, 1e-15);
  EXPECT_EQ(animationPhase(2.0, 1.0), 0.0);
  // After ten hours at 2 cycles/s the phase is still exact to 1e-9 rad.
  const double t = 36000.0 + 0.125;
  EXPECT_NEAR(animationPhase(t, 2.0), M_PI / 2, 1e-9);
  const double wrapped = animationPhase(123.456, 1.7);
  EXPECT_GE(wrapped, 0.0);
  EXPECT_LT(wrapped, 2 * M_PI);
}

TEST(Animation, DeformedPointsAreBasePlusAmplitudeTimesImOfShapeTimesPhasor) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const int n = 50;
  NodePoints base(n, 3);
  NodeDisplacements u(n, 3);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      base(i, c) = uni(rng);
      u(i, c) = Complex(uni(rng), uni(rng));
    }
  const NodePoints re = realPart(u), im = imagPart(u);
  const double amplitude = 0.037;
  for (double theta : {0.0, 0.3, M_PI / 2, 2.0, M_PI, 5.5}) {
    NodePoints out;
    Vector magnitude;
    deformPoints(base, re, im, warpScales(amplitude, theta), out, &magnitude);
    const Complex phasor = std::polar(1.0, theta);
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) {
        const double expected = base(i, c) + amplitude * (u(i, c) * phasor).imag();
        EXPECT_NEAR(out(i, c), expected, 1e-15) << "node " << i << " axis " << c << " theta " << theta;
      }
      EXPECT_NEAR(magnitude[i], (out.row(i) - base.row(i)).norm(), 1e-15);
    }
  }
  // A real mode goes as A u sin(theta): at theta = 0 nothing moves.
  NodeDisplacements real = u.real().cast<Complex>();
  NodePoints out;
  deformPoints(base, realPart(real), imagPart(real), warpScales(1.0, 0.0), out);
  EXPECT_EQ((out - base).norm(), 0.0);
}

TEST(Animation, AutoAmplitudeMakesThePeakATenthOfTheMeshDiagonal) {
  NodePoints base(2, 3);
  base << 0, 0, 0, 3, 4, 0;  // diagonal 5 m
  NodeDisplacements u(2, 3);
  u << Complex(0, 0), Complex(0, 0), Complex(0, 2), Complex(1, 0), Complex(0, 0), Complex(0, 0);
  auto a = autoAmplitude(base, u);
  ASSERT_TRUE(a.ok());
  EXPECT_NEAR(*a, 0.1 * 5.0 / 2.0, 1e-15);  // peak |u| = 2
  const ColourRange range = colourRange(u, *a);
  EXPECT_EQ(range.min, 0.0);
  EXPECT_NEAR(range.max, 0.5, 1e-15);
  EXPECT_FALSE(autoAmplitude(base, NodeDisplacements::Zero(2, 3)).ok());
  EXPECT_FALSE(autoAmplitude(NodePoints::Zero(2, 3), u).ok());
}

TEST(Animation, ColourValuesAreThePeakDisplacementOverACycle) {
  // Node 0 real, node 1 circular (Re u and Im u orthogonal, equal norms:
  // constant magnitude), node 2 a general complex vector.
  NodeDisplacements u(3, 3);
  u << Complex(3, 0), Complex(4, 0), Complex(0, 0),  //
      Complex(2, 0), Complex(0, 2), Complex(0, 0),   //
      Complex(1, 0.5), Complex(-0.2, 0.7), Complex(0.3, -0.4);
  const double amplitude = -0.01;  // the sign of A does not change a magnitude
  const Vector values = colourValues(u, amplitude);
  ASSERT_EQ(values.size(), 3);
  EXPECT_NEAR(values[0], 0.01 * 5.0, 1e-15);
  EXPECT_NEAR(values[1], 0.01 * 2.0, 1e-15);
  // Node 2 against the largest displacement of a 20,000-step sweep of one
  // cycle: the sweep misses the peak by at most 1 - cos(pi/20000) ~ 1.2e-8 relative.
  NodePoints base = NodePoints::Zero(3, 3), out;
  Vector magnitude;
  double sweptPeak = 0.0;
  for (int k = 0; k < 20000; ++k) {
    deformPoints(base, realPart(u), imagPart(u), warpScales(amplitude, 2.0 * M_PI * k / 20000), out, &magnitude);
    sweptPeak = std::max(sweptPeak, magnitude[2]);
  }
  EXPECT_NEAR(values[2], sweptPeak, 2e-8 * sweptPeak);
  EXPECT_GE(values[2], sweptPeak * (1.0 - 1e-15));
  // The colour range runs from 0 to the largest of them.
  EXPECT_NEAR(colourRange(u, amplitude).max, values.maxCoeff(), 1e-15);
}

TEST(Animation, FramesCoverOneCycleAndCarryTheRateInTheirNames) {
  const Vector phases = framePhases(4);
  ASSERT_EQ(phases.size(), 4);
  EXPECT_NEAR(phases[3], 1.5 * M_PI, 1e-15);
  EXPECT_EQ(framePhases(0).size(), 0);
  EXPECT_EQ(frameFileName("mode-2", 25, 7), "mode-2_25fps_0007.png");
}

}  // namespace
}  // namespace mozzi::core::geometry
