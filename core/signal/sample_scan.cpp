#include "core/signal/sample_scan.h"

#include <algorithm>
#include <cstring>

namespace mozzi::core::signal {

namespace {
// Two doubles (one SSE2 register), four of them per accumulator: GCC's and
// Clang's vector extensions, so the compiler emits packed compares and
// selects in independent chains without depending on its auto-vectoriser
// (which kept plain arrays of lanes on the stack).
using Pair = double __attribute__((vector_size(16)));
using PairCount = long long __attribute__((vector_size(16)));
constexpr int kChains = 4;
constexpr Eigen::Index kStep = 2 * kChains;

Pair load(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);  // unaligned load
  return v;
}
}  // namespace

SampleExtremes scanSamples(const double* x, Eigen::Index n) {
  Pair lo[kChains], hi[kChains], poison[kChains];
  const Pair zero{0.0, 0.0};
  for (int k = 0; k < kChains; ++k) {
    lo[k] = hi[k] = Pair{x[0], x[0]};
    poison[k] = zero;
  }
  Eigen::Index i = 0;
  for (; i + kStep <= n; i += kStep) {
    for (int k = 0; k < kChains; ++k) {
      const Pair a = load(x + i + 2 * k);
      // The compare-select the processor's min and max instructions do.
      lo[k] = a < lo[k] ? a : lo[k];
      hi[k] = a > hi[k] ? a : hi[k];
      poison[k] += a * zero;  // 0 for a finite sample, NaN for NaN or an infinity
    }
  }
  SampleExtremes e{x[0], x[0], true};
  double p = 0.0;
  for (int k = 0; k < kChains; ++k) {
    for (int j = 0; j < 2; ++j) {
      e.min = std::min(e.min, lo[k][j]);
      e.max = std::max(e.max, hi[k][j]);
      p += poison[k][j];
    }
  }
  for (; i < n; ++i) {
    e.min = x[i] < e.min ? x[i] : e.min;
    e.max = x[i] > e.max ? x[i] : e.max;
    p += x[i] * 0.0;
  }
  e.finite = p == 0.0;
  return e;
}

ThresholdCounts countBeyond(const double* x, Eigen::Index n, double above, double below) {
  // A packed compare gives -1 where true: subtracted, it counts.
  const Pair up{above, above}, down{below, below};
  PairCount ups[kChains], downs[kChains];
  for (int k = 0; k < kChains; ++k) ups[k] = downs[k] = PairCount{0, 0};
  Eigen::Index i = 0;
  for (; i + kStep <= n; i += kStep) {
    for (int k = 0; k < kChains; ++k) {
      const Pair a = load(x + i + 2 * k);
      ups[k] -= (a >= up);
      downs[k] -= (a <= down);
    }
  }
  ThresholdCounts c;
  for (int k = 0; k < kChains; ++k) {
    c.atOrAbove += ups[k][0] + ups[k][1];
    c.atOrBelow += downs[k][0] + downs[k][1];
  }
  for (; i < n; ++i) {
    c.atOrAbove += x[i] >= above ? 1 : 0;
    c.atOrBelow += x[i] <= below ? 1 : 0;
  }
  return c;
}

}  // namespace mozzi::core::signal
