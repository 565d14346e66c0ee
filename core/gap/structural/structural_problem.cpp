#include "core/gap/structural/structural_problem.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/text.h"
#include "core/modal/sdof.h"
#include "core/modal/shape_tools.h"
#include "core/signal/frf_estimator.h"

namespace mozzi::core::gap::structural {
namespace {

// Coordinates up to which non-proportional damping is solved directly per line.
constexpr Eigen::Index kDirectSolveLimit = 24;

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
  const CandidateDef* effect = nullptr;
  double upper = 0.0, curvature = 0.0, lower = 0.0;  // residual-mode terms
  double angle = 0.0;                                // misalignment
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
        // +/- 0.6 rad (34 deg): a sensor glued further off is a wiring error.
        def.candidate = {
            effectName(def.effect), {label(o), label(p)}, {Parameter{"angle", "rad", 0.0, -0.6, 0.6, 0.0}}};
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

  // Builds and solves the augmented model. False when it cannot be evaluated
  // (mass matrix no longer positive definite, non-finite values).
  bool solve(const double* theta, int candidate, const double* phi, ModalSystem& sys) const {
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
        for (std::size_t s = 0; s < model.springs.size(); ++s)
          if (model.springs[s].name == name) k += (scale - 1.0) * springK[s];
        for (std::size_t s = 0; s < model.masses.size(); ++s)
          if (model.masses[s].name == name) m += (scale - 1.0) * massM[s];
      }
    }
    sys = ModalSystem{};
    if (candidate >= 0) {
      const CandidateDef& def = defs[static_cast<std::size_t>(candidate)];
      sys.effect = &def;
      const double x = phi[0];
      if (!std::isfinite(x)) return false;
      switch (def.effect) {
        case Effect::MassLoading: {
          const Vector t = model.t.row(def.dof).transpose();
          m += x * t * t.transpose();
          break;
        }
        case Effect::Boundary:
        case Effect::Element: k += (x - 1.0) * springK[static_cast<std::size_t>(def.spring)]; break;
        case Effect::ResidualMode:
          sys.upper = x;
          sys.curvature = phi[1];
          sys.lower = phi[2];
          if (!std::isfinite(sys.lower) || !std::isfinite(sys.curvature)) return false;
          break;
        case Effect::Hysteretic: sys.eta = x; break;
        case Effect::Window: sys.decay = x; break;
        case Effect::Misalignment: sys.angle = x; break;
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
      p_.resize(no, terms);
      q_.resize(terms, ni);
      for (Eigen::Index o = 0; o < no; ++o)
        p_.row(o) = ss ? ComplexMatrix(sys.ssLeft.row(resp[static_cast<std::size_t>(o)]))
                       : ComplexMatrix(sys.a.row(resp[static_cast<std::size_t>(o)]).cast<Complex>());
      for (Eigen::Index i = 0; i < ni; ++i)
        q_.col(i) = ss ? ComplexMatrix(sys.ssRight.col(refs[static_cast<std::size_t>(i)]))
                       : ComplexMatrix(sys.a.row(refs[static_cast<std::size_t>(i)]).transpose().cast<Complex>());
      g_.resize(terms);
      w_.resize(terms);
    }

    // H at s into h (rows x refs), before type conversion.
    void at(Complex s, ComplexMatrix& h) {
      if (direct_) {
        h.noalias() = p_ * dynamicStiffness(sys_, s).partialPivLu().solve(q_);
      } else {
        if (sys_.ssPoles.size() > 0) {
          g_ = (s - sys_.ssPoles.array()).inverse().matrix();
        } else {
          const Complex stiff(1.0, sys_.eta);
          for (Eigen::Index r = 0; r < g_.size(); ++r) g_[r] = 1.0 / (sys_.w2[r] * stiff + s * sys_.cdiag[r] + s * s);
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
      if (sys_.effect && sys_.effect->effect == Effect::ResidualMode) {
        const Complex term =
            sys_.upper - sys_.curvature * s * s / (sys_.effect->wTop * sys_.effect->wTop) + sys_.lower / (s * s);
        for (std::size_t o = 0; o < resp_.size(); ++o)
          for (std::size_t i = 0; i < refs_.size(); ++i)
            h(static_cast<Eigen::Index>(o), static_cast<Eigen::Index>(i)) +=
                term * sys_.effect->shape[resp_[o]] * sys_.effect->shape[refs_[i]];
      }
    }

   private:
    const ModalSystem& sys_;
    const std::vector<int>& resp_;
    const std::vector<int>& refs_;
    bool direct_ = false;
    ComplexMatrix p_, q_;
    ComplexVector g_, w_;
  };
};

double normalUpperTail(double z) {
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

// Holm-Bonferroni over the rows of one kind at 5%: a row is flagged when its
// one-sided p-value (from z) survives the step-down sequence.
void holmFlags(std::vector<GapEntry>& rows, std::size_t first) {
  std::vector<std::size_t> idx;
  for (std::size_t i = first; i < rows.size(); ++i) idx.push_back(i);
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return rows[a].z > rows[b].z; });
  const double m = static_cast<double>(idx.size());
  for (std::size_t j = 0; j < idx.size(); ++j) {
    if (normalUpperTail(rows[idx[j]].z) > 0.05 / (m - static_cast<double>(j))) break;
    rows[idx[j]].flagged = true;
  }
}

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

class FrfProblem final : public GapProblem {
 public:
  FrfProblem(std::shared_ptr<const StructuralCore> core, FrfMatrix measured, std::vector<ChannelMap> resp,
             std::vector<ChannelMap> refs, std::vector<double> relSigma, StructuralOptions options)
      : core_(std::move(core)),
        data_(std::move(measured)),
        resp_(std::move(resp)),
        refs_(std::move(refs)),
        relSigma_(std::move(relSigma)),
        options_(std::move(options)) {
    for (const auto& c : resp_) respDofs_.push_back(c.dof);
    for (const auto& c : refs_) refDofs_.push_back(c.dof);
    // Rows to evaluate: responses, then the DOFs misaligned channels lean to.
    evalDofs_ = respDofs_;
    for (const auto& def : core_->defs)
      if (def.effect == Effect::Misalignment) evalDofs_.push_back(def.other);
    computeSigma();
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

  bool residuals(const double* theta, int candidate, const double* phi, double* r) const override {
    std::vector<ComplexMatrix> h;
    if (!predict(theta, candidate, phi, h)) return false;
    std::size_t j = 0;
    const Eigen::Index nf = data_.lineCount();
    for (std::size_t i = 0; i < h.size(); ++i) {
      for (Eigen::Index o = 0; o < data_.responseCount(); ++o) {
        for (Eigen::Index k = 0; k < nf; ++k) {
          const Complex d = h[i](k, o) - data_.h[i](k, o);
          const double s = sigma_[i](k, o);
          r[j++] = d.real() / s;
          r[j++] = d.imag() / s;
        }
      }
    }
    for (std::size_t q = 0; q < j; ++q)
      if (!std::isfinite(r[q])) return false;
    return true;
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

  std::unique_ptr<GapProblem> simulated(const double* theta, int candidate, const double* phi,
                                        std::mt19937_64& rng) const override {
    std::vector<ComplexMatrix> h;
    FrfMatrix sim = data_;
    if (!predict(theta, candidate, phi, h)) h = data_.h;
    std::normal_distribution<double> nd(0.0, 1.0);
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount();
    for (std::size_t i = 0; i < h.size(); ++i)
      for (Eigen::Index o = 0; o < no; ++o)
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double s = relSigma(i, o, k) * std::abs(h[i](k, o));
          const double re = nd(rng), im = nd(rng);
          sim.h[i](k, o) = h[i](k, o) + Complex(s * re, s * im);
        }
    return std::make_unique<FrfProblem>(core_, std::move(sim), resp_, refs_, relSigma_, options_);
  }

  GapMetrics metrics(const double* theta, int candidate, const double* phi) const override;
  std::vector<OverlayCurve> overlay(const double* theta, int candidate, const double* phi) const override;

  // Predicted FRFs in the measured layout and type: h[i] is nf x no.
  bool predict(const double* theta, int candidate, const double* phi, std::vector<ComplexMatrix>& h) const {
    ModalSystem sys;
    if (!core_->solve(theta, candidate, phi, sys)) return false;
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
    h.assign(static_cast<std::size_t>(ni), ComplexMatrix(nf, no));
    const int order = frfTypeOrder(data_.type);
    const CandidateDef* mis = sys.effect && sys.effect->effect == Effect::Misalignment ? sys.effect : nullptr;
    const double ca = std::cos(sys.angle), sa = std::sin(sys.angle);
    const std::vector<int>& rows = mis ? evalDofs_ : respDofs_;
    StructuralCore::Receptance receptance(sys, rows, refDofs_);
    ComplexMatrix x(static_cast<Eigen::Index>(rows.size()), ni);
    const long otherRow =
        mis ? std::find(evalDofs_.begin() + static_cast<long>(respDofs_.size()), evalDofs_.end(), mis->other) -
                  evalDofs_.begin()
            : 0;
    for (Eigen::Index k = 0; k < nf; ++k) {
      const Complex s(sys.decay, 2 * M_PI * data_.frequencyHz[k]);
      receptance.at(s, x);
      Complex factor(1.0, 0.0);
      for (int n = 0; n < order; ++n) factor *= s;
      for (Eigen::Index i = 0; i < ni; ++i) {
        for (Eigen::Index o = 0; o < no; ++o) {
          Complex v = x(o, i);
          if (mis && respDofs_[static_cast<std::size_t>(o)] == mis->dof) v = ca * v + sa * x(otherRow, i);
          h[static_cast<std::size_t>(i)](k, o) =
              factor * v * resp_[static_cast<std::size_t>(o)].sign * refs_[static_cast<std::size_t>(i)].sign;
        }
      }
    }
    for (const auto& m : h)
      if (!m.allFinite()) return false;
    return true;
  }

 private:
  // Relative sigma of (reference i, response o, line k).
  double relSigma(std::size_t i, Eigen::Index o, Eigen::Index k) const {
    const auto no = static_cast<std::size_t>(data_.responseCount()), nf = static_cast<std::size_t>(data_.lineCount());
    return relSigma_[(i * no + static_cast<std::size_t>(o)) * nf + static_cast<std::size_t>(k)];
  }

  void computeSigma() {
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount();
    sigma_.assign(data_.h.size(), Matrix(nf, no));
    for (std::size_t i = 0; i < data_.h.size(); ++i)
      for (Eigen::Index o = 0; o < no; ++o) {
        // An absolute floor of 1e-12 of the channel's largest |H| keeps a line
        // that reads exactly zero from getting an infinite weight (a weakly
        // coupled cross FRF at low frequency can lie 1e-7 below its peak).
        const double tiny = 1e-12 * data_.h[i].col(o).cwiseAbs().maxCoeff() + 1e-300;
        for (Eigen::Index k = 0; k < nf; ++k) {
          sigma_[i](k, o) = std::max(relSigma(i, o, k) * std::abs(data_.h[i](k, o)), tiny);
        }
      }
  }

  std::shared_ptr<const StructuralCore> core_;
  FrfMatrix data_;
  std::vector<ChannelMap> resp_, refs_;
  std::vector<int> respDofs_, refDofs_, evalDofs_;
  std::vector<double> relSigma_;  // per (reference, response, line)
  std::vector<Matrix> sigma_;     // absolute sigma per component, as h
  StructuralOptions options_;
};

GapMetrics FrfProblem::metrics(const double* theta, int candidate, const double* phi) const {
  GapMetrics out;
  out.residualName = "frf_residual";
  std::vector<ComplexMatrix> h;
  if (!predict(theta, candidate, phi, h)) {
    out.overall = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
  // Per (line, response) sums over references: squared relative error and chi2.
  Matrix rel2 = Matrix::Zero(nf, no), chi2 = Matrix::Zero(nf, no), noise2 = Matrix::Zero(nf, no);
  for (Eigen::Index i = 0; i < ni; ++i)
    for (Eigen::Index o = 0; o < no; ++o)
      for (Eigen::Index k = 0; k < nf; ++k) {
        const Complex meas = data_.h[static_cast<std::size_t>(i)](k, o);
        const Complex d = h[static_cast<std::size_t>(i)](k, o) - meas;
        const double s = sigma_[static_cast<std::size_t>(i)](k, o);
        rel2(k, o) += std::norm(d) / std::max(std::norm(meas), 1e-300);
        const double rel = relSigma(static_cast<std::size_t>(i), o, k);
        noise2(k, o) += 2 * rel * rel;  // expected |dH / H|^2 from noise alone (two components)
        chi2(k, o) += std::norm(d) / (s * s);
      }
  const double perCell = static_cast<double>(2 * ni);
  auto row = [&](const std::string& kind, const std::string& label, Eigen::Index k0, Eigen::Index k1, Eigen::Index o0,
                 Eigen::Index o1) {
    GapEntry e;
    e.kind = kind;
    e.label = label;
    const double cells = static_cast<double>((k1 - k0) * (o1 - o0));
    const double r2 = rel2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double c2 = chi2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double n2 = noise2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double count = cells * static_cast<double>(ni);
    // The gap is the relative FRF residual in excess of the noise:
    // sqrt(max(0, mean |dH/H|^2 - mean 2 sigma_rel^2)); 0 for a model that
    // fits within noise, so the shrink measures what an effect explains.
    e.value = cells > 0 ? std::sqrt(std::max(0.0, r2 - n2) / count) : 0.0;
    e.z = chiSquareZ(c2, cells * perCell);
    e.details = {{"raw_residual", cells > 0 ? std::sqrt(r2 / count) : 0.0},
                 {"noise_floor", cells > 0 ? std::sqrt(n2 / count) : 0.0},
                 {"chi2_per_residual", cells > 0 ? c2 / (cells * perCell) : 0.0},
                 {"lines", static_cast<double>(k1 - k0)}};
    return e;
  };
  out.overall = row("overall", "all", 0, nf, 0, no).value;
  const double flo = data_.frequencyHz[0], fhi = data_.frequencyHz[nf - 1];
  auto bands = options_.reportBands.empty() ? octaveBands(flo, fhi) : options_.reportBands;
  std::size_t first = out.entries.size();
  for (const auto& b : bands) {
    Eigen::Index k0 = 0, k1 = nf;
    while (k0 < nf && data_.frequencyHz[k0] < b.first) ++k0;
    k1 = k0;
    while (k1 < nf && data_.frequencyHz[k1] <= b.second) ++k1;
    if (k1 <= k0) continue;
    out.entries.push_back(row("band", hzLabel(b.first, b.second), k0, k1, 0, no));
  }
  holmFlags(out.entries, first);
  first = out.entries.size();
  for (Eigen::Index o = 0; o < no; ++o) {
    out.entries.push_back(row("dof", core_->label(respDofs_[static_cast<std::size_t>(o)]), 0, nf, o, o + 1));
  }
  holmFlags(out.entries, first);
  // Per model mode in the band: the residual over its half-power neighbourhood
  // (at least +/- 2 lines), and the measured mode from a circle fit between
  // the neighbouring predicted modes (frequency and damping errors, MAC).
  ModalSystem sys;
  first = out.entries.size();
  if (core_->solve(theta, candidate, phi, sys)) {
    const Eigen::Index nq = sys.w2.size();
    std::vector<double> fr(static_cast<std::size_t>(nq)), zr(static_cast<std::size_t>(nq));
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double w = std::sqrt(sys.w2[r]);
      double zeta = w > 0 ? sys.cdiag[r] / (2 * w) + sys.eta / 2 : 0.0;
      Complex lambda = modal::poleFromFrequencyDamping(w / (2 * M_PI), std::min(zeta, 0.99)) - sys.decay;
      fr[static_cast<std::size_t>(r)] = modal::poleFrequencyHz(lambda);
      zr[static_cast<std::size_t>(r)] = modal::poleZeta(lambda);
    }
    int modeNumber = 0;
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double f = fr[static_cast<std::size_t>(r)], z = zr[static_cast<std::size_t>(r)];
      if (f < flo || f > fhi) continue;
      ++modeNumber;
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
  holmFlags(out.entries, first);
  return out;
}

std::vector<OverlayCurve> FrfProblem::overlay(const double* theta, int candidate, const double* phi) const {
  std::vector<OverlayCurve> curves;
  std::vector<ComplexMatrix> h;
  if (!predict(theta, candidate, phi, h)) return curves;
  const char* unit = data_.type == FrfType::Receptance ? "m/N" : data_.type == FrfType::Mobility ? "m/s/N" : "m/s^2/N";
  for (Eigen::Index i = 0; i < data_.referenceCount(); ++i)
    for (Eigen::Index o = 0; o < data_.responseCount(); ++o) {
      OverlayCurve c;
      c.label = core_->label(respDofs_[static_cast<std::size_t>(o)]) + " / " +
                core_->label(refDofs_[static_cast<std::size_t>(i)]);
      c.xLabel = "Frequency [Hz]";
      c.yLabel = std::string("|H| [") + unit + "]";
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
    const CandidateDef* mis = sys.effect && sys.effect->effect == Effect::Misalignment ? sys.effect : nullptr;
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
        if (mis && ch_[c].dof == mis->dof) v = std::cos(sys.angle) * v + std::sin(sys.angle) * sys.a(mis->other, r);
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

    std::size_t first = out.entries.size();
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
    holmFlags(out.entries, first);
    for (Eigen::Index j = 0; j < data_.f.size(); ++j) {
      if (std::find(pairs_.begin(), pairs_.end(), static_cast<int>(j)) != pairs_.end()) continue;
      GapEntry e;
      e.kind = "mode";
      e.label = "mode " + std::to_string(j + 1) + " (" + formatNumber(data_.f[j], 4) + " Hz) unpaired";
      e.flagged = true;
      e.details = {{"measured_hz", data_.f[j]}};
      out.entries.push_back(e);
    }
    first = out.entries.size();
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
      out.entries.push_back(e);
    }
    holmFlags(out.entries, first);
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
  if (!(options.relativeFloor > 0)) {
    return makeError(ErrorCode::InvalidArgument, "the relative noise floor must be positive", "noise floor");
  }
  // The fitted band: lines inside [lo, hi] and above 0 Hz (the type
  // conversion and the lower residual divide by s).
  auto banded = signal::selectBand(measured, std::max(options.bandLowHz, std::nextafter(0.0, 1.0)), options.bandHighHz);
  if (!banded.ok() || banded->lineCount() < 4) {
    return makeError(ErrorCode::InvalidArgument,
                     "fewer than 4 frequency lines in the band " + hzLabel(options.bandLowHz, options.bandHighHz),
                     "--band");
  }
  FrfMatrix data = std::move(banded).value();
  const Eigen::Index nf = data.lineCount();
  const Eigen::Index no = data.responseCount();
  std::vector<double> rel;
  for (std::size_t i = 0; i < data.h.size(); ++i) {
    for (Eigen::Index o = 0; o < no; ++o)
      for (Eigen::Index k = 0; k < nf; ++k) {
        double r = options.relativeFloor;
        if (!data.coherence.empty() && options.averages > 0) {
          const double g2 = std::clamp(data.coherence[i](k, o), 1e-6, 1.0);
          r = std::max(r, std::sqrt((1 - g2) / (2.0 * options.averages * g2)));
        }
        rel.push_back(r);
      }
  }
  data.coherence.clear();  // used only for the noise model above
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
  return std::unique_ptr<GapProblem>(std::make_unique<FrfProblem>(std::move(core), std::move(data), std::move(resp),
                                                                  std::move(refs), std::move(rel), options));
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
