// Windows and the exponential-window damping bookkeeping.
#include "core/signal/window.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/signal/fft.h"

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Window, HannIsPeriodicWithCoherentGainOneHalf) {
  auto w = makeWindow({WindowKind::Hann}, 64, 1000.0);
  ASSERT_TRUE(w.ok());
  EXPECT_NEAR((*w)[0], 0.0, 1e-15);
  EXPECT_NEAR((*w)[32], 1.0, 1e-15);
  EXPECT_NEAR((*w)[16], 0.5, 1e-15);
  EXPECT_NEAR((*w)[1], (*w)[63], 1e-15);  // periodic: w[i] = w[n - i]
  EXPECT_NEAR(w->sum(), 32.0, 1e-12);     // sum = n / 2 exactly for the periodic form
}

// Flat-top: the amplitude of a sine read from the highest line is correct
// whatever the sine's position between lines (scalloping loss of the
// five-term flat-top is below 0.01 dB = 0.12%; Heinzel et al. 2002, table).
TEST(Window, FlatTopReadsAmplitudeBetweenLines) {
  const Eigen::Index n = 1024;
  auto w = makeWindow({WindowKind::FlatTop}, n, 1024.0);
  ASSERT_TRUE(w.ok());
  auto fft = RealFft::forLength(n);
  ASSERT_TRUE(fft.ok());
  for (double offset : {0.0, 0.25, 0.5}) {
    const double f = 100.0 + offset;  // 1 Hz lines
    Vector x(n);
    for (Eigen::Index i = 0; i < n; ++i) x[i] = 3.0 * std::cos(2 * kPi * f * i / 1024.0 + 0.3) * (*w)[i];
    auto X = (*fft)->transform(x);
    ASSERT_TRUE(X.ok());
    const double amp = 2.0 * X->cwiseAbs().maxCoeff() / w->sum();
    EXPECT_NEAR(amp / 3.0, 1.0, 0.0012) << "offset " << offset;
  }
}

TEST(Window, ForceWindowWidthAndTaper) {
  // fs = 1 kHz, origin at sample 100, width 10 ms, taper 4 ms
  WindowSpec spec{WindowKind::Force, 0.010, 0.004, 0.0};
  auto w = makeWindow(spec, 200, 1000.0, 100);
  ASSERT_TRUE(w.ok());
  EXPECT_EQ((*w)[0], 1.0);             // pre-trigger kept
  EXPECT_EQ((*w)[110], 1.0);           // t = width
  EXPECT_NEAR((*w)[112], 0.5, 1e-12);  // half-way through the taper: 0.5 (1 + cos(pi/2))
  EXPECT_EQ((*w)[114], 0.0);
  EXPECT_EQ((*w)[199], 0.0);
  EXPECT_FALSE(makeWindow({WindowKind::Force, 0.0, 0.0, 0.0}, 10, 1000.0).ok());
  EXPECT_FALSE(makeWindow({WindowKind::Force, 0.01, -1.0, 0.0}, 10, 1000.0).ok());
}

TEST(Window, ExponentialWindowFromTheOrigin) {
  WindowSpec spec{WindowKind::Exponential, 0.0, 0.0, 0.05};
  auto w = makeWindow(spec, 300, 1000.0, 20);
  ASSERT_TRUE(w.ok());
  EXPECT_EQ((*w)[10], 1.0);
  EXPECT_NEAR((*w)[20], 1.0, 1e-15);
  EXPECT_NEAR((*w)[70], std::exp(-1.0), 1e-15);  // t = tau
  EXPECT_NEAR((*w)[220], std::exp(-4.0), 1e-15);
  // force x exponential
  WindowSpec both{WindowKind::Force, 0.01, 0.0, 0.05};
  auto wb = makeWindow(both, 300, 1000.0, 20);
  ASSERT_TRUE(wb.ok());
  EXPECT_NEAR((*wb)[25], std::exp(-0.1), 1e-15);
  EXPECT_EQ((*wb)[40], 0.0);
  EXPECT_FALSE(makeWindow({WindowKind::Exponential, 0.0, 0.0, 0.0}, 10, 1000.0).ok());
  EXPECT_FALSE(makeWindow({WindowKind::Hann}, 0, 1000.0).ok());
  EXPECT_FALSE(makeWindow({WindowKind::Hann}, 10, 0.0).ok());
}

TEST(Window, ExponentialDampingAddedAndRemoved) {
  // sigma_meas = sigma_true + 1/tau with omega_d unchanged.
  const PoleEstimate truth{60.0, 0.002};
  const double tau = 0.5;
  auto m = applyExponentialWindowDamping(truth, tau);
  ASSERT_TRUE(m.ok());
  const double wt = 2 * kPi * truth.naturalFrequencyHz, wm = 2 * kPi * m->naturalFrequencyHz;
  EXPECT_NEAR(m->zeta * wm, truth.zeta * wt + 1.0 / tau, 1e-12);
  EXPECT_NEAR(wm * std::sqrt(1 - m->zeta * m->zeta), wt * std::sqrt(1 - truth.zeta * truth.zeta), 1e-9);
  EXPECT_DOUBLE_EQ(exponentialWindowAddedDecayRate(tau), 2.0);
  auto back = correctExponentialWindowDamping(*m, tau);
  ASSERT_TRUE(back.ok());
  EXPECT_NEAR(back->zeta, truth.zeta, 1e-12);
  EXPECT_NEAR(back->naturalFrequencyHz, truth.naturalFrequencyHz, 1e-9);
  // a measured decay below the window's own cannot be corrected
  auto bad = correctExponentialWindowDamping(PoleEstimate{60.0, 0.001}, 0.5);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::NumericalFailure);
  EXPECT_FALSE(correctExponentialWindowDamping(PoleEstimate{60.0, 0.01}, 0.0).ok());
  EXPECT_FALSE(correctExponentialWindowDamping(PoleEstimate{-1.0, 0.01}, 1.0).ok());
}

}  // namespace
}  // namespace mozzi::core::signal
