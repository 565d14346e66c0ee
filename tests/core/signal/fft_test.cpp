// FFTW plan cache: correctness against a direct DFT, plan reuse, and use from
// several threads at once.
#include "core/signal/fft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

ComplexVector directDft(const Vector& x) {
  const Eigen::Index n = x.size();
  ComplexVector X(n / 2 + 1);
  for (Eigen::Index k = 0; k <= n / 2; ++k) {
    Complex s = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) s += x[i] * std::polar(1.0, -2 * kPi * double(k) * double(i) / double(n));
    X[k] = s;
  }
  return X;
}

Vector randomVector(Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> d;
  Vector v(n);
  for (auto& x : v) x = d(rng);
  return v;
}

TEST(RealFft, MatchesDirectDftForEvenAndOddLengths) {
  for (Eigen::Index n : {2, 7, 64, 100, 257}) {
    auto fft = RealFft::forLength(n);
    ASSERT_TRUE(fft.ok());
    const Vector x = randomVector(n, static_cast<std::uint64_t>(n));
    auto X = (*fft)->transform(x);
    ASSERT_TRUE(X.ok());
    const ComplexVector ref = directDft(x);
    // FFT rounding grows like log n eps |x| sqrt(n); 1e-10 is far above it
    EXPECT_LT((*X - ref).cwiseAbs().maxCoeff(), 1e-10 * std::sqrt(double(n))) << "n = " << n;
    Vector back(n);
    ASSERT_TRUE((*fft)->inverse(X->data(), back.data()));
    EXPECT_LT((back / double(n) - x).cwiseAbs().maxCoeff(), 1e-12) << "n = " << n;
  }
}

// The lengths planned from the wisdom of core/signal/fftw_wisdom.h (measured
// plans, another factorisation than the estimate's): the same accuracy.
TEST(RealFft, PlansFromKeptWisdomMatchDirectDftAndAnalyticSpectra) {
  for (Eigen::Index n : {1024, 2048}) {
    auto fft = RealFft::forLength(n);
    ASSERT_TRUE(fft.ok());
    const Vector x = randomVector(n, static_cast<std::uint64_t>(n) + 1);
    auto X = (*fft)->transform(x);
    ASSERT_TRUE(X.ok());
    EXPECT_LT((*X - directDft(x)).cwiseAbs().maxCoeff(), 1e-10 * std::sqrt(double(n))) << "n = " << n;
  }
  // 65,536 samples (the hammer hits of the CLI benchmark), against the
  // analytic spectrum of two tones on lines 1000 and 20000: n/2 and -i n/4
  // there, zero elsewhere. Rounding: at most about log2(n) eps |X| = 16 x
  // 2.2e-16 x 32768 = 1.2e-10 (4e-12 measured); 1e-9 is 3e-14 of the peak.
  const Eigen::Index n = 65536;
  auto fft = RealFft::forLength(n);
  ASSERT_TRUE(fft.ok());
  // The phases reduced modulo n in integers first: 2 pi k i / n in doubles
  // would carry phase errors growing with i (up to 3e-11 rad at line
  // 20000), whose leakage (about 2e-8) is larger than the FFT's rounding.
  Vector x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double a = 2 * kPi * double((1000 * i) % n) / double(n), b = 2 * kPi * double((20000 * i) % n) / double(n);
    x[i] = std::cos(a) + 0.5 * std::sin(b);
  }
  auto X = (*fft)->transform(x);
  ASSERT_TRUE(X.ok());
  ComplexVector ref = ComplexVector::Zero(n / 2 + 1);
  ref[1000] = Complex(double(n) / 2, 0.0);
  ref[20000] = Complex(0.0, -double(n) / 4);
  EXPECT_LT((*X - ref).cwiseAbs().maxCoeff(), 1e-9);
  Vector back(n);
  ASSERT_TRUE((*fft)->inverse(X->data(), back.data()));
  EXPECT_LT((back / double(n) - x).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(RealFft, PlanIsCreatedOnceAndReused) {
  auto a = RealFft::forLength(4096);
  auto b = RealFft::forLength(4096);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->get(), b->get());
  EXPECT_FALSE(RealFft::forLength(1).ok());
  EXPECT_FALSE((*a)->transform(Vector::Zero(10)).ok());
}

TEST(RealFft, UnalignedPointersGiveTheSameResult) {
  const Eigen::Index n = 1000;
  auto fft = RealFft::forLength(n);
  ASSERT_TRUE(fft.ok());
  const Vector x = randomVector(n, 3);
  std::vector<double> shifted(n + 1);
  for (Eigen::Index i = 0; i < n; ++i) shifted[static_cast<std::size_t>(i + 1)] = x[i];
  std::vector<Complex> out(static_cast<std::size_t>(n / 2 + 2));
  (*fft)->forward(shifted.data() + 1, out.data() + 1);  // 8-byte offsets
  auto ref = (*fft)->transform(x);
  ASSERT_TRUE(ref.ok());
  for (Eigen::Index k = 0; k <= n / 2; ++k) EXPECT_EQ(out[static_cast<std::size_t>(k + 1)], (*ref)[k]);
}

TEST(RealFft, ConcurrentPlanningAndExecutionAreSafe) {
  // 4 threads, each planning several new lengths and transforming; results
  // must equal the single-threaded ones bit for bit.
  const std::vector<Eigen::Index> lengths = {300, 301, 302, 303, 304, 305, 306, 307};
  std::vector<ComplexVector> expected;
  for (auto n : lengths) expected.push_back(directDft(randomVector(n, static_cast<std::uint64_t>(n))));
  std::vector<int> failures(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int rep = 0; rep < 20; ++rep) {
        for (std::size_t j = 0; j < lengths.size(); ++j) {
          const Eigen::Index n = lengths[(j + static_cast<std::size_t>(t)) % lengths.size()];
          auto fft = RealFft::forLength(n);
          if (!fft.ok()) {
            ++failures[static_cast<std::size_t>(t)];
            continue;
          }
          auto X = (*fft)->transform(randomVector(n, static_cast<std::uint64_t>(n)));
          const auto& ref = expected[(j + static_cast<std::size_t>(t)) % lengths.size()];
          if (!X.ok() || (*X - ref).cwiseAbs().maxCoeff() > 1e-9) ++failures[static_cast<std::size_t>(t)];
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) EXPECT_EQ(failures[static_cast<std::size_t>(t)], 0) << "thread " << t;
}

}  // namespace
}  // namespace mozzi::core::signal
