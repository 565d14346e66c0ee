#pragma once
// Benchmark generator for the structural sim-to-real gap (issues 10 and 16,
// GAP.md "Testing it honestly"): four lumped structures of thesis magnitude, each
// effect of the catalogue applied to a hidden truth, measurement noise, and
// FRFs computed INDEPENDENTLY of core/gap (direct inversion of
// K' + s C' + s^2 M' per line, no modal expansion), so a wrong modal sum or a
// wrong effect implementation in the problem shows up as a misfit.
//
// Structures (masses and stiffnesses of the thesis' components: fork legs of
// 1-2 kg on 1e5-1e6 N/m, a 2.5 kg wheel on a 1.5e5 N/m tyre, frame nodes of
// 2-4 kg, a swing arm with a 1e4 N/m shock):
//  - fork_wheel: crown, two leg stations and the axle, X (fore-aft) and Z
//    (vertical) at each; steering-head clamp as grounded springs, tyre spring.
//  - frame: five nodes of a closed loop, X and Y each, two engine mounts
//    grounded.
//  - swing_arm: pivot, mid-arm and axle with Z and X, pivot bearing grounded,
//    shock between mid-arm Z and ground.
//  - subframe: a seat subframe, 5 DOFs, two hammer points.
// Measurement noise: relative and/or an additive floor, with or without
// coherence records (issue 16).
// Each has Rayleigh damping (viscous C = alpha M + beta K, zeta 1-3%) and two
// calibration parameters: a damping scale and a stiffness group with a 5% prior.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/frf_matrix.h"
#include "core/gap/structural/model_file.h"
#include "core/io/uff/uff.h"

namespace mozzi::gap_bench {

using core::Complex;
using core::ComplexMatrix;
using core::Matrix;
using core::Vector;
using core::gap::structural::StructuralModel;

struct SpringSpec {
  std::string name;
  std::string a, b;  // labels; b = "ground"
  double k;
};

struct Structure {
  std::string name;
  StructuralModel model;
  std::vector<std::string> references;  // hammer DOFs
  double bandLowHz = 0, bandHighHz = 0;
  std::string calibratedGroup;  // springs the stiffness calibration parameter scales
  double alpha = 0, beta = 0;   // Rayleigh coefficients behind the modal damping
};

// The same structure with viscous C = alpha M + beta K (non-proportional once
// a mass or spring changes): exercises the C path of the problem.
inline Structure viscousC(Structure s) {
  s.model.c = s.alpha * s.model.m + s.beta * s.model.k;
  s.model.modalDamping.resize(0);
  return s;
}

inline StructuralModel buildModel(const std::string& name, const std::vector<std::string>& labels,
                                  const std::vector<double>& masses, const std::vector<SpringSpec>& springs,
                                  double alpha, double beta, const std::vector<std::string>& calibrated) {
  StructuralModel m;
  m.name = name;
  const int n = static_cast<int>(labels.size());
  for (const auto& l : labels) {
    m.dofs.push_back(*core::parseDof(l));
    m.labels.push_back(l);
  }
  m.t = Matrix::Identity(n, n);
  m.m = Matrix::Zero(n, n);
  for (int i = 0; i < n; ++i) m.m(i, i) = masses[static_cast<std::size_t>(i)];
  m.k = Matrix::Zero(n, n);
  for (const auto& s : springs) {
    core::gap::structural::Spring sp;
    sp.name = s.name;
    sp.a = m.findDof(*core::parseDof(s.a));
    sp.b = s.b == "ground" ? -1 : m.findDof(*core::parseDof(s.b));
    sp.stiffness = s.k;
    m.k(sp.a, sp.a) += s.k;
    if (sp.b >= 0) {
      m.k(sp.b, sp.b) += s.k;
      m.k(sp.a, sp.b) -= s.k;
      m.k(sp.b, sp.a) -= s.k;
    }
    m.springs.push_back(sp);
  }
  // Modal damping with the Rayleigh pattern zeta_r = alpha / (2 w_r) + beta w_r / 2
  // at the nominal modes (each mode keeps its ratio when masses or springs
  // change); viscousC() turns it into C = alpha M + beta K instead.
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(m.k, m.m);
  const Vector w = eig.eigenvalues().cwiseSqrt();
  m.modalDamping = (alpha * w.cwiseInverse() + beta * w) / 2;
  // Damping is never known well: a scale on C from 0 (no viscous damping) to 5.
  m.parameters.push_back({"damping_scale", {"damping"}, 1.0, 0.0, 5.0, 0.0});
  // One stiffness group calibrated with a 5% prior (the model's own uncertainty).
  m.parameters.push_back({"k_group", calibrated, 1.0, 0.5, 2.0, 0.05});
  return m;
}

// Rayleigh coefficients giving zeta1 at f1 and zeta2 at f2.
inline std::pair<double, double> rayleigh(double f1, double z1, double f2, double z2) {
  const double w1 = 2 * M_PI * f1, w2 = 2 * M_PI * f2;
  // zeta = alpha / (2 w) + beta w / 2
  Eigen::Matrix2d a;
  a << 1 / (2 * w1), w1 / 2, 1 / (2 * w2), w2 / 2;
  const Eigen::Vector2d x = a.inverse() * Eigen::Vector2d(z1, z2);
  return {x[0], x[1]};
}

inline Structure forkWheel() {
  Structure s;
  s.name = "fork_wheel";
  const std::vector<std::string> l = {"1+X", "1+Z", "2+X", "2+Z", "3+X", "3+Z", "4+X", "4+Z"};
  const std::vector<double> mass = {1.8, 1.8, 1.2, 1.2, 1.0, 1.0, 2.5, 2.5};
  const std::vector<SpringSpec> sp = {{"head_x", "1+X", "ground", 6.0e5}, {"head_z", "1+Z", "ground", 2.0e6},
                                      {"leg_x12", "1+X", "2+X", 4.0e5},   {"leg_x23", "2+X", "3+X", 3.5e5},
                                      {"leg_x34", "3+X", "4+X", 3.0e5},   {"leg_z12", "1+Z", "2+Z", 1.5e6},
                                      {"leg_z23", "2+Z", "3+Z", 1.4e6},   {"leg_z34", "3+Z", "4+Z", 1.2e6},
                                      {"tyre", "4+Z", "ground", 1.5e5},   {"brace", "3+X", "3+Z", 8.0e4}};
  const auto [al, be] = rayleigh(30, 0.02, 300, 0.015);
  s.model = buildModel(s.name, l, mass, sp, al, be, {"leg_z12", "leg_z23", "leg_z34"});
  s.references = {"4+X"};
  s.bandLowHz = 5;
  s.bandHighHz = 500;
  s.calibratedGroup = "leg_z";
  s.alpha = al;
  s.beta = be;
  return s;
}

inline Structure frame() {
  Structure s;
  s.name = "frame";
  const std::vector<std::string> l = {"1+X", "1+Y", "2+X", "2+Y", "3+X", "3+Y", "4+X", "4+Y", "5+X", "5+Y"};
  const std::vector<double> mass = {3.0, 3.0, 2.0, 2.0, 4.0, 4.0, 2.5, 2.5, 2.0, 2.0};
  const std::vector<SpringSpec> sp = {
      {"mount_1x", "1+X", "ground", 8.0e5}, {"mount_1y", "1+Y", "ground", 8.0e5}, {"mount_3x", "3+X", "ground", 5.0e5},
      {"mount_3y", "3+Y", "ground", 5.0e5}, {"tube_x12", "1+X", "2+X", 6.0e5},    {"tube_x23", "2+X", "3+X", 4.0e5},
      {"tube_x34", "3+X", "4+X", 5.0e5},    {"tube_x45", "4+X", "5+X", 3.0e5},    {"tube_x51", "5+X", "1+X", 7.0e5},
      {"tube_y12", "1+Y", "2+Y", 2.0e5},    {"tube_y23", "2+Y", "3+Y", 2.5e5},    {"tube_y34", "3+Y", "4+Y", 1.8e5},
      {"tube_y45", "4+Y", "5+Y", 2.2e5},    {"tube_y51", "5+Y", "1+Y", 3.0e5},    {"gusset", "4+X", "4+Y", 6.0e4}};
  const auto [al, be] = rayleigh(40, 0.015, 300, 0.02);
  s.model = buildModel(s.name, l, mass, sp, al, be, {"tube_y12", "tube_y23", "tube_y34", "tube_y45", "tube_y51"});
  s.references = {"2+X", "4+Y"};
  s.bandLowHz = 10;
  s.bandHighHz = 450;
  s.calibratedGroup = "tube_y";
  s.alpha = al;
  s.beta = be;
  return s;
}

inline Structure swingArm() {
  Structure s;
  s.name = "swing_arm";
  const std::vector<std::string> l = {"1+X", "1+Z", "2+X", "2+Z", "3+X", "3+Z"};
  const std::vector<double> mass = {1.5, 1.5, 2.0, 2.0, 3.0, 3.0};
  const std::vector<SpringSpec> sp = {{"pivot_x", "1+X", "ground", 1.2e6}, {"pivot_z", "1+Z", "ground", 9.0e5},
                                      {"arm_x12", "1+X", "2+X", 8.0e5},    {"arm_x23", "2+X", "3+X", 6.0e5},
                                      {"arm_z12", "1+Z", "2+Z", 2.5e5},    {"arm_z23", "2+Z", "3+Z", 1.8e5},
                                      {"shock", "2+Z", "ground", 4.0e4},   {"chain", "3+X", "3+Z", 5.0e4}};
  const auto [al, be] = rayleigh(20, 0.025, 250, 0.015);
  s.model = buildModel(s.name, l, mass, sp, al, be, {"arm_x12", "arm_x23"});
  s.references = {"3+Z"};
  s.bandLowHz = 4;
  s.bandHighHz = 400;
  s.calibratedGroup = "arm_x";
  s.alpha = al;
  s.beta = be;
  return s;
}

// A seat subframe: two nodes with X and Z, a rear node with Z only (5 DOFs),
// two hammer points (2+Z, 3+Z); mounts to the main frame as grounded springs.
// Also the 5-DOF model of the speed benchmark (docs/performance/gap.md).
inline Structure seatSubframe() {
  Structure s;
  s.name = "subframe";
  const std::vector<std::string> l = {"1+X", "1+Z", "2+X", "2+Z", "3+Z"};
  const std::vector<double> mass = {1.2, 1.2, 0.9, 0.9, 1.6};
  const std::vector<SpringSpec> sp = {{"mount_x", "1+X", "ground", 7.0e5}, {"mount_z", "1+Z", "ground", 4.0e5},
                                      {"rail_x", "1+X", "2+X", 3.0e5},     {"rail_z", "1+Z", "2+Z", 2.2e5},
                                      {"strut", "2+Z", "ground", 1.2e5},   {"tail", "2+Z", "3+Z", 9.0e4},
                                      {"web", "2+X", "2+Z", 5.0e4}};
  const auto [al, be] = rayleigh(25, 0.02, 200, 0.02);
  s.model = buildModel(s.name, l, mass, sp, al, be, {"rail_x", "rail_z"});
  s.references = {"2+Z", "3+Z"};
  s.bandLowHz = 5;
  s.bandHighHz = 350;
  s.calibratedGroup = "rail";
  s.alpha = al;
  s.beta = be;
  return s;
}

inline std::vector<Structure> structures() {
  return {forkWheel(), frame(), swingArm(), seatSubframe()};
}

// Stiffness matrix of one named spring of the model (independent of core/gap).
inline Matrix springMatrix(const StructuralModel& m, const std::string& name) {
  Matrix k = Matrix::Zero(m.dofCount(), m.dofCount());
  for (const auto& s : m.springs) {
    if (s.name != name) continue;
    k(s.a, s.a) += s.stiffness;
    if (s.b >= 0) {
      k(s.b, s.b) += s.stiffness;
      k(s.a, s.b) -= s.stiffness;
      k(s.b, s.a) -= s.stiffness;
    }
  }
  return k;
}

// ---------------------------------------------------------------------------
// Truth: the nominal model with calibration offsets and at most one effect.

struct Truth {
  double dampingScale = 1.0;  // true damping relative to the model
  double groupScale = 1.0;    // true stiffness of the calibrated group
  Matrix dm;                  // added mass matrix (n x n), zero when none
  Matrix dk;                  // stiffness change (n x n)
  double eta = 0.0;           // structural damping i eta K
  double decay = 0.0;         // exponential window 1/tau
  int misDof = -1, misOther = -1;
  double misAngle = 0.0;
  // residual term H += (upper + lower / s^2) u u^T
  Vector residualShape;
  double residualModeHz = 0.0, residualModalConstant = 0.0;  // an out-of-band mode A u u^T / (w_x^2 + s^2)
  // Out-of-catalogue: a tuned absorber (mass on a spring, own damper) at one DOF.
  int absorberDof = -1;
  double absorberMass = 0.0, absorberHz = 0.0, absorberZeta = 0.0;

  explicit Truth(int n = 0) : dm(Matrix::Zero(n, n)), dk(Matrix::Zero(n, n)) {}
};

// Receptance of the truth at s, all DOFs: the absorber adds one coordinate
// and is condensed out exactly (dynamic stiffness of a base-excited SDOF).
inline ComplexMatrix truthReceptance(const StructuralModel& m, const Truth& t, Complex s) {
  const Eigen::Index n = m.m.rows();
  Matrix kGroup = Matrix::Zero(n, n);
  for (const auto& name : m.parameters[1].actsOn) kGroup += springMatrix(m, name);
  const Matrix k = m.k + (t.groupScale - 1.0) * kGroup + t.dk;
  const Matrix mm = m.m + t.dm;
  Matrix c;
  if (m.usesModalDamping()) {
    // Modal damping: each mode of the truth keeps the model's ratio,
    // C = M Phi diag(2 zeta_r w_r) Phi^T M with the truth's own modes.
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(k, mm);
    const Vector w = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    const Matrix mp = mm * eig.eigenvectors();
    c = mp * (2.0 * t.dampingScale * m.modalDamping.cwiseProduct(w)).asDiagonal() * mp.transpose();
  } else {
    c = t.dampingScale * m.c;
  }
  ComplexMatrix z = k.cast<Complex>() * Complex(1.0, t.eta) + s * c.cast<Complex>() + s * s * mm.cast<Complex>();
  if (t.absorberDof >= 0) {
    const double wa = 2 * M_PI * t.absorberHz;
    const double ka = t.absorberMass * wa * wa, ca = 2 * t.absorberZeta * t.absorberMass * wa;
    const Complex kc = ka + s * ca;
    // Force on the host from a base-driven SDOF: kc - kc^2 / (kc + s^2 ma).
    z(t.absorberDof, t.absorberDof) += kc - kc * kc / (kc + s * s * t.absorberMass);
  }
  ComplexMatrix h = z.partialPivLu().inverse();
  if (t.residualShape.size() == n) {
    const double wx = 2 * M_PI * t.residualModeHz;
    const Complex term = t.residualModalConstant / (wx * wx + s * s);
    h += term * (t.residualShape * t.residualShape.transpose()).cast<Complex>();
  }
  return h;
}

struct Measurement {
  std::vector<std::string> responses;  // labels
  std::vector<std::string> references;
  double lowHz = 0, highHz = 0;
  int lines = 0;
  double relativeNoise = 0.01;  // per real/imaginary component, relative to |H|
  // Additive floor per component, as a fraction of the FRF's median |H| over
  // the band: it dominates near antiresonances and at the low end (issue 16).
  double floorNoise = 0.0;
  // Write coherence consistent with the noise (H1 from `averages` averages:
  // g^2 = 1 / (1 + 2 n_avg (sigma / |H|)^2), Bendat & Piersol eq. 9.65 inverted).
  bool coherence = false;
  int averages = 10;
};

// Noisy accelerances of the truth as a FrfMatrix (what the diagnosis gets):
// relative noise plus an additive floor per component, and coherence when the
// spec asks for it.
inline core::FrfMatrix measure(const StructuralModel& m, const Truth& t, const Measurement& spec,
                               std::mt19937_64& rng) {
  core::FrfMatrix frf;
  frf.type = core::FrfType::Accelerance;
  for (const auto& r : spec.responses) frf.responses.push_back(*core::parseDof(r));
  for (const auto& r : spec.references) frf.references.push_back(*core::parseDof(r));
  frf.frequencyHz = Vector::LinSpaced(spec.lines, spec.lowHz, spec.highHz);
  const auto no = static_cast<Eigen::Index>(spec.responses.size());
  frf.h.assign(spec.references.size(), ComplexMatrix(spec.lines, no));
  for (int k = 0; k < spec.lines; ++k) {
    const double w = 2 * M_PI * frf.frequencyHz[k];
    // The exponential window multiplies the impulse response by exp(-a t):
    // the windowed spectrum is H(s) at s = i omega + a, and the accelerance
    // impulse response is windowed, so the s^2 factor is taken at that s too.
    const Complex s(t.decay, w);
    ComplexMatrix h = truthReceptance(m, t, s) * (s * s);
    for (std::size_t i = 0; i < spec.references.size(); ++i) {
      const int ri = m.findDof(frf.references[i]);
      for (Eigen::Index o = 0; o < no; ++o) {
        const int ro = m.findDof(frf.responses[static_cast<std::size_t>(o)]);
        Complex v = h(ro, ri);
        if (ro == t.misDof) v = std::cos(t.misAngle) * v + std::sin(t.misAngle) * h(t.misOther, ri);
        frf.h[i](k, o) = v;
      }
    }
  }
  std::normal_distribution<double> nd(0.0, 1.0);
  if (spec.coherence) frf.coherence.assign(spec.references.size(), core::Matrix(spec.lines, no));
  for (std::size_t i = 0; i < spec.references.size(); ++i)
    for (Eigen::Index o = 0; o < no; ++o) {
      std::vector<double> mags;
      for (int k = 0; k < spec.lines; ++k) mags.push_back(std::abs(frf.h[i](k, o)));
      std::nth_element(mags.begin(), mags.begin() + static_cast<long>(mags.size() / 2), mags.end());
      const double floor = spec.floorNoise * mags[mags.size() / 2];
      for (int k = 0; k < spec.lines; ++k) {
        const Complex v = frf.h[i](k, o);
        const double sd = std::hypot(spec.relativeNoise * std::abs(v), floor);
        frf.h[i](k, o) = v + Complex(sd * nd(rng), sd * nd(rng));
        if (spec.coherence) {
          const double rel = sd / std::max(std::abs(v), 1e-300);
          frf.coherence[i](k, o) = 1.0 / (1.0 + 2.0 * spec.averages * rel * rel);
        }
      }
    }
  return frf;
}

// Identified modes of the truth at the response DOFs (modes with a frequency in
// the measurement band), with the noise of GAP.md step 0's floors: frequency
// 0.2%, damping 15%, shapes 3% of the largest component. Effects on stiffness
// and mass only (the mode cases use no damping or sensor effect).
inline core::io::uff::ModalData measureModes(const StructuralModel& m, const Truth& t, const Measurement& spec,
                                             std::mt19937_64& rng) {
  Matrix kGroup = Matrix::Zero(m.dofCount(), m.dofCount());
  for (const auto& name : m.parameters[1].actsOn) kGroup += springMatrix(m, name);
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(m.k + (t.groupScale - 1.0) * kGroup + t.dk, m.m + t.dm);
  std::normal_distribution<double> nd(0.0, 1.0);
  core::io::uff::ModalData d;
  for (const auto& r : spec.responses) d.dofs.push_back(*core::parseDof(r));
  std::vector<Eigen::Index> keep;
  for (Eigen::Index r = 0; r < eig.eigenvalues().size(); ++r) {
    const double f = std::sqrt(eig.eigenvalues()[r]) / (2 * M_PI);
    if (f >= spec.lowHz && f <= spec.highHz) keep.push_back(r);
  }
  const auto nk = static_cast<Eigen::Index>(keep.size()), nd_ = static_cast<Eigen::Index>(d.dofs.size());
  d.frequencyHz.resize(nk);
  d.dampingRatio.resize(nk);
  d.modalMass = Vector::Zero(nk);
  d.shapes.resize(nd_, nk);
  for (Eigen::Index q = 0; q < nk; ++q) {
    const Eigen::Index r = keep[static_cast<std::size_t>(q)];
    const double f = std::sqrt(eig.eigenvalues()[r]) / (2 * M_PI);
    d.frequencyHz[q] = f * (1 + 0.002 * nd(rng));
    d.dampingRatio[q] = t.dampingScale * m.modalDamping[r] * (1 + 0.15 * nd(rng));
    Vector shape(nd_);
    for (Eigen::Index o = 0; o < nd_; ++o)
      shape[o] = eig.eigenvectors()(m.findDof(d.dofs[static_cast<std::size_t>(o)]), r);
    const double big = shape.cwiseAbs().maxCoeff();
    for (Eigen::Index o = 0; o < nd_; ++o) d.shapes(o, q) = shape[o] + 0.03 * big * nd(rng);
  }
  return d;
}

// The files a user would hand to `mozzi-cli gap` or the Model vs Test view:
// the swing arm as mozzi-model/1 JSON and its accelerances (200 lines, 1%
// noise, seed 7) with a hidden 0.6 kg mass at the axle, 3+X (20% of the node's
// 3 kg), as UFF 58. Empty string on success, else what failed.
inline std::string writeSwingArmWithHiddenMass(const std::string& modelPath, const std::string& frfPath) {
  const auto s = swingArm();
  auto text = core::gap::structural::writeModelJson(s.model);
  if (!text.ok()) return text.error().describe();
  std::ofstream(modelPath) << *text;
  Truth truth(s.model.dofCount());
  truth.dm(4, 4) = 0.6;  // 3+X
  Measurement m;
  m.responses = s.model.labels;
  m.references = s.references;
  m.lowHz = s.bandLowHz;
  m.highHz = s.bandHighHz;
  m.lines = 200;
  m.relativeNoise = 0.01;
  std::mt19937_64 rng(7);
  auto records = core::io::uff::fromFrfMatrix(measure(s.model, truth, m, rng));
  if (!records.ok()) return records.error().describe();
  core::io::uff::UffFile file;
  for (auto& r : *records) file.datasets.push_back(core::io::uff::makeDataset(std::move(r)));
  if (auto w = core::io::uff::writeFile(frfPath, file); !w.ok()) return w.error().describe();
  return {};
}

}  // namespace mozzi::gap_bench
