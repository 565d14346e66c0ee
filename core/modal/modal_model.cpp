#include "core/modal/modal_model.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

namespace mozzi::core::modal {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;
const Complex kI(0.0, 1.0);

Complex iOmegaPower(double omega, int n) {
  Complex f(1.0, 0.0);
  for (int p = 0; p < n; ++p) f *= Complex(0.0, omega);
  return f;
}

Result<void> checkSquare(const MatrixRef& a, Eigen::Index n, const char* name) {
  if (a.rows() != n || a.cols() != n) {
    return makeError(ErrorCode::InvalidArgument,
                     std::string(name) + " is " + std::to_string(a.rows()) + "x" + std::to_string(a.cols()) +
                         ", expected " + std::to_string(n) + "x" + std::to_string(n),
                     "spatial model");
  }
  if (!a.allFinite())
    return makeError(ErrorCode::InvalidArgument, std::string(name) + " holds NaN or inf", "spatial model");
  return {};
}
}  // namespace

Complex poleFromFrequencyDamping(double frequencyHz, double zeta) {
  const double wn = kTwoPi * frequencyHz;
  return {-zeta * wn, wn * std::sqrt(std::max(0.0, 1.0 - zeta * zeta))};
}

double poleFrequencyHz(Complex pole) {
  return std::abs(pole) / kTwoPi;
}

double poleZeta(Complex pole) {
  const double a = std::abs(pole);
  return a > 0.0 ? -pole.real() / a : 0.0;
}

Result<void> ModalModel::validate() const {
  const Eigen::Index no = responseCount(), ni = referenceCount();
  if (no == 0 || ni == 0) return makeError(ErrorCode::InvalidArgument, "no response or reference DOF", "modal model");
  for (std::size_t r = 0; r < modes.size(); ++r) {
    const auto& md = modes[r];
    const std::string where = "modal model, mode " + std::to_string(r + 1);
    if (!std::isfinite(md.pole.real()) || !std::isfinite(md.pole.imag()) || md.pole.imag() <= 0.0 ||
        md.pole.real() >= 0.0) {
      return makeError(ErrorCode::InvalidArgument, "pole must be finite, stable (Re < 0) and have Im > 0", where);
    }
    if (md.residue.rows() != no || md.residue.cols() != ni || !md.residue.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "residue matrix must be finite and no x ni", where);
    }
  }
  for (const auto* res : {&lowerResidual, &upperResidual}) {
    if (res->size() != 0 && (res->rows() != no || res->cols() != ni || !res->allFinite())) {
      return makeError(ErrorCode::InvalidArgument, "residual term must be empty or finite no x ni", "modal model");
    }
  }
  return {};
}

Complex synthesize(const ModalModel& model, Eigen::Index o, Eigen::Index i, double omega, FrfType type) {
  const Complex iw(0.0, omega);
  Complex h(0.0, 0.0);
  // Receptance: sum_r R/(iw - lambda) + conj(R)/(iw - conj(lambda)) + U - L/w^2 (header).
  for (const auto& md : model.modes) {
    const Complex r = md.residue(o, i);
    h += r / (iw - md.pole) + std::conj(r) / (iw - std::conj(md.pole));
  }
  if (model.upperResidual.size() != 0) h += model.upperResidual(o, i);
  const int n = frfTypeOrder(type);
  Complex out = h * iOmegaPower(omega, n);
  if (model.lowerResidual.size() != 0) {
    // -L/w^2 times (iw)^n = L (iw)^(n-2): accelerance gets the constant L.
    out += model.lowerResidual(o, i) * (n >= 2 ? iOmegaPower(omega, n - 2) : 1.0 / iOmegaPower(omega, 2 - n));
  }
  return out;
}

Result<FrfMatrix> synthesizeFrf(const ModalModel& model, const VectorRef& frequencyHz, FrfType type) {
  MOZZI_TRY(model.validate());
  if (model.lowerResidual.size() != 0 && frfTypeOrder(type) < 2) {
    for (Eigen::Index k = 0; k < frequencyHz.size(); ++k) {
      if (frequencyHz[k] == 0.0) {
        return makeError(ErrorCode::InvalidArgument, "the lower residual -L/omega^2 is infinite at 0 Hz",
                         "synthesis, line " + std::to_string(k));
      }
    }
  }
  FrfMatrix out;
  out.frequencyHz = frequencyHz;
  out.responses = model.responses;
  out.references = model.references;
  out.type = type;
  const Eigen::Index nf = frequencyHz.size();
  for (Eigen::Index i = 0; i < model.referenceCount(); ++i) {
    ComplexMatrix block(nf, model.responseCount());
    for (Eigen::Index o = 0; o < model.responseCount(); ++o) {
      for (Eigen::Index k = 0; k < nf; ++k) block(k, o) = synthesize(model, o, i, kTwoPi * frequencyHz[k], type);
    }
    out.h.push_back(std::move(block));
  }
  return out;
}

Result<ModalModel> modalFromSpatial(const MatrixRef& m, const MatrixRef& c, const MatrixRef& k,
                                    const std::vector<Dof>& dofs) {
  const Eigen::Index n = m.rows();
  if (n == 0) return makeError(ErrorCode::InvalidArgument, "empty mass matrix", "spatial model");
  for (auto [a, name] : {std::pair<const MatrixRef*, const char*>{&m, "M"}, {&c, "C"}, {&k, "K"}}) {
    MOZZI_TRY(checkSquare(*a, n, name));
  }
  if (static_cast<Eigen::Index>(dofs.size()) != n) {
    return makeError(ErrorCode::InvalidArgument, "need one DOF label per coordinate", "spatial model");
  }
  Eigen::LLT<Matrix> mllt(m);
  if (mllt.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "mass matrix is not positive definite", "spatial model");
  }
  // State matrix A = [0 I; -M^-1 K, -M^-1 C]; eigenvectors [psi; lambda psi].
  Matrix a = Matrix::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).setIdentity();
  a.bottomLeftCorner(n, n) = -mllt.solve(Matrix(k));
  a.bottomRightCorner(n, n) = -mllt.solve(Matrix(c));
  Eigen::EigenSolver<Matrix> es(a, true);
  if (es.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "state-space eigenproblem did not converge", "spatial model");
  }
  ModalModel model;
  model.responses = dofs;
  model.references = dofs;
  const double scale = std::max(1.0, es.eigenvalues().cwiseAbs().maxCoeff());
  for (Eigen::Index r = 0; r < 2 * n; ++r) {
    const Complex lambda = es.eigenvalues()[r];
    if (std::abs(lambda.imag()) <= 1e-12 * scale) {
      return makeError(ErrorCode::Unsupported,
                       "overdamped or rigid-body pole (real eigenvalue) cannot be written as a mode pair",
                       "spatial model, eigenvalue " + std::to_string(r));
    }
    if (lambda.imag() < 0.0) continue;
    const ComplexVector psi = es.eigenvectors().col(r).head(n);
    // Modal A: a_r = psi^T (2 lambda M + C) psi (unconjugated); R_r = psi psi^T / a_r.
    const Complex ar = (psi.transpose() * (2.0 * lambda * m.cast<Complex>() + c.cast<Complex>()) * psi)(0, 0);
    Mode md;
    md.pole = lambda;
    md.residue = psi * psi.transpose() / ar;
    model.modes.push_back(std::move(md));
  }
  std::sort(model.modes.begin(), model.modes.end(),
            [](const Mode& x, const Mode& y) { return std::abs(x.pole) < std::abs(y.pole); });
  return model;
}

Result<SpatialModel> spatialFromModal(const ModalModel& model) {
  MOZZI_TRY(model.validate());
  const Eigen::Index n = model.responseCount();
  if (model.referenceCount() != n || static_cast<Eigen::Index>(model.modes.size()) != n) {
    return makeError(ErrorCode::InvalidArgument,
                     "a spatial model needs a complete modal model: N modes with full N x N residues (have " +
                         std::to_string(model.modes.size()) + " modes, " + std::to_string(n) + " x " +
                         std::to_string(model.referenceCount()) + " residues)",
                     "modal -> spatial");
  }
  // Sums over both members of each conjugate pair: sum_r (x + conj x) = 2 Re(x).
  Matrix minv = Matrix::Zero(n, n), kinv = Matrix::Zero(n, n), w = Matrix::Zero(n, n);
  for (const auto& md : model.modes) {
    minv += 2.0 * (md.pole * md.residue).real();
    kinv -= 2.0 * (md.residue / md.pole).real();
    w += 2.0 * (md.pole * md.pole * md.residue).real();
  }
  Eigen::FullPivLU<Matrix> mlu(minv), klu(kinv);
  if (!mlu.isInvertible() || !klu.isInvertible()) {
    return makeError(ErrorCode::NumericalFailure, "modal model gives a singular flexibility or inverse mass",
                     "modal -> spatial");
  }
  SpatialModel s;
  s.m = mlu.inverse();
  s.k = klu.inverse();
  s.c = -s.m * w * s.m;  // lower-right block of A_s^-1 = -M^-1 C M^-1
  s.m = 0.5 * (s.m + s.m.transpose()).eval();
  s.k = 0.5 * (s.k + s.k.transpose()).eval();
  s.c = 0.5 * (s.c + s.c.transpose()).eval();
  return s;
}

Result<HystereticModalModel> hystereticModalFromSpatial(const MatrixRef& m, const MatrixRef& k, const MatrixRef& d) {
  const Eigen::Index n = m.rows();
  if (n == 0) return makeError(ErrorCode::InvalidArgument, "empty mass matrix", "spatial model");
  for (auto [a, name] : {std::pair<const MatrixRef*, const char*>{&m, "M"}, {&k, "K"}, {&d, "D"}}) {
    MOZZI_TRY(checkSquare(*a, n, name));
  }
  Eigen::LLT<Matrix> mllt(m);
  if (mllt.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "mass matrix is not positive definite", "spatial model");
  }
  // (K + i D) phi = lambda^2 M phi  ->  M^-1 (K + i D) phi = lambda^2 phi.
  const ComplexMatrix kc = k.cast<Complex>() + kI * d.cast<Complex>();
  const ComplexMatrix a = mllt.solve(Matrix::Identity(n, n)).cast<Complex>() * kc;
  Eigen::ComplexEigenSolver<ComplexMatrix> es(a, true);
  if (es.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "hysteretic eigenproblem did not converge", "spatial model");
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  for (Eigen::Index r = 0; r < n; ++r) order[static_cast<std::size_t>(r)] = r;
  std::sort(order.begin(), order.end(),
            [&](Eigen::Index x, Eigen::Index y) { return es.eigenvalues()[x].real() < es.eigenvalues()[y].real(); });
  HystereticModalModel out;
  out.omega2.resize(n);
  out.eta.resize(n);
  out.phi.resize(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index r = order[static_cast<std::size_t>(j)];
    const Complex l2 = es.eigenvalues()[r];
    if (l2.real() <= 0.0) {
      return makeError(ErrorCode::Unsupported, "non-positive stiffness eigenvalue (rigid-body mode)",
                       "spatial model, mode " + std::to_string(j + 1));
    }
    ComplexVector v = es.eigenvectors().col(r);
    const Complex mr = (v.transpose() * m.cast<Complex>() * v)(0, 0);  // unconjugated, eq. 1
    v /= std::sqrt(mr);
    out.phi.col(j) = v;
    out.omega2[j] = l2.real();
    out.eta[j] = l2.imag() / l2.real();  // lambda^2 = omega^2 (1 + i eta), thesis eq. 1
  }
  return out;
}

Result<HystereticSpatialModel> spatialFromHystereticModal(const HystereticModalModel& model) {
  const Eigen::Index n = model.phi.rows();
  if (n == 0 || model.phi.cols() != n || model.omega2.size() != n || model.eta.size() != n) {
    return makeError(ErrorCode::InvalidArgument, "complete hysteretic model needs N x N shapes and N poles",
                     "modal -> spatial");
  }
  Eigen::FullPivLU<ComplexMatrix> lu(model.phi);
  if (!lu.isInvertible()) {
    return makeError(ErrorCode::NumericalFailure, "mode-shape matrix is singular", "modal -> spatial");
  }
  const ComplexMatrix phiInv = lu.inverse();
  ComplexVector l2(n);
  for (Eigen::Index r = 0; r < n; ++r) l2[r] = model.omega2[r] * Complex(1.0, model.eta[r]);
  // Thesis eq. 2: M = Phi^-T Phi^-1; K + i D = Phi^-T diag(lambda^2) Phi^-1.
  const ComplexMatrix mm = phiInv.transpose() * phiInv;
  const ComplexMatrix kd = phiInv.transpose() * l2.asDiagonal() * phiInv;
  HystereticSpatialModel s;
  s.m = mm.real();
  s.k = kd.real();
  s.d = kd.imag();
  return s;
}

ComplexMatrix hystereticReceptance(const HystereticModalModel& model, double omega) {
  const Eigen::Index n = model.phi.cols();
  ComplexVector g(n);
  for (Eigen::Index r = 0; r < n; ++r) g[r] = 1.0 / (model.omega2[r] * Complex(1.0, model.eta[r]) - omega * omega);
  return model.phi * g.asDiagonal() * model.phi.transpose();
}

ComplexMatrix spatialReceptance(const MatrixRef& m, const MatrixRef& c, const MatrixRef& k, double omega) {
  const ComplexMatrix z = k.cast<Complex>() - omega * omega * m.cast<Complex>() + kI * omega * c.cast<Complex>();
  return z.partialPivLu().inverse();
}

}  // namespace mozzi::core::modal
