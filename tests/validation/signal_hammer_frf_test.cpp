// Validation of the hammer FRF chain (thesis §1.4, §1.6, §5.2) against analytic
// FRFs: hits on SDOF and 2-DOF systems are synthesised by exact state-transition
// simulation with measurement noise, processed like a campaign (quality check,
// windows, averaging) and compared with the closed-form accelerance
//   A(omega) = -omega^2 (K - omega^2 M + i omega C)^-1   (thesis eq. 19, usual sign form, notes.md).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/signal/frf_estimator.h"
#include "core/signal/hit_quality.h"
#include "core/signal/hit_synthesis.h"
#include "core/signal/window.h"

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Analytic accelerance column for a force at DOF `input`.
ComplexVector analyticAccelerance(const LinearMdof& s, double fHz, Eigen::Index input) {
  const double w = 2.0 * kPi * fHz;
  const ComplexMatrix z =
      s.stiffness.cast<Complex>() - w * w * s.mass.cast<Complex>() + Complex(0.0, w) * s.damping.cast<Complex>();
  ComplexVector e = ComplexVector::Zero(s.dofCount());
  e[input] = 1.0;
  return -w * w * z.partialPivLu().solve(e);
}

LinearMdof sdof(double m, double fn, double zeta) {
  const double w = 2.0 * kPi * fn;
  LinearMdof s;
  s.mass = Matrix::Constant(1, 1, m);
  s.stiffness = Matrix::Constant(1, 1, m * w * w);
  s.damping = Matrix::Constant(1, 1, 2.0 * zeta * m * w);
  return s;
}

// Chain ground-k1-m1-k2-m2 with stiffness-proportional damping C = beta K:
// modes at 35.6 Hz and 71.2 Hz (eigenvalues 5e4 and 2e5 (rad/s)^2).
LinearMdof twoDof() {
  LinearMdof s;
  s.mass = Eigen::Vector2d(1.0, 0.5).asDiagonal();
  s.stiffness.resize(2, 2);
  s.stiffness << 1.5e5, -5e4, -5e4, 5e4;
  s.damping = 2e-4 * s.stiffness;  // zeta_r = beta omega_r / 2 = 2.2%, 4.5%
  return s;
}

struct Campaign {
  std::vector<TimeRecord> hits;
  std::vector<HitQuality> quality;
};

Campaign hammer(const LinearMdof& sys, int hits, double forceNoise, double responseNoise, std::uint64_t seed,
                double pulseWidthS = 2e-3) {
  Campaign c;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> peak(70.0, 130.0);
  for (int h = 0; h < hits; ++h) {
    HammerHitSpec spec;
    spec.peakForceN = peak(rng);  // technicians never hit twice alike
    spec.pulseWidthS = pulseWidthS;
    spec.forceNoiseRms = forceNoise;
    spec.responseNoiseRms = responseNoise;
    spec.seed = seed * 1000 + static_cast<std::uint64_t>(h);
    auto rec = synthesizeHammerHit(sys, spec);
    EXPECT_TRUE(rec.ok()) << (rec.ok() ? "" : rec.error().describe());
    auto q = assessHit(*rec);
    EXPECT_TRUE(q.ok());
    c.hits.push_back(*rec);
    c.quality.push_back(*q);
  }
  return c;
}

struct BandError {
  double maxMagRel = 0.0;
  double maxPhaseDeg = 0.0;
  double minCoherence = 1.0;
  double worstHz = 0.0;  // line of the largest |H| error, for the failure message
  int lines = 0;
};

BandError compare(const FrfMatrix& frf, const LinearMdof& sys, Eigen::Index input, double fLo, double fHi,
                  Eigen::Index onlyResponse = -1) {
  BandError e;
  for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
    const double f = frf.frequencyHz[k];
    if (f < fLo || f > fHi) continue;
    const ComplexVector a = analyticAccelerance(sys, f, input);
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      if (onlyResponse >= 0 && o != onlyResponse) continue;
      const Eigen::Index dof = frf.responses[static_cast<std::size_t>(o)].node - 1;
      const Complex ratio = frf.h[0](k, o) / a[dof];
      if (std::abs(std::abs(ratio) - 1.0) > e.maxMagRel) e.worstHz = f;
      e.maxMagRel = std::max(e.maxMagRel, std::abs(std::abs(ratio) - 1.0));
      e.maxPhaseDeg = std::max(e.maxPhaseDeg, std::abs(std::arg(ratio)) * 180.0 / kPi);
      e.minCoherence = std::min(e.minCoherence, frf.coherence[0](k, o));
    }
    ++e.lines;
  }
  return e;
}

// Lower band edge: a grounded system's accelerance vanishes like omega^2 at DC,
// so far below the first mode the response is buried in the sensor noise of
// any real accelerometer; the test band is [20 Hz, f_-10dB of the force
// spectrum], i.e. from a third of the first natural frequency upwards.
constexpr double kLowEdgeHz = 20.0;
// Noise: 0.02 N on the force and 0.002 m/s^2 on the accelerometers, about
// 2e-4 and 4e-5 of the peaks (74 and 88 dB, a 24-bit DAQ with IEPE sensors).
constexpr double kForceNoise = 0.02;
constexpr double kAccelNoise = 0.002;

double usableBand(const Campaign& c) {
  double band = 1e300;
  for (const auto& q : c.quality) band = std::min(band, q.usableBand10dBHz.value_or(1e300));
  return band;
}

TEST(SignalHammerFrf, SdofRecoveredWithinOnePercentAndOneDegree) {
  const LinearMdof sys = sdof(1.0, 60.0, 0.02);
  const Campaign c = hammer(sys, 5, kForceNoise, kAccelNoise, 11);
  for (const auto& q : c.quality) ASSERT_TRUE(q.accepted) << q.verdictText();
  const double band = usableBand(c);
  // half-sine of 2 ms: -10 dB near f = 1.02 / Tp = 510 Hz
  ASSERT_GT(band, 400.0);
  for (auto est : {FrfEstimator::H1, FrfEstimator::H2, FrfEstimator::Hv}) {
    // force window 10 ms + 5 ms taper: keeps the force noise of the 4 s record
    // out of G_ff (standard hammer processing; the pulse lasts 2 ms)
    const FrfOptions opt = FrfOptions::hammer(est, 0.010, 0.005, std::nullopt);
    auto frf = estimateFrf(c.hits, opt);
    ASSERT_TRUE(frf.ok()) << frf.error().describe();
    ASSERT_TRUE(frf->validate().ok());
    EXPECT_EQ(frf->type, FrfType::Accelerance);
    const BandError e = compare(*frf, sys, 0, kLowEdgeHz, band);
    std::printf(
        "SDOF %s: %d lines %.0f..%.0f Hz, max |H| error %.3f%% (at %.2f Hz), max phase error %.3f deg, "
        "min coherence %.5f\n",
        frfEstimatorName(est), e.lines, kLowEdgeHz, band, 100 * e.maxMagRel, e.worstHz, e.maxPhaseDeg, e.minCoherence);
    EXPECT_GT(e.lines, 1000);
    EXPECT_LT(e.maxMagRel, 0.01);     // issue 3: |H| within 1%
    EXPECT_LT(e.maxPhaseDeg, 1.0);    // issue 3: phase within 1 degree
    EXPECT_GT(e.minCoherence, 0.99);  // issue 3: coherence above 0.99 in band
  }
}

TEST(SignalHammerFrf, TwoDofPointAndTransferRecovered) {
  // Modes at 35.6 and 71.2 Hz: a softer tip (5 ms pulse, band ~200 Hz, about
  // three times the highest mode, as a technician would choose) keeps the
  // transfer accelerance, which falls as 1/omega^2 above the second mode,
  // well above the sensor noise across the band.
  const LinearMdof sys = twoDof();
  const Campaign c = hammer(sys, 10, kForceNoise, kAccelNoise, 23, 5e-3);
  for (const auto& q : c.quality) ASSERT_TRUE(q.accepted) << q.verdictText();
  const double band = usableBand(c);
  ASSERT_GT(band, 180.0);  // -10 dB near 1.02 / Tp = 204 Hz
  auto frf = estimateFrf(c.hits, FrfOptions::hammer(FrfEstimator::H1, 0.015, 0.005, std::nullopt));
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  ASSERT_EQ(frf->responseCount(), 2);
  for (Eigen::Index o = 0; o < 2; ++o) {
    const BandError e = compare(*frf, sys, 0, kLowEdgeHz, band, o);
    std::printf(
        "2-DOF H1 response %ld: %d lines %.0f..%.0f Hz, max |H| error %.3f%% (at %.2f Hz), max phase error "
        "%.3f deg, min coherence %.5f\n",
        static_cast<long>(o), e.lines, kLowEdgeHz, band, 100 * e.maxMagRel, e.worstHz, e.maxPhaseDeg, e.minCoherence);
    EXPECT_LT(e.maxMagRel, 0.01);
    EXPECT_LT(e.maxPhaseDeg, 1.0);
    EXPECT_GT(e.minCoherence, 0.99);
  }
  // Resonances where theory puts them: |H11| peaks within one line (0.25 Hz)
  // of the damped natural frequencies 35.58 and 71.18 Hz... checked through
  // the analytic comparison above; here the receptance conversion (thesis
  // eq. 7, divide by -omega^2) of a line off DC matches the analytic receptance.
  auto rec = [&] {
    FrfMatrix noDc = *frf;
    const Eigen::Index nf = noDc.lineCount() - 1;
    noDc.frequencyHz = frf->frequencyHz.tail(nf).eval();
    noDc.h[0] = frf->h[0].bottomRows(nf).eval();
    noDc.coherence[0] = frf->coherence[0].bottomRows(nf).eval();
    return noDc.convertedTo(FrfType::Receptance);
  }();
  ASSERT_TRUE(rec.ok()) << rec.error().describe();
  const Eigen::Index k = 4 * 50 - 1;  // 50 Hz (line 200 of the full axis, df = 0.25 Hz)
  ASSERT_DOUBLE_EQ(rec->frequencyHz[k], 50.0);
  const ComplexVector a = analyticAccelerance(sys, 50.0, 0);
  const double w = 2 * kPi * 50.0;
  EXPECT_NEAR(std::abs(rec->h[0](k, 1) / (a[1] / (-w * w)) - 1.0), 0.0, 0.01);
}

// Under input (force) noise H1 is biased low by G_ss / (G_ss + G_mm); under
// output noise H2 is biased high by (1 + G_nn / (|H|^2 G_ss)), while the other
// estimator stays unbiased (Bendat & Piersol, Random Data, ch. 9).
TEST(SignalHammerFrf, H1LowH2HighUnderNoise) {
  const LinearMdof sys = sdof(1.0, 60.0, 0.02);
  const Eigen::Index n = 32768;
  const double band = 300.0;
  // Noise levels chosen for a bias of several percent in band.
  const double sigmaF = 1.0, sigmaX = 2.0;
  auto ratioStats = [&](const FrfMatrix& frf) {
    std::vector<double> r;
    for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
      const double f = frf.frequencyHz[k];
      if (f < 20.0 || f > band) continue;
      r.push_back(std::abs(frf.h[0](k, 0) / analyticAccelerance(sys, f, 0)[0]));
    }
    std::sort(r.begin(), r.end());
    return r[r.size() / 2];  // median of |H_est / H_true| over the band
  };
  // Expected biases from the noise-free spectra of the same hits.
  const Campaign clean = hammer(sys, 20, 0.0, 0.0, 31);
  auto cleanAvg = SpectralAverager::create(clean.hits.front(), FrfOptions{});
  ASSERT_TRUE(cleanAvg.ok());
  for (const auto& h : clean.hits) ASSERT_TRUE(cleanAvg->add(h).ok());
  const Vector gss = cleanAvg->gff();
  const Matrix gxx = cleanAvg->gxx();
  const Vector& freq = cleanAvg->frequencyHz();
  const double fs = clean.hits.front().sampleRateHz;
  // white noise of variance s^2 in this ESD scaling: 2 s^2 n / fs^2 per line
  const double gmm = 2.0 * sigmaF * sigmaF * static_cast<double>(n) / (fs * fs);
  const double gnn = 2.0 * sigmaX * sigmaX * static_cast<double>(n) / (fs * fs);
  std::vector<double> h1Expected, h2Expected;
  for (Eigen::Index k = 0; k < freq.size(); ++k) {
    if (freq[k] < 20.0 || freq[k] > band) continue;
    h1Expected.push_back(gss[k] / (gss[k] + gmm));
    h2Expected.push_back(1.0 + gnn / gxx(k, 0));
  }
  std::sort(h1Expected.begin(), h1Expected.end());
  std::sort(h2Expected.begin(), h2Expected.end());
  const double h1Theory = h1Expected[h1Expected.size() / 2];
  const double h2Theory = h2Expected[h2Expected.size() / 2];

  const Campaign inputNoise = hammer(sys, 20, sigmaF, 0.0, 31);
  const Campaign outputNoise = hammer(sys, 20, 0.0, sigmaX, 31);
  FrfOptions o1, o2;
  o1.estimator = FrfEstimator::H1;
  o2.estimator = FrfEstimator::H2;
  const double h1In = ratioStats(*estimateFrf(inputNoise.hits, o1));
  const double h2In = ratioStats(*estimateFrf(inputNoise.hits, o2));
  const double h1Out = ratioStats(*estimateFrf(outputNoise.hits, o1));
  const double h2Out = ratioStats(*estimateFrf(outputNoise.hits, o2));
  std::printf("input noise: median |H1/H| %.4f (theory %.4f), |H2/H| %.4f\n", h1In, h1Theory, h2In);
  std::printf("output noise: median |H1/H| %.4f, |H2/H| %.4f (theory %.4f)\n", h1Out, h2Out, h2Theory);
  EXPECT_LT(h1Theory, 0.97);  // the set-up does produce a visible bias
  EXPECT_GT(h2Theory, 1.03);
  // measured bias within 15% of the theoretical bias: the theory is the
  // large-average limit E[G_xx] / E[G_xf]; with 20 hits the ratio of averages
  // still carries a random part of relative size ~ sqrt(G_nn / G_xx / 20).
  EXPECT_NEAR((1.0 - h1In) / (1.0 - h1Theory), 1.0, 0.15);
  EXPECT_NEAR((h2Out - 1.0) / (h2Theory - 1.0), 1.0, 0.15);
  // the other estimator unbiased within 1%
  EXPECT_NEAR(h2In, 1.0, 0.01);
  EXPECT_NEAR(h1Out, 1.0, 0.01);

  // With both noises, |H1| <= |Hv| <= |H2| at every line (|H1|/|H2| = gamma^2 <= 1).
  Campaign both = hammer(sys, 10, sigmaF, sigmaX, 37);
  auto avg = SpectralAverager::create(both.hits.front(), FrfOptions{});
  ASSERT_TRUE(avg.ok());
  for (const auto& h : both.hits) ASSERT_TRUE(avg->add(h).ok());
  auto h1 = avg->frf(FrfEstimator::H1), h2 = avg->frf(FrfEstimator::H2), hv = avg->frf(FrfEstimator::Hv);
  ASSERT_TRUE(h1.ok() && h2.ok() && hv.ok());
  for (Eigen::Index k = 1; k < h1->lineCount(); ++k) {
    const double a1 = std::abs(h1->h[0](k, 0)), a2 = std::abs(h2->h[0](k, 0)), av = std::abs(hv->h[0](k, 0));
    ASSERT_LE(a1, av * (1 + 1e-12)) << "line " << k;
    ASSERT_LE(av, a2 * (1 + 1e-12)) << "line " << k;
    ASSERT_NEAR(a1 / a2, h1->coherence[0](k, 0), 1e-9) << "line " << k;
  }
}

// Second-order rational fit (Levy): H (s^2 + a1 s + a0) = b0 + b1 s + b2 s^2,
// linear least squares in (a1, a0, b0, b1, b2); pole s^2 + a1 s + a0 = 0 gives
// omega_n = sqrt(a0), zeta = a1 / (2 omega_n). Independent of core/signal.
PoleEstimate levyPole(const FrfMatrix& frf, double fLo, double fHi) {
  std::vector<Eigen::Index> lines;
  for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
    if (frf.frequencyHz[k] >= fLo && frf.frequencyHz[k] <= fHi) lines.push_back(k);
  }
  const auto m = static_cast<Eigen::Index>(lines.size());
  Matrix a(2 * m, 5);
  Vector b(2 * m);
  for (Eigen::Index r = 0; r < m; ++r) {
    const Eigen::Index k = lines[static_cast<std::size_t>(r)];
    const Complex s(0.0, 2 * kPi * frf.frequencyHz[k]);
    const Complex h = frf.h[0](k, 0);
    // H s a1 + H a0 - b0 - b1 s - b2 s^2 = -H s^2
    const Complex row[5] = {h * s, h, -1.0, -s, -s * s};
    const Complex rhs = -h * s * s;
    for (int j = 0; j < 5; ++j) {
      a(2 * r, j) = row[j].real();
      a(2 * r + 1, j) = row[j].imag();
    }
    b[2 * r] = rhs.real();
    b[2 * r + 1] = rhs.imag();
  }
  const Vector x = a.colPivHouseholderQr().solve(b);
  const double wn = std::sqrt(x[1]);
  return PoleEstimate{wn / (2 * kPi), x[0] / (2 * wn)};
}

// Issue 3: the exponential window's added damping is reported and corrected;
// corrected damping within 2% relative of the truth on synthetic data.
TEST(SignalHammerFrf, ExponentialWindowDampingCorrectedWithinTwoPercent) {
  // Lightly damped: sigma = 0.2% x 377 = 0.75 1/s, only e^-3 decay in the 4 s
  // record, so an exponential window is needed against leakage.
  const double fn = 60.0, zeta = 0.002, tau = 0.5;
  const LinearMdof sys = sdof(1.0, fn, zeta);
  const Campaign c = hammer(sys, 5, kForceNoise, kAccelNoise, 41);
  auto opt = FrfOptions::hammer(FrfEstimator::H1, 0.01, 0.005, tau);
  EXPECT_DOUBLE_EQ(opt.exponentialTauS(), tau);
  auto frf = estimateFrf(c.hits, opt);
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  const PoleEstimate measured = levyPole(*frf, fn - 5.0, fn + 5.0);
  auto corrected = correctExponentialWindowDamping(measured, tau);
  ASSERT_TRUE(corrected.ok()) << corrected.error().describe();
  auto predicted = applyExponentialWindowDamping(PoleEstimate{fn, zeta}, tau);
  ASSERT_TRUE(predicted.ok());
  std::printf("exp window tau %.2f s: measured zeta %.5f (predicted %.5f), corrected %.6f (true %.6f), fn %.4f Hz\n",
              tau, measured.zeta, predicted->zeta, corrected->zeta, zeta, corrected->naturalFrequencyHz);
  // The window's bias is large: zeta_meas ~ (0.75 + 2) / 377 = 0.0073.
  EXPECT_GT(measured.zeta, 3.0 * zeta);
  EXPECT_NEAR(measured.zeta / predicted->zeta, 1.0, 0.02);
  EXPECT_NEAR(corrected->zeta / zeta, 1.0, 0.02);  // issue 3: within 2% relative
  EXPECT_NEAR(corrected->naturalFrequencyHz / fn, 1.0, 1e-3);
}

}  // namespace
}  // namespace mozzi::core::signal
