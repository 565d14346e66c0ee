#include "core/common/plot_math.h"

#include <cmath>

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

}  // namespace mozzi::core
