// Dynamic and modal twist axes (thesis §1.3, §1.4): in-phase phasors give the
// static axis, general phases switch to the three-instant method, a sweep
// reports each frequency, and accelerance FRFs are turned into receptance.
#include "core/stiffness/dynamic_twist.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

const std::vector<Vector2> kLayout{{0.2, -0.3}, {0, -0.3}, {0, 0}};

Vector rigidAmplitudes(const Vector2& q, const Vector2& d, double theta) {
  Vector w(3);
  for (int i = 0; i < 3; ++i) {
    const Vector2 r = kLayout[static_cast<std::size_t>(i)] - q;
    w(i) = theta * (r(0) * d(1) - r(1) * d(0));
  }
  return w;
}

// A mode shape (real) times a common complex factor: in-phase case, and the
// axis is the static axis of that shape.
TEST(PhasorTwistAxis, InPhaseGivesTheShapeAxis) {
  const double beta0 = 0.5;
  const Vector2 d(std::sin(beta0), std::cos(beta0)), q(0.05, -0.5);
  const Vector shape = rigidAmplitudes(q, d, 1e-3);
  const ComplexVector y = shape.cast<Complex>() * std::polar(1.0, 1.3);
  const auto r = phasorTwistAxis(kLayout, y, Vector2(0, 0));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r->method, PhasorAxisCase::InPhase);
  EXPECT_NEAR(r->axis.axis.beta, beta0, 1e-12);
  EXPECT_LT(r->maxPhaseDeviation, 1e-12);
  EXPECT_FALSE(r->lowConfidence);
}

// Two modes in quadrature: the axis moves during the cycle; the tool reports
// the three-instant method, keeps the instant axes, and its averaged beta lies
// between the two modal axes.
TEST(PhasorTwistAxis, GeneralPhasesUseTheThreeInstantMethod) {
  const Vector2 d1(std::sin(0.2), std::cos(0.2)), d2(std::sin(1.2), std::cos(1.2));
  const Vector a = rigidAmplitudes(Vector2(0.0, -0.6), d1, 1e-3);
  const Vector b = rigidAmplitudes(Vector2(0.3, 0.0), d2, 0.6e-3);
  const ComplexVector y = a.cast<Complex>() + Complex(0, 1) * b.cast<Complex>();
  const auto r = phasorTwistAxis(kLayout, y, Vector2(0, 0));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r->method, PhasorAxisCase::ThreeInstant);
  EXPECT_STREQ(phasorAxisCaseName(r->method), "three-instant");
  EXPECT_EQ(r->instantAxes.size(), 3u);
  EXPECT_TRUE(r->lowConfidence);
  EXPECT_GT(r->maxPhaseDeviation, 0.1745);
  // Each instant axis is the plane of y_i(t_j) = |Y_i| cos(phi_i - phi_j): check one directly.
  for (std::size_t j = 0; j < 3; ++j) {
    std::vector<double> w;
    for (int i = 0; i < 3; ++i)
      w.push_back(std::abs(y(i)) * std::cos(std::arg(y(i)) - std::arg(y(static_cast<Eigen::Index>(j)))));
    const auto s = staticTwistAxis(kLayout, w, Vector2(0, 0));
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR(s->axis.beta, r->instantAxes[j].beta, 1e-12);
  }
  EXPECT_GE(r->axis.axis.betaSigma, r->betaSpread);
}

TEST(DynamicTwistSweep, AxisPerFrequencyAndStiffness) {
  // Frequencies 1..45 Hz: a quasi-static axis that rotates linearly with f.
  std::vector<SweepPoint> sweep;
  const Vector2 load(0.1, -0.8);
  for (int f = 1; f <= 45; f += 4) {
    const double beta = 0.1 + 0.02 * f;
    const Vector2 d(std::sin(beta), std::cos(beta)), q(0.1, -0.4);
    const Vector a = rigidAmplitudes(q, d, 1e-3);
    SweepPoint s;
    s.frequencyHz = f;
    s.amplitude = a.cwiseAbs();
    s.phase.resize(3);
    for (int i = 0; i < 3; ++i) s.phase(i) = a(i) >= 0 ? 0.3 : 0.3 + kPi;
    s.forceAmplitude = 200.0;
    sweep.push_back(s);
  }
  const auto r = dynamicTwistSweep(kLayout, sweep, load);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  ASSERT_EQ(r->size(), sweep.size());
  for (const auto& s : *r) {
    ASSERT_TRUE(s.axis.ok()) << s.axis.error().describe();
    EXPECT_NEAR(s.axis->axis.axis.beta, 0.1 + 0.02 * s.frequencyHz, 1e-12);
    // |x_lat| = theta |arm|, arm = distance from (0.1, -0.4) along the normal.
    const double beta = 0.1 + 0.02 * s.frequencyHz;
    const Vector2 d(std::sin(beta), std::cos(beta));
    const Vector2 r2 = load - Vector2(0.1, -0.4);
    const double arm = std::abs(r2(0) * d(1) - r2(1) * d(0));
    EXPECT_NEAR(s.twistArm, arm, 1e-12);
    EXPECT_NEAR(s.dynamicLateralStiffness, 200.0 / (1e-3 * arm), 1e-6 * s.dynamicLateralStiffness);
  }
  // Wrong shapes are an error; an all-zero row keeps its own error.
  auto bad = sweep;
  bad[0].amplitude = Vector::Zero(3);
  const auto r2 = dynamicTwistSweep(kLayout, bad, load);
  ASSERT_TRUE(r2.ok());
  EXPECT_FALSE((*r2)[0].axis.ok());
  EXPECT_TRUE((*r2)[1].axis.ok());
  bad[1].phase = Vector::Zero(2);
  EXPECT_FALSE(dynamicTwistSweep(kLayout, bad, load).ok());
}

// Accelerance FRFs of the three accelerometers at a resonance: receptance =
// A / (-omega^2) (eq. 7); the in-phase axis is that of the mode shape.
TEST(ModalTwistAxis, FromAccelerometerFrfs) {
  const double beta0 = -0.4;
  const Vector2 d(std::sin(beta0), std::cos(beta0)), q(0.0, -0.9);
  const Vector shape = rigidAmplitudes(q, d, 1.0);
  FrfMatrix frf;
  frf.type = FrfType::Accelerance;
  frf.frequencyHz = Vector::LinSpaced(101, 0.0, 100.0).tail(100);  // 1..100 Hz
  for (int i = 0; i < 3; ++i) frf.responses.push_back(Dof{i + 1, Direction::Y, false});
  frf.references.push_back(Dof{10, Direction::Y, false});
  ComplexMatrix h(100, 3);
  const double fn = 67.0, zeta = 0.02;
  for (int k = 0; k < 100; ++k) {
    const double f = frf.frequencyHz(k);
    const double r = f / fn;
    // Single mode: receptance = shape / (k (1 - r^2 + 2 i zeta r)), accelerance = -w^2 receptance.
    const Complex rec = 1.0 / (1e5 * Complex(1 - r * r, 2 * zeta * r));
    const double w = 2 * kPi * f;
    for (int i = 0; i < 3; ++i) h(k, i) = -w * w * rec * shape(i);
  }
  frf.h.push_back(h);
  const auto r = modalTwistAxis(frf, {0, 1, 2}, 0, 67.0, kLayout, Vector2(0, 0));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r->axis.method, PhasorAxisCase::InPhase);
  EXPECT_NEAR(r->axis.axis.axis.beta, beta0, 1e-9);
  // At resonance the receptance is -i shape / (2 zeta k): phase -pi/2 relative to the shape.
  EXPECT_NEAR(std::abs(r->receptance(0)), std::abs(shape(0)) / (2 * zeta * 1e5),
              1e-9 * std::abs(shape(0)) / (2 * zeta * 1e5));
  EXPECT_FALSE(modalTwistAxis(frf, {0, 1, 2}, 0, 500.0, kLayout, Vector2(0, 0)).ok());
  EXPECT_FALSE(modalTwistAxis(frf, {0, 1, 7}, 0, 50.0, kLayout, Vector2(0, 0)).ok());
  EXPECT_FALSE(modalTwistAxis(frf, {0, 1}, 0, 50.0, kLayout, Vector2(0, 0)).ok());
}

// Two close modes with different shapes (like Fig. 6, fork A at 67 Hz): between
// them the FRF phases are general, so the tool switches to the three-instant
// method and says so; at the first resonance it stays in-phase.
TEST(ModalTwistAxis, ReportsWhichCaseApplied) {
  // Mode 1 dominates its own resonance (participation 10x), as in a well-separated bending mode.
  const Vector s1 = rigidAmplitudes(Vector2(0.0, -0.9), Vector2(std::sin(0.1), std::cos(0.1)), 10.0);
  const Vector s2 = rigidAmplitudes(Vector2(0.1, 0.0), Vector2(std::sin(1.4), std::cos(1.4)), 1.0);
  FrfMatrix frf;
  frf.type = FrfType::Receptance;
  frf.frequencyHz = Vector::LinSpaced(200, 40.0, 90.0);
  for (int i = 0; i < 3; ++i) frf.responses.push_back(Dof{i + 1, Direction::Y, false});
  frf.references.push_back(Dof{10, Direction::Y, false});
  ComplexMatrix h(200, 3);
  for (int k = 0; k < 200; ++k) {
    const double f = frf.frequencyHz(k);
    const Complex m1 = 1.0 / (1e5 * Complex(1 - std::pow(f / 60.0, 2), 2 * 0.01 * f / 60.0));
    const Complex m2 = 1.0 / (1e5 * Complex(1 - std::pow(f / 67.0, 2), 2 * 0.03 * f / 67.0));
    for (int i = 0; i < 3; ++i) h(k, i) = m1 * s1(i) + m2 * s2(i);
  }
  frf.h.push_back(h);
  const auto at60 = modalTwistAxis(frf, {0, 1, 2}, 0, 60.0, kLayout, Vector2(0, 0));
  ASSERT_TRUE(at60.ok()) << at60.error().describe();
  EXPECT_EQ(at60->axis.method, PhasorAxisCase::InPhase);
  const auto between = modalTwistAxis(frf, {0, 1, 2}, 0, 64.0, kLayout, Vector2(0, 0));
  ASSERT_TRUE(between.ok()) << between.error().describe();
  EXPECT_EQ(between->axis.method, PhasorAxisCase::ThreeInstant);
  EXPECT_TRUE(between->axis.lowConfidence);
  EXPECT_NE(between->axis.note.find("instants"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::stiffness
