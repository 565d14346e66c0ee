// The one-pass scans behind the hit check (core/signal/sample_scan.h) against
// the plain definitions: std::min_element / std::max_element, std::isfinite
// and a counting loop, on every length from 1 to 40 (the packed loop's
// remainders) and at every position of a NaN or an infinity.
#include "core/signal/sample_scan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace mozzi::core::signal {
namespace {

std::vector<double> randomSamples(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.3, 2.0);
  std::vector<double> x(n);
  for (double& v : x) v = normal(rng);
  return x;
}

TEST(SampleScan, ExtremesAreThoseOfThePlainDefinitionAtEveryLength) {
  for (std::size_t n = 1; n <= 40; ++n) {
    const auto x = randomSamples(n, static_cast<unsigned>(n));
    const SampleExtremes e = scanSamples(x.data(), static_cast<Eigen::Index>(n));
    EXPECT_TRUE(e.finite) << n;
    EXPECT_EQ(e.min, *std::min_element(x.begin(), x.end())) << n;
    EXPECT_EQ(e.max, *std::max_element(x.begin(), x.end())) << n;
  }
}

TEST(SampleScan, ANanOrAnInfinityAnywhereIsFound) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (const std::size_t n : {1u, 7u, 8u, 9u, 33u}) {
    for (std::size_t at = 0; at < n; ++at) {
      for (const double b : bad) {
        auto x = randomSamples(n, 7);
        x[at] = b;
        EXPECT_FALSE(scanSamples(x.data(), static_cast<Eigen::Index>(n)).finite) << n << " " << at << " " << b;
      }
    }
  }
  // Large finite samples are finite: no sum that could overflow.
  std::vector<double> huge(17, std::numeric_limits<double>::max());
  EXPECT_TRUE(scanSamples(huge.data(), 17).finite);
}

TEST(SampleScan, CountsBeyondAreThoseOfACountingLoop) {
  for (std::size_t n = 1; n <= 40; ++n) {
    auto x = randomSamples(n, static_cast<unsigned>(100 + n));
    if (n > 3) x[n / 2] = x[n / 3] = 1.5;  // samples exactly at a threshold count
    const ThresholdCounts c = countBeyond(x.data(), static_cast<Eigen::Index>(n), 1.5, -0.5);
    EXPECT_EQ(c.atOrAbove, std::count_if(x.begin(), x.end(), [](double v) { return v >= 1.5; })) << n;
    EXPECT_EQ(c.atOrBelow, std::count_if(x.begin(), x.end(), [](double v) { return v <= -0.5; })) << n;
  }
}

}  // namespace
}  // namespace mozzi::core::signal
