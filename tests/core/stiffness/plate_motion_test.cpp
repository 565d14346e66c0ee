// Static twist axis, planar Mozzi axis and static test (thesis §1.2, §1.5):
// analytic rigid motions, the worked example of reference/notes.md, noise
// within the reported uncertainty, and bad input.
#include "core/stiffness/plate_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Out-of-plane displacement of p for a rotation theta about the directed line
// (q, d) plus a translation t along w that is the same everywhere: w = t + theta cross2(p - q, d).
double rigid(const Vector2& p, const Vector2& q, const Vector2& d, double theta, double t = 0.0) {
  const Vector2 r = p - q;
  return t + theta * (r(0) * d(1) - r(1) * d(0));
}

// Laser layout of Fig. 3 (eq. 3): L1 = (x0, -z0), L2 = (0, -z0), L3 = (0, 0) in (x, z).
std::vector<Vector2> fig3Layout(double x0 = 0.2, double z0 = 0.3) {
  return {Vector2(x0, -z0), Vector2(0, -z0), Vector2(0, 0)};
}

// reference/notes.md, eq. 5: x0 = 0.2 m, z0 = 0.3 m, dy = (1.0, 0.6, 0.2) mm give
// a = 10, b = -5000, c = -6.6667 1/m (d = 1), the axis crossing x = 0 at z = 0.15 m
// and z = 0 at x = -0.10 m. Exact data, so the tolerance is round-off (1e-12).
TEST(StaticTwistAxis, ReproducesTheCorrectedEq5Example) {
  const auto r = staticTwistAxis(fig3Layout(), {1.0e-3, 0.6e-3, 0.2e-3}, Vector2(0, 0));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  // Plane y = w0 + gu x + gv z  <=>  a x + b y + c z + 1 = 0 with b = -1/w0, a = -b gu, c = -b gv.
  const double b = -1.0 / r->plane.coefficients(0);
  EXPECT_NEAR(b, -5000.0, 1e-9);
  EXPECT_NEAR(-b * r->plane.coefficients(1), 10.0, 1e-9);
  EXPECT_NEAR(-b * r->plane.coefficients(2), -6.666666666666667, 1e-9);
  const auto atX0 = r->axis.pointAtV(0.0);  // z = 0
  ASSERT_TRUE(atX0.ok());
  EXPECT_NEAR((*atX0)(0), -0.10, 1e-12);
  // Crossing of x = 0: point + t d with u = 0.
  const double t = -r->axis.point(0) / r->axis.direction(0);
  EXPECT_NEAR(r->axis.point(1) + t * r->axis.direction(1), 0.15, 1e-12);
}

// A known small rigid motion is given back exactly by 3 and by 4 sensors.
TEST(StaticTwistAxis, RecoversAKnownRigidMotionExactly) {
  const double beta0 = 0.7;  // rad from z towards x
  const Vector2 d(std::sin(beta0), std::cos(beta0));
  const Vector2 q(0.05, -0.4);
  const double theta = 2.5e-3;
  for (const auto& pts : {fig3Layout(), std::vector<Vector2>{{0.2, -0.3}, {0, -0.3}, {0, 0}, {0.2, 0}}}) {
    std::vector<double> w;
    for (const auto& p : pts) w.push_back(rigid(p, q, d, theta));
    PlaneFitOptions o;
    o.sigmaFloor = 0.0;
    const Vector2 load(0.5, 0.1);
    const auto r = staticTwistAxis(pts, w, load, o);
    ASSERT_TRUE(r.ok()) << r.error().describe();
    EXPECT_NEAR(r->axis.beta, beta0, 1e-12);
    EXPECT_NEAR(r->axis.rotation, theta, 1e-15);
    // The foot point lies on the true axis and the signed arm of the load point matches.
    const Vector2 rq = r->axis.point - q;
    EXPECT_NEAR(rq(0) * d(1) - rq(1) * d(0), 0.0, 1e-12);
    EXPECT_NEAR(r->axis.signedArm(load), (load - q)(0) * d(1) - (load - q)(1) * d(0), 1e-12);
    EXPECT_FALSE(r->lowConfidence);
  }
}

// With noise of known sigma the reported uncertainty is calibrated: for three
// sensors (no redundancy, sigma = the floor) the normalised errors of beta and
// of the axis offset have unit standard deviation. 4000 trials: the sample
// std of a unit normal is within +-0.05 with > 99.9 % probability (se 0.011).
TEST(StaticTwistAxis, NoiseIsWithinTheReportedUncertainty) {
  const auto pts = fig3Layout();
  const double beta0 = -0.3;
  const Vector2 d(std::sin(beta0), std::cos(beta0));
  const Vector2 q(0.1, -0.1);
  const double theta = 2e-3;  // 0.6 mm over the plate: typical static test
  const double sigma = 4e-6;
  PlaneFitOptions o;
  o.sigmaFloor = sigma;
  std::mt19937 rng(12345);
  std::normal_distribution<double> noise(0.0, sigma);
  const Vector2 load(0.3, -0.5);
  double sb = 0, se = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    std::vector<double> w;
    for (const auto& p : pts) w.push_back(rigid(p, q, d, theta) + noise(rng));
    const auto r = staticTwistAxis(pts, w, load, o);
    ASSERT_TRUE(r.ok());
    const double eb = (r->axis.beta - beta0) / r->axis.betaSigma;
    const Vector2 rl = load - q;
    const double trueArm = rl(0) * d(1) - rl(1) * d(0);
    const double eo = (r->axis.signedArm(load) - trueArm) / r->axis.offsetSigma;
    sb += eb * eb;
    se += eo * eo;
  }
  EXPECT_NEAR(std::sqrt(sb / n), 1.0, 0.05);
  EXPECT_NEAR(std::sqrt(se / n), 1.0, 0.05);
}

// Four lasers: sigma is estimated from the residual (floored), so coverage of
// the 3-sigma interval is at least nominal (99.7 %); asserted >= 97 % over 2000 trials.
TEST(StaticTwistAxis, FourLaserUncertaintyCoversTheTruth) {
  const std::vector<Vector2> pts{{0.2, -0.3}, {0, -0.3}, {0, 0}, {0.2, 0}};
  const double beta0 = 0.4;
  const Vector2 d(std::sin(beta0), std::cos(beta0));
  const Vector2 q(0.0, -0.2);
  PlaneFitOptions o;
  o.sigmaFloor = 3e-6;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 3e-6);
  int inside = 0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    std::vector<double> w;
    for (const auto& p : pts) w.push_back(rigid(p, q, d, 1.5e-3, 2e-4) + noise(rng));
    const auto r = staticTwistAxis(pts, w, Vector2(0.1, -0.15), o);
    ASSERT_TRUE(r.ok());
    if (std::abs(r->axis.beta - beta0) <= 3 * r->axis.betaSigma) ++inside;
  }
  EXPECT_GE(inside, static_cast<int>(0.97 * n));
}

TEST(StaticTwistAxis, RejectsBadGeometry) {
  // Collinear sensors.
  auto r = staticTwistAxis({{0, 0}, {0.1, 0.1}, {0.2, 0.2}}, {1e-4, 2e-4, 3e-4}, Vector2(0, 0));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("collinear"), std::string::npos);
  // Two coincident points of three.
  r = staticTwistAxis({{0, 0}, {0, 0}, {0.2, 0.3}}, {1e-4, 2e-4, 3e-4}, Vector2(0, 0));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("collinear"), std::string::npos);
  // All coincident.
  r = staticTwistAxis({{0.1, 0.1}, {0.1, 0.1}, {0.1, 0.1}}, {1e-4, 2e-4, 3e-4}, Vector2(0, 0));
  ASSERT_FALSE(r.ok());
  // Too few, mismatched, non-finite.
  EXPECT_FALSE(staticTwistAxis({{0, 0}, {1, 0}}, {0, 0}, Vector2(0, 0)).ok());
  EXPECT_FALSE(staticTwistAxis(fig3Layout(), {0, 0}, Vector2(0, 0)).ok());
  EXPECT_FALSE(staticTwistAxis(fig3Layout(), {0, NAN, 0}, Vector2(0, 0)).ok());
}

// Pure translation: the loaded plane is parallel to the unloaded one and the
// axis is at infinity; the fit must refuse rather than return a far axis.
TEST(StaticTwistAxis, PureTranslationIsAnError) {
  const auto r = staticTwistAxis(fig3Layout(), {5e-4, 5e-4, 5e-4}, Vector2(0, 0));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("infinity"), std::string::npos);
}

// Displacements at the 4 um laser resolution: a rotation of 1e-6 rad (0.3 um
// across the plate) quantised to 4 um steps gives readings one step apart.
// The rotation 4e-6 / 0.3 = 1.3e-5 rad is below 3 sigma of the quantisation
// noise (sigma_theta = 1.15e-6 * sqrt(2) / 0.3... about 6e-6), so it is refused.
TEST(StaticTwistAxis, DisplacementsAtSensorResolutionAreRefused) {
  const auto r = staticTwistAxis(fig3Layout(), {8e-6, 8e-6, 4e-6}, Vector2(0, 0));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("not resolved"), std::string::npos);
}

// Small but resolved rotation far from the plate: the axis is returned but
// flagged, since its position uncertainty exceeds 10 % of the layout.
TEST(StaticTwistAxis, FarAxisIsFlaggedLowConfidence) {
  const auto pts = fig3Layout();
  const Vector2 q(3.0, 0.0), d(0, 1);  // axis 3 m away, parallel to z
  std::vector<double> w;
  for (const auto& p : pts) w.push_back(rigid(p, q, d, 2e-4));
  const auto r = staticTwistAxis(pts, w, Vector2(0, 0));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_TRUE(r->lowConfidence);
  EXPECT_NE(r->note.find("position uncertain"), std::string::npos);
}

// reference/notes.md, eq. 17: the general solution of eq. 16 for any layout.
double notesYP(const std::vector<Vector2>& p, const std::vector<double>& dx, double zP) {
  const double y1 = p[0](0), z1 = p[0](1), y2 = p[1](0), z2 = p[1](1), y3 = p[2](0), z3 = p[2](1);
  const double num = dx[0] * (y2 * z3 - y3 * z2 + (y3 - y2) * zP) + dx[1] * (y3 * z1 - y1 * z3 + (y1 - y3) * zP) +
                     dx[2] * (y1 * z2 - y2 * z1 + (y2 - y1) * zP);
  const double den = dx[0] * (z3 - z2) + dx[1] * (z1 - z3) + dx[2] * (z2 - z1);
  return num / den;
}

TEST(PlanarMozzi, SolvesEq16ForAnyLayoutAsTheNotesClosedForm) {
  const std::vector<Vector2> pts{{0.03, -0.11}, {0.27, 0.05}, {-0.08, 0.21}};  // no right angle
  const double dxQ = 3e-4, thY = 1.2e-3, thZ = -0.8e-3;
  std::vector<double> dx;
  for (const auto& p : pts) dx.push_back(dxQ - thZ * p(0) + thY * p(1));  // eq. 16
  PlaneFitOptions o;
  o.sigmaFloor = 0.0;
  const auto m = planarMozziAxis(pts, dx, Vector2(0, 0), o);
  ASSERT_TRUE(m.ok()) << m.error().describe();
  EXPECT_NEAR(m->dxQ, dxQ, 1e-15);
  EXPECT_NEAR(m->dThetaY, thY, 1e-15);
  EXPECT_NEAR(m->dThetaZ, thZ, 1e-15);
  for (double zP : {-0.3, 0.0, 0.4}) {
    const auto p = m->twist.axis.pointAtV(zP);
    ASSERT_TRUE(p.ok());
    EXPECT_NEAR((*p)(0), notesYP(pts, dx, zP), 1e-12);        // notes' general eq. 17
    EXPECT_NEAR((*p)(0), dxQ / thZ + thY / thZ * zP, 1e-12);  // eq. 13
  }
}

// Eq. 17 as printed is right for the layout z2 = z1, y3 = y1 (notes.md).
TEST(PlanarMozzi, PrintedEq17HoldsForItsRightAngleLayout) {
  const std::vector<Vector2> pts{{0.1, 0.2}, {0.35, 0.2}, {0.1, -0.15}};
  const double dxQ = -2e-4, thY = 0.5e-3, thZ = 1.1e-3;
  std::vector<double> dx;
  for (const auto& p : pts) dx.push_back(dxQ - thZ * p(0) + thY * p(1));
  const auto m = planarMozziAxis(pts, dx, Vector2(0, 0));
  ASSERT_TRUE(m.ok());
  const double y1 = pts[0](0), z1 = pts[0](1), y2 = pts[1](0), z3 = pts[2](1);
  for (double zP : {-0.2, 0.3}) {
    const double printed = ((y2 * z3 - y1 * z1) * dx[0] + (z1 - z3) * dx[1] * y1 + (y1 - y2) * dx[2] * z1) /
                               ((dx[1] - dx[0]) * (z1 - z3)) -
                           zP * (dx[2] - dx[0]) * (y1 - y2) / ((dx[1] - dx[0]) * (z1 - z3));
    const auto p = m->twist.axis.pointAtV(zP);
    ASSERT_TRUE(p.ok());
    EXPECT_NEAR((*p)(0), printed, 1e-12);
  }
}

// Twist axis (plane intersection, eq. 6) and Mozzi axis (eq. 13) coincide when
// the plate has no in-plane motion (notes.md cross-check).
TEST(PlanarMozzi, CoincidesWithTheTwistAxis) {
  const auto pts = fig3Layout();
  std::vector<double> w{1.0e-3, 0.6e-3, 0.2e-3};
  const auto t = staticTwistAxis(pts, w, Vector2(0.1, 0.1));
  const auto m = planarMozziAxis(pts, w, Vector2(0.1, 0.1));
  ASSERT_TRUE(t.ok() && m.ok());
  EXPECT_NEAR(t->axis.beta, m->twist.axis.beta, 1e-14);
  EXPECT_NEAR((t->axis.point - m->twist.axis.point).norm(), 0.0, 1e-14);
}

// Eq. 13 parametrises the axis by z_P (v): an axis parallel to the u axis
// (dtheta_z = 0 in §1.5) has no such form, which is an error, while the axis
// itself is still returned as a line.
TEST(PlanarMozzi, AxisParallelToTheUAxisCannotBeParametrisedByV) {
  const auto pts = fig3Layout();
  std::vector<double> w;
  for (const auto& p : pts) w.push_back(rigid(p, Vector2(0.0, -0.1), Vector2(1.0, 0.0), 1e-3));
  const auto m = planarMozziAxis(pts, w, Vector2(0, 0));
  ASSERT_TRUE(m.ok()) << m.error().describe();
  EXPECT_NEAR(m->dThetaZ, 0.0, 1e-15);
  EXPECT_NEAR(m->twist.axis.point(1), -0.1, 1e-12);
  const auto p = m->twist.axis.pointAtV(0.0);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("parallel"), std::string::npos);
}

TEST(LinearRegression, MatchesTheClosedForm) {
  // y = 1 + 2x with residuals (+1, -2, +1) at x = (0, 1, 2): slope 2, intercept 1,
  // s^2 = 6 / 1, Sxx = 2, se(slope) = sqrt(3).
  const auto r = linearRegression({0, 1, 2}, {2, 1, 6});
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r->slope, 2.0, 1e-14);
  EXPECT_NEAR(r->intercept, 1.0, 1e-14);
  EXPECT_NEAR(r->slopeSe, std::sqrt(3.0), 1e-14);
  EXPECT_FALSE(linearRegression({1, 1, 1}, {1, 2, 3}).ok());
}

// Static test over a +-300 N ramp (§2.1) with k_lat = 167 kN/m and a_tw = 0.551 m
// (Table 3, frame A front-constrained). Noise 1 um on each laser: k_lat within
// 3 standard errors, k_tw within 3 sigma of 50.7 kNm/rad.
struct Ramp {
  std::vector<Vector2> pts{{0.2, -0.3}, {0, -0.3}, {0, 0}, {0.2, 0}};
  Vector2 load{0.1, -0.6};
  Vector2 q{0.1 + 0.551 * std::cos(0.3), -0.6 - 0.551 * std::sin(0.3)};  // axis point at 0.551 m from the load
  Vector2 d{std::sin(0.3), std::cos(0.3)};                               // perpendicular to (load - q)
  Vector force;
  Matrix disp;
  Ramp(double kLat, double noiseSigma, double negativeScale = 1.0, unsigned seed = 3) {
    const int n = 61;
    force.resize(n);
    disp.resize(n, 4);
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, noiseSigma);
    const Vector2 rl = load - q;
    const double arm = rl(0) * d(1) - rl(1) * d(0);
    for (int k = 0; k < n; ++k) {
      const double f = -300.0 + 600.0 * k / (n - 1);
      force(k) = f;
      const double xlat = f / kLat * (f < 0 ? negativeScale : 1.0);
      const double theta = xlat / arm;
      for (int i = 0; i < 4; ++i) disp(k, i) = rigid(pts[static_cast<std::size_t>(i)], q, d, theta) + 2e-5 + noise(rng);
    }
  }
};

TEST(StaticTwistTest, RecoversStiffnessAndArmFromARamp) {
  Ramp ramp(167e3, 1e-6);
  const auto r = staticTwistTest(ramp.pts, ramp.force, ramp.disp, ramp.load);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_NEAR(r->lateralStiffness, 167e3, 3 * r->lateralStiffnessSe);
  EXPECT_LT(r->lateralStiffnessSe / r->lateralStiffness, 0.01);
  EXPECT_NEAR(r->twistArm, 0.551, 3 * r->twistArmSigma + 1e-9);
  EXPECT_NEAR(r->twistStiffness, 167e3 * 0.551 * 0.551, 3 * r->twistStiffnessSigma);
  EXPECT_NEAR(r->axis.axis.beta, 0.3, 3 * r->axis.axis.betaSigma);
  EXPECT_TRUE(r->linear);
  EXPECT_GT(r->loadPoint.rSquared, 0.999);
}

// Play in the rig: the negative branch is 30 % softer, flagged as non-linear.
TEST(StaticTwistTest, FlagsDifferentLoadBranches) {
  Ramp ramp(167e3, 1e-6, 1.3);
  const auto r = staticTwistTest(ramp.pts, ramp.force, ramp.disp, ramp.load);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_FALSE(r->linear);
  EXPECT_TRUE(r->lowConfidence);
  EXPECT_NE(r->note.find("branches differ"), std::string::npos);
}

TEST(StaticTwistTest, RejectsZeroConstantOrReversedLoad) {
  Ramp ramp(167e3, 1e-6);
  Vector zero = Vector::Zero(ramp.force.size());
  auto r = staticTwistTest(ramp.pts, zero, ramp.disp, ramp.load);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("zero"), std::string::npos);
  Vector constant = Vector::Constant(ramp.force.size(), 100.0);
  r = staticTwistTest(ramp.pts, constant, ramp.disp, ramp.load);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("does not vary"), std::string::npos);
  r = staticTwistTest(ramp.pts, -ramp.force, ramp.disp, ramp.load);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("against the force"), std::string::npos);
  Matrix wrong = ramp.disp.leftCols(3);
  EXPECT_FALSE(staticTwistTest(ramp.pts, ramp.force, wrong, ramp.load).ok());
  // Single-load form: zero force is an error.
  EXPECT_FALSE(staticTwistSingleLoad(ramp.pts, {1e-4, 2e-4, 3e-4, 4e-4}, 0.0, ramp.load).ok());
}

TEST(StaticTwistTest, SingleLoadGivesEq29And30) {
  const auto pts = fig3Layout();
  const Vector2 q(0.0, 0.15), d(-0.5547001962252291, 0.8320502943378437);  // the notes' axis
  const Vector2 load(0.0, -0.5);
  const double theta = -2e-3;  // sense that moves the load point along +w
  std::vector<double> w;
  for (const auto& p : pts) w.push_back(rigid(p, q, d, theta));
  const Vector2 rl = load - q;
  const double arm = rl(0) * d(1) - rl(1) * d(0);
  const double xlat = theta * arm;
  ASSERT_GT(xlat, 0.0);
  const auto r = staticTwistSingleLoad(pts, w, 300.0, load);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_NEAR(r->lateralStiffness, 300.0 / xlat, 1e-9 * 300.0 / xlat);  // eq. 29
  EXPECT_NEAR(r->twistArm, std::abs(arm), 1e-12);
  EXPECT_NEAR(r->twistStiffness, 300.0 / xlat * arm * arm, 1e-9 * r->twistStiffness);  // eq. 30
  // The same load in the other sense with displacements reversed gives the same stiffness.
  for (auto& x : w) x = -x;
  const auto back = staticTwistSingleLoad(pts, w, -300.0, load);
  ASSERT_TRUE(back.ok());
  EXPECT_NEAR(back->twistStiffness, r->twistStiffness, 1e-9 * r->twistStiffness);
}

}  // namespace
}  // namespace mozzi::core::stiffness
