// Exact state-transition simulation against closed-form SDOF and modal
// solutions (thesis eq. 18).
#include "core/signal/mdof_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

LinearMdof sdof(double m, double k, double c) {
  return LinearMdof{Matrix::Constant(1, 1, m), Matrix::Constant(1, 1, c), Matrix::Constant(1, 1, k)};
}

// Tolerances: the discretisation is exact, so only rounding in the matrix
// exponential (Pade, ~1e-15 relative) accumulated over the steps remains;
// 1e-9 relative to the response amplitude is far above that and far below
// any discretisation error (a ZOH/Euler scheme would be off by ~1e-3 here).

TEST(MdofSimulation, FreeDecayMatchesClosedForm) {
  const double m = 2.0, wn = 2 * kPi * 15.0, zeta = 0.03;
  const auto sys = sdof(m, m * wn * wn, 2 * zeta * m * wn);
  const double fs = 200.0, q0 = 1e-3;
  auto r = simulateMdof(sys, Matrix::Zero(400, 1), fs, ForceHold::ZeroOrder, Vector::Constant(1, q0));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const double wd = wn * std::sqrt(1 - zeta * zeta), s = zeta * wn;
  for (Eigen::Index i = 0; i < 400; ++i) {
    const double t = i / fs;
    // q = e^{-s t} (q0 cos wd t + s q0 / wd sin wd t)
    const double q = std::exp(-s * t) * (q0 * std::cos(wd * t) + s * q0 / wd * std::sin(wd * t));
    ASSERT_NEAR(r->displacement(i, 0), q, 1e-9 * q0) << "sample " << i;
  }
}

TEST(MdofSimulation, ZeroOrderHoldIsExactForAStep) {
  const double m = 1.0, wn = 2 * kPi * 8.0, zeta = 0.05, F = 3.0;
  const double k = m * wn * wn;
  const auto sys = sdof(m, k, 2 * zeta * m * wn);
  const double fs = 100.0;
  auto r = simulateMdof(sys, Matrix::Constant(300, 1, F), fs, ForceHold::ZeroOrder);
  ASSERT_TRUE(r.ok());
  const double wd = wn * std::sqrt(1 - zeta * zeta), s = zeta * wn;
  for (Eigen::Index i = 0; i < 300; ++i) {
    const double t = i / fs;
    // q = F/k (1 - e^{-s t} (cos wd t + s/wd sin wd t))
    const double q = F / k * (1 - std::exp(-s * t) * (std::cos(wd * t) + s / wd * std::sin(wd * t)));
    ASSERT_NEAR(r->displacement(i, 0), q, 1e-9 * F / k) << "sample " << i;
    // q'' from the equation of motion at the sample
    ASSERT_NEAR(r->acceleration(i, 0), (F - sys.damping(0, 0) * r->velocity(i, 0) - k * r->displacement(i, 0)) / m,
                1e-9 * F / m);
  }
}

TEST(MdofSimulation, FirstOrderHoldIsExactForARamp) {
  // undamped SDOF under f = r t: q = (r / k) (t - sin(wn t) / wn)
  const double m = 0.5, wn = 2 * kPi * 4.0, rate = 10.0;
  const double k = m * wn * wn;
  const auto sys = sdof(m, k, 0.0);
  const double fs = 50.0;
  Matrix f(200, 1);
  for (Eigen::Index i = 0; i < 200; ++i) f(i, 0) = rate * i / fs;
  auto r = simulateMdof(sys, f, fs, ForceHold::FirstOrder);
  ASSERT_TRUE(r.ok());
  for (Eigen::Index i = 0; i < 200; ++i) {
    const double t = i / fs;
    ASSERT_NEAR(r->displacement(i, 0), rate / k * (t - std::sin(wn * t) / wn), 1e-9 * rate * 4.0 / k) << i;
  }
  // the same ramp with a zero-order hold lags by half a step: clearly different
  auto z = simulateMdof(sys, f, fs, ForceHold::ZeroOrder);
  ASSERT_TRUE(z.ok());
  EXPECT_GT((z->displacement - r->displacement).cwiseAbs().maxCoeff(), 1e-3 * rate / k);
}

TEST(MdofSimulation, UndampedTwoDofStaysInItsMode) {
  // chain ground-k1-m1-k2-m2: eigenvalues of M^-1 K are 5e4 and 2e5 (rad/s)^2
  LinearMdof s;
  s.mass = Eigen::Vector2d(1.0, 0.5).asDiagonal();
  s.stiffness.resize(2, 2);
  s.stiffness << 1.5e5, -5e4, -5e4, 5e4;
  s.damping = Matrix::Zero(2, 2);
  // mode 1: (K - w^2 M) phi = 0 with w^2 = 5e4: phi = (1, 2)
  const Eigen::Vector2d phi(1.0, 2.0);
  const double w = std::sqrt(5e4), fs = 1000.0;
  auto r = simulateMdof(s, Matrix::Zero(500, 2), fs, ForceHold::ZeroOrder, 1e-3 * phi);
  ASSERT_TRUE(r.ok());
  for (Eigen::Index i = 0; i < 500; ++i) {
    const double c = std::cos(w * i / fs);
    ASSERT_NEAR(r->displacement(i, 0), 1e-3 * c, 1e-12) << i;
    ASSERT_NEAR(r->displacement(i, 1), 2e-3 * c, 1e-12) << i;
  }
}

TEST(MdofSimulation, BadInputIsAnError) {
  const auto sys = sdof(1.0, 100.0, 1.0);
  EXPECT_FALSE(simulateMdof(sys, Matrix::Zero(10, 1), 0.0).ok());
  EXPECT_FALSE(simulateMdof(sys, Matrix::Zero(10, 2), 100.0).ok());
  EXPECT_FALSE(simulateMdof(sys, Matrix::Zero(0, 1), 100.0).ok());
  Matrix f = Matrix::Zero(10, 1);
  f(3, 0) = std::nan("");
  EXPECT_FALSE(simulateMdof(sys, f, 100.0).ok());
  EXPECT_FALSE(simulateMdof(sdof(-1.0, 100.0, 1.0), Matrix::Zero(10, 1), 100.0).ok());  // M not positive definite
  LinearMdof nonSquare = sys;
  nonSquare.stiffness = Matrix::Zero(1, 2);
  EXPECT_FALSE(simulateMdof(nonSquare, Matrix::Zero(10, 1), 100.0).ok());
  EXPECT_FALSE(simulateMdof(sys, Matrix::Zero(10, 1), 100.0, ForceHold::ZeroOrder, Vector::Zero(3)).ok());
}

}  // namespace
}  // namespace mozzi::core::signal
