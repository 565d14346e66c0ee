// parallelFor: every index runs exactly once whatever the thread count, each
// task's slot holds what a serial loop gives, and a task's exception reaches
// the caller after the threads have stopped.
#include "core/common/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace mozzi::core {
namespace {

TEST(ParallelFor, EveryIndexOnceAndTheSameResultsForAnyThreadCount) {
  constexpr std::size_t n = 1000;
  std::vector<double> serial(n);
  for (std::size_t i = 0; i < n; ++i) serial[i] = std::sin(0.01 * static_cast<double>(i));
  for (unsigned threads : {0u, 1u, 2u, 7u}) {
    std::vector<double> out(n, -2.0);
    std::vector<std::atomic<int>> runs(n);
    parallelFor(
        n,
        [&](std::size_t i) {
          ++runs[i];
          out[i] = std::sin(0.01 * static_cast<double>(i));
        },
        threads);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(runs[i].load(), 1) << "index " << i << ", " << threads << " threads";
      ASSERT_EQ(out[i], serial[i]) << "index " << i;
    }
  }
  int none = 0;
  parallelFor(
      0, [&](std::size_t) { ++none; }, 2);
  EXPECT_EQ(none, 0);
}

TEST(ParallelFor, ATasksExceptionReachesTheCaller) {
  std::atomic<int> ran{0};
  EXPECT_THROW(parallelFor(
                   100,
                   [&](std::size_t i) {
                     ++ran;
                     if (i == 17) throw std::runtime_error("task 17");
                   },
                   2),
               std::runtime_error);
  EXPECT_GE(ran.load(), 1);
  EXPECT_LE(ran.load(), 100);
}

}  // namespace
}  // namespace mozzi::core
