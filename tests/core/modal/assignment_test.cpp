// The assignment solver against a brute-force search over every assignment
// (small random matrices), and the MAC pairing built on it.
#include "core/modal/assignment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace mozzi::core::modal {
namespace {

// Total cost of an assignment; checks that it is one: every column used at
// most once and exactly min(rows, cols) rows assigned.
double assignmentCost(const Matrix& cost, const std::vector<int>& rowToCol) {
  EXPECT_EQ(rowToCol.size(), static_cast<std::size_t>(cost.rows()));
  std::vector<int> used;
  double total = 0.0;
  for (std::size_t r = 0; r < rowToCol.size(); ++r) {
    const int c = rowToCol[r];
    if (c < 0) continue;
    EXPECT_LT(c, cost.cols());
    EXPECT_EQ(std::count(used.begin(), used.end(), c), 0) << "column " << c << " assigned twice";
    used.push_back(c);
    total += cost(static_cast<Eigen::Index>(r), c);
  }
  EXPECT_EQ(used.size(), static_cast<std::size_t>(std::min(cost.rows(), cost.cols())));
  return total;
}

// The least total cost over every injective assignment of the smaller side
// into the larger (every permutation of the larger side's indices, the first
// min(rows, cols) of them paired with the smaller side in order).
double bruteForceMinimum(const Matrix& cost) {
  const auto n = cost.rows(), m = cost.cols();
  std::vector<Eigen::Index> perm(static_cast<std::size_t>(std::max(n, m)));
  std::iota(perm.begin(), perm.end(), Eigen::Index{0});
  double best = std::numeric_limits<double>::infinity();
  do {
    double total = 0.0;
    for (Eigen::Index k = 0; k < std::min(n, m); ++k) {
      const Eigen::Index other = perm[static_cast<std::size_t>(k)];
      total += n <= m ? cost(k, other) : cost(other, k);
    }
    best = std::min(best, total);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

TEST(Assignment, HandWorkedCases) {
  Matrix cost(3, 3);
  cost << 4, 1, 3, 2, 0, 5, 3, 2, 2;  // optimum 1 + 2 + 2 = 5: (0,1), (1,0), (2,2)
  EXPECT_EQ(hungarianAssignment(cost), (std::vector<int>{1, 0, 2}));
  Matrix rect(2, 3);
  rect << 5, 1, 9, 1, 2, 9;
  EXPECT_EQ(hungarianAssignment(rect), (std::vector<int>{1, 0}));
}

// Random costs, square and rectangular both ways, up to 6 x 6 (720
// permutations), signed and with integer ties: the solver's total equals the
// brute-force minimum. Both sum the same few doubles in different orders, so
// the totals agree to a few ulps of their magnitude (1e-12 relative).
TEST(Assignment, MatchesBruteForceOnRandomMatrices) {
  std::mt19937_64 rng(24);
  std::uniform_int_distribution<int> size(1, 6);
  std::uniform_real_distribution<double> real(-1.0, 1.0);
  std::uniform_int_distribution<int> small(0, 3);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = size(rng), m = size(rng);
    Matrix cost(n, m);
    const bool ties = trial % 3 == 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) cost(i, j) = ties ? small(rng) : 10.0 * real(rng);
    const std::vector<int> result = hungarianAssignment(cost);
    const double expected = bruteForceMinimum(cost);
    EXPECT_NEAR(assignmentCost(cost, result), expected, 1e-12 * (1.0 + std::abs(expected)))
        << "trial " << trial << ", " << n << " x " << m << ":\n"
        << cost;
  }
}

TEST(Assignment, MacPairing) {
  // Measured modes in swapped order, the third unlike any model mode.
  ComplexMatrix model = ComplexMatrix::Zero(4, 3), meas = ComplexMatrix::Zero(4, 3);
  model(0, 0) = 1;
  model(1, 1) = 1;
  model(2, 2) = 1;
  meas(1, 0) = 1;
  meas(0, 1) = 1;
  meas(0, 2) = 0.5;
  meas(3, 2) = 1;  // MAC with model mode 3 is 0
  EXPECT_EQ(pairModesByMac(model, meas, 0.6), (std::vector<int>{1, 0, -1}));
  // One DOF: every MAC is 1, the frequencies decide (measured 31 Hz is the
  // model's 30 Hz mode, not its 80 Hz one).
  const ComplexMatrix oneModel = ComplexMatrix::Ones(1, 2), oneMeas = ComplexMatrix::Ones(1, 1);
  Vector modelHz(2), measHz(1);
  modelHz << 30.0, 80.0;
  measHz << 31.0;
  EXPECT_EQ(pairModesByMac(oneModel, oneMeas, 0.6, modelHz, measHz), (std::vector<int>{0, -1}));
  modelHz << 80.0, 30.0;
  EXPECT_EQ(pairModesByMac(oneModel, oneMeas, 0.6, modelHz, measHz), (std::vector<int>{-1, 0}));
}

}  // namespace
}  // namespace mozzi::core::modal
