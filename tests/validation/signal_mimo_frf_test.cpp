// Validation of the multiple-reference H1 estimator (H = Gyf Gff^-1 per line,
// frf_estimator.h) against the analytic FRF matrix of 2-DOF and 3-DOF systems
// driven by two uncorrelated random forces at once (a two-shaker test):
//   receptance  H(omega) = (K - omega^2 M + i omega C)^-1, accelerance -omega^2 H
// (thesis eq. 19 in the usual sign form, notes.md).
//
// Excitation: periodic random (core/signal/shaker_synthesis), i.e. per block a
// multisine on every DFT line with independent random phases for each force,
// run from rest for three blocks (all modes decay by >= 3.26 1/s: transient
// below 3e-9 after 6 s) and measured on the fourth; exact state-transition
// simulation (core/signal/mdof_simulation, first-order hold) on a grid 32
// times finer than the DAQ rate, so every block is leakage-free with
// rectangular windows.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "core/signal/fft.h"
#include "core/signal/frf_estimator.h"
#include "core/signal/mdof_simulation.h"
#include "core/signal/shaker_synthesis.h"

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFs = 512.0;         // DAQ rate [Hz]
constexpr Eigen::Index kN = 1024;     // block: 2 s, lines 0.5 Hz apart
constexpr Eigen::Index kFine = 32;    // simulation grid kFine * kFs
constexpr Eigen::Index kPeriods = 4;  // three to settle, the last measured
constexpr double kForceRms = 10.0;    // [N] per force

// (K - omega^2 M + i omega C)^-1
ComplexMatrix analyticReceptance(const LinearMdof& s, double fHz) {
  const double w = 2.0 * kPi * fHz;
  const ComplexMatrix z =
      s.stiffness.cast<Complex>() - w * w * s.mass.cast<Complex>() + Complex(0.0, w) * s.damping.cast<Complex>();
  return z.inverse();
}

// Chain ground-k1-m1-k2-m2-k3-m3, C = 6 M + 1e-4 K: modes 11.5, 26.5 and
// 37.5 Hz, zeta 4.5 %, 2.6 %, 2.5 %.
LinearMdof threeDof() {
  LinearMdof s;
  s.mass = Eigen::Vector3d(2.0, 1.5, 1.0).asDiagonal();
  s.stiffness.resize(3, 3);
  s.stiffness << 7e4, -3e4, 0.0, -3e4, 5e4, -2e4, 0.0, -2e4, 2e4;
  s.damping = 6.0 * s.mass + 1e-4 * s.stiffness;
  return s;
}

// Chain ground-k1-m1-k2-m2, C = 6 M + 1e-4 K: modes 35.6 and 71.2 Hz.
LinearMdof twoDof() {
  LinearMdof s;
  s.mass = Eigen::Vector2d(1.0, 0.5).asDiagonal();
  s.stiffness.resize(2, 2);
  s.stiffness << 1.5e5, -5e4, -5e4, 5e4;
  s.damping = 6.0 * s.mass + 1e-4 * s.stiffness;
  return s;
}

struct Campaign {
  std::vector<TimeRecord> receptance;       // forces, then displacement of every DOF
  std::vector<TimeRecord> accelerance;      // the same forces, then acceleration of every DOF
  std::vector<ComplexMatrix> forceSpectra;  // per block: lines x forces (DFT of the force samples)
};

struct CampaignSpec {
  std::vector<Eigen::Index> forcedDofs;
  int realisations = 16;
  std::uint64_t seed = 1;
  double responseNoiseRms = 0.0;        // white noise on each response [EU]
  Eigen::Index copyLo = 1, copyHi = 0;  // lines where the second force copies the first's phases
};

Campaign simulate(const LinearMdof& sys, const CampaignSpec& spec) {
  ShakerTestSpec s;
  s.sampleRateHz = kFs;
  s.blockSamples = kN;
  s.oversampling = kFine;
  s.settleBlocks = kPeriods - 1;
  s.forcedDofs = spec.forcedDofs;
  s.forceRmsN = kForceRms;
  s.blocks = spec.realisations;
  s.seed = spec.seed;  // same seed: the same forces for both response kinds
  s.responseNoiseRms = spec.responseNoiseRms;
  s.correlatedFromLine = spec.copyLo;
  s.correlatedToLine = spec.copyHi;
  Campaign c;
  s.responseKind = TransducerKind::Displacement;
  auto rec = synthesizeShakerBlocks(sys, s);
  s.responseKind = TransducerKind::Acceleration;
  auto acc = synthesizeShakerBlocks(sys, s);
  EXPECT_TRUE(rec.ok() && acc.ok());
  if (!rec.ok() || !acc.ok()) return c;
  c.receptance = std::move(*rec);
  c.accelerance = std::move(*acc);
  auto daqFft = RealFft::forLength(kN);
  const auto nr = static_cast<Eigen::Index>(spec.forcedDofs.size());
  for (const auto& r : c.receptance) {
    ComplexMatrix fs(kN / 2 + 1, nr);
    for (Eigen::Index i = 0; i < nr; ++i) fs.col(i) = *(*daqFft)->transform(r.samples.col(i));
    c.forceSpectra.push_back(fs);
  }
  return c;
}

// Largest relative complex error |H_est - H| / |H| over 0 < f <= fMax, over
// every (response, reference) pair; accelerance when `accel`.
double maxRelativeError(const FrfMatrix& m, const LinearMdof& sys, const std::vector<Eigen::Index>& forced, bool accel,
                        double fMax) {
  double worst = 0.0;
  for (Eigen::Index k = 1; k < m.lineCount() && m.frequencyHz[k] <= fMax; ++k) {
    const double f = m.frequencyHz[k];
    ComplexMatrix h = analyticReceptance(sys, f);
    if (accel) h *= -std::pow(2.0 * kPi * f, 2);
    for (std::size_t i = 0; i < forced.size(); ++i) {
      for (Eigen::Index o = 0; o < m.responseCount(); ++o) {
        const Complex truth = h(o, forced[i]);
        worst = std::max(worst, std::abs(m.h[i](k, o) - truth) / std::abs(truth));
      }
    }
  }
  return worst;
}

// The accuracy bound of the simulation itself: the first-order hold applies
// the piecewise-linear interpolant of the multisine, whose component at f is
// scaled by sinc^2(pi f h) ~ 1 - (pi f h)^2 / 3 (h = 1 / (32 fs)): 2.0e-4 at
// 128 Hz. The images of the interpolant near multiples of 32 fs, aliased back
// by the sampling, add (pi f h)^2 / pi^2 times H there over H in band, below
// 1e-4 relative for these systems away from the antiresonances. Tolerance:
// 2e-3 relative (ten times the hold's bound, for the antiresonances where
// |H| is small); the transient left after three blocks (3e-9) and rounding
// are far below.
constexpr double kExactTolerance = 2e-3;
constexpr double kBandHz = 128.0;  // fs / 4, above every mode of both systems

TEST(MultiReferenceFrf, ThreeDofTwoUncorrelatedForcesGiveTheAnalyticReceptanceAndAccelerance) {
  const LinearMdof sys = threeDof();
  CampaignSpec spec;
  spec.forcedDofs = {0, 2};
  const Campaign c = simulate(sys, spec);
  auto rec = estimateFrf(c.receptance, FrfOptions{});
  ASSERT_TRUE(rec.ok()) << rec.error().describe();
  ASSERT_EQ(rec->referenceCount(), 2);
  ASSERT_EQ(rec->responseCount(), 3);
  EXPECT_EQ(rec->type, FrfType::Receptance);
  EXPECT_EQ(rec->references[1], (Dof{3, Direction::Z, false}));
  EXPECT_TRUE(rec->validate().ok());
  const double eRec = maxRelativeError(*rec, sys, spec.forcedDofs, false, kBandHz);
  EXPECT_LT(eRec, kExactTolerance);

  auto acc = estimateFrf(c.accelerance, FrfOptions{});
  ASSERT_TRUE(acc.ok()) << acc.error().describe();
  EXPECT_EQ(acc->type, FrfType::Accelerance);
  const double eAcc = maxRelativeError(*acc, sys, spec.forcedDofs, true, kBandHz);
  EXPECT_LT(eAcc, kExactTolerance);

  // Noise-free and linear: every output is fully explained by the two forces,
  // multiple coherence 1 (to rounding and the hold's error).
  double minCoh = 1.0;
  for (Eigen::Index k = 1; k < rec->lineCount() && rec->frequencyHz[k] <= kBandHz; ++k) {
    minCoh = std::min(minCoh, rec->coherence[0].row(k).minCoeff());
  }
  EXPECT_GT(minCoh, 0.9999);
  std::printf(
      "3-DOF, 2 forces, 16 blocks: max rel. error receptance %.2e, accelerance %.2e, min multiple coherence %.6f\n",
      eRec, eAcc, minCoh);
}

TEST(MultiReferenceFrf, TwoDofBothDofsDrivenGiveTheWholeAccelerance) {
  const LinearMdof sys = twoDof();
  CampaignSpec spec;
  spec.forcedDofs = {0, 1};
  spec.seed = 7;
  spec.realisations = 8;
  const Campaign c = simulate(sys, spec);
  auto acc = estimateFrf(c.accelerance, FrfOptions{});
  ASSERT_TRUE(acc.ok()) << acc.error().describe();
  const double e = maxRelativeError(*acc, sys, spec.forcedDofs, true, kBandHz);
  EXPECT_LT(e, kExactTolerance);
  // reciprocity of the estimate (not imposed by H1): A_12 = A_21
  double recip = 0.0;
  for (Eigen::Index k = 1; k < acc->lineCount() && acc->frequencyHz[k] <= kBandHz; ++k) {
    recip = std::max(recip, std::abs(acc->h[1](k, 0) - acc->h[0](k, 1)) / std::abs(acc->h[0](k, 1)));
  }
  EXPECT_LT(recip, kExactTolerance);
  std::printf("2-DOF, 2 forces, 8 blocks: max rel. error %.2e, reciprocity %.2e\n", e, recip);
}

// With output noise the H1 error at a line is the least-squares error of
// Y = H F over the blocks: complex Gaussian with variance
// sigma_n^2 [(F^H F)^-1]_ii per (output, reference i), sigma_n^2 = n sigma^2
// the noise power of one DFT line. So |error|^2 / that variance is Exp(1):
// its mean over the 3,066 comparisons must be 1 (standard error 0.018; the
// bounds 0.85..1.15 are 8 standard errors) and no single one may exceed 25
// (probability e^-25 each). This checks that H1 = Gyf Gff^-1 is unbiased by
// output noise and as precise as the theory says, not merely "close".
TEST(MultiReferenceFrf, OutputNoiseErrorsFollowLeastSquaresTheory) {
  const LinearMdof sys = threeDof();
  CampaignSpec spec;
  spec.forcedDofs = {0, 2};
  spec.realisations = 24;
  spec.seed = 3;
  spec.responseNoiseRms = 2e-6;  // [m], about 5 % of the displacement RMS
  const Campaign c = simulate(sys, spec);
  auto rec = estimateFrf(c.receptance, FrfOptions{});
  ASSERT_TRUE(rec.ok()) << rec.error().describe();
  const double noiseLine = static_cast<double>(kN) * spec.responseNoiseRms * spec.responseNoiseRms;
  double sum = 0.0, worst = 0.0;
  int count = 0;
  for (Eigen::Index k = 1; k < rec->lineCount() - 1; ++k) {  // DC and Nyquist are real lines
    ComplexMatrix ff = ComplexMatrix::Zero(2, 2);
    for (const auto& fs : c.forceSpectra) ff += fs.row(k).adjoint() * fs.row(k);  // F^H F
    const ComplexMatrix ffInv = ff.inverse();
    const ComplexMatrix h = analyticReceptance(sys, rec->frequencyHz[k]);
    for (int i = 0; i < 2; ++i) {
      for (Eigen::Index o = 0; o < 3; ++o) {
        const double z2 =
            std::norm(rec->h[static_cast<std::size_t>(i)](k, o) - h(o, spec.forcedDofs[static_cast<std::size_t>(i)])) /
            (noiseLine * ffInv(i, i).real());
        sum += z2;
        worst = std::max(worst, z2);
        ++count;
      }
    }
  }
  const double mean = sum / count;
  EXPECT_GT(mean, 0.85);
  EXPECT_LT(mean, 1.15);
  EXPECT_LT(worst, 25.0);
  std::printf("output noise: %d comparisons, mean normalised squared error %.3f (theory 1), max %.1f\n", count, mean,
              worst);
}

TEST(MultiReferenceFrf, CorrelatedForcesAreAClearErrorNamingTheLines) {
  const LinearMdof sys = twoDof();
  // The second force copies the first one's phases on lines 80..120 (40 to
  // 60 Hz): there the two are fully coherent and Gff is singular.
  CampaignSpec spec;
  spec.forcedDofs = {0, 1};
  spec.realisations = 8;
  spec.copyLo = 80;
  spec.copyHi = 120;
  const Campaign c = simulate(sys, spec);
  auto avg = SpectralAverager::create(c.accelerance.front(), FrfOptions{});
  ASSERT_TRUE(avg.ok());
  for (const auto& r : c.accelerance) ASSERT_TRUE(avg->add(r).ok());
  auto frf = avg->frf();
  ASSERT_FALSE(frf.ok());
  const std::string msg = frf.error().message;
  EXPECT_NE(msg.find("correlated"), std::string::npos) << msg;
  EXPECT_NE(msg.find("41 of 513 lines"), std::string::npos) << msg;
  EXPECT_NE(msg.find("40 Hz to 60 Hz"), std::string::npos) << msg;  // the band is named
  const Vector cond = avg->referenceConditionNumber();
  EXPECT_GT(cond.segment(80, 41).minCoeff(), 1e6);  // singular to rounding
  EXPECT_LT(cond.head(80).maxCoeff(), 100.0);
  std::printf("correlated band: %s\n", msg.c_str());

  // one signal driving both shakers: every line bad
  CampaignSpec same = spec;
  same.copyLo = 0;
  same.copyHi = 512;
  const Campaign s = simulate(sys, same);
  auto all = estimateFrf(s.accelerance, FrfOptions{});
  ASSERT_FALSE(all.ok());
  EXPECT_NE(all.error().message.find("513 of 513 lines"), std::string::npos) << all.error().message;

  // fewer blocks than references: Gff has rank 1 everywhere
  auto one = estimateFrf({c.accelerance.front()}, FrfOptions{});
  ASSERT_FALSE(one.ok());
  EXPECT_NE(one.error().message.find("ill-conditioned"), std::string::npos);
}

TEST(MultiReferenceFrf, OneReferenceOfTwoActingForcesIsWrongAndItsCoherenceSaysSo) {
  // Why the multiple-input estimator is needed: H1 against force 1 alone (the
  // second force's channel dropped) sees force 2 as uncorrelated noise.
  const LinearMdof sys = threeDof();
  CampaignSpec spec;
  spec.forcedDofs = {0, 2};
  const Campaign c = simulate(sys, spec);
  std::vector<TimeRecord> firstOnly;
  for (TimeRecord r : c.receptance) {
    r.channels.erase(r.channels.begin() + 1);
    Matrix keep(r.samples.rows(), r.samples.cols() - 1);
    keep << r.samples.col(0), r.samples.rightCols(r.samples.cols() - 2);
    r.samples = keep;
    firstOnly.push_back(std::move(r));
  }
  auto single = estimateFrf(firstOnly, FrfOptions{});
  ASSERT_TRUE(single.ok()) << single.error().describe();
  ASSERT_EQ(single->referenceCount(), 1);
  EXPECT_GT(maxRelativeError(*single, sys, {0}, false, kBandHz), 0.1);
  // DOF 3 is driven mostly by force 2 at its own DOF: low ordinary coherence with force 1
  double meanCoh = 0.0;
  int lines = 0;
  for (Eigen::Index k = 1; k < single->lineCount() && single->frequencyHz[k] <= kBandHz; ++k, ++lines) {
    meanCoh += single->coherence[0](k, 2);
  }
  EXPECT_LT(meanCoh / lines, 0.9);

  // H2 and Hv are single-reference estimators
  FrfOptions h2;
  h2.estimator = FrfEstimator::H2;
  auto bad = SpectralAverager::create(c.receptance.front(), h2);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("use H1"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::signal
