// Issue 17: `stability bicycle --fork-bending 1e308,0.8,0.21` never returned.
// Whatever the CLI's range table lets through, the core must answer a finite
// sweep or an error in bounded time for inputs at the edges of the double
// range: the state matrix is checked finite before every (iterative) QR
// eigen-solve, which has Eigen's own iteration cap.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/mode_tracking.h"

namespace mozzi::core::stability {
namespace {

TEST(StabilityExtremeInputs, HugeOrTinyForkJointsEndQuickly) {
  const BenchmarkParameters p = meijaard2007Parameters();
  auto speeds = speedGrid(0.0, 10.0, 1.0);
  ASSERT_TRUE(speeds.ok());
  for (double k : {1e308, 1e200, 1e15, 1e-300}) {
    for (double c : {0.8, 1e308}) {
      const auto start = std::chrono::steady_clock::now();
      for (int joint = 0; joint < 2; ++joint) {
        auto m = joint == 0 ? forkBendingModel(p, {k, c, 0.21}) : forkTorsionModel(p, {k, c, 0.0});
        if (!m) continue;  // refused up front: fine
        auto sweep = sweepSpeeds(bicycleSystem(*m), *speeds);
        if (!sweep) continue;  // an error naming the problem: fine
        for (const auto& point : sweep->points) {
          for (const auto& root : point.roots) {
            EXPECT_TRUE(std::isfinite(root.lambda.real()) && std::isfinite(root.lambda.imag()))
                << "k = " << k << ", c = " << c << ", v = " << point.v;
          }
        }
      }
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_LT(s, 20.0) << "k = " << k << ", c = " << c;
    }
  }
}

}  // namespace
}  // namespace mozzi::core::stability
