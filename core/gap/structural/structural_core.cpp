#include "core/gap/structural/structural_core.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/common/text.h"
#include "core/gap/structural/structural_problem.h"

namespace mozzi::core::gap::structural::detail {
namespace {

// Coordinates up to which non-proportional damping is solved directly per line.
constexpr Eigen::Index kDirectSolveLimit = 24;

const char* effectName(Effect e) {
  switch (e) {
    case Effect::MassLoading: return "mass_loading";
    case Effect::Boundary: return "boundary_stiffness";
    case Effect::Element: return "element_stiffness";
    case Effect::ResidualMode: return "residual_mode";
    case Effect::Hysteretic: return "hysteretic_damping";
    case Effect::Window: return "exponential_window";
    case Effect::Misalignment: return "sensor_misalignment";
  }
  return "";
}

}  // namespace

Result<ChannelMap> mapDof(const StructuralModel& model, const Dof& dof, const std::string& what) {
  for (int i = 0; i < model.dofCount(); ++i) {
    const Dof& d = model.dofs[static_cast<std::size_t>(i)];
    if (d.node == dof.node && d.direction == dof.direction)
      return ChannelMap{i, d.negative == dof.negative ? 1.0 : -1.0};
  }
  return makeError(ErrorCode::NotFound, what + " DOF " + formatDof(dof) + " is not a DOF of the model", formatDof(dof));
}

StructuralCore::StructuralCore(const StructuralModel& m) : model(m) {
  for (const auto& s : model.springs) springK.push_back(springMatrix(s.a, s.b, s.stiffness));
  for (const auto& ms : model.masses) {
    const Vector t = model.t.row(ms.dof).transpose();
    massM.push_back(ms.mass * t * t.transpose());
  }
  for (const auto& p : model.parameters) {
    calibration.push_back(Parameter{p.name, "", p.nominal, p.lower, p.upper, p.priorSigma});
  }
}

Matrix StructuralCore::springMatrix(int a, int b, double k) const {
  Vector g = model.t.row(a).transpose();
  if (b >= 0) g -= model.t.row(b).transpose();
  return k * g * g.transpose();
}

double StructuralCore::effectiveMass(int d) const {
  const Vector t = model.t.row(d).transpose();
  const double flex = t.dot(model.m.ldlt().solve(t));
  return flex > 0 ? 1.0 / flex : 0.0;
}

void StructuralCore::buildCandidates(const std::vector<int>& measured, const std::vector<int>& responses,
                                     const std::vector<int>& references, bool frfData, double bandHighHz,
                                     const Vector& nominalW2) {
  std::vector<int> unique;
  for (int d : measured)
    if (std::find(unique.begin(), unique.end(), d) == unique.end()) unique.push_back(d);
  double meanMass = 0;
  for (int d = 0; d < model.dofCount(); ++d) meanMass += effectiveMass(d) / model.dofCount();
  for (int d : unique) {
    const double md = effectiveMass(d);
    CandidateDef def;
    def.effect = Effect::MassLoading;
    def.dof = d;
    def.candidate = {effectName(def.effect),
                     {label(d)},
                     {Parameter{"added_mass", "kg", 0.0, -0.5 * md, std::max(3.0 * md, meanMass), 0.0}}};
    defs.push_back(def);
  }
  for (std::size_t s = 0; s < model.springs.size(); ++s) {
    const Spring& sp = model.springs[s];
    CandidateDef def;
    def.effect = sp.grounded() ? Effect::Boundary : Effect::Element;
    def.spring = static_cast<int>(s);
    std::vector<std::string> loc{label(sp.a)};
    if (!sp.grounded()) loc.push_back(label(sp.b));
    // Scale factors from 1/20 to 20: a clamp or joint off by more than that
    // is a different structure, not a calibration gap.
    def.candidate = {effectName(def.effect), loc, {Parameter{"scale_" + sp.name, "", 1.0, 0.05, 20.0, 0.0}}};
    defs.push_back(def);
  }
  if (frfData) {
    // An out-of-band mode enters FRF column i as the quasi-static deflection
    // under the load at reference i (upper residual, Ewins ch. 4), so the
    // residual-mode candidates sit at the reference DOFs.
    const Matrix g = pseudoFlexibility(nominalW2);
    std::vector<int> refs;
    for (int d : references)
      if (std::find(refs.begin(), refs.end(), d) == refs.end()) refs.push_back(d);
    for (int d : refs) {
      CandidateDef def;
      def.effect = Effect::ResidualMode;
      def.dof = d;
      const double peak = g.col(d).cwiseAbs().maxCoeff();
      if (!(peak > 0)) continue;
      def.shape = g.col(d) / g(d, d) * (g(d, d) < 0 ? -1.0 : 1.0);
      def.shape /= def.shape.cwiseAbs().maxCoeff();
      const double md = effectiveMass(d);
      // A mode above the band, A / (w_x^2 + s^2) = A / w_x^2 (1 - s^2 / w_x^2 + ...):
      // the upper residual and its curvature term (the omega^2 growth,
      // given as its value at the band's top); a lower residual L / s^2 for
      // modes below the band. Upper terms up to 5x the model's own static
      // compliance at d, lower up to 5x the inverse effective mass: beyond
      // that the "residual" would dominate the band.
      def.wTop = std::isfinite(bandHighHz) ? 2 * M_PI * bandHighHz : 1.0;
      def.candidate = {effectName(def.effect),
                       {label(d)},
                       {Parameter{"upper_residual", "m/N", 0.0, -5 * peak, 5 * peak, 0.0},
                        Parameter{"upper_curvature", "m/N", 0.0, -5 * peak, 5 * peak, 0.0},
                        Parameter{"lower_residual", "1/kg", 0.0, -5 / md, 5 / md, 0.0}}};
      defs.push_back(def);
    }
  }
  {
    CandidateDef def;
    def.effect = Effect::Hysteretic;
    def.candidate = {effectName(def.effect), {}, {Parameter{"eta", "", 0.0, 0.0, 0.5, 0.0}}};
    defs.push_back(def);
  }
  {
    // Decay up to 0.3 omega_1: a window adding 30% damping to the first mode
    // is a gross processing error; beyond it the fit would wander.
    const double w1 = std::sqrt(std::max(nominalW2.maxCoeff() * 1e-12, firstElastic(nominalW2)));
    double upper = 0.3 * w1;
    if (std::isfinite(bandHighHz)) upper = std::max(upper, 1e-3 * 2 * M_PI * bandHighHz);
    CandidateDef def;
    def.effect = Effect::Window;
    def.candidate = {effectName(def.effect), {}, {Parameter{"decay", "1/s", 0.0, 0.0, upper, 0.0}}};
    defs.push_back(def);
  }
  std::vector<int> seen;
  for (int o : responses) {
    if (std::find(seen.begin(), seen.end(), o) != seen.end()) continue;
    seen.push_back(o);
    const Dof& dof = model.dofs[static_cast<std::size_t>(o)];
    for (int p = 0; p < model.dofCount(); ++p) {
      const Dof& q = model.dofs[static_cast<std::size_t>(p)];
      if (p == o || q.node != dof.node || q.isRotation() != dof.isRotation()) continue;
      CandidateDef def;
      def.effect = Effect::Misalignment;
      def.dof = o;
      def.other = p;
      // A tilt in degrees towards p, +/- 34 deg (0.6 rad): a sensor glued
      // further off is a wiring error.
      def.candidate = {
          effectName(def.effect), {label(o), label(p)}, {Parameter{"angle", "deg", 0.0, -34.0, 34.0, 0.0}}};
      defs.push_back(def);
    }
  }
}

double StructuralCore::firstElastic(const Vector& w2) {
  const double tol = 1e-8 * std::max(w2.maxCoeff(), 1e-300);
  for (Eigen::Index r = 0; r < w2.size(); ++r)
    if (w2[r] > tol) return w2[r];
  return w2.maxCoeff();
}

Matrix StructuralCore::pseudoFlexibility(const Vector& w2) const {
  ModalSystem sys;
  std::vector<double> none(model.parameters.size());
  for (std::size_t p = 0; p < none.size(); ++p) none[p] = model.parameters[p].nominal;
  if (!solve({none.data(), -1, nullptr}, sys)) return Matrix::Zero(model.dofCount(), model.dofCount());
  (void)w2;
  const double tol = 1e-8 * std::max(sys.w2.maxCoeff(), 1e-300);
  Matrix g = Matrix::Zero(model.dofCount(), model.dofCount());
  for (Eigen::Index r = 0; r < sys.w2.size(); ++r) {
    if (sys.w2[r] > tol) g += sys.a.col(r) * sys.a.col(r).transpose() / sys.w2[r];
  }
  return g;
}

bool StructuralCore::solve(const double* theta, const std::vector<int>& combo, const double* phi,
                           ModalSystem& sys) const {
  Matrix m = model.m, k = model.k;
  double dampingScale = 1.0;
  for (std::size_t p = 0; p < model.parameters.size(); ++p) {
    const double scale = theta[p];
    if (!std::isfinite(scale)) return false;
    for (const auto& name : model.parameters[p].actsOn) {
      if (name == "damping") {
        dampingScale *= scale;
        continue;
      }
      if (name == "stiffness") {
        k += (scale - 1.0) * model.k;
        continue;
      }
      if (name == "mass") {
        m += (scale - 1.0) * model.m;
        continue;
      }
      for (std::size_t s = 0; s < model.springs.size(); ++s)
        if (model.springs[s].name == name) k += (scale - 1.0) * springK[s];
      for (std::size_t s = 0; s < model.masses.size(); ++s)
        if (model.masses[s].name == name) m += (scale - 1.0) * massM[s];
    }
  }
  sys = ModalSystem{};
  std::size_t offset = 0;
  for (int candidate : combo) {
    const CandidateDef& def = defs[static_cast<std::size_t>(candidate)];
    const double* x = phi + offset;
    offset += def.candidate.parameters.size();
    for (std::size_t j = 0; j < def.candidate.parameters.size(); ++j)
      if (!std::isfinite(x[j])) return false;
    switch (def.effect) {
      case Effect::MassLoading: {
        const Vector t = model.t.row(def.dof).transpose();
        m += x[0] * t * t.transpose();
        break;
      }
      case Effect::Boundary:
      case Effect::Element: k += (x[0] - 1.0) * springK[static_cast<std::size_t>(def.spring)]; break;
      case Effect::ResidualMode: sys.residualTerms.push_back({&def, x[0], x[1], x[2]}); break;
      case Effect::Hysteretic: sys.eta += x[0]; break;
      case Effect::Window: sys.decay += x[0]; break;
      case Effect::Misalignment: sys.tilts.push_back({candidate, &def, x[0] * M_PI / 180.0}); break;
    }
  }
  Eigen::LLT<Matrix> llt(m);
  if (llt.info() != Eigen::Success) return false;
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(k, m);
  if (eig.info() != Eigen::Success) return false;
  sys.w2 = eig.eigenvalues().cwiseMax(0.0);
  const Matrix& phiq = eig.eigenvectors();
  sys.a = model.t * phiq;
  const Vector w = sys.w2.cwiseSqrt();
  if (model.usesModalDamping()) {
    sys.cdiag = 2.0 * dampingScale * model.modalDamping.cwiseProduct(w);
  } else {
    const Matrix ct = dampingScale * (phiq.transpose() * model.c * phiq);
    sys.cdiag = ct.diagonal();
    const double diagMax = std::max(ct.diagonal().cwiseAbs().maxCoeff(), 1e-300);
    Matrix off = ct;
    off.diagonal().setZero();
    // Off-diagonal modal damping below 1e-9 of the diagonal is round-off of a
    // proportional C: take the cheap diagonal path.
    if (off.cwiseAbs().maxCoeff() > 1e-9 * diagMax) sys.cfull = ct;
  }
  if (!(sys.a.allFinite() && sys.w2.allFinite() && sys.cdiag.allFinite())) return false;
  // Non-proportional damping: a direct solve per line is exact and cheap for
  // lumped models; the state-space expansion (one eigenproblem, then sums)
  // pays off for larger ones but loses digits in weakly coupled FRFs lying
  // far below the peaks (its round-off scales with the largest terms).
  if (sys.cfull.size() > 0 && sys.w2.size() > kDirectSolveLimit) stateSpaceModes(sys);
  return true;
}

ComplexMatrix StructuralCore::dynamicStiffness(const ModalSystem& sys, Complex s) {
  ComplexMatrix z = s * sys.cfull.cast<Complex>();
  for (Eigen::Index r = 0; r < sys.w2.size(); ++r) z(r, r) += sys.w2[r] * Complex(1.0, sys.eta) + s * s;
  return z;
}

void StructuralCore::stateSpaceModes(ModalSystem& sys) {
  const Eigen::Index nq = sys.w2.size();
  ComplexVector poles;
  ComplexMatrix v;
  if (sys.eta == 0.0) {
    // Real state matrix: the real Hessenberg QR is several times cheaper.
    Matrix a = Matrix::Zero(2 * nq, 2 * nq);
    a.topRightCorner(nq, nq).setIdentity();
    a.bottomLeftCorner(nq, nq).diagonal() = -sys.w2;
    a.bottomRightCorner(nq, nq) = -sys.cfull;
    Eigen::EigenSolver<Matrix> eig(a);
    if (eig.info() != Eigen::Success) return;
    poles = eig.eigenvalues();
    v = eig.eigenvectors();
  } else {
    ComplexMatrix a = ComplexMatrix::Zero(2 * nq, 2 * nq);
    a.topRightCorner(nq, nq).setIdentity();
    for (Eigen::Index r = 0; r < nq; ++r) a(nq + r, r) = -sys.w2[r] * Complex(1.0, sys.eta);
    a.bottomRightCorner(nq, nq) = -sys.cfull.cast<Complex>();
    Eigen::ComplexEigenSolver<ComplexMatrix> eig(a);
    if (eig.info() != Eigen::Success) return;
    poles = eig.eigenvalues();
    v = eig.eigenvectors();
  }
  const ComplexMatrix vinv = v.partialPivLu().inverse();
  if (!vinv.allFinite()) return;
  const ComplexMatrix left = v.topRows(nq), right = vinv.rightCols(nq);
  double wmean = 0;
  int count = 0;
  for (Eigen::Index r = 0; r < nq; ++r)
    if (sys.w2[r] > 0) {
      wmean += 0.5 * std::log(sys.w2[r]);
      ++count;
    }
  const Complex s0(0.0, count ? std::exp(wmean / count) : 1.0);
  const ComplexMatrix direct = dynamicStiffness(sys, s0).partialPivLu().inverse();
  const ComplexVector g = (s0 - poles.array()).inverse().matrix();
  const ComplexMatrix expanded = left * g.asDiagonal() * right;
  if ((expanded - direct).norm() > 1e-9 * direct.norm()) return;
  sys.ssPoles = poles;
  sys.ssLeft = sys.a.cast<Complex>() * left;
  sys.ssRight = right * sys.a.transpose().cast<Complex>();
}

StructuralCore::Receptance::Receptance(const ModalSystem& sys, const std::vector<int>& resp,
                                       const std::vector<int>& refs)
    : sys_(sys), resp_(resp), refs_(refs) {
  const auto no = static_cast<Eigen::Index>(resp.size()), ni = static_cast<Eigen::Index>(refs.size());
  if (sys.cfull.size() > 0 && sys.ssPoles.size() == 0) {
    direct_ = true;
    p_.resize(no, sys.w2.size());
    q_.resize(sys.w2.size(), ni);
    for (Eigen::Index o = 0; o < no; ++o) p_.row(o) = sys.a.row(resp[static_cast<std::size_t>(o)]).cast<Complex>();
    for (Eigen::Index i = 0; i < ni; ++i)
      q_.col(i) = sys.a.row(refs[static_cast<std::size_t>(i)]).transpose().cast<Complex>();
    return;
  }
  const bool ss = sys.ssPoles.size() > 0;
  const Eigen::Index terms = ss ? sys.ssPoles.size() : sys.w2.size();
  if (!ss) {
    // Diagonal modal damping: real mode shapes, so H_oi = sum_r R_oir g_r
    // with real R_oir = a_or a_ir, kept contiguous per (o, i).
    modal_ = true;
    coef_.resize(static_cast<std::size_t>(no * ni * terms));
    std::size_t m = 0;
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o)
        for (Eigen::Index r = 0; r < terms; ++r)
          coef_[m++] = sys.a(resp[static_cast<std::size_t>(o)], r) * sys.a(refs[static_cast<std::size_t>(i)], r);
    gRe_.resize(static_cast<std::size_t>(terms));
    gIm_.resize(static_cast<std::size_t>(terms));
    return;
  }
  g_.resize(terms);
  w_.resize(terms);
  p_.resize(no, terms);
  q_.resize(terms, ni);
  for (Eigen::Index o = 0; o < no; ++o) p_.row(o) = sys.ssLeft.row(resp[static_cast<std::size_t>(o)]);
  for (Eigen::Index i = 0; i < ni; ++i) q_.col(i) = sys.ssRight.col(refs[static_cast<std::size_t>(i)]);
}

void StructuralCore::Receptance::at(Complex s, ComplexMatrix& h) {
  if (direct_) {
    h.noalias() = p_ * dynamicStiffness(sys_, s).partialPivLu().solve(q_);
  } else if (modal_) {
    // g_r = 1 / z_r, z_r = omega_r^2 (1 + i eta) + s c_r + s^2 with
    // s = a + i omega, in real arithmetic (std::complex products carry
    // NaN-recovery branches that cost as much as the sums here).
    const double a = s.real(), w = s.imag();
    const double s2Re = a * a - w * w, s2Im = 2.0 * a * w;
    const auto terms = static_cast<std::size_t>(sys_.w2.size());
    for (std::size_t r = 0; r < terms; ++r) {
      const double w2 = sys_.w2[static_cast<Eigen::Index>(r)], c = sys_.cdiag[static_cast<Eigen::Index>(r)];
      const double zRe = w2 + a * c + s2Re, zIm = w2 * sys_.eta + w * c + s2Im;
      const double inv = 1.0 / (zRe * zRe + zIm * zIm);
      gRe_[r] = zRe * inv;
      gIm_[r] = -zIm * inv;
    }
    const double* coef = coef_.data();
    for (Eigen::Index i = 0; i < h.cols(); ++i) {
      for (Eigen::Index o = 0; o < h.rows(); ++o) {
        double re = 0.0, im = 0.0;
        for (std::size_t r = 0; r < terms; ++r) {
          re += coef[r] * gRe_[r];
          im += coef[r] * gIm_[r];
        }
        coef += terms;
        h(o, i) = Complex(re, im);
      }
    }
  } else {
    // 1 / z as conj(z) / |z|^2: a real division instead of the library's
    // scaled complex one (__divdc3), which took a sixth of a diagnosis.
    for (Eigen::Index r = 0; r < g_.size(); ++r) {
      const Complex z = s - sys_.ssPoles[r];
      g_[r] = std::conj(z) / std::norm(z);
    }
    // Explicit sums: at these sizes (a few DOFs, tens of terms) a general
    // product expression costs more in dispatch than in arithmetic.
    const Eigen::Index terms = g_.size();
    for (Eigen::Index i = 0; i < h.cols(); ++i) {
      for (Eigen::Index j = 0; j < terms; ++j) w_[j] = g_[j] * q_(j, i);
      for (Eigen::Index o = 0; o < h.rows(); ++o) {
        Complex sum(0.0, 0.0);
        for (Eigen::Index j = 0; j < terms; ++j) sum += p_(o, j) * w_[j];
        h(o, i) = sum;
      }
    }
  }
  for (const auto& rt : sys_.residualTerms) {
    const Complex term = rt.upper - rt.curvature * s * s / (rt.def->wTop * rt.def->wTop) + rt.lower / (s * s);
    for (std::size_t o = 0; o < resp_.size(); ++o)
      for (std::size_t i = 0; i < refs_.size(); ++i)
        h(static_cast<Eigen::Index>(o), static_cast<Eigen::Index>(i)) +=
            term * rt.def->shape[resp_[o]] * rt.def->shape[refs_[i]];
  }
}

std::string hzLabel(double lo, double hi) {
  return formatNumber(lo, 4) + "-" + formatNumber(hi, 4) + " Hz";
}

std::vector<double> nominalTheta(const StructuralModel& model) {
  std::vector<double> t;
  for (const auto& p : model.parameters) t.push_back(p.nominal);
  return t;
}

}  // namespace mozzi::core::gap::structural::detail

namespace mozzi::core::gap::structural {

const std::vector<std::string>& structuralEffectNames() {
  static const std::vector<std::string> names = {"mass_loading",       "boundary_stiffness", "element_stiffness",
                                                 "residual_mode",      "hysteretic_damping", "exponential_window",
                                                 "sensor_misalignment"};
  return names;
}

}  // namespace mozzi::core::gap::structural
