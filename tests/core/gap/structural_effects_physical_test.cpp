// Every structural catalogue effect is a physical quantity (issue 16): added
// mass in kg, a spring scale, the window's decay rate in 1/s by which every
// pole's real part moves, the loss factor eta, a tilt in degrees, residual
// terms in m/N and 1/kg. Each is checked here against a system built without
// the catalogue code:
//  - mass, springs, eta, tilt, residual terms and two effects at once: a
//    direct solve of the augmented matrices, H = (K'(1 + i eta) + s C + s^2 M')^-1
//    per line (no modal expansion);
//  - the exponential window: the impulse response of the nominal system in
//    the time domain (state-space eigen-solution), multiplied by exp(-a t),
//    sampled at 20 kHz and transformed by FFT.
// The problem gets the independent FRFs as "measured" data with a stated
// relative sigma of 1 per component, so each whitened residual is the relative
// error of the catalogue's prediction.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/gap/structural/structural_problem.h"
#include "core/signal/fft.h"
#include "validation/gap/structural_benchmark.h"

namespace mozzi::core::gap::structural {
namespace {

const gap_bench::Structure kArm = gap_bench::viscousC(gap_bench::swingArm());

int findCandidate(const GapProblem& p, const std::string& effect, const std::vector<std::string>& location) {
  const auto c = p.candidates();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].effect == effect && c[i].location == location) return static_cast<int>(i);
  return -1;
}

// Receptance FRFs (all DOFs / reference 3+Z) of the augmented system by a
// direct solve per line; `extra` adds a term per line (residual effects) and
// `tilt` mixes response o with p.
struct Augmented {
  Matrix dm, dk;
  double eta = 0.0;
  int tiltDof = -1, tiltOther = -1;
  double tiltRad = 0.0;
  std::function<ComplexMatrix(Complex)> extra;
};

FrfMatrix directFrf(const StructuralModel& m, const Augmented& a, const Vector& hz) {
  FrfMatrix frf;
  frf.type = FrfType::Receptance;
  frf.responses = m.dofs;
  frf.references = {*parseDof("3+Z")};
  frf.frequencyHz = hz;
  const int ref = m.findDof(frf.references[0]);
  const auto n = static_cast<Eigen::Index>(m.dofCount());
  frf.h.assign(1, ComplexMatrix(hz.size(), n));
  for (Eigen::Index k = 0; k < hz.size(); ++k) {
    const Complex s(0.0, 2 * M_PI * hz[k]);
    const ComplexMatrix z = (m.k + a.dk).cast<Complex>() * Complex(1.0, a.eta) + s * m.c.cast<Complex>() +
                            s * s * (m.m + a.dm).cast<Complex>();
    ComplexMatrix h = z.partialPivLu().inverse();
    if (a.extra) h += a.extra(s);
    for (Eigen::Index o = 0; o < n; ++o) {
      Complex v = h(o, ref);
      if (o == a.tiltDof) v = std::cos(a.tiltRad) * v + std::sin(a.tiltRad) * h(a.tiltOther, ref);
      frf.h[0](k, o) = v;
    }
  }
  return frf;
}

// Largest relative error of the prediction at (theta nominal, combo, phi).
double worstRelative(const FrfMatrix& truth, const std::vector<std::string>& effects,
                     const std::vector<std::vector<std::string>>& locations, const std::vector<double>& phi) {
  StructuralOptions opt;
  opt.noise = StructuralOptions::NoiseSource::Stated;
  opt.relativeFloor = 1.0;  // whitened residual = relative error per component
  auto p = makeFrfProblem(kArm.model, truth, opt);
  EXPECT_TRUE(p.ok()) << p.error().describe();
  if (!p.ok()) return 1e9;
  std::vector<int> combo;
  for (std::size_t i = 0; i < effects.size(); ++i) {
    combo.push_back(findCandidate(**p, effects[i], locations[i]));
    EXPECT_GE(combo.back(), 0) << effects[i];
    if (combo.back() < 0) return 1e9;
  }
  const std::vector<double> theta{1.0, 1.0};
  std::vector<double> r(static_cast<std::size_t>((*p)->residualCount()));
  const bool ok = combo.size() == 1 ? (*p)->residuals({theta.data(), combo[0], phi.data()}, r.data())
                                    : (*p)->combinedResiduals(theta.data(), combo, phi.data(), r.data());
  EXPECT_TRUE(ok);
  double worst = 0;
  for (double x : r) worst = std::max(worst, std::abs(x));
  return worst;
}

Vector lines() {
  return Vector::LinSpaced(200, kArm.bandLowHz, kArm.bandHighHz);
}

Matrix zeros() {
  return Matrix::Zero(kArm.model.dofCount(), kArm.model.dofCount());
}

Augmented plain() {
  Augmented a;
  a.dm = zeros();
  a.dk = zeros();
  return a;
}

// Round-off of a per-line solve against another: 1e-9 relative.
constexpr double kDirectTol = 1e-9;

TEST(StructuralEffectsPhysical, AddedMassInKilograms) {
  Augmented a = plain();
  a.dm(4, 4) = 0.45;  // 0.45 kg at 3+X
  EXPECT_LT(worstRelative(directFrf(kArm.model, a, lines()), {"mass_loading"}, {{"3+X"}}, {0.45}), kDirectTol);
}

TEST(StructuralEffectsPhysical, SpringScales) {
  Augmented a = plain();
  a.dk = (0.4 - 1.0) * gap_bench::springMatrix(kArm.model, "shock");  // the shock at 0.4 of its stiffness
  EXPECT_LT(worstRelative(directFrf(kArm.model, a, lines()), {"boundary_stiffness"}, {{"2+Z"}}, {0.4}), kDirectTol);
  Augmented b = plain();
  b.dk = (1.7 - 1.0) * gap_bench::springMatrix(kArm.model, "arm_z23");
  EXPECT_LT(worstRelative(directFrf(kArm.model, b, lines()), {"element_stiffness"}, {{"2+Z", "3+Z"}}, {1.7}),
            kDirectTol);
}

TEST(StructuralEffectsPhysical, LossFactorEta) {
  Augmented a = plain();
  a.eta = 0.04;  // K (1 + 0.04 i) on top of the viscous C
  EXPECT_LT(worstRelative(directFrf(kArm.model, a, lines()), {"hysteretic_damping"}, {{}}, {0.04}), kDirectTol);
}

TEST(StructuralEffectsPhysical, TiltInDegrees) {
  Augmented a = plain();
  a.tiltDof = 4;  // 3+X leans 12 degrees towards 3+Z
  a.tiltOther = 5;
  a.tiltRad = 12.0 * M_PI / 180.0;
  EXPECT_LT(worstRelative(directFrf(kArm.model, a, lines()), {"sensor_misalignment"}, {{"3+X", "3+Z"}}, {12.0}),
            kDirectTol);
}

// Residual terms (U - V s^2 / omega_t^2 + L / s^2) u u^T along the static
// deflection u under a unit load at the reference (K^-1 column, max |u| = 1),
// omega_t the top of the band: U, V in m/N, L in 1/kg.
TEST(StructuralEffectsPhysical, ResidualTermsInMetresPerNewtonAndPerKilogram) {
  const Matrix g = kArm.model.k.inverse();
  const int ref = kArm.model.findDof(*parseDof("3+Z"));
  Vector u = g.col(ref) / g(ref, ref);
  u /= u.cwiseAbs().maxCoeff();
  const double U = 2e-6, V = 5e-7, L = 0.05, wt = 2 * M_PI * kArm.bandHighHz;
  Augmented a = plain();
  a.extra = [&](Complex s) {
    return ComplexMatrix(((U - V * s * s / (wt * wt) + L / (s * s)) * (u * u.transpose()).cast<Complex>()));
  };
  EXPECT_LT(worstRelative(directFrf(kArm.model, a, lines()), {"residual_mode"}, {{"3+Z"}}, {U, V, L}), kDirectTol);
}

// Two effects at once: a mass and a tilted sensor, applied together.
TEST(StructuralEffectsPhysical, TwoEffectsTogether) {
  Augmented a = plain();
  a.dm(2, 2) = 0.3;  // 2+X
  a.tiltDof = 4;
  a.tiltOther = 5;
  a.tiltRad = -7.0 * M_PI / 180.0;
  EXPECT_LT(worstRelative(directFrf(kArm.model, a, lines()), {"mass_loading", "sensor_misalignment"},
                          {{"2+X"}, {"3+X", "3+Z"}}, {0.3, -7.0}),
            kDirectTol);
  Augmented b = plain();
  b.dm(4, 4) = 0.2;
  b.dk = (0.6 - 1.0) * gap_bench::springMatrix(kArm.model, "pivot_z");
  EXPECT_LT(worstRelative(directFrf(kArm.model, b, lines()), {"mass_loading", "boundary_stiffness"}, {{"3+X"}, {"1+Z"}},
                          {0.2, 0.6}),
            kDirectTol);
}

// The exponential window w(t) = exp(-a t) on the impulse response: the
// windowed FRF is the transform of h(t) exp(-a t), computed here in the time
// domain. h(t) = [I 0] exp(A t) [0; M^-1 e_ref] from the eigen-solution of the
// state matrix A = [0 I; -M^-1 K, -M^-1 C]; sampled at 20 kHz over 6.6 s (every
// pole's envelope below 1e-14 of its start with a = 6 /s), transformed by FFT
// as dt sum_n g(n dt) exp(-i omega n dt) plus the Euler-Maclaurin end
// correction dt^2 / 12 g'(0) (h(0) = 0, g'(0) = the velocity after a unit
// impulse, M^-1 e_ref). Tolerance 1e-5 relative: the remaining O(dt^4 omega^4)
// and aliasing terms at 400 Hz against 10 kHz Nyquist are below 1e-6.
TEST(StructuralEffectsPhysical, WindowDecayRateFromTheTimeDomain) {
  const StructuralModel& m = kArm.model;
  const Eigen::Index n = m.dofCount();
  const double decay = 6.0;  // 1/s
  const int ref = m.findDof(*parseDof("3+Z"));
  Matrix a = Matrix::Zero(2 * n, 2 * n);
  const Matrix minv = m.m.inverse();
  a.topRightCorner(n, n).setIdentity();
  a.bottomLeftCorner(n, n) = -minv * m.k;
  a.bottomRightCorner(n, n) = -minv * m.c;
  Eigen::EigenSolver<Matrix> eig(a);
  ASSERT_EQ(eig.info(), Eigen::Success);
  const ComplexVector lambda = eig.eigenvalues();
  const ComplexMatrix v = eig.eigenvectors();
  Vector b = Vector::Zero(2 * n);
  b.tail(n) = minv.col(ref);
  const ComplexVector q = v.partialPivLu().solve(b.cast<Complex>());
  const double fs = 20000.0, dt = 1.0 / fs;
  const Eigen::Index samples = 131072;  // 6.55 s
  auto fft = signal::RealFft::forLength(samples);
  ASSERT_TRUE(fft.ok());
  // Every 50th FFT line from the band's bottom to its top.
  const double df = fs / static_cast<double>(samples);
  std::vector<Eigen::Index> k;
  for (Eigen::Index j = static_cast<Eigen::Index>(std::ceil(kArm.bandLowHz / df)); j * df <= kArm.bandHighHz; j += 50)
    k.push_back(j);
  FrfMatrix frf;
  frf.type = FrfType::Receptance;
  frf.responses = m.dofs;
  frf.references = {m.dofs[static_cast<std::size_t>(ref)]};
  frf.frequencyHz.resize(static_cast<Eigen::Index>(k.size()));
  for (std::size_t j = 0; j < k.size(); ++j) frf.frequencyHz[static_cast<Eigen::Index>(j)] = k[j] * df;
  frf.h.assign(1, ComplexMatrix(static_cast<Eigen::Index>(k.size()), n));
  Vector g(samples);
  for (Eigen::Index o = 0; o < n; ++o) {
    for (Eigen::Index i = 0; i < samples; ++i) {
      const double t = static_cast<double>(i) * dt;
      Complex sum(0.0, 0.0);
      for (Eigen::Index j = 0; j < lambda.size(); ++j) sum += v(o, j) * std::exp(lambda[j] * t) * q[j];
      g[i] = sum.real() * std::exp(-decay * t);
    }
    auto spectrum = (*fft)->transform(g);
    ASSERT_TRUE(spectrum.ok());
    for (std::size_t j = 0; j < k.size(); ++j)
      frf.h[0](static_cast<Eigen::Index>(j), o) = dt * (*spectrum)[k[j]] + dt * dt / 12.0 * minv(o, ref);
  }
  StructuralOptions opt;
  opt.noise = StructuralOptions::NoiseSource::Stated;
  opt.relativeFloor = 1.0;
  auto p = makeFrfProblem(m, frf, opt);
  ASSERT_TRUE(p.ok()) << p.error().describe();
  const int cand = findCandidate(**p, "exponential_window", {});
  ASSERT_GE(cand, 0);
  const std::vector<double> theta{1.0, 1.0};
  std::vector<double> r(static_cast<std::size_t>((*p)->residualCount()));
  ASSERT_TRUE((*p)->residuals({theta.data(), cand, &decay}, r.data()));
  double worst = 0;
  for (double x : r) worst = std::max(worst, std::abs(x));
  EXPECT_LT(worst, 1e-5);
  // Without the window the prediction is off by far more (the decay is
  // 6 /s against the first pole's ~3 /s).
  ASSERT_TRUE((*p)->residuals({theta.data(), -1, nullptr}, r.data()));
  worst = 0;
  for (double x : r) worst = std::max(worst, std::abs(x));
  EXPECT_GT(worst, 0.1);
  // The unit says what it is.
  EXPECT_EQ((*p)->candidates()[static_cast<std::size_t>(cand)].parameters[0].unit, "1/s");
}

TEST(StructuralEffectsPhysical, Units) {
  StructuralOptions opt;
  opt.noise = StructuralOptions::NoiseSource::Stated;
  Augmented none = plain();
  auto p = makeFrfProblem(kArm.model, directFrf(kArm.model, none, lines()), opt);
  ASSERT_TRUE(p.ok());
  for (const auto& c : (*p)->candidates()) {
    const std::string unit = c.parameters[0].unit;
    if (c.effect == "mass_loading") {
      EXPECT_EQ(unit, "kg");
    } else if (c.effect == "boundary_stiffness" || c.effect == "element_stiffness" ||
               c.effect == "hysteretic_damping") {
      EXPECT_EQ(unit, "");
    } else if (c.effect == "exponential_window") {
      EXPECT_EQ(unit, "1/s");
    } else if (c.effect == "sensor_misalignment") {
      EXPECT_EQ(unit, "deg");
    }
    if (c.effect == "residual_mode") {
      EXPECT_EQ(unit, "m/N");
      EXPECT_EQ(c.parameters[2].unit, "1/kg");
    }
  }
}

}  // namespace
}  // namespace mozzi::core::gap::structural
