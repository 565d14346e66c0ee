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

bool equalAspectRanges(AxisRange& x, AxisRange& y, double widthPx, double heightPx) {
  if (!(x.upper >= x.lower) || !(y.upper >= y.lower) || !std::isfinite(x.upper - x.lower) ||
      !std::isfinite(y.upper - y.lower))
    return false;
  if (!(widthPx > 0.0) || !(heightPx > 0.0) || !std::isfinite(widthPx) || !std::isfinite(heightPx)) return false;
  double w = x.upper - x.lower, h = y.upper - y.lower;
  if (w == 0.0 && h == 0.0) w = h = 1.0;
  // Units per pixel: the larger of the two needs, applied to both axes.
  const double perPixel = std::max(w / widthPx, h / heightPx);
  const double cx = 0.5 * (x.lower + x.upper), cy = 0.5 * (y.lower + y.upper);
  x = AxisRange{cx - 0.5 * perPixel * widthPx, cx + 0.5 * perPixel * widthPx};
  y = AxisRange{cy - 0.5 * perPixel * heightPx, cy + 0.5 * perPixel * heightPx};
  return true;
}

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

std::vector<Eigen::Index> pixelColumnStarts(const VectorRef& x, double xLo, double xHi, int columns,
                                            bool logarithmicX) {
  std::vector<Eigen::Index> starts;
  const Eigen::Index n = x.size();
  if (columns < 1) return starts;
  if (xLo > xHi) std::swap(xLo, xHi);
  const bool logX = logarithmicX && xLo > 0.0 && xHi > xLo;
  const double a = logX ? std::log10(xLo) : xLo, b = logX ? std::log10(xHi) : xHi;
  const double* xb = x.data();
  starts.resize(static_cast<std::size_t>(columns) + 1);
  Eigen::Index from = 0;
  for (int c = 0; c < columns; ++c) {
    const double t = a + (b - a) * static_cast<double>(c) / static_cast<double>(columns);
    const double edge = c == 0 ? xLo : (logX ? std::pow(10.0, t) : t);
    from = std::lower_bound(xb + from, xb + n, edge) - xb;
    starts[static_cast<std::size_t>(c)] = from;
  }
  starts[static_cast<std::size_t>(columns)] = std::upper_bound(xb + from, xb + n, xHi) - xb;
  return starts;
}

DecimatedCurve decimateMinMax(const VectorRef& x, const VectorRef& y, const std::vector<Eigen::Index>& starts) {
  DecimatedCurve out;
  const Eigen::Index n = std::min(x.size(), y.size());
  if (n == 0 || starts.size() < 2) return out;
  std::vector<Eigen::Index>& idx = out.index;
  idx.reserve(2 * starts.size() + 2);
  const Eigen::Index first = std::min(starts.front(), n), end = std::min(starts.back(), n);
  // The last sample left of the range, so the line runs to the left edge.
  for (Eigen::Index k = first - 1; k >= 0; --k) {
    if (std::isfinite(y[k])) {
      idx.push_back(k);
      break;
    }
  }
  for (std::size_t c = 0; c + 1 < starts.size(); ++c) {
    const Eigen::Index b = std::min(starts[c], n), e = std::min(starts[c + 1], n);
    Eigen::Index lo = -1, hi = -1;
    for (Eigen::Index j = b; j < e; ++j) {
      const double v = y[j];
      if (!std::isfinite(v)) continue;
      if (lo < 0 || v < y[lo]) lo = j;
      if (hi < 0 || v > y[hi]) hi = j;
    }
    if (lo < 0) continue;
    idx.push_back(std::min(lo, hi));
    if (hi != lo) idx.push_back(std::max(lo, hi));
  }
  for (Eigen::Index k = end; k < n; ++k) {
    if (std::isfinite(y[k])) {
      idx.push_back(k);
      break;
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

DecimatedCurve decimateMinMax(const VectorRef& x, const VectorRef& y, double xLo, double xHi, int columns,
                              bool logarithmicX) {
  return decimateMinMax(x, y, pixelColumnStarts(x, xLo, xHi, columns, logarithmicX));
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

AxisRange dataRange(const VectorRef& x, const VectorRef& y, double xLo, double xHi, bool logarithmicY, double margin,
                    double floor) {
  if (xLo > xHi) std::swap(xLo, xHi);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const Eigen::Index n = std::min(x.size(), y.size());
  for (Eigen::Index k = 0; k < n; ++k) {
    if (x[k] < xLo || x[k] > xHi || !std::isfinite(y[k])) continue;
    if (logarithmicY && !(y[k] > 0.0)) continue;
    if (y[k] <= floor) continue;
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

Rgb heatColour(double v) {
  if (!(v >= 0.0)) v = 0.0;
  if (v > 1.0) v = 1.0;
  // Piecewise linear through white, yellow (255, 230, 90), orange (245, 130, 30),
  // dark red (150, 0, 20) at 0, 1/3, 2/3, 1.
  static const double stops[4][3] = {{255, 255, 255}, {255, 230, 90}, {245, 130, 30}, {150, 0, 20}};
  const double u = v * 3.0;
  const int i = std::min(2, static_cast<int>(u));
  const double t = u - i;
  auto mix = [&](int c) { return static_cast<int>(std::lround(stops[i][c] + t * (stops[i + 1][c] - stops[i][c]))); };
  return {mix(0), mix(1), mix(2)};
}

bool heatColourIsDark(double v) {
  const Rgb c = heatColour(v);
  return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b < 140.0;
}

}  // namespace mozzi::core
