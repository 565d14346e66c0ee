#include "core/modal/assignment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/modal/shape_tools.h"

namespace mozzi::core::modal {

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

}  // namespace mozzi::core::modal
