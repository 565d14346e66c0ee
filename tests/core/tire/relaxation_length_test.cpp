// Relaxation length from the harmonic yaw test (thesis §1.9, eq. 28): the
// ground truth is a first-order tyre with a known sigma, whose lag is
// atan(w a/V) + atan(w sigma/V) (appendix 1, first-order FRF).
#include "core/tire/relaxation_length.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mozzi::core::tire {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kV = 5.0 / 3.6;  // thesis §1.9: 5 km/h
constexpr double kA = 0.07;       // Table 17, 120/70 R17 at 2 bar

// Yaw rate and force of a first-order tyre under psi = psi0 sin(w t)
// (1.5 deg, §5.1), sampled at fs for `cycles` cycles, with Gaussian noise.
HarmonicYawRecord synthesise(double f, double sigma, double cycles, double fs, double noiseRate, double noiseForce,
                             std::mt19937& rng) {
  const double w = 2 * kPi * f;
  const double psi0 = 1.5 * kPi / 180.0;
  const double C = 19500.0;  // N/rad, only scales the force
  const std::complex<double> h = C * std::complex<double>(kV, -w * kA) / std::complex<double>(kV, w * sigma);
  const auto n = static_cast<Eigen::Index>(std::round(cycles * fs / f));
  std::normal_distribution<double> g(0.0, 1.0);
  HarmonicYawRecord r;
  r.excitationFrequencyHz = f;
  r.sampleRateHz = fs;
  r.yawRate.resize(n);
  r.lateralForce.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    r.yawRate[i] = psi0 * w * std::cos(w * t) + noiseRate * g(rng);
    r.lateralForce[i] = std::abs(h) * psi0 * std::sin(w * t + std::arg(h)) + 15.0 + noiseForce * g(rng);
  }
  return r;
}

TEST(RelaxationFromPhase, InvertsTheFirstOrderLagExactly) {
  for (double sigma : {0.02, 0.13, 0.4}) {
    for (double f : {0.42, 1.26, 2.10}) {
      const double w = 2 * kPi * f;
      const double lag = firstOrderPhaseLag(sigma, w, kV, kA);
      auto r = relaxationLengthFromPhaseLag(lag, w, kV, kA);
      ASSERT_TRUE(r) << r.error().describe();
      EXPECT_NEAR(r->sigma, sigma, 1e-12) << f;  // closed-form inverse: rounding only
    }
  }
}

TEST(RelaxationFromPhase, AgreesWithEquation28WrittenWithTheSignedPhase) {
  // eq. 28 without the dimensionally spurious C_bFalpha factor, phi = -lag.
  const double sigma = 0.15, f = 1.26, w = 2 * kPi * f, k = w / kV;
  const double phi = -firstOrderPhaseLag(sigma, w, kV, kA);
  const double eq28 = (std::tan(phi) + kA * k) / (kA * k * k * std::tan(phi) - k);
  auto r = relaxationLengthFromPhaseLag(-phi, w, kV, kA);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->sigma, eq28, 1e-12);
  EXPECT_NEAR(eq28, sigma, 1e-12);
}

TEST(RelaxationFromPhase, PropagatesThePhaseErrorToFirstOrder) {
  const double sigma = 0.15, w = 2 * kPi * 1.26, se = 0.01;
  const double lag = firstOrderPhaseLag(sigma, w, kV, kA);
  auto r = relaxationLengthFromPhaseLag(lag, w, kV, kA, se);
  auto up = relaxationLengthFromPhaseLag(lag + 1e-6, w, kV, kA);
  auto dn = relaxationLengthFromPhaseLag(lag - 1e-6, w, kV, kA);
  ASSERT_TRUE(r && up && dn);
  const double derivative = (up->sigma - dn->sigma) / 2e-6;
  EXPECT_NEAR(r->sigmaStdError, derivative * se, 1e-6 * derivative * se);  // central difference, O(h^2)
}

TEST(RelaxationFromPhase, ReportsLagsOutsideTheModelRange) {
  const double w = 2 * kPi * 1.26;
  const double contactLag = std::atan(w * kA / kV);
  auto below = relaxationLengthFromPhaseLag(contactLag * 0.5, w, kV, kA);
  ASSERT_FALSE(below);
  EXPECT_NE(below.error().message.find("contact-patch lag"), std::string::npos);
  auto pole = relaxationLengthFromPhaseLag(contactLag + kPi / 2, w, kV, kA);  // eq. 28 denominator = 0
  ASSERT_FALSE(pole);
  EXPECT_NE(pole.error().message.find("denominator"), std::string::npos);
  EXPECT_FALSE(relaxationLengthFromPhaseLag(0.5, w, 0.0, kA));   // V = 0
  EXPECT_FALSE(relaxationLengthFromPhaseLag(0.5, 0.0, kV, kA));  // w = 0
  EXPECT_FALSE(relaxationLengthFromPhaseLag(std::nan(""), w, kV, kA));
}

TEST(HarmonicYaw, RecoversSigmaFromNoiseFreeSineRecords) {
  std::mt19937 rng(1);
  const double sigma = 0.16;
  std::vector<HarmonicYawRecord> recs;
  for (double f : {0.42, 0.84, 1.26, 1.68, 2.10}) recs.push_back(synthesise(f, sigma, 10, 200.0, 0, 0, rng));
  HarmonicYawSettings s;
  s.halfLength = kA;
  auto r = relaxationFromHarmonicYaw(recs, s);
  ASSERT_TRUE(r) << r.error().describe();
  ASSERT_EQ(r->points.size(), 5u);
  for (const auto& p : r->points) {
    EXPECT_TRUE(p.valid) << p.note;
    EXPECT_NEAR(p.sigma, sigma, 1e-9) << p.frequencyHz;  // exact sines: fit error is rounding only
    EXPECT_NEAR(p.yawAmplitude, 1.5 * kPi / 180.0, 1e-12);
  }
  EXPECT_EQ(r->pointsInBand, 3);  // 0.84, 1.26, 1.68 Hz (§5.4)
  EXPECT_NEAR(r->meanSigma, sigma, 1e-9);
}

TEST(HarmonicYaw, InvertedLoadCellSignIsUndoneBySetting) {
  std::mt19937 rng(2);
  auto rec = synthesise(1.26, 0.12, 10, 200.0, 0, 0, rng);
  rec.lateralForce = -rec.lateralForce;
  HarmonicYawSettings s;
  s.halfLength = kA;
  s.forceSign = -1.0;
  auto r = relaxationFromHarmonicYaw({rec}, s);
  ASSERT_TRUE(r) << r.error().describe();
  EXPECT_NEAR(r->meanSigma, 0.12, 1e-9);
}

// Under noise the estimate scatters by about the propagated standard error:
// 200 seeded realisations; the spread of sigma must match the mean reported SE
// within 20% (the sample SD of 200 draws has a ~5% relative SE, the linear
// propagation a few % bias at this noise) and the mean must be unbiased within
// 4 standard errors of the mean.
TEST(HarmonicYaw, ReportedUncertaintyMatchesTheScatterUnderNoise) {
  std::mt19937 rng(7);
  const double sigma = 0.16;
  HarmonicYawSettings s;
  s.halfLength = kA;
  std::vector<double> est, se;
  for (int rep = 0; rep < 200; ++rep) {
    auto rec = synthesise(1.26, sigma, 10, 200.0, 0.02, 40.0, rng);  // ~10% of the rate and force amplitudes
    auto r = relaxationFromHarmonicYaw({rec}, s);
    ASSERT_TRUE(r) << r.error().describe();
    est.push_back(r->meanSigma);
    se.push_back(r->meanSigmaStdError);
  }
  double mean = 0, meanSe = 0;
  for (std::size_t i = 0; i < est.size(); ++i) mean += est[i] / est.size(), meanSe += se[i] / se.size();
  double var = 0;
  for (double e : est) var += (e - mean) * (e - mean) / (est.size() - 1);
  const double sd = std::sqrt(var);
  EXPECT_NEAR(sd / meanSe, 1.0, 0.2) << "scatter " << sd << " vs reported " << meanSe;
  EXPECT_NEAR(mean, sigma, 4 * sd / std::sqrt(200.0));
}

TEST(HarmonicYaw, BadInputGivesClearErrors) {
  std::mt19937 rng(3);
  HarmonicYawSettings s;
  s.halfLength = kA;
  auto shortRec = synthesise(1.26, 0.1, 1.2, 200.0, 0, 0, rng);
  auto r = relaxationFromHarmonicYaw({shortRec}, s);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("cycles"), std::string::npos) << r.error().describe();
  EXPECT_NE(r.error().where.find("record 1"), std::string::npos);

  HarmonicYawSettings still = s;
  still.speed = 0.0;
  auto v0 = relaxationFromHarmonicYaw({synthesise(1.26, 0.1, 10, 200.0, 0, 0, rng)}, still);
  ASSERT_FALSE(v0);
  EXPECT_NE(v0.error().message.find("speed"), std::string::npos);

  auto mismatch = synthesise(1.26, 0.1, 10, 200.0, 0, 0, rng);
  mismatch.lateralForce.conservativeResize(mismatch.lateralForce.size() - 3);
  EXPECT_FALSE(relaxationFromHarmonicYaw({mismatch}, s));
  EXPECT_FALSE(relaxationFromHarmonicYaw({}, s));
}

TEST(HarmonicYaw, FlagsAPointWhoseLagIsOutsideTheModelAndErrorsWhenTheBandIsEmpty) {
  std::mt19937 rng(4);
  HarmonicYawSettings s;
  s.halfLength = kA;
  // The force leads the yaw angle (lag < atan(w a/V)): inverted sign not declared.
  auto rec = synthesise(1.26, 0.1, 10, 200.0, 0, 0, rng);
  rec.lateralForce = -rec.lateralForce;
  auto good = synthesise(0.84, 0.1, 10, 200.0, 0, 0, rng);
  auto r = relaxationFromHarmonicYaw({good, rec}, s);
  ASSERT_TRUE(r) << r.error().describe();
  EXPECT_TRUE(r->points[0].valid);
  EXPECT_FALSE(r->points[1].valid);
  EXPECT_FALSE(r->points[1].note.empty());
  EXPECT_EQ(r->pointsInBand, 1);
  auto none = relaxationFromHarmonicYaw({rec}, s);
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("no valid relaxation length"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::tire
