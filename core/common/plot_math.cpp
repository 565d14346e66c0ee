#include "core/common/plot_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mozzi::core {

Vector magnitudeDb(const ComplexVectorRef& h, double reference) {
  Vector out(h.size());
  for (Eigen::Index k = 0; k < h.size(); ++k) {
    const double m = std::abs(h[k]) / reference;
    out[k] = m > 0.0 ? std::max(20.0 * std::log10(m), kMagnitudeFloorDb) : kMagnitudeFloorDb;
  }
  return out;
}

Vector phaseDegrees(const ComplexVectorRef& h, bool unwrap) {
  Vector out(h.size());
  double offset = 0.0;
  for (Eigen::Index k = 0; k < h.size(); ++k) {
    const double wrapped = std::arg(h[k]) * 180.0 / M_PI;
    if (unwrap && k > 0) {
      double jump = wrapped + offset - out[k - 1];
      while (jump > 180.0) {
        offset -= 360.0;
        jump -= 360.0;
      }
      while (jump <= -180.0) {
        offset += 360.0;
        jump += 360.0;
      }
    }
    out[k] = wrapped + (unwrap ? offset : 0.0);
  }
  return out;
}

namespace {

// Smallest of 1, 2, 5 x 10^n not below x (x > 0).
double roundStep(double x) {
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * decade >= x * (1.0 - 1e-12)) return m * decade;
  }
  return 10.0 * decade;
}

}  // namespace

AxisRange roundedRange(double lo, double hi, bool logarithmic) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (lo > hi) std::swap(lo, hi);
  if (logarithmic) {
    if (!(lo > 0.0) || !(hi > 0.0)) return {1.0, 10.0};
    double a = std::pow(10.0, std::floor(std::log10(lo)));
    double b = std::pow(10.0, std::ceil(std::log10(hi)));
    if (a == b) b = 10.0 * a;
    return {a, b};
  }
  if (hi - lo <= 1e-300 * std::max(1.0, std::abs(hi))) {
    return {lo - 0.5, hi + 0.5};
  }
  // About five major ticks over the span.
  const double step = roundStep((hi - lo) / 5.0);
  return {std::floor(lo / step) * step, std::ceil(hi / step) * step};
}

DecimatedCurve decimateMinMax(const VectorRef& x, const VectorRef& y, double xLo, double xHi, int columns,
                              bool logarithmicX) {
  DecimatedCurve out;
  const Eigen::Index n = std::min(x.size(), y.size());
  if (n == 0 || columns < 1) return out;
  if (xLo > xHi) std::swap(xLo, xHi);
  // First sample >= xLo and first > xHi; one sample either side is kept.
  const double* xb = x.data();
  Eigen::Index first = std::lower_bound(xb, xb + n, xLo) - xb;
  Eigen::Index last = std::upper_bound(xb, xb + n, xHi) - xb;  // one past
  first = std::max<Eigen::Index>(0, first - 1);
  last = std::min<Eigen::Index>(n, last + 1);
  std::vector<Eigen::Index>& idx = out.index;
  const bool logX = logarithmicX && xLo > 0.0 && xHi > xLo;
  if (last - first <= 2 * static_cast<Eigen::Index>(columns) + 2) {
    for (Eigen::Index k = first; k < last; ++k) {
      if (std::isfinite(y[k])) idx.push_back(k);
    }
  } else {
    const double a = logX ? std::log10(xLo) : xLo;
    const double b = logX ? std::log10(xHi) : xHi;
    const double scale = b > a ? static_cast<double>(columns) / (b - a) : 0.0;
    auto column = [&](double xv) -> long {
      if (xv < xLo) return -1;
      if (xv > xHi) return columns;
      const double u = ((logX ? std::log10(xv) : xv) - a) * scale;
      return std::min<long>(columns - 1, static_cast<long>(u));
    };
    Eigen::Index k = first;
    while (k < last) {
      const long c = column(x[k]);
      Eigen::Index lo = -1, hi = -1;
      Eigen::Index j = k;
      for (; j < last && column(x[j]) == c; ++j) {
        if (!std::isfinite(y[j])) continue;
        if (lo < 0 || y[j] < y[lo]) lo = j;
        if (hi < 0 || y[j] > y[hi]) hi = j;
      }
      if (c < 0 || c >= columns) {
        // Outside the range: only the sample nearest the edge.
        Eigen::Index edge = c < 0 ? j - 1 : k;
        if (std::isfinite(y[edge])) idx.push_back(edge);
      } else if (lo >= 0) {
        idx.push_back(std::min(lo, hi));
        if (hi != lo) idx.push_back(std::max(lo, hi));
      }
      k = j;
    }
  }
  out.x.resize(static_cast<Eigen::Index>(idx.size()));
  out.y.resize(static_cast<Eigen::Index>(idx.size()));
  for (std::size_t q = 0; q < idx.size(); ++q) {
    out.x[static_cast<Eigen::Index>(q)] = x[idx[q]];
    out.y[static_cast<Eigen::Index>(q)] = y[idx[q]];
  }
  return out;
}

Eigen::Index nearestSample(const VectorRef& x, double value) {
  const Eigen::Index n = x.size();
  if (n == 0) return -1;
  const double* xb = x.data();
  const Eigen::Index k = std::lower_bound(xb, xb + n, value) - xb;
  if (k <= 0) return 0;
  if (k >= n) return n - 1;
  return value - x[k - 1] <= x[k] - value ? k - 1 : k;
}

AxisRange dataRange(const VectorRef& x, const VectorRef& y, double xLo, double xHi, bool logarithmicY,
                    double margin) {
  if (xLo > xHi) std::swap(xLo, xHi);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const Eigen::Index n = std::min(x.size(), y.size());
  for (Eigen::Index k = 0; k < n; ++k) {
    if (x[k] < xLo || x[k] > xHi || !std::isfinite(y[k])) continue;
    if (logarithmicY && !(y[k] > 0.0)) continue;
    lo = std::min(lo, y[k]);
    hi = std::max(hi, y[k]);
  }
  if (!(lo <= hi)) return logarithmicY ? AxisRange{1.0, 10.0} : AxisRange{0.0, 1.0};
  if (logarithmicY) {
    const double f = std::pow(hi / lo, margin);
    const double g = f > 1.0 ? f : 1.0 + margin;
    return {lo / g, hi * g};
  }
  const double pad = hi > lo ? margin * (hi - lo) : std::max(0.5, 0.5 * std::abs(hi));
  return {lo - pad, hi + pad};
}

}  // namespace mozzi::core
