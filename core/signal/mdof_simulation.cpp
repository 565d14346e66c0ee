#include "core/signal/mdof_simulation.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

namespace mozzi::core::signal {

namespace {
bool allFinite(const MatrixRef& m) {
  return m.allFinite();
}
}  // namespace

Result<MdofResponse> simulateMdof(const LinearMdof& sys, const MatrixRef& force, double sampleRateHz, ForceHold hold,
                                  const Vector& q0, const Vector& v0) {
  const std::string where = "MDOF simulation";
  const Eigen::Index n = sys.mass.rows();
  if (n < 1 || sys.mass.cols() != n || sys.damping.rows() != n || sys.damping.cols() != n ||
      sys.stiffness.rows() != n || sys.stiffness.cols() != n) {
    return makeError(ErrorCode::InvalidArgument, "M, C and K must be square and of the same size", where);
  }
  if (!allFinite(sys.mass) || !allFinite(sys.damping) || !allFinite(sys.stiffness)) {
    return makeError(ErrorCode::InvalidArgument, "M, C or K holds NaN or infinite values", where);
  }
  if (!std::isfinite(sampleRateHz) || sampleRateHz <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be finite and positive", where);
  }
  if (force.cols() != n) {
    return makeError(ErrorCode::InvalidArgument,
                     "force has " + std::to_string(force.cols()) + " columns for " + std::to_string(n) + " DOFs",
                     where);
  }
  if (force.rows() < 1) return makeError(ErrorCode::InvalidArgument, "force history is empty", where);
  if (!allFinite(force)) return makeError(ErrorCode::InvalidArgument, "force holds NaN or infinite samples", where);
  if ((q0.size() != 0 && q0.size() != n) || (v0.size() != 0 && v0.size() != n)) {
    return makeError(ErrorCode::InvalidArgument, "initial state has the wrong size", where);
  }
  Eigen::LLT<Matrix> llt(sys.mass);
  if (llt.info() != Eigen::Success) {
    return makeError(ErrorCode::InvalidArgument, "mass matrix is not symmetric positive definite", where);
  }
  const Matrix mInv = llt.solve(Matrix::Identity(n, n));
  const double T = 1.0 / sampleRateHz;

  // Augmented matrix (Van Loan): exp([A B 0; 0 0 I/T; 0 0 0] T) holds in its
  // top row Ad, G0 and G1 (the integrals of the header) for a force ramp.
  const Eigen::Index s = 2 * n;
  Matrix aug = Matrix::Zero(s + 2 * n, s + 2 * n);
  aug.block(0, n, n, n) = Matrix::Identity(n, n);
  aug.block(n, 0, n, n) = -mInv * sys.stiffness;
  aug.block(n, n, n, n) = -mInv * sys.damping;
  aug.block(n, s, n, n) = mInv;                            // B = [0; M^-1]
  aug.block(s, s + n, n, n) = Matrix::Identity(n, n) / T;  // ramp generator
  const Matrix e = (aug * T).exp();
  const Matrix ad = e.block(0, 0, s, s);
  const Matrix g0 = e.block(0, s, s, n);
  const Matrix g1 = e.block(0, s + n, s, n);
  if (!ad.allFinite() || !g0.allFinite() || !g1.allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "matrix exponential of the state matrix is not finite", where);
  }
  Matrix b0, b1;
  if (hold == ForceHold::ZeroOrder) {
    b0 = g0;
    b1 = Matrix::Zero(s, n);
  } else {
    b0 = g0 - g1;
    b1 = g1;
  }

  const Eigen::Index ns = force.rows();
  MdofResponse r;
  r.displacement.resize(ns, n);
  r.velocity.resize(ns, n);
  r.acceleration.resize(ns, n);
  Vector x = Vector::Zero(s);
  if (q0.size() == n) x.head(n) = q0;
  if (v0.size() == n) x.tail(n) = v0;
  const Matrix mInvC = mInv * sys.damping;
  const Matrix mInvK = mInv * sys.stiffness;
  Vector next(s), fk(n), fk1(n);
  for (Eigen::Index k = 0; k < ns; ++k) {
    fk = force.row(k).transpose();
    r.displacement.row(k) = x.head(n).transpose();
    r.velocity.row(k) = x.tail(n).transpose();
    // q'' = M^-1 (f - C q' - K q), eq. 18 at t_k
    r.acceleration.row(k).noalias() = (mInv * fk - mInvC * x.tail(n) - mInvK * x.head(n)).transpose();
    if (k + 1 < ns) {
      next.noalias() = ad * x;
      next.noalias() += b0 * fk;
      if (hold == ForceHold::FirstOrder) {
        fk1 = force.row(k + 1).transpose();
        next.noalias() += b1 * fk1;
      }
      x.swap(next);
    }
  }
  return r;
}

}  // namespace mozzi::core::signal
