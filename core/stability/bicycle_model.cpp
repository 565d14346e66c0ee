#include "core/stability/bicycle_model.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/stability/balance.h"

namespace mozzi::core::stability {

namespace {

bool allFinite(const Matrix& m) {
  return m.allFinite();
}

// Solves the fixed-size state matrix without heap allocation for n = 2, 3.
template <int N>
Result<ComplexVector> eigenvaluesFixed(const BicycleModel& m, double v) {
  using Mat = Eigen::Matrix<double, N, N>;
  using Big = Eigen::Matrix<double, 2 * N, 2 * N>;
  const Mat M = m.M;
  const Mat Cv = v * m.C1 + m.C;
  const Mat Kv = m.g * m.K0 + v * v * m.K2 + m.K;
  const Eigen::LLT<Mat> llt(M);
  if (llt.info() != Eigen::Success || !M.allFinite() || !Cv.allFinite() || !Kv.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "mass matrix not positive definite or a matrix is not finite",
                     "BicycleModel");
  }
  Big A = Big::Zero();
  A.template block<N, N>(0, N).setIdentity();
  A.template block<N, N>(N, 0) = -llt.solve(Kv);
  A.template block<N, N>(N, N) = -llt.solve(Cv);
  if (!A.allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "the state matrix is not finite (a parameter out of range)", "v");
  }
  balanceInPlace(A);  // stiff fork joints: see balance.h
  if (!A.allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "the state matrix is not finite (a parameter out of range)", "v");
  }
  Eigen::EigenSolver<Big> es(A, false);
  if (es.info() != Eigen::Success) return makeError(ErrorCode::NumericalFailure, "eigenvalue iteration failed", "v");
  return ComplexVector(es.eigenvalues());
}

}  // namespace

Result<void> validate(const BicycleModel& model) {
  const int n = model.size();
  if (n < 1) return makeError(ErrorCode::InvalidArgument, "empty mass matrix", "BicycleModel.M");
  const std::pair<const Matrix*, const char*> all[] = {{&model.M, "M"},   {&model.C1, "C1"}, {&model.K0, "K0"},
                                                       {&model.K2, "K2"}, {&model.C, "C"},   {&model.K, "K"}};
  for (const auto& [m, name] : all) {
    if (m->rows() != n || m->cols() != n) {
      return makeError(ErrorCode::InvalidArgument, "matrix is not " + std::to_string(n) + "x" + std::to_string(n),
                       std::string("BicycleModel.") + name);
    }
    if (!allFinite(*m)) {
      return makeError(ErrorCode::InvalidArgument, "matrix has a non-finite entry",
                       std::string("BicycleModel.") + name);
    }
  }
  if (!std::isfinite(model.g)) return makeError(ErrorCode::InvalidArgument, "gravity is not finite", "BicycleModel.g");
  if ((model.M - model.M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * model.M.cwiseAbs().maxCoeff()) {
    return makeError(ErrorCode::InvalidArgument, "mass matrix is not symmetric", "BicycleModel.M");
  }
  if (Eigen::LLT<Matrix>(model.M).info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "mass matrix is not positive definite", "BicycleModel.M");
  }
  return Result<void>();
}

Result<Matrix> BicycleModel::stateMatrix(double v) const {
  if (!std::isfinite(v)) return makeError(ErrorCode::InvalidArgument, "speed is not finite", "v");
  MOZZI_TRY(validate(*this));
  const int n = size();
  const Eigen::LLT<Matrix> llt(M);
  Matrix A = Matrix::Zero(2 * n, 2 * n);
  A.block(0, n, n, n).setIdentity();
  A.block(n, 0, n, n) = -llt.solve(g * K0 + v * v * K2 + K);
  A.block(n, n, n, n) = -llt.solve(v * C1 + C);
  return A;
}

Result<ComplexVector> BicycleModel::eigenvalues(double v) const {
  if (!std::isfinite(v)) return makeError(ErrorCode::InvalidArgument, "speed is not finite", "v");
  const int n = size();
  if (n == 2 && M.cols() == 2 && C1.rows() == 2 && K0.rows() == 2 && K2.rows() == 2 && C.rows() == 2 && K.rows() == 2) {
    return eigenvaluesFixed<2>(*this, v);
  }
  if (n == 3 && M.cols() == 3 && C1.rows() == 3 && K0.rows() == 3 && K2.rows() == 3 && C.rows() == 3 && K.rows() == 3) {
    return eigenvaluesFixed<3>(*this, v);
  }
  MOZZI_TRY_ASSIGN(auto A, stateMatrix(v));
  if (!A.allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "the state matrix is not finite (a parameter out of range)", "v");
  }
  balanceInPlace(A);
  if (!A.allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "the state matrix is not finite (a parameter out of range)", "v");
  }
  Eigen::EigenSolver<Matrix> es(A, false);
  if (es.info() != Eigen::Success) return makeError(ErrorCode::NumericalFailure, "eigenvalue iteration failed", "v");
  return ComplexVector(es.eigenvalues());
}

}  // namespace mozzi::core::stability
