#include "core/gap/structural/structural_problem.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/common/text.h"
#include "core/gap/structural/frf_noise.h"
#include "core/modal/sdof.h"
#include "core/modal/shape_tools.h"
#include "core/signal/frf_estimator.h"

namespace mozzi::core::gap::structural {
namespace {

// Coordinates up to which non-proportional damping is solved directly per line.
constexpr Eigen::Index kDirectSolveLimit = 24;

// a b without std::complex's recovery of NaN products (Annex G): the same
// value for finite operands, without its test and branch on every product.
inline Complex times(Complex a, Complex b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

enum class Effect { MassLoading, Boundary, Element, ResidualMode, Hysteretic, Window, Misalignment };

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

struct CandidateDef {
  Effect effect = Effect::MassLoading;
  int dof = -1;     // mass / residual-mode DOF, misaligned channel DOF
  int other = -1;   // DOF the misaligned channel leans towards
  int spring = -1;  // boundary / element spring
  Vector shape;     // residual-mode shape over all DOFs (max |.| = 1)
  double wTop = 1;  // residual mode: top of the band [rad/s] (curvature term reference)
  Candidate candidate;
};

// A measured DOF as seen by the model: index and the sign between the two
// (a channel "21-Z" against a model DOF "21+Z" reads -x).
struct ChannelMap {
  int dof = -1;
  double sign = 1.0;
};

Result<ChannelMap> mapDof(const StructuralModel& model, const Dof& dof, const std::string& what) {
  for (int i = 0; i < model.dofCount(); ++i) {
    const Dof& d = model.dofs[static_cast<std::size_t>(i)];
    if (d.node == dof.node && d.direction == dof.direction)
      return ChannelMap{i, d.negative == dof.negative ? 1.0 : -1.0};
  }
  return makeError(ErrorCode::NotFound, what + " DOF " + formatDof(dof) + " is not a DOF of the model", formatDof(dof));
}

// The augmented model at (theta, candidate, phi), in undamped modal form.
struct ModalSystem {
  Vector w2;     // omega_r^2, ascending
  Matrix a;      // ndof x nq: T Phi, mass-normalised shapes at the physical DOFs
  Vector cdiag;  // modal viscous damping 2 zeta_r omega_r (diagonal part)
  Matrix cfull;  // Phi^T C Phi when not diagonal, else empty
  // Non-proportional damping: first-order (state-space) modes of
  // [0 I; -Omega^2 (1 + i eta), -Phi^T C Phi], so that
  // H(s) = sum_j left_j right_j / (s - pole_j) (Ewins ch. 2.7); empty when the
  // eigenvectors are too ill-conditioned (then a solve per line).
  ComplexVector ssPoles;
  ComplexMatrix ssLeft;   // ndof x 2nq
  ComplexMatrix ssRight;  // 2nq x ndof
  double eta = 0.0;       // hysteretic loss factor
  double decay = 0.0;     // exponential-window decay a [1/s]
  struct ResidualTerm {
    const CandidateDef* def = nullptr;
    double upper = 0.0, curvature = 0.0, lower = 0.0;
  };
  struct Tilt {
    int candidate = -1;  // index into the defs (locates the row of the DOF it leans to)
    const CandidateDef* def = nullptr;
    double angle = 0.0;  // rad
  };
  std::vector<ResidualTerm> residualTerms;  // residual-mode effects applied
  std::vector<Tilt> tilts;                  // misaligned channels
};

// The model, its element matrices and the candidate list: the part shared by
// the FRF and mode problems.
class StructuralCore {
 public:
  StructuralModel model;
  std::vector<Parameter> calibration;
  std::vector<CandidateDef> defs;
  std::vector<Matrix> springK;  // nq x nq per spring at scale 1
  std::vector<Matrix> massM;    // nq x nq per mass at scale 1

  explicit StructuralCore(const StructuralModel& m) : model(m) {
    for (const auto& s : model.springs) springK.push_back(springMatrix(s.a, s.b, s.stiffness));
    for (const auto& ms : model.masses) {
      const Vector t = model.t.row(ms.dof).transpose();
      massM.push_back(ms.mass * t * t.transpose());
    }
    for (const auto& p : model.parameters) {
      calibration.push_back(Parameter{p.name, "", p.nominal, p.lower, p.upper, p.priorSigma});
    }
  }

  Matrix springMatrix(int a, int b, double k) const {
    Vector g = model.t.row(a).transpose();
    if (b >= 0) g -= model.t.row(b).transpose();
    return k * g * g.transpose();
  }

  // Effective mass at a DOF: 1 / (t_d M_q^-1 t_d^T), the mass of a rigid
  // attachment that would move with that DOF alone (M_dd for a diagonal
  // spatial mass matrix).
  double effectiveMass(int d) const {
    const Vector t = model.t.row(d).transpose();
    const double flex = t.dot(model.m.ldlt().solve(t));
    return flex > 0 ? 1.0 / flex : 0.0;
  }

  // Candidates at the measured DOFs (`measured`: model DOF indices of all
  // channels, responses first; `responses`: the response channels).
  void buildCandidates(const std::vector<int>& measured, const std::vector<int>& responses,
                       const std::vector<int>& references, bool frfData, double bandHighHz, const Vector& nominalW2) {
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

  std::string label(int d) const { return model.labels[static_cast<std::size_t>(d)]; }

  static double firstElastic(const Vector& w2) {
    const double tol = 1e-8 * std::max(w2.maxCoeff(), 1e-300);
    for (Eigen::Index r = 0; r < w2.size(); ++r)
      if (w2[r] > tol) return w2[r];
    return w2.maxCoeff();
  }

  // Static flexibility of the elastic modes, sum_r a_r a_r^T / omega_r^2 (rigid
  // modes left out so free structures have one too).
  Matrix pseudoFlexibility(const Vector& w2) const {
    ModalSystem sys;
    std::vector<double> none(model.parameters.size());
    for (std::size_t p = 0; p < none.size(); ++p) none[p] = model.parameters[p].nominal;
    if (!solve(none.data(), -1, nullptr, sys)) return Matrix::Zero(model.dofCount(), model.dofCount());
    (void)w2;
    const double tol = 1e-8 * std::max(sys.w2.maxCoeff(), 1e-300);
    Matrix g = Matrix::Zero(model.dofCount(), model.dofCount());
    for (Eigen::Index r = 0; r < sys.w2.size(); ++r) {
      if (sys.w2[r] > tol) g += sys.a.col(r) * sys.a.col(r).transpose() / sys.w2[r];
    }
    return g;
  }

  // Parameter count of a set of candidates (their phi concatenated).
  int phiCount(const std::vector<int>& combo) const {
    int q = 0;
    for (int c : combo) q += static_cast<int>(defs[static_cast<std::size_t>(c)].candidate.parameters.size());
    return q;
  }

  bool solve(const double* theta, int candidate, const double* phi, ModalSystem& sys) const {
    static const std::vector<int> none;
    return candidate < 0 ? solve(theta, none, phi, sys) : solve(theta, std::vector<int>{candidate}, phi, sys);
  }

  // Builds and solves the augmented model with the candidates in `combo` all
  // applied (phi concatenated in that order). False when it cannot be
  // evaluated (mass matrix no longer positive definite, non-finite values).
  bool solve(const double* theta, const std::vector<int>& combo, const double* phi, ModalSystem& sys) const {
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

  static ComplexMatrix dynamicStiffness(const ModalSystem& sys, Complex s) {
    ComplexMatrix z = s * sys.cfull.cast<Complex>();
    for (Eigen::Index r = 0; r < sys.w2.size(); ++r) z(r, r) += sys.w2[r] * Complex(1.0, sys.eta) + s * s;
    return z;
  }

  // The state-space expansion, kept only when it reproduces a direct solve at
  // the geometric mean of the natural frequencies to 1e-9 (repeated poles give
  // a defective eigenvector matrix; the per-line solve is then used).
  static void stateSpaceModes(ModalSystem& sys) {
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

  // Receptance between model DOFs `resp` (rows) and `refs` (columns) in
  // pole-residue form H(s) = P diag(g(s)) Q, set up once per evaluation:
  // g_j = 1 / (s - pole_j) for the state-space modes, or
  // g_r = 1 / (omega_r^2 (1 + i eta) + s c_r + s^2) for diagonal modal
  // damping; a solve per line when the state-space modes were refused.
  class Receptance {
   public:
    Receptance(const ModalSystem& sys, const std::vector<int>& resp, const std::vector<int>& refs)
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

    // H at s into h (rows x refs), before type conversion.
    void at(Complex s, ComplexMatrix& h) {
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

   private:
    const ModalSystem& sys_;
    const std::vector<int>& resp_;
    const std::vector<int>& refs_;
    bool direct_ = false;
    bool modal_ = false;
    ComplexMatrix p_, q_;
    ComplexVector g_, w_;
    std::vector<double> coef_, gRe_, gIm_;  // modal_: R_oir (i, o, r order) and g_r
  };
};

// z of a chi-square sum of n whitened residuals against its expectation n.
double chiSquareZ(double chi2, double n) {
  return n > 0 ? (chi2 - n) / std::sqrt(2.0 * n) : 0.0;
}

std::string hzLabel(double lo, double hi) {
  return formatNumber(lo, 4) + "-" + formatNumber(hi, 4) + " Hz";
}

std::vector<std::pair<double, double>> octaveBands(double lo, double hi) {
  std::vector<std::pair<double, double>> bands;
  if (!(hi > lo)) return bands;
  double start = std::max(lo, 1e-3);
  // Octaves anchored at 1 kHz / 2^n (nominal octave edges times sqrt 2).
  double edge = 1000.0 / std::sqrt(2.0);
  while (edge > start) edge /= 2;
  while (edge * 2 <= start) edge *= 2;
  while (edge < hi) {
    bands.emplace_back(std::max(edge, lo), std::min(edge * 2, hi));
    edge *= 2;
  }
  return bands;
}

// ---------------------------------------------------------------------------
// FRF problem

using NoiseSource = StructuralOptions::NoiseSource;

// Estimate the noise from the residual against the nominal model rather than
// from the FRF itself: the difference kernel then sees the (small) curvature
// of the model error instead of the FRF's own, which lowers its bias where the
// line spacing is coarse against the peaks (docs/gap.md, "Noise from the data").
constexpr bool kNoiseFromNominalResidual = true;
// Relative sigma assumed for an FRF whose own lines cannot give one (fewer than
// 16 usable lines, or all exactly zero): the floor stated in the report.
constexpr double kFallbackRelative = 0.01;
// With coherence, the H1 random error never below 0.1% per component (a
// coherence of exactly 1, e.g. simulated data, would give an infinite weight).
constexpr double kCoherenceFloor = 0.001;

const char* frfUnit(FrfType type) {
  return type == FrfType::Receptance ? "m/N" : type == FrfType::Mobility ? "m/s/N" : "m/s^2/N";
}

// The noise behind the whitening of an FRF problem: absolute sigma per line and
// component, and how it was obtained.
struct FrfNoise {
  NoiseSource source = NoiseSource::Stated;
  std::vector<Matrix> sigma;  // per reference: nf x no, per real/imaginary component
  Matrix logVariance;         // ni x no: variance of log sigma^2 of each FRF (0 unless estimated)
  NoiseModel report;
  // Estimated noise: the fit per FRF (reference-major) and the curve its
  // differences were taken of (the nominal model's FRFs), kept so that a
  // simulated data set refits the level only (frf_noise.h, rescaleFrfNoise).
  std::vector<FrfNoiseFit> fits;
  std::shared_ptr<const std::vector<ComplexMatrix>> reference;
  std::string referenceName = "the nominal model";  // what `reference` is, for the report
  // Coherence: the relative H1 error per line (per reference, nf x no); the
  // sigma follows from it and the FRF read, on simulated data too.
  std::vector<Matrix> coherenceRelative;
};

// Sigma from the coherence's relative errors r (Bendat & Piersol eq. 9.65).
// The error is relative to the true |H|, which the reading overstates on
// average by 1 + 2 r^2 (its own noise) and, where the noise dominates (r > 1),
// scatters down to zero: |H|^2 is taken as the larger of the line's own and
// the median over five lines, so a reading that happens to fall near zero
// does not get a near-zero sigma.
std::vector<Matrix> coherenceSigma(const FrfMatrix& data, const std::vector<Matrix>& rel, double tiny) {
  const Eigen::Index nf = data.lineCount(), no = data.responseCount();
  std::vector<Matrix> out;
  for (std::size_t i = 0; i < data.h.size(); ++i) {
    Matrix s(nf, no);
    for (Eigen::Index o = 0; o < no; ++o) {
      const ComplexVector h = data.h[i].col(o);
      for (Eigen::Index k = 0; k < nf; ++k) {
        std::array<double, 5> near{};
        int count = 0;
        for (Eigen::Index j = std::max<Eigen::Index>(0, k - 2); j <= std::min(nf - 1, k + 2); ++j)
          near[static_cast<std::size_t>(count++)] = std::norm(h[j]);
        std::nth_element(near.begin(), near.begin() + count / 2, near.begin() + count);
        const double mag2 = std::max(std::norm(h[k]), near[static_cast<std::size_t>(count / 2)]);
        const double r = rel[i](k, o);
        s(k, o) = std::max(r * std::sqrt(mag2 / (1.0 + 2.0 * r * r)), tiny);
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

class FrfProblem final : public GapProblem {
 public:
  FrfProblem(std::shared_ptr<const StructuralCore> core, FrfMatrix measured, std::vector<ChannelMap> resp,
             std::vector<ChannelMap> refs, FrfNoise noise, StructuralOptions options)
      : core_(std::move(core)),
        data_(std::move(measured)),
        resp_(std::move(resp)),
        refs_(std::move(refs)),
        noise_(std::move(noise)),
        options_(std::move(options)) {
    for (const auto& c : resp_) respDofs_.push_back(c.dof);
    for (const auto& c : refs_) refDofs_.push_back(c.dof);
    // Rows to evaluate: responses, then the DOFs misaligned channels lean to.
    evalDofs_ = respDofs_;
    misRow_.assign(core_->defs.size(), -1);
    for (std::size_t c = 0; c < core_->defs.size(); ++c) {
      if (core_->defs[c].effect != Effect::Misalignment) continue;
      misRow_[c] = static_cast<Eigen::Index>(evalDofs_.size());
      evalDofs_.push_back(core_->defs[c].other);
    }
    if (noise_.sigma.empty()) {
      if (noise_.source == NoiseSource::Coherence) {
        noise_.sigma = coherenceSigma(data_, noise_.coherenceRelative, tinySigma());
      } else {
        estimateNoise();
      }
    }
  }

  std::string dataKind() const override { return "frf"; }
  std::vector<Parameter> calibrationParameters() const override { return core_->calibration; }
  std::vector<Candidate> candidates() const override {
    std::vector<Candidate> out;
    for (const auto& d : core_->defs) out.push_back(d.candidate);
    return out;
  }
  int residualCount() const override {
    return static_cast<int>(2 * data_.lineCount() * data_.responseCount() * data_.referenceCount());
  }
  NoiseModel noiseModel() const override { return noise_.report; }

  bool residuals(const double* theta, int candidate, const double* phi, double* r) const override {
    return residualsFor(theta, comboOf(candidate), phi, r);
  }

  bool combinable(const std::vector<int>& combo) const override {
    for (std::size_t a = 0; a < combo.size(); ++a) {
      if (combo[a] < 0 || combo[a] >= static_cast<int>(core_->defs.size())) return false;
      const CandidateDef& da = core_->defs[static_cast<std::size_t>(combo[a])];
      for (std::size_t b = a + 1; b < combo.size(); ++b) {
        if (combo[a] == combo[b]) return false;
        const CandidateDef& db = core_->defs[static_cast<std::size_t>(combo[b])];
        // One loss factor, one window, one tilt per channel: the same global
        // effect twice is one effect.
        if (da.effect == db.effect && (da.effect == Effect::Hysteretic || da.effect == Effect::Window)) return false;
        if (da.effect == Effect::Misalignment && db.effect == Effect::Misalignment && da.dof == db.dof) return false;
      }
    }
    return true;
  }
  bool combinedResiduals(const double* theta, const std::vector<int>& combo, const double* phi,
                         double* r) const override {
    return residualsFor(theta, combo, phi, r);
  }
  GapMetrics combinedMetrics(const double* theta, const std::vector<int>& combo, const double* phi) const override {
    return metricsFor(theta, combo, phi);
  }
  std::vector<OverlayCurve> combinedOverlay(const double* theta, const std::vector<int>& combo,
                                            const double* phi) const override {
    return overlayFor(theta, combo, phi);
  }

  std::vector<int> folds() const override {
    std::vector<int> f;
    const Eigen::Index nf = data_.lineCount();
    const int nfold = std::max(1, options_.folds);
    f.reserve(static_cast<std::size_t>(residualCount()));
    for (Eigen::Index i = 0; i < data_.referenceCount(); ++i)
      for (Eigen::Index o = 0; o < data_.responseCount(); ++o)
        for (Eigen::Index k = 0; k < nf; ++k) {
          const int fold = static_cast<int>((k * nfold) / std::max<Eigen::Index>(nf, 1));
          f.push_back(fold);
          f.push_back(fold);
        }
    return f;
  }

  // Prediction plus noise drawn with the whitening sigma of this problem. A
  // noise model estimated from the data is estimated again from the simulated
  // data, one from the coherence re-derived from the simulated reading (the
  // bootstrap then carries their own error); a replicate or stated one is kept.
  std::unique_ptr<GapProblem> simulated(const double* theta, int candidate, const double* phi,
                                        std::mt19937_64& rng) const override {
    std::vector<ComplexMatrix> h;
    FrfMatrix sim = data_;
    if (!predict(theta, comboOf(candidate), phi, h)) h = data_.h;
    std::normal_distribution<double> nd(0.0, 1.0);
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount();
    const double tiny = tinySigma();
    for (std::size_t i = 0; i < h.size(); ++i)
      for (Eigen::Index o = 0; o < no; ++o)
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double s = simulationSigma(i, k, o, std::norm(h[i](k, o)), tiny);
          const double re = nd(rng), im = nd(rng);
          sim.h[i](k, o) = h[i](k, o) + Complex(s * re, s * im);
        }
    FrfNoise noise = noise_;
    // Estimated: its level refitted from the simulated lines, against the
    // simulated truth (the best reference there is, as for the measurement
    // after withNoiseReference); coherence: the sigma re-derived from the
    // simulated reading (the same relative errors).
    if (noise.source == NoiseSource::Estimated) {
      noise.reference = std::make_shared<const std::vector<ComplexMatrix>>(h);
    }
    if (noise.source == NoiseSource::Estimated || noise.source == NoiseSource::Coherence) noise.sigma.clear();
    return std::make_unique<FrfProblem>(core_, std::move(sim), resp_, refs_, std::move(noise), options_);
  }

  // Sigma of the noise drawn around a simulated truth of magnitude^2 `mag2`:
  // the part of the noise model that is relative follows the simulated FRF,
  // not the measured one, exactly as the simulated problem whitens it. (With
  // the measured |H| a peak the effect moved would put large noise where the
  // baseline has none and whiten it with a small sigma: a null chi-square
  // many times its degrees of freedom, and no residual read as beyond noise.)
  double simulationSigma(std::size_t i, Eigen::Index k, Eigen::Index o, double mag2, double tiny) const {
    const auto ii = static_cast<Eigen::Index>(i);
    if (noise_.source == NoiseSource::Estimated && !noise_.fits.empty()) {
      const FrfNoiseFit& fit = noise_.fits[static_cast<std::size_t>(ii * data_.responseCount() + o)];
      return std::max(fit.ok ? fit.sigma(k, mag2) : kFallbackRelative * std::sqrt(mag2), tiny);
    }
    if (noise_.source == NoiseSource::Coherence && i < noise_.coherenceRelative.size()) {
      return std::max(noise_.coherenceRelative[i](k, o) * std::sqrt(mag2), tiny);
    }
    return noise_.sigma[i](k, o);
  }

  std::unique_ptr<GapProblem> withNoiseReference(const double* theta, const std::vector<int>& combo,
                                                 const double* phi) const override {
    if (noise_.source != NoiseSource::Estimated) return nullptr;
    auto ref = std::make_shared<std::vector<ComplexMatrix>>();
    if (!predict(theta, combo, phi, *ref)) return nullptr;
    FrfNoise noise;
    noise.source = NoiseSource::Estimated;
    noise.reference = std::move(ref);
    noise.referenceName = "the calibrated model with";
    const auto all = candidates();
    for (std::size_t c = 0; c < combo.size(); ++c)
      noise.referenceName += (c ? " and " : " ") + label(all[static_cast<std::size_t>(combo[c])]);
    return std::make_unique<FrfProblem>(core_, data_, resp_, refs_, std::move(noise), options_);
  }

  GapMetrics metrics(const double* theta, int candidate, const double* phi) const override {
    return metricsFor(theta, comboOf(candidate), phi);
  }
  std::vector<OverlayCurve> overlay(const double* theta, int candidate, const double* phi) const override {
    return overlayFor(theta, comboOf(candidate), phi);
  }

  // Predicted FRFs in the measured layout and type: h[i] is nf x no.
  bool predict(const double* theta, const std::vector<int>& combo, const double* phi,
               std::vector<ComplexMatrix>& h) const {
    ModalSystem sys;
    if (!core_->solve(theta, combo, phi, sys)) return false;
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
    h.resize(static_cast<std::size_t>(ni));
    for (auto& m : h)
      if (m.rows() != nf || m.cols() != no) m.resize(nf, no);
    const int order = frfTypeOrder(data_.type);
    const std::vector<int>& rows = sys.tilts.empty() ? respDofs_ : evalDofs_;
    StructuralCore::Receptance receptance(sys, rows, refDofs_);
    ComplexMatrix x(static_cast<Eigen::Index>(rows.size()), ni);
    for (Eigen::Index k = 0; k < nf; ++k) {
      const Complex s(sys.decay, 2 * M_PI * data_.frequencyHz[k]);
      receptance.at(s, x);
      Complex factor(1.0, 0.0);
      for (int n = 0; n < order; ++n) factor = times(factor, s);
      for (Eigen::Index i = 0; i < ni; ++i) {
        for (Eigen::Index o = 0; o < no; ++o) {
          Complex v = x(o, i);
          for (const auto& tilt : sys.tilts) {
            if (respDofs_[static_cast<std::size_t>(o)] != tilt.def->dof) continue;
            v = std::cos(tilt.angle) * x(o, i) +
                std::sin(tilt.angle) * x(misRow_[static_cast<std::size_t>(tilt.candidate)], i);
          }
          h[static_cast<std::size_t>(i)](k, o) =
              times(factor, v) * (resp_[static_cast<std::size_t>(o)].sign * refs_[static_cast<std::size_t>(i)].sign);
        }
      }
    }
    for (const auto& m : h)
      if (!m.allFinite()) return false;
    return true;
  }

 private:
  static std::vector<int> comboOf(int candidate) {
    return candidate < 0 ? std::vector<int>{} : std::vector<int>{candidate};
  }

  bool residualsFor(const double* theta, const std::vector<int>& combo, const double* phi, double* r) const {
    thread_local std::vector<ComplexMatrix> h;  // reused: one allocation per thread, not per evaluation
    if (!predict(theta, combo, phi, h)) return false;
    std::size_t j = 0;
    const Eigen::Index nf = data_.lineCount();
    for (std::size_t i = 0; i < h.size(); ++i) {
      for (Eigen::Index o = 0; o < data_.responseCount(); ++o) {
        for (Eigen::Index k = 0; k < nf; ++k) {
          const Complex d = h[i](k, o) - data_.h[i](k, o);
          const double s = noise_.sigma[i](k, o);
          r[j++] = d.real() / s;
          r[j++] = d.imag() / s;
        }
      }
    }
    // (Vectorised, without an early exit: a non-finite entry is the rare case.)
    return Eigen::Map<const Eigen::VectorXd>(r, static_cast<Eigen::Index>(j)).allFinite();
  }

  GapMetrics metricsFor(const double* theta, const std::vector<int>& combo, const double* phi) const;
  std::vector<OverlayCurve> overlayFor(const double* theta, const std::vector<int>& combo, const double* phi) const;

  // The smallest sigma of any line: 1e-12 of the largest |H| of the whole set,
  // so a line (or a whole uncoupled FRF) that reads exactly zero never gets an
  // infinite weight (a weakly coupled cross FRF at low frequency can lie 1e-7
  // below its peak, well above this).
  double tinySigma() const {
    double peak = 0.0;
    for (const auto& m : data_.h) peak = std::max(peak, m.cwiseAbs().maxCoeff());
    return 1e-12 * peak + 1e-300;
  }

  std::string frfLabel(Eigen::Index i, Eigen::Index o) const {
    return core_->label(respDofs_[static_cast<std::size_t>(o)]) + " / " +
           core_->label(refDofs_[static_cast<std::size_t>(i)]);
  }

  // Noise per FRF (and band) from the data's own lines (frf_noise.h). With
  // fits from an earlier estimate (a simulated data set), only their level is
  // refitted.
  void estimateNoise() {
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
    const bool rescale = noise_.fits.size() == static_cast<std::size_t>(ni * no);
    if (!rescale && !noise_.reference && kNoiseFromNominalResidual) {
      std::vector<double> nominal;
      for (const auto& p : core_->model.parameters) nominal.push_back(p.nominal);
      auto ref = std::make_shared<std::vector<ComplexMatrix>>();
      if (predict(nominal.data(), {}, nullptr, *ref)) noise_.reference = std::move(ref);
    }
    const int nfold = std::max(1, options_.folds);
    std::vector<Eigen::Index> edges;
    for (int b = 0; b <= nfold; ++b) edges.push_back(static_cast<Eigen::Index>((nf * b) / nfold));
    const double tiny = tinySigma();
    noise_.source = NoiseSource::Estimated;
    noise_.sigma.assign(static_cast<std::size_t>(ni), Matrix(nf, no));
    noise_.logVariance = Matrix::Zero(ni, no);
    noise_.report = NoiseModel{};
    noise_.report.source = "estimated";
    noise_.report.estimated = true;
    std::vector<FrfNoiseFit> fits;
    int fallbacks = 0;
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o) {
        const ComplexVector h = data_.h[static_cast<std::size_t>(i)].col(o);
        const Vector mag2 = h.cwiseAbs2();
        const ComplexVector y =
            noise_.reference ? ComplexVector(h - (*noise_.reference)[static_cast<std::size_t>(i)].col(o)) : h;
        const FrfNoiseFit fit = rescale
                                    ? rescaleFrfNoise(noise_.fits[static_cast<std::size_t>(i * no + o)], y, mag2, edges)
                                    : estimateFrfNoise(y, mag2, edges);
        fits.push_back(fit);
        NoiseEntry entry;
        entry.label = frfLabel(i, o);
        entry.unit = frfUnit(data_.type);
        if (fit.ok) {
          entry.relative = fit.relative;
          entry.floor = fit.floor;
          entry.lines = fit.lines;
          noise_.logVariance(i, o) = fit.logVariance;
        } else {
          ++fallbacks;
          entry.relative = kFallbackRelative;
          entry.floor = 0.0;
        }
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double s = fit.ok ? fit.sigma(k, mag2[k]) : kFallbackRelative * std::sqrt(mag2[k]);
          noise_.sigma[static_cast<std::size_t>(i)](k, o) = std::max(s, tiny);
        }
        noise_.report.entries.push_back(entry);
        for (const auto& b : fit.bands) {
          if (b.scale == 1.0 || b.last <= b.first) continue;
          NoiseEntry e = entry;
          e.band = hzLabel(data_.frequencyHz[b.first], data_.frequencyHz[b.last - 1]);
          e.relative *= std::sqrt(b.scale);
          e.floor *= std::sqrt(b.scale);
          e.lines = b.lines;
          noise_.report.entries.push_back(e);
        }
      }
    noise_.fits = std::move(fits);
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o)
        noise_.report.chiSquareVariance += 4.0 * static_cast<double>(nf * nf) * noise_.logVariance(i, o);
    std::ostringstream d;
    d << "Estimated from the data (no coherence given): per FRF a relative part and an additive floor, fitted "
         "robustly to the scatter of third differences of neighbouring lines"
      << (noise_.reference ? " of the residual against " + noise_.referenceName : std::string())
      << ", with a level of its own for a band where the data show one; its level is refitted on every simulated "
         "data set of the bootstrap.";
    if (fallbacks > 0) {
      d << " " << fallbacks
        << " FRF(s) had too few usable lines (or read exactly zero): " << formatNumber(100 * kFallbackRelative, 2)
        << "% relative assumed there.";
    }
    noise_.report.description = d.str();
  }

  std::shared_ptr<const StructuralCore> core_;
  FrfMatrix data_;
  std::vector<ChannelMap> resp_, refs_;
  std::vector<int> respDofs_, refDofs_, evalDofs_;
  std::vector<Eigen::Index> misRow_;  // per candidate: row of the DOF a misaligned channel leans to, -1 otherwise
  FrfNoise noise_;
  StructuralOptions options_;
};

GapMetrics FrfProblem::metricsFor(const double* theta, const std::vector<int>& combo, const double* phi) const {
  GapMetrics out;
  out.residualName = "frf_residual";
  std::vector<ComplexMatrix> h;
  if (!predict(theta, combo, phi, h)) {
    out.overall = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
  // Per (line, response) sums over references: squared relative error, the
  // same expected from noise alone (lines with a nonzero reading), chi2.
  Matrix rel2 = Matrix::Zero(nf, no), chi2 = Matrix::Zero(nf, no), noise2 = Matrix::Zero(nf, no),
         cells = Matrix::Zero(nf, no);
  for (Eigen::Index i = 0; i < ni; ++i)
    for (Eigen::Index o = 0; o < no; ++o)
      for (Eigen::Index k = 0; k < nf; ++k) {
        const Complex meas = data_.h[static_cast<std::size_t>(i)](k, o);
        const Complex d = h[static_cast<std::size_t>(i)](k, o) - meas;
        const double s = noise_.sigma[static_cast<std::size_t>(i)](k, o);
        chi2(k, o) += std::norm(d) / (s * s);
        if (std::norm(meas) > 0) {
          rel2(k, o) += std::norm(d) / std::norm(meas);
          noise2(k, o) += 2 * s * s / std::norm(meas);  // expected |dH / H|^2 from noise alone (two components)
          cells(k, o) += 1;
        }
      }
  auto row = [&](const std::string& kind, const std::string& label, Eigen::Index k0, Eigen::Index k1, Eigen::Index o0,
                 Eigen::Index o1) {
    GapEntry e;
    e.kind = kind;
    e.label = label;
    e.oneSided = true;
    const double count = cells.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double r2 = rel2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double c2 = chi2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double n2 = noise2.block(k0, o0, k1 - k0, o1 - o0).sum();
    // The gap is the relative FRF residual in excess of the noise:
    // sqrt(max(0, mean |dH/H|^2 - mean 2 sigma^2 / |H|^2)); 0 for a model that
    // fits within noise, so the shrink measures what an effect explains.
    e.value = count > 0 ? std::sqrt(std::max(0.0, r2 - n2) / count) : 0.0;
    // z of the chi-square sum against its expectation n: variance 2 n, plus,
    // for a noise level estimated from the data, (n_f)^2 var(log sigma_f^2)
    // per FRF f (the whole row scales with the estimate).
    const double n = static_cast<double>(2 * (k1 - k0) * (o1 - o0) * ni);
    double var = 2 * n;
    const double perFrf = static_cast<double>(2 * (k1 - k0));
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = o0; o < o1; ++o) var += perFrf * perFrf * noise_.logVariance(i, o);
    e.z = n > 0 ? (c2 - n) / std::sqrt(var) : 0.0;
    e.details = {{"raw_residual", count > 0 ? std::sqrt(r2 / count) : 0.0},
                 {"noise_floor", count > 0 ? std::sqrt(n2 / count) : 0.0},
                 {"chi2_per_residual", n > 0 ? c2 / n : 0.0},
                 {"lines", static_cast<double>(k1 - k0)}};
    return e;
  };
  out.overall = row("overall", "all", 0, nf, 0, no).value;
  const double flo = data_.frequencyHz[0], fhi = data_.frequencyHz[nf - 1];
  auto bands = options_.reportBands.empty() ? octaveBands(flo, fhi) : options_.reportBands;
  for (const auto& b : bands) {
    Eigen::Index k0 = 0, k1 = nf;
    while (k0 < nf && data_.frequencyHz[k0] < b.first) ++k0;
    k1 = k0;
    while (k1 < nf && data_.frequencyHz[k1] <= b.second) ++k1;
    if (k1 <= k0) continue;
    out.entries.push_back(row("band", hzLabel(b.first, b.second), k0, k1, 0, no));
  }
  for (Eigen::Index o = 0; o < no; ++o) {
    out.entries.push_back(row("dof", core_->label(respDofs_[static_cast<std::size_t>(o)]), 0, nf, o, o + 1));
  }
  // Per model mode in the band: the residual over its half-power neighbourhood
  // (at least +/- 2 lines), and the measured mode from a circle fit between
  // the neighbouring predicted modes (frequency and damping errors, MAC).
  ModalSystem sys;
  if (core_->solve(theta, combo, phi, sys)) {
    const Eigen::Index nq = sys.w2.size();
    std::vector<double> fr(static_cast<std::size_t>(nq)), zr(static_cast<std::size_t>(nq));
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double w = std::sqrt(sys.w2[r]);
      double zeta = w > 0 ? sys.cdiag[r] / (2 * w) + sys.eta / 2 : 0.0;
      Complex lambda = modal::poleFromFrequencyDamping(w / (2 * M_PI), std::min(zeta, 0.99)) - sys.decay;
      fr[static_cast<std::size_t>(r)] = modal::poleFrequencyHz(lambda);
      zr[static_cast<std::size_t>(r)] = modal::poleZeta(lambda);
    }
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double f = fr[static_cast<std::size_t>(r)], z = zr[static_cast<std::size_t>(r)];
      if (f < flo || f > fhi) continue;
      const double half = std::max(z * f, 1e-9);
      Eigen::Index k0 = 0;
      while (k0 < nf && data_.frequencyHz[k0] < f - half) ++k0;
      Eigen::Index k1 = k0;
      while (k1 < nf && data_.frequencyHz[k1] <= f + half) ++k1;
      k0 = std::max<Eigen::Index>(0, std::min(k0, k1) - 2);
      k1 = std::min(nf, k1 + 2);
      GapEntry e = row("mode", "mode " + std::to_string(r + 1) + " (" + formatNumber(f, 4) + " Hz)", k0, k1, 0, no);
      e.details.push_back({"predicted_hz", f});
      e.details.push_back({"predicted_zeta", z});
      const double lo = r > 0 ? std::sqrt(f * fr[static_cast<std::size_t>(r - 1)]) : flo;
      const double hi = r + 1 < nq ? std::sqrt(f * fr[static_cast<std::size_t>(r + 1)]) : fhi;
      auto fit = modal::circleFit(data_, 0, std::max(lo, flo), std::min(hi, fhi));
      if (fit && fit->frequencyHz > 0) {
        e.details.push_back({"measured_hz", fit->frequencyHz});
        e.details.push_back({"measured_zeta", fit->zeta});
        e.details.push_back({"frequency_error_pct", 100 * (f - fit->frequencyHz) / fit->frequencyHz});
        if (fit->zeta > 0) e.details.push_back({"zeta_error_pct", 100 * (z - fit->zeta) / fit->zeta});
        ComplexVector model(no);
        for (Eigen::Index o = 0; o < no; ++o)
          model[o] = sys.a(respDofs_[static_cast<std::size_t>(o)], r) * resp_[static_cast<std::size_t>(o)].sign;
        if (fit->residue.size() == no) e.details.push_back({"mac", modal::mac(model, fit->residue)});
      }
      out.entries.push_back(e);
    }
  }
  return out;
}

std::vector<OverlayCurve> FrfProblem::overlayFor(const double* theta, const std::vector<int>& combo,
                                                 const double* phi) const {
  std::vector<OverlayCurve> curves;
  std::vector<ComplexMatrix> h;
  if (!predict(theta, combo, phi, h)) return curves;
  for (Eigen::Index i = 0; i < data_.referenceCount(); ++i)
    for (Eigen::Index o = 0; o < data_.responseCount(); ++o) {
      OverlayCurve c;
      c.label = frfLabel(i, o);
      c.xLabel = "Frequency [Hz]";
      c.yLabel = std::string("|H| [") + frfUnit(data_.type) + "]";
      c.logY = true;
      for (Eigen::Index k = 0; k < data_.lineCount(); ++k) {
        c.x.push_back(data_.frequencyHz[k]);
        c.measured.push_back(std::abs(data_.h[static_cast<std::size_t>(i)](k, o)));
        c.predicted.push_back(std::abs(h[static_cast<std::size_t>(i)](k, o)));
      }
      curves.push_back(std::move(c));
    }
  return curves;
}

// ---------------------------------------------------------------------------
// Mode problem

struct ModeData {
  Vector f, zeta;
  Matrix shapes;  // measured DOFs x modes, real
};

class ModesProblem final : public GapProblem {
 public:
  ModesProblem(std::shared_ptr<const StructuralCore> core, ModeData data, std::vector<ChannelMap> channels,
               std::vector<int> pairs, StructuralOptions options)
      : core_(std::move(core)),
        data_(std::move(data)),
        ch_(std::move(channels)),
        pairs_(std::move(pairs)),
        options_(std::move(options)) {
    for (const auto& c : ch_) dofs_.push_back(c.dof);
    for (std::size_t r = 0; r < pairs_.size(); ++r)
      if (pairs_[r] >= 0) paired_.push_back(static_cast<int>(r));
  }

  std::string dataKind() const override { return "modes"; }
  NoiseModel noiseModel() const override {
    NoiseModel n;
    n.source = "floors";
    n.description = "Sigma floors of GAP.md step 0: frequency " + formatNumber(100 * options_.frequencySigmaFloor, 3) +
                    "%, damping " + formatNumber(100 * options_.dampingSigmaFloor, 3) +
                    "% of the measured ratio (at least 1e-4), shape components " +
                    formatNumber(100 * options_.shapeSigma, 3) + "% of each mode's largest component.";
    n.entries.push_back({"frequency", "", options_.frequencySigmaFloor, 0.0, "Hz", 0});
    n.entries.push_back({"damping ratio", "", options_.dampingSigmaFloor, 1e-4, "", 0});
    n.entries.push_back({"shape", "", options_.shapeSigma, 0.0, "", 0});
    return n;
  }
  std::vector<Parameter> calibrationParameters() const override { return core_->calibration; }
  std::vector<Candidate> candidates() const override {
    std::vector<Candidate> out;
    for (const auto& d : core_->defs) out.push_back(d.candidate);
    return out;
  }
  int residualCount() const override { return static_cast<int>(paired_.size() * (2 + ch_.size())); }

  struct Predicted {
    std::vector<double> f, zeta;
    Matrix shapes;  // channels x model modes
  };

  bool predict(const double* theta, int candidate, const double* phi, Predicted& p) const {
    ModalSystem sys;
    if (!core_->solve(theta, candidate, phi, sys)) return false;
    const Eigen::Index nq = sys.w2.size();
    p.f.resize(static_cast<std::size_t>(nq));
    p.zeta.resize(static_cast<std::size_t>(nq));
    p.shapes.resize(static_cast<Eigen::Index>(ch_.size()), nq);
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double w = std::sqrt(sys.w2[r]);
      // Modal damping from the diagonal of Phi^T C Phi (the coupling terms of
      // a non-proportional C change zeta only to second order) plus eta / 2.
      const double zeta = w > 0 ? sys.cdiag[r] / (2 * w) + sys.eta / 2 : 0.0;
      if (!(zeta < 1)) return false;
      const Complex lambda = modal::poleFromFrequencyDamping(w / (2 * M_PI), zeta) - sys.decay;
      p.f[static_cast<std::size_t>(r)] = modal::poleFrequencyHz(lambda);
      p.zeta[static_cast<std::size_t>(r)] = modal::poleZeta(lambda);
      for (std::size_t c = 0; c < ch_.size(); ++c) {
        double v = sys.a(ch_[c].dof, r);
        for (const auto& tilt : sys.tilts)
          if (ch_[c].dof == tilt.def->dof)
            v = std::cos(tilt.angle) * sys.a(ch_[c].dof, r) + std::sin(tilt.angle) * sys.a(tilt.def->other, r);
        p.shapes(static_cast<Eigen::Index>(c), r) = v * ch_[c].sign;
      }
    }
    return p.shapes.allFinite();
  }

  double sigmaF(int j) const { return options_.frequencySigmaFloor * data_.f[j]; }
  // 15% of the measured ratio, and never below 1e-4 absolute (an identified
  // zeta of exactly 0 must not get an infinite weight).
  double sigmaZ(int j) const { return std::max(options_.dampingSigmaFloor * data_.zeta[j], 1e-4); }
  double sigmaPhi(int j) const { return options_.shapeSigma * data_.shapes.col(j).cwiseAbs().maxCoeff(); }

  // Model shape scaled onto the measured one (least squares).
  static Vector scaled(const Vector& model, const Vector& meas) {
    const double mm = model.squaredNorm();
    return mm > 0 ? Vector(model * (model.dot(meas) / mm)) : model;
  }

  bool residuals(const double* theta, int candidate, const double* phi, double* r) const override {
    Predicted p;
    if (!predict(theta, candidate, phi, p)) return false;
    std::size_t k = 0;
    for (int m : paired_) {
      const int j = pairs_[static_cast<std::size_t>(m)];
      r[k++] = (p.f[static_cast<std::size_t>(m)] - data_.f[j]) / sigmaF(j);
      r[k++] = (p.zeta[static_cast<std::size_t>(m)] - data_.zeta[j]) / sigmaZ(j);
      const Vector s = scaled(p.shapes.col(m), data_.shapes.col(j));
      const double sp = sigmaPhi(j);
      for (Eigen::Index c = 0; c < s.size(); ++c) r[k++] = (s[c] - data_.shapes(c, j)) / sp;
    }
    for (std::size_t q = 0; q < k; ++q)
      if (!std::isfinite(r[q])) return false;
    return true;
  }

  std::vector<int> folds() const override {
    std::vector<int> f;
    const int nfold = std::max(1, options_.folds);
    const int np = static_cast<int>(paired_.size());
    for (int q = 0; q < np; ++q) {
      const int fold = np > 0 ? (q * nfold) / np : 0;
      for (std::size_t c = 0; c < 2 + ch_.size(); ++c) f.push_back(fold);
    }
    return f;
  }

  std::unique_ptr<GapProblem> simulated(const double* theta, int candidate, const double* phi,
                                        std::mt19937_64& rng) const override {
    Predicted p;
    ModeData sim = data_;
    std::normal_distribution<double> nd(0.0, 1.0);
    if (predict(theta, candidate, phi, p)) {
      for (int m : paired_) {
        const int j = pairs_[static_cast<std::size_t>(m)];
        sim.f[j] = p.f[static_cast<std::size_t>(m)] + sigmaF(j) * nd(rng);
        sim.zeta[j] = std::max(0.0, p.zeta[static_cast<std::size_t>(m)] + sigmaZ(j) * nd(rng));
        const Vector s = scaled(p.shapes.col(m), data_.shapes.col(j));
        const double sp = sigmaPhi(j);
        for (Eigen::Index c = 0; c < s.size(); ++c) sim.shapes(c, j) = s[c] + sp * nd(rng);
      }
    }
    return std::make_unique<ModesProblem>(core_, std::move(sim), ch_, pairs_, options_);
  }

  GapMetrics metrics(const double* theta, int candidate, const double* phi) const override {
    GapMetrics out;
    out.residualName = "mode_residual";
    Predicted p;
    if (!predict(theta, candidate, phi, p)) {
      out.overall = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
    std::vector<double> r(static_cast<std::size_t>(residualCount()));
    if (!residuals(theta, candidate, phi, r.data())) {
      out.overall = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
    double chi2 = 0;
    for (double x : r) chi2 += x * x;
    // The overall gap of mode data: RMS of the whitened residuals (frequency,
    // damping and shape misfits in units of their sigma; about 1 at a fit
    // within noise).
    out.overall = r.empty() ? 0.0 : std::sqrt(chi2 / static_cast<double>(r.size()));

    for (int m : paired_) {
      const int j = pairs_[static_cast<std::size_t>(m)];
      const double fp = p.f[static_cast<std::size_t>(m)], zp = p.zeta[static_cast<std::size_t>(m)];
      const double fz = (fp - data_.f[j]) / sigmaF(j), zz = (zp - data_.zeta[j]) / sigmaZ(j);
      const double macValue = modal::mac(p.shapes.col(m).cast<Complex>(), data_.shapes.col(j).cast<Complex>());
      GapEntry e;
      e.kind = "mode";
      e.label = "mode " + std::to_string(j + 1) + " (" + formatNumber(data_.f[j], 4) + " Hz)";
      e.value = 100 * (fp - data_.f[j]) / data_.f[j];
      // The mode's z: the largest of its frequency and damping z (two-sided,
      // as a magnitude) so a damping-only gap is flagged too.
      e.z = std::max(std::abs(fz), std::abs(zz));
      e.details = {{"measured_hz", data_.f[j]},
                   {"predicted_hz", fp},
                   {"frequency_error_pct", e.value},
                   {"frequency_z", fz},
                   {"measured_zeta", data_.zeta[j]},
                   {"predicted_zeta", zp},
                   {"zeta_error_pct", data_.zeta[j] > 0 ? 100 * (zp - data_.zeta[j]) / data_.zeta[j] : 0.0},
                   {"zeta_z", zz},
                   {"mac", macValue},
                   {"model_mode", static_cast<double>(m + 1)}};
      out.entries.push_back(e);
    }
    for (Eigen::Index j = 0; j < data_.f.size(); ++j) {
      if (std::find(pairs_.begin(), pairs_.end(), static_cast<int>(j)) != pairs_.end()) continue;
      GapEntry e;
      e.kind = "mode";
      e.label = "mode " + std::to_string(j + 1) + " (" + formatNumber(data_.f[j], 4) + " Hz) unpaired";
      e.flagged = true;
      e.details = {{"measured_hz", data_.f[j]}};
      out.entries.push_back(e);
    }
    for (std::size_t c = 0; c < ch_.size(); ++c) {
      double c2 = 0, rel2 = 0;
      for (int m : paired_) {
        const int j = pairs_[static_cast<std::size_t>(m)];
        const Vector s = scaled(p.shapes.col(m), data_.shapes.col(j));
        const double d = s[static_cast<Eigen::Index>(c)] - data_.shapes(static_cast<Eigen::Index>(c), j);
        c2 += std::pow(d / sigmaPhi(j), 2);
        rel2 += std::pow(d / data_.shapes.col(j).cwiseAbs().maxCoeff(), 2);
      }
      const double n = static_cast<double>(paired_.size());
      GapEntry e;
      e.kind = "dof";
      e.label = core_->label(ch_[c].dof);
      e.value = n > 0 ? std::sqrt(rel2 / n) : 0.0;  // shape misfit relative to each mode's largest component
      e.z = chiSquareZ(c2, n);
      e.oneSided = true;
      out.entries.push_back(e);
    }
    return out;
  }

 private:
  std::shared_ptr<const StructuralCore> core_;
  ModeData data_;
  std::vector<ChannelMap> ch_;
  std::vector<int> dofs_;
  std::vector<int> pairs_;   // per model mode: measured mode or -1
  std::vector<int> paired_;  // model modes that have a partner
  StructuralOptions options_;
};

std::vector<double> nominalTheta(const StructuralModel& model) {
  std::vector<double> t;
  for (const auto& p : model.parameters) t.push_back(p.nominal);
  return t;
}

}  // namespace

const std::vector<std::string>& structuralEffectNames() {
  static const std::vector<std::string> names = {"mass_loading",       "boundary_stiffness", "element_stiffness",
                                                 "residual_mode",      "hysteretic_damping", "exponential_window",
                                                 "sensor_misalignment"};
  return names;
}

std::vector<int> hungarianAssignment(const Matrix& cost) {
  // Kuhn-Munkres with potentials (O(n^2 m)), rows <= columns after padding.
  const int n0 = static_cast<int>(cost.rows()), m0 = static_cast<int>(cost.cols());
  const int n = std::max(n0, m0);
  const double big = cost.size() ? cost.cwiseAbs().maxCoeff() * 10 + 1 : 1;
  Matrix a = Matrix::Constant(n, n, big);
  a.topLeftCorner(n0, m0) = cost;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(static_cast<std::size_t>(n + 1)), v(static_cast<std::size_t>(n + 1));
  std::vector<int> p(static_cast<std::size_t>(n + 1)), way(static_cast<std::size_t>(n + 1));
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::vector<double> minv(static_cast<std::size_t>(n + 1), inf);
    std::vector<char> used(static_cast<std::size_t>(n + 1), 0);
    do {
      used[static_cast<std::size_t>(j0)] = 1;
      const int i0 = p[static_cast<std::size_t>(j0)];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const double cur = a(i0 - 1, j - 1) - u[static_cast<std::size_t>(i0)] - v[static_cast<std::size_t>(j)];
        if (cur < minv[static_cast<std::size_t>(j)]) {
          minv[static_cast<std::size_t>(j)] = cur;
          way[static_cast<std::size_t>(j)] = j0;
        }
        if (minv[static_cast<std::size_t>(j)] < delta) {
          delta = minv[static_cast<std::size_t>(j)];
          j1 = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (used[static_cast<std::size_t>(j)]) {
          u[static_cast<std::size_t>(p[static_cast<std::size_t>(j)])] += delta;
          v[static_cast<std::size_t>(j)] -= delta;
        } else {
          minv[static_cast<std::size_t>(j)] -= delta;
        }
      }
      j0 = j1;
    } while (p[static_cast<std::size_t>(j0)] != 0);
    do {
      const int j1 = way[static_cast<std::size_t>(j0)];
      p[static_cast<std::size_t>(j0)] = p[static_cast<std::size_t>(j1)];
      j0 = j1;
    } while (j0);
  }
  std::vector<int> result(static_cast<std::size_t>(n0), -1);
  for (int j = 1; j <= n; ++j) {
    const int i = p[static_cast<std::size_t>(j)];
    if (i >= 1 && i <= n0 && j <= m0) result[static_cast<std::size_t>(i - 1)] = j - 1;
  }
  return result;
}

std::vector<int> pairModesByMac(const ComplexMatrix& model, const ComplexMatrix& measured, double minMac,
                                const Vector& modelHz, const Vector& measuredHz) {
  const Matrix macs = modal::macMatrix(model, measured);
  Matrix cost = Matrix::Ones(macs.rows(), macs.cols()) - macs;
  if (modelHz.size() == macs.rows() && measuredHz.size() == macs.cols()) {
    for (Eigen::Index r = 0; r < cost.rows(); ++r)
      for (Eigen::Index j = 0; j < cost.cols(); ++j)
        if (modelHz[r] > 0 && measuredHz[j] > 0) cost(r, j) += 0.01 * std::abs(std::log(modelHz[r] / measuredHz[j]));
  }
  std::vector<int> pairs = hungarianAssignment(cost);
  for (std::size_t r = 0; r < pairs.size(); ++r)
    if (pairs[r] >= 0 && macs(static_cast<Eigen::Index>(r), pairs[r]) < minMac) pairs[r] = -1;
  return pairs;
}

Result<std::unique_ptr<GapProblem>> makeFrfProblem(const StructuralModel& model, const FrfMatrix& measured,
                                                   const StructuralOptions& options) {
  if (auto v = measured.validate(); !v) return v.error();
  if (measured.lineCount() == 0 || measured.responseCount() == 0 || measured.referenceCount() == 0) {
    return makeError(ErrorCode::InvalidArgument, "the measured FRF set is empty", "measured FRFs");
  }
  std::vector<ChannelMap> resp, refs;
  for (const auto& d : measured.responses) {
    auto c = mapDof(model, d, "response");
    if (!c) return c.error();
    resp.push_back(*c);
  }
  for (const auto& d : measured.references) {
    auto c = mapDof(model, d, "reference");
    if (!c) return c.error();
    refs.push_back(*c);
  }
  if (options.noise == NoiseSource::Stated && !(options.relativeFloor > 0) && !(options.additiveFloor > 0)) {
    return makeError(ErrorCode::InvalidArgument, "a stated noise needs a positive relative or additive sigma",
                     "noise floor");
  }
  if (!(options.relativeFloor >= 0) || !(options.additiveFloor >= 0) || !std::isfinite(options.relativeFloor) ||
      !std::isfinite(options.additiveFloor)) {
    return makeError(ErrorCode::InvalidArgument, "noise floors must be finite and not negative", "noise floor");
  }
  // The fitted band: lines inside [lo, hi] and above 0 Hz (the type
  // conversion and the lower residual divide by s).
  const double bandLow = std::max(options.bandLowHz, std::nextafter(0.0, 1.0));
  auto banded = signal::selectBand(measured, bandLow, options.bandHighHz);
  if (!banded.ok() || banded->lineCount() < 4) {
    return makeError(ErrorCode::InvalidArgument,
                     "fewer than 4 frequency lines in the band " + hzLabel(options.bandLowHz, options.bandHighHz),
                     "--band");
  }
  FrfMatrix data = std::move(banded).value();
  const Eigen::Index nf = data.lineCount();
  const Eigen::Index no = data.responseCount(), ni = data.referenceCount();
  NoiseSource source = options.noise;
  if (source == NoiseSource::Auto) {
    source = !data.coherence.empty()       ? NoiseSource::Coherence
             : !options.replicates.empty() ? NoiseSource::Replicates
                                           : NoiseSource::Estimated;
  }
  if (source == NoiseSource::Coherence && data.coherence.empty()) {
    return makeError(ErrorCode::InvalidArgument, "the noise model 'coherence' needs coherence in the test file",
                     "--noise");
  }
  if (source == NoiseSource::Replicates && options.replicates.size() < 2) {
    return makeError(ErrorCode::InvalidArgument, "the noise model 'replicates' needs at least two repeated FRF sets",
                     "--noise");
  }
  FrfNoise noise;
  noise.source = source;
  noise.logVariance = Matrix::Zero(ni, no);
  double peak = 0.0;
  for (const auto& m : data.h) peak = std::max(peak, m.cwiseAbs().maxCoeff());
  const double tiny = 1e-12 * peak + 1e-300;
  const char* unit = frfUnit(data.type);
  auto label = [&](Eigen::Index i, Eigen::Index o) {
    return model.labels[static_cast<std::size_t>(resp[static_cast<std::size_t>(o)].dof)] + " / " +
           model.labels[static_cast<std::size_t>(refs[static_cast<std::size_t>(i)].dof)];
  };
  if (source == NoiseSource::Stated) {
    noise.report.source = "stated";
    noise.report.description = "Stated by the user: sigma^2 = (" + formatNumber(options.relativeFloor, 3) +
                               " |H|)^2 + (" + formatNumber(options.additiveFloor, 3) + " " + unit +
                               ")^2 per real and imaginary component, on every line.";
    noise.report.entries.push_back({"all", "", options.relativeFloor, options.additiveFloor, unit, 0});
    for (Eigen::Index i = 0; i < ni; ++i) {
      Matrix s(nf, no);
      for (Eigen::Index o = 0; o < no; ++o)
        for (Eigen::Index k = 0; k < nf; ++k)
          s(k, o) = std::max(std::hypot(options.relativeFloor * std::abs(data.h[static_cast<std::size_t>(i)](k, o)),
                                        options.additiveFloor),
                             tiny);
      noise.sigma.push_back(s);
    }
  } else if (source == NoiseSource::Coherence) {
    // The normalised random error of an H1 estimate from n_avg averages with
    // coherence g: sqrt(1 - g^2) / (g sqrt(2 n_avg)) (Bendat & Piersol,
    // "Random data", eq. 9.65), per component, never below 0.1%.
    if (options.averages < 1) return makeError(ErrorCode::InvalidArgument, "averages must be at least 1", "--averages");
    noise.report.source = "coherence";
    noise.report.description = "From the coherence in the file (H1 random error, Bendat & Piersol eq. 9.65, " +
                               std::to_string(options.averages) + " averages), at least " +
                               formatNumber(100 * kCoherenceFloor, 2) + "% per component.";
    noise.report.estimated = true;  // read from the same data: its |H| is noisy too
    for (Eigen::Index i = 0; i < ni; ++i) {
      Matrix rel(nf, no);
      for (Eigen::Index o = 0; o < no; ++o) {
        double sum = 0;
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double g2 = std::clamp(data.coherence[static_cast<std::size_t>(i)](k, o), 1e-6, 1.0);
          rel(k, o) = std::max(kCoherenceFloor, std::sqrt((1 - g2) / (2.0 * options.averages * g2)));
          sum += rel(k, o);
        }
        noise.report.entries.push_back({label(i, o), "", sum / static_cast<double>(nf), 0.0, unit, 0});
      }
      noise.coherenceRelative.push_back(rel);
    }
    noise.sigma = coherenceSigma(data, noise.coherenceRelative, tiny);
  } else if (source == NoiseSource::Replicates) {
    noise.report.source = "replicates";
    noise.report.description = "From the scatter of " + std::to_string(options.replicates.size()) +
                               " repeated FRF sets (hits): the variance of their mean per line, smoothed by a "
                               "relative part and an additive floor per FRF.";
    std::vector<FrfMatrix> reps;
    for (std::size_t r = 0; r < options.replicates.size(); ++r) {
      auto b = signal::selectBand(options.replicates[r], bandLow, options.bandHighHz);
      if (!b.ok() || b->lineCount() != nf || b->responseCount() != no || b->referenceCount() != ni ||
          b->responses != data.responses || b->references != data.references) {
        return makeError(ErrorCode::InvalidArgument, "does not have the layout of the measured FRF set",
                         "repeated FRF set " + std::to_string(r + 1));
      }
      reps.push_back(std::move(b).value());
    }
    const int nfold = std::max(1, options.folds);
    std::vector<Eigen::Index> edges;
    for (int b = 0; b <= nfold; ++b) edges.push_back(static_cast<Eigen::Index>((nf * b) / nfold));
    for (Eigen::Index i = 0; i < ni; ++i) {
      Matrix s(nf, no);
      for (Eigen::Index o = 0; o < no; ++o) {
        std::vector<ComplexVector> hits;
        for (const auto& r : reps) hits.push_back(r.h[static_cast<std::size_t>(i)].col(o));
        const FrfNoiseFit fit = replicateFrfNoise(hits, edges);
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double m2 = std::norm(data.h[static_cast<std::size_t>(i)](k, o));
          s(k, o) = std::max(fit.ok ? fit.sigma(k, m2) : kFallbackRelative * std::sqrt(m2), tiny);
        }
        noise.report.entries.push_back(
            {label(i, o), "", fit.ok ? fit.relative : kFallbackRelative, fit.ok ? fit.floor : 0.0, unit, fit.lines});
      }
      noise.sigma.push_back(s);
    }
  }
  // Estimated: left empty here, the problem estimates it from its own lines.
  auto core = std::make_shared<StructuralCore>(model);
  std::vector<int> measuredDofs, responseDofs;
  for (const auto& c : resp) {
    measuredDofs.push_back(c.dof);
    responseDofs.push_back(c.dof);
  }
  for (const auto& c : refs) measuredDofs.push_back(c.dof);
  ModalSystem nominal;
  const auto theta = nominalTheta(model);
  if (!core->solve(theta.data(), -1, nullptr, nominal)) {
    return makeError(ErrorCode::NumericalFailure, "the model cannot be solved at its nominal parameters", model.name);
  }
  std::vector<int> referenceDofs;
  for (const auto& c : refs) referenceDofs.push_back(c.dof);
  core->buildCandidates(measuredDofs, responseDofs, referenceDofs, true, data.frequencyHz[nf - 1], nominal.w2);
  data.coherence.clear();  // used only for the noise model above
  return std::unique_ptr<GapProblem>(std::make_unique<FrfProblem>(std::move(core), std::move(data), std::move(resp),
                                                                  std::move(refs), std::move(noise), options));
}

Result<std::unique_ptr<GapProblem>> makeModesProblem(const StructuralModel& model, const io::uff::ModalData& measured,
                                                     const StructuralOptions& options) {
  const auto nm = measured.frequencyHz.size();
  if (nm == 0) return makeError(ErrorCode::InvalidArgument, "no measured modes", "measured modes");
  if (measured.shapes.rows() != static_cast<Eigen::Index>(measured.dofs.size()) || measured.shapes.cols() != nm ||
      measured.dampingRatio.size() != nm) {
    return makeError(ErrorCode::InvalidArgument, "mode shapes, frequencies and damping disagree in size",
                     "measured modes");
  }
  // Measured DOFs the model does not have (a 3-DOF-per-node file against a
  // planar model) are left out; at least one must remain.
  std::vector<ChannelMap> channels;
  std::vector<Eigen::Index> rows;
  for (std::size_t i = 0; i < measured.dofs.size(); ++i) {
    auto c = mapDof(model, measured.dofs[i], "measured");
    if (!c) continue;
    channels.push_back(*c);
    rows.push_back(static_cast<Eigen::Index>(i));
  }
  if (channels.empty()) {
    return makeError(ErrorCode::NotFound, "no measured DOF matches a DOF of the model", "measured modes");
  }
  std::vector<Eigen::Index> modes;
  for (Eigen::Index j = 0; j < nm; ++j) {
    const double f = measured.frequencyHz[j], z = measured.dampingRatio[j];
    if (!(std::isfinite(f) && f > 0 && std::isfinite(z) && z >= 0)) {
      return makeError(ErrorCode::InvalidArgument, "frequency or damping not valid",
                       "measured mode " + std::to_string(j + 1));
    }
    if (f >= options.bandLowHz && f <= options.bandHighHz) modes.push_back(j);
  }
  if (modes.empty()) return makeError(ErrorCode::InvalidArgument, "no measured mode in the band", "--band");
  ModeData data;
  const auto nd = static_cast<Eigen::Index>(channels.size()), nk = static_cast<Eigen::Index>(modes.size());
  data.f.resize(nk);
  data.zeta.resize(nk);
  data.shapes.resize(nd, nk);
  for (Eigen::Index q = 0; q < nk; ++q) {
    const Eigen::Index j = modes[static_cast<std::size_t>(q)];
    data.f[q] = measured.frequencyHz[j];
    data.zeta[q] = measured.dampingRatio[j];
    ComplexVector col(nd);
    for (Eigen::Index c = 0; c < nd; ++c) col[c] = measured.shapes(rows[static_cast<std::size_t>(c)], j);
    Eigen::Index big = 0;
    col.cwiseAbs().maxCoeff(&big);
    if (!col.allFinite() || std::abs(col[big]) == 0) {
      return makeError(ErrorCode::InvalidArgument, "mode shape is zero or not finite at the model's DOFs",
                       "measured mode " + std::to_string(j + 1));
    }
    // Rotate to the real line through the largest component (normal modes).
    data.shapes.col(q) = (col * (std::abs(col[big]) / col[big])).real();
  }
  auto core = std::make_shared<StructuralCore>(model);
  const auto theta = nominalTheta(model);
  ModalSystem nominal;
  if (!core->solve(theta.data(), -1, nullptr, nominal)) {
    return makeError(ErrorCode::NumericalFailure, "the model cannot be solved at its nominal parameters", model.name);
  }
  std::vector<int> dofs;
  for (const auto& c : channels) dofs.push_back(c.dof);
  core->buildCandidates(dofs, dofs, {}, false, options.bandHighHz, nominal.w2);
  ComplexMatrix modelShapes(nd, nominal.w2.size());
  for (Eigen::Index c = 0; c < nd; ++c)
    for (Eigen::Index r = 0; r < nominal.w2.size(); ++r)
      modelShapes(c, r) =
          nominal.a(channels[static_cast<std::size_t>(c)].dof, r) * channels[static_cast<std::size_t>(c)].sign;
  const Vector modelHz = nominal.w2.cwiseSqrt() / (2 * M_PI);
  const std::vector<int> pairs =
      pairModesByMac(modelShapes, data.shapes.cast<Complex>(), options.macPairing, modelHz, data.f);
  if (std::count_if(pairs.begin(), pairs.end(), [](int p) { return p >= 0; }) == 0) {
    return makeError(
        ErrorCode::NumericalFailure,
        "no measured mode pairs with a model mode (every MAC below " + formatNumber(options.macPairing) + ")",
        "measured modes");
  }
  return std::unique_ptr<GapProblem>(
      std::make_unique<ModesProblem>(std::move(core), std::move(data), std::move(channels), pairs, options));
}

}  // namespace mozzi::core::gap::structural
