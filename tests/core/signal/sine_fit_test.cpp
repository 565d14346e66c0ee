// Sine fitting (thesis §1.3 dynamic twist axis, §1.9 relaxation test): exact
// recovery on clean data and honest uncertainties on noisy data.
#include "core/signal/sine_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vector sine(Eigen::Index n, double fs, double f, double amp, double phase, double offset, double t0 = 0.0) {
  Vector y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    y[i] = offset + amp * std::cos(2 * kPi * f * (t0 + static_cast<double>(i) / fs) + phase);
  }
  return y;
}

// Issue 3: exact on clean data to 1e-9 relative.
TEST(SineFit, KnownFrequencyExactOnCleanData) {
  // 5 Hz actuator test (thesis Fig. 4) sampled at 1 kHz, 2.3 periods (not an
  // integer number, so the cos/sin columns are not orthogonal)
  const Vector y = sine(460, 1000.0, 5.0, 0.8e-3, 1.1, 2e-4, 0.013);
  auto fit = fitSineKnownFrequency(y, 1000.0, 5.0, 0.013);
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  EXPECT_NEAR(fit->amplitude / 0.8e-3, 1.0, 1e-9);
  EXPECT_NEAR(fit->phaseRad, 1.1, 1e-9);
  EXPECT_NEAR(fit->offset / 2e-4, 1.0, 1e-9);
  EXPECT_LT(fit->residualRms, 1e-9 * 0.8e-3);
}

TEST(SineFit, UnknownFrequencyExactOnCleanData) {
  // 0.42 Hz yaw oscillation of the Mototiremeter (thesis §1.9), 100 Hz, 12 s
  const Vector y = sine(1200, 100.0, 0.42, 1.5, -2.0, 0.1);
  auto fit = fitSine(y, 100.0);
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  EXPECT_NEAR(fit->frequencyHz / 0.42, 1.0, 1e-9);
  EXPECT_NEAR(fit->amplitude / 1.5, 1.0, 1e-9);
  EXPECT_NEAR(fit->phaseRad, -2.0, 1e-9);
  EXPECT_NEAR(fit->offset / 0.1, 1.0, 1e-9);
}

TEST(SineFit, PhaseWrapsAndNegativeAmplitudeConventions) {
  const Vector y = sine(300, 200.0, 7.0, 2.0, kPi, 0.0);  // phase exactly pi
  auto fit = fitSineKnownFrequency(y, 200.0, 7.0);
  ASSERT_TRUE(fit.ok());
  EXPECT_NEAR(std::abs(fit->phaseRad), kPi, 1e-9);
  EXPECT_GT(fit->amplitude, 0.0);
  EXPECT_NEAR(wrapPhase(3 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrapPhase(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrapPhase(0.5 - 4 * kPi), 0.5, 1e-12);
}

// §1.9: the yaw angle phase follows from the yaw-rate fit, velocity leading
// displacement by pi/2; the force's lag against the angle is a phase difference.
TEST(SineFit, YawRateGivesAnglePhaseAndForceLag) {
  const double fs = 200.0, f = 1.26, w = 2 * kPi * f;
  const double psi0 = 1.5 * kPi / 180.0, phiAngle = 0.3, lag = 0.25;
  // yaw rate psi' = -w psi0 sin(wt + phi) = w psi0 cos(wt + phi + pi/2)
  Vector rate(800);
  for (Eigen::Index i = 0; i < rate.size(); ++i) rate[i] = -w * psi0 * std::sin(w * i / fs + phiAngle);
  const Vector force = sine(800, fs, f, 250.0, phiAngle - lag, 0.0);
  auto r = fitSineKnownFrequency(rate, fs, f);
  auto F = fitSineKnownFrequency(force, fs, f);
  ASSERT_TRUE(r.ok() && F.ok());
  EXPECT_NEAR(displacementPhaseFromVelocity(r->phaseRad), phiAngle, 1e-9);
  EXPECT_NEAR(r->amplitude / w, psi0, 1e-12);
  SineFit angle = *r;
  angle.phaseRad = displacementPhaseFromVelocity(r->phaseRad);
  EXPECT_NEAR(phaseDifference(*F, angle).phaseRad, -lag, 1e-9);  // force lags: negative
}

TEST(SineFit, StudentQuantileMatchesTables) {
  // t(0.975, dof) from standard tables (e.g. Abramowitz & Stegun 26.10)
  EXPECT_NEAR(studentT975(5), 2.5706, 2e-3);
  EXPECT_NEAR(studentT975(10), 2.2281, 5e-4);
  EXPECT_NEAR(studentT975(30), 2.0423, 1e-4);
  EXPECT_NEAR(studentT975(1000), 1.9623, 1e-4);
}

// Issue 3: the true amplitude and phase fall inside the reported 95% intervals
// in 93%..97% of 1000 seeded trials. With p = 0.95 the count over 1000 trials
// has standard deviation 6.9, so 930..970 is a +-2.9 sigma window: an honest
// interval passes, one 20% too narrow (coverage ~89%) or too wide (~98.5%)
// does not.
struct Coverage {
  int amplitude = 0, phase = 0;
};

template <class Fit>
Coverage coverage(Fit fitFn, std::uint64_t seed, Eigen::Index n, double noise) {
  const double fs = 500.0, f = 12.3, amp = 1.0, phase = 0.7, offset = 0.2;
  const Vector clean = sine(n, fs, f, amp, phase, offset);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, noise);
  Coverage c;
  for (int trial = 0; trial < 1000; ++trial) {
    Vector y = clean;
    for (Eigen::Index i = 0; i < n; ++i) y[i] += normal(rng);
    auto fit = fitFn(y, fs, f);
    EXPECT_TRUE(fit.ok());
    if (!fit.ok()) continue;
    if (std::abs(fit->amplitude - amp) <= fit->amplitudeCi95()) ++c.amplitude;
    if (std::abs(wrapPhase(fit->phaseRad - phase)) <= fit->phaseCi95()) ++c.phase;
  }
  return c;
}

TEST(SineFit, KnownFrequencyConfidenceIntervalsAreHonest) {
  // 60 samples, noise 0.3 of the amplitude: SNR low enough that the
  // uncertainty is not trivial, t-quantile with 57 dof matters (2.00 vs 1.96)
  const Coverage c =
      coverage([](const Vector& y, double fs, double f) { return fitSineKnownFrequency(y, fs, f); }, 20261121, 60, 0.3);
  std::printf("known frequency: amplitude coverage %d/1000, phase coverage %d/1000\n", c.amplitude, c.phase);
  EXPECT_GE(c.amplitude, 930);
  EXPECT_LE(c.amplitude, 970);
  EXPECT_GE(c.phase, 930);
  EXPECT_LE(c.phase, 970);
}

TEST(SineFit, UnknownFrequencyConfidenceIntervalsAreHonest) {
  const Coverage c =
      coverage([](const Vector& y, double fs, double f) { return fitSine(y, fs, f * 1.002); }, 77, 200, 0.3);
  std::printf("unknown frequency: amplitude coverage %d/1000, phase coverage %d/1000\n", c.amplitude, c.phase);
  EXPECT_GE(c.amplitude, 930);
  EXPECT_LE(c.amplitude, 970);
  EXPECT_GE(c.phase, 930);
  EXPECT_LE(c.phase, 970);
}

TEST(SineFit, StandardErrorsMatchNoiseLevel) {
  // For n samples over whole periods, var(a) = var(b) = 2 s^2 / n, so
  // se(A) = s sqrt(2/n) and se(phi) = se(A) / A.
  const Eigen::Index n = 1000;
  const double fs = 1000.0, f = 10.0, s = 0.05;
  Vector y = sine(n, fs, f, 2.0, 0.4, 0.0);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, s);
  for (Eigen::Index i = 0; i < n; ++i) y[i] += normal(rng);
  auto fit = fitSineKnownFrequency(y, fs, f);
  ASSERT_TRUE(fit.ok());
  // sigma estimated from 997 dof: relative spread 1/sqrt(2 * 997) = 2.2%; 8% is 3.5 sigma
  EXPECT_NEAR(fit->sigma / s, 1.0, 0.08);
  EXPECT_NEAR(fit->amplitudeStdError / (fit->sigma * std::sqrt(2.0 / n)), 1.0, 1e-6);
  EXPECT_NEAR(fit->phaseStdError / (fit->amplitudeStdError / fit->amplitude), 1.0, 1e-6);
}

TEST(SineFit, BadInputIsAnError) {
  const Vector y = sine(100, 100.0, 5.0, 1.0, 0.0, 0.0);
  EXPECT_FALSE(fitSineKnownFrequency(y, 0.0, 5.0).ok());            // sample rate 0
  EXPECT_FALSE(fitSineKnownFrequency(y, 100.0, 0.0).ok());          // f = 0
  EXPECT_FALSE(fitSineKnownFrequency(y, 100.0, 50.0).ok());         // Nyquist
  EXPECT_FALSE(fitSineKnownFrequency(Vector(3), 100.0, 5.0).ok());  // too short
  EXPECT_FALSE(fitSine(Vector(), 100.0).ok());                      // empty
  Vector bad = y;
  bad[17] = std::nan("");
  auto r = fitSineKnownFrequency(bad, 100.0, 5.0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().where.find("sample 17"), std::string::npos) << r.error().describe();
  EXPECT_FALSE(fitSine(bad, 100.0).ok());
  // constant record: no sine to find, the frequency is undetermined
  auto flat = fitSine(Vector::Constant(100, 3.0), 100.0, 5.0);
  EXPECT_FALSE(flat.ok());
}

}  // namespace
}  // namespace mozzi::core::signal
