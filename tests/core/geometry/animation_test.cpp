// Animation numerics: the phase from elapsed time, the deformed points at a
// phase against x0 + A Im(u e^{i theta}) computed with complex arithmetic,
// the automatic amplitude, the colour range and frame names.
#include "core/geometry/animation.h"

#include <gtest/gtest.h>

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

TEST(Animation, FramesCoverOneCycleAndCarryTheRateInTheirNames) {
  const Vector phases = framePhases(4);
  ASSERT_EQ(phases.size(), 4);
  EXPECT_NEAR(phases[3], 1.5 * M_PI, 1e-15);
  EXPECT_EQ(framePhases(0).size(), 0);
  EXPECT_EQ(frameFileName("mode-2", 25, 7), "mode-2_25fps_0007.png");
}

}  // namespace
}  // namespace mozzi::core::geometry
