// Thesis stiffness tables for frames, swing-arms and motorcycle forks
// (Tables 3, 4, 5, 7, 9, 10, 13), reproduced through core/stiffness from the
// inputs the thesis prints. Tolerances follow the printed precision; where the
// thesis is internally inconsistent the test says so (see also
// docs/validation/stiffness.md).
#include <gtest/gtest.h>

#include <cmath>

#include "core/stiffness/decomposition.h"
#include "core/stiffness/plate_motion.h"

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A static +-300 N ramp (§2.1) on a four-laser plate whose twist axis lies at
// `arm` from the load point; the lasers see a rigid rotation giving the
// lateral stiffness kLat. Noise-free, so the library must return kLat and
// arm to round-off; k_tw then follows from eq. 30.
Result<StaticTwistResult> rampFor(double kLat, double arm) {
  const std::vector<Vector2> pts{{0.2, -0.3}, {0, -0.3}, {0, 0}, {0.2, 0}};
  const Vector2 load(0.1, -0.7);
  const double beta = 0.4;
  const Vector2 d(std::sin(beta), std::cos(beta));
  const Vector2 nrm(d(1), -d(0));
  const Vector2 q = load - arm * nrm;  // signedArm(load) = arm
  const int n = 31;
  Vector f(n);
  Matrix disp(n, 4);
  for (int k = 0; k < n; ++k) {
    f(k) = -300.0 + 600.0 * k / (n - 1);
    const double theta = f(k) / kLat / arm;
    for (int i = 0; i < 4; ++i) {
      const Vector2 r = pts[static_cast<std::size_t>(i)] - q;
      disp(k, i) = theta * (r(0) * d(1) - r(1) * d(0));
    }
  }
  StaticTestOptions o;
  o.plane.sigmaFloor = 0.0;
  return staticTwistTest(pts, f, disp, load, o);
}

// Table 3: k_tw = k_lat a_tw^2. Inputs have 3 significant figures (k_lat to
// +-0.3 %, a_tw to +-0.1 %, so a_tw^2 to +-0.2 %): tolerance 0.5 %.
// Measured: 50.70, 129.1, 57.08, 59.02 kNm/rad against 50.8, 129, 57.0, 59.1.
TEST(ThesisTable3, RotationalStiffnessAboutTheStaticTwistAxis) {
  const struct {
    const char* row;
    double kLat, arm, kTw;
  } rows[] = {{"frame A front", 167e3, 0.551, 50.8e3},
              {"frame B front", 272e3, 0.689, 129e3},
              {"frame A rear", 253e3, 0.475, 57.0e3},
              {"frame B rear", 238e3, 0.498, 59.1e3}};
  for (const auto& r : rows) {
    const auto res = rampFor(r.kLat, r.arm);
    ASSERT_TRUE(res.ok()) << r.row << ": " << res.error().describe();
    EXPECT_NEAR(res->lateralStiffness, r.kLat, 1e-8 * r.kLat) << r.row;
    EXPECT_NEAR(res->twistArm, r.arm, 1e-10) << r.row;
    EXPECT_NEAR(res->twistStiffness, r.kTw, 0.005 * r.kTw) << r.row;
  }
}

// Eq. 24 must balance: a_tw^2/k_tw = a_b^2/k_b + a_t^2/k_t. The thesis does not
// print the modal-axis angles, so the decomposition is run with perpendicular
// bending/torsion axes (beta_b = 0, beta_t = 90 deg) and the static-axis angle
// alpha that eq. 27 implies for the printed k_b, k_t; it must give back the
// printed k_b and k_t to within the eq. 24 imbalance of the printed, rounded
// numbers. Tolerance 0.5 % (arms of 2-3 figures, stiffness of 3-4 figures);
// measured imbalances 0.05 %, 0.04 %, 0.08 %, 0.12 % (Table 4), 0.06 % (Table 7),
// 0.01 % (Table 9), 0.03 % (Table 10 modal column).
struct DecompRow {
  const char* row;
  double kTw, aTw, aB, kB, aT, kT;
};

void checkBalanceAndRoundTrip(const DecompRow& r) {
  const double lhs = r.aTw * r.aTw / r.kTw;
  const double rhs = r.aB * r.aB / r.kB + r.aT * r.aT / r.kT;
  EXPECT_NEAR(rhs / lhs, 1.0, 0.005) << r.row << ": eq. 24 imbalance";
  const double alpha = std::atan2(r.aT / r.kT, r.aB / r.kB);  // eq. 27 with perpendicular axes
  const auto d = decomposeStiffness(DecompositionInput{r.kTw, r.aTw, alpha, r.aB, 0.0, r.aT, kPi / 2});
  ASSERT_TRUE(d.ok()) << r.row << ": " << d.error().describe();
  EXPECT_NEAR(d->bendStiffness / r.kB, 1.0, 0.005) << r.row;
  EXPECT_NEAR(d->torsStiffness / r.kT, 1.0, 0.005) << r.row;
  EXPECT_NEAR(d->balanceResidual, 0.0, 1e-12) << r.row;
}

TEST(ThesisTable4, BendingTorsionDecompositionBalances) {
  // k_tw and a_tw from Table 3.
  const DecompRow rows[] = {{"frame A front", 50.8e3, 0.551, 0.556, 52.1e3, 0.032, 22.0e3},
                            {"frame B front", 129e3, 0.689, 0.553, 138.3e3, 0.298, 60.4e3},
                            {"frame A rear", 57.0e3, 0.475, 0.458, 53.5e3, 0.026, 19.6e3},
                            {"frame B rear", 59.1e3, 0.498, 0.510, 64.3e3, 0.097, 60.2e3}};
  for (const auto& r : rows) checkBalanceAndRoundTrip(r);
}

// Table 7 (swing-arm A) and Table 9 (swing-arm B). Table 9 prints the lateral
// stiffness as "1083 N/m": it is 1083 kN/m (notes.md), since 1083e3 x 0.477^2 =
// 246.4 kNm/rad, the printed twist stiffness (measured 246.41 kNm/rad).
TEST(ThesisTables7And9, SwingArmStiffness) {
  auto a = rampFor(623e3, 0.375);
  ASSERT_TRUE(a.ok());
  EXPECT_NEAR(a->twistStiffness, 87.6e3, 0.005 * 87.6e3);  // measured 87.61
  auto b = rampFor(1083e3, 0.477);
  ASSERT_TRUE(b.ok());
  EXPECT_NEAR(b->twistStiffness, 246.4e3, 0.005 * 246.4e3);  // measured 246.41
  checkBalanceAndRoundTrip({"Table 7 swing-arm A", 87.6e3, 0.375, 0.388, 94.2e3, 0.025, 98.8e3});
  checkBalanceAndRoundTrip({"Table 9 swing-arm B", 246.4e3, 0.477, 0.451, 222.4e3, 0.026, 77.4e3});
}

// Fork variant (eq. 35, 36) from the full printed inputs: lateral stiffness,
// twist arm, bending and torsion arms, inclination of the twist axis. The
// printed results have 1-2 significant figures, so the test asserts that the
// computed value rounds to the printed one.
// Table 10 (simple method): 56.1 kN/m, 0.517 m, 0.67 m, 0.066 m, 45.5 deg ->
//   k_b = 27.72 (printed 28), k_t = 2.68 (printed 3) kNm/rad.
// Table 13: 109.3 kN/m, 0.452 m, 0.528 m, 0.083 m, 41.2 deg ->
//   k_b = 34.66 (printed 35), k_t = 6.22 (printed 6) kNm/rad. Table 13 prints the
//   twist stiffness as "22 kNm 7 rad" (22 kNm/rad, notes.md); the unrounded
//   109.3e3 x 0.452^2 = 22.33 kNm/rad must be used: with 22.0 k_b would be 34.15,
//   which prints as 34, not 35.
TEST(ThesisTables10And13, ForkDecompositionFromPrintedInputs) {
  const struct {
    const char* row;
    double kLat, aTw, aB, aT, alphaDeg, kTwPrinted, kBPrinted, kTPrinted, kBDigit, kTDigit;
  } rows[] = {{"Table 10 simple (fork A)", 56.1e3, 0.517, 0.67, 0.066, 45.5, 15e3, 28e3, 3e3, 1e3, 1e3},
              {"Table 13 (fork B)", 109.3e3, 0.452, 0.528, 0.083, 41.2, 22e3, 35e3, 6e3, 1e3, 1e3}};
  for (const auto& r : rows) {
    const double kTw = r.kLat * r.aTw * r.aTw;       // eq. 30
    EXPECT_NEAR(kTw, r.kTwPrinted, 0.5e3) << r.row;  // printed to 1 kNm/rad
    const auto d = decomposeForkStiffness({kTw, r.aTw, r.aB, r.aT, r.alphaDeg * kPi / 180});
    ASSERT_TRUE(d.ok()) << r.row << ": " << d.error().describe();
    EXPECT_NEAR(d->bendStiffness, r.kBPrinted, 0.5 * r.kBDigit) << r.row;
    EXPECT_NEAR(d->torsStiffness, r.kTPrinted, 0.5 * r.kTDigit) << r.row;
  }
  // Table 13 with the rounded 22 kNm/rad would not round to the printed 35.
  const auto rounded = decomposeForkStiffness({22e3, 0.452, 0.528, 0.083, 41.2 * kPi / 180});
  ASSERT_TRUE(rounded.ok());
  EXPECT_LT(rounded->bendStiffness, 34.5e3);
}

// Table 10, modal method: bending and torsion axes from the three-accelerometer
// test (Fig. 30, angles not printed), so only eq. 24 can be checked; the column
// prints kN/m for rotational stiffness, meaning kNm/rad (notes.md). The fork
// formula eq. 36 with alpha = 45.5 deg does NOT give these values (it gives
// k_t = 6.5, not 7.4 kNm/rad): the modal method uses the general eq. 27 with the
// measured modal-axis angles, as §4.1 says.
TEST(ThesisTable10, ModalMethodBalances) {
  checkBalanceAndRoundTrip({"Table 10 modal", 56.1e3 * 0.517 * 0.517, 0.517, 0.861, 46.7e3, 0.120, 7.4e3});
  const auto viaFork = decomposeForkStiffness({56.1e3 * 0.517 * 0.517, 0.517, 0.861, 0.120, 45.5 * kPi / 180});
  ASSERT_TRUE(viaFork.ok());
  EXPECT_GT(std::abs(viaFork->torsStiffness - 7.4e3) / 7.4e3, 0.1);
}

// Table 5 (frame C) prints no arms, so eq. 24 cannot be checked; the twist arm
// follows from eq. 30, a_tw = sqrt(k_tw / k_lat) = 0.849 m and 0.877 m. The
// text says the linear stiffness rises "about 50 %" (computed 49.3 %) and twist
// and bending "about 60 %": twist rises 59.3 % but bending only 45.8 %, an
// inconsistency of the text recorded in docs/validation/stiffness.md.
TEST(ThesisTable5, FrameCWithAndWithoutEngine) {
  const double kLat0 = 361e3, kLat1 = 539e3, kTw0 = 260.2e3, kTw1 = 414.6e3, kB0 = 358.6e3, kB1 = 522.9e3;
  EXPECT_NEAR(std::sqrt(kTw0 / kLat0), 0.849, 0.0005);
  EXPECT_NEAR(std::sqrt(kTw1 / kLat1), 0.877, 0.0005);
  EXPECT_NEAR(kLat1 / kLat0, 1.5, 0.01);
  EXPECT_NEAR(kTw1 / kTw0, 1.6, 0.01);
  EXPECT_NEAR(kB1 / kB0, 1.458, 0.001);  // not "about 60 %"
}

}  // namespace
}  // namespace mozzi::core::stiffness
