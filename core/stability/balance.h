#pragma once
// Diagonal similarity scaling ("balancing", Parlett & Reinsch 1969, as in
// LAPACK dgebal without permutation): B = D^-1 A D with D a diagonal of powers
// of two chosen so rows and columns have comparable norms. Eigenvalues of B
// equal those of A but are computed with errors ~ eps ||B|| instead of
// eps ||A||, which matters for stiff fork joints (k up to 1e12 N m/rad).

#include <cmath>

#include "core/common/eigen_types.h"

namespace mozzi::core::stability {

// Balances A in place and returns the diagonal of D (eigenvectors of the
// original matrix are D times those of the balanced one).
template <class MatrixType>
Eigen::Matrix<double, MatrixType::RowsAtCompileTime, 1> balanceInPlace(MatrixType& A) {
  const int n = static_cast<int>(A.rows());
  Eigen::Matrix<double, MatrixType::RowsAtCompileTime, 1> d(n);
  d.setOnes();
  const double radix = 2.0;
  bool converged = false;
  for (int sweep = 0; sweep < 100 && !converged; ++sweep) {
    converged = true;
    for (int i = 0; i < n; ++i) {
      double c = 0.0, r = 0.0;
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        c += std::abs(A(j, i));
        r += std::abs(A(i, j));
      }
      // A row or column whose norm overflows (entries near 1e308) cannot be
      // balanced: dividing inf by the radix never ends the loop below.
      if (c == 0.0 || r == 0.0 || !std::isfinite(c + r)) continue;
      double g = r / radix, f = 1.0;
      const double s = c + r;
      while (c < g) {
        f *= radix;
        c *= radix * radix;
      }
      g = r * radix;
      while (c > g) {
        f /= radix;
        c /= radix * radix;
      }
      if ((c + r) / f < 0.95 * s) {
        converged = false;
        d(i) *= f;
        A.row(i) /= f;
        A.col(i) *= f;
      }
    }
  }
  return d;
}

}  // namespace mozzi::core::stability
