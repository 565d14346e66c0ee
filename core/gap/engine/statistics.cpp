#include "core/gap/engine/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace mozzi::core::gap {

namespace {

// Regularised lower incomplete gamma P(a, x): series for x < a + 1, Lentz
// continued fraction for Q otherwise (Press et al., Numerical Recipes 3rd ed.,
// §6.2); both converge to double precision within a few hundred terms.
double gammaP(double a, double x) {
  if (x <= 0.0) return 0.0;
  const double logPrefactor = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 1000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    return std::min(1.0, sum * std::exp(logPrefactor));
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::max(0.0, 1.0 - std::exp(logPrefactor) * h);
}

}  // namespace

double chiSquareSurvival(double x, double dof) {
  if (!(dof > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x <= 0.0) return 1.0;
  return 1.0 - gammaP(0.5 * dof, 0.5 * x);
}

double chiSquareQuantile(double p, double dof) {
  if (!(dof > 0.0) || !(p >= 0.0) || !(p < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  if (p == 0.0) return 0.0;
  // Bisection on the CDF in log space: monotone, robust for every dof; 200
  // halvings of [1e-12, 1e4 + 100 dof] reach double precision.
  double lo = 0.0, hi = 1e4 + 100.0 * dof;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (1.0 - chiSquareSurvival(mid, dof) < p) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

double normalTwoSidedP(double z) {
  return std::erfc(std::abs(z) / std::sqrt(2.0));
}

double normalQuantile(double p) {
  if (!(p > 0.0) || !(p < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  // z^2 is chi-square with 1 dof: invert that, then restore the sign.
  const double z = std::sqrt(chiSquareQuantile(std::abs(2.0 * p - 1.0), 1.0));
  return p < 0.5 ? -z : z;
}

double empiricalQuantile(std::vector<double> values, double p) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double h = (static_cast<double>(values.size()) - 1.0) * std::clamp(p, 0.0, 1.0);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

std::vector<bool> holmReject(const std::vector<double>& pValues, double alpha) {
  const std::size_t m = pValues.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pValues[a] < pValues[b]; });
  std::vector<bool> reject(m, false);
  for (std::size_t i = 0; i < m; ++i) {
    // Holm: reject p_(i) while p_(i) <= alpha / (m - i); stop at the first failure.
    if (!(pValues[order[i]] <= alpha / static_cast<double>(m - i))) break;
    reject[order[i]] = true;
  }
  return reject;
}

void applyHolmFlags(GapMetrics& metrics, double alpha) {
  std::map<std::string, std::vector<std::size_t>> byKind;
  for (std::size_t i = 0; i < metrics.entries.size(); ++i) {
    GapEntry& e = metrics.entries[i];
    if (e.z != 0.0 && std::isfinite(e.z)) {
      byKind[e.kind].push_back(i);
    } else if (!std::isfinite(e.z)) {
      e.flagged = false;  // no figure, no finding (issue 17: z = NaN was flagged)
    }
  }
  for (const auto& [kind, rows] : byKind) {
    std::vector<double> p;
    for (std::size_t i : rows) {
      const GapEntry& e = metrics.entries[i];
      // One-sided rows (chi-square excess): P(Z > z); a row better than noise is no gap.
      p.push_back(e.oneSided ? 0.5 * std::erfc(e.z / std::sqrt(2.0)) : normalTwoSidedP(e.z));
    }
    const auto reject = holmReject(p, alpha);
    for (std::size_t j = 0; j < rows.size(); ++j) metrics.entries[rows[j]].flagged = reject[j];
  }
}

}  // namespace mozzi::core::gap
