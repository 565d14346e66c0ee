#pragma once
// Hyper-dual numbers a + b e1 + c e2 + d e1e2 with e1^2 = e2^2 = 0: evaluating
// f(x + e1 h1 + e2 h2) gives f, both first derivatives and the mixed second
// derivative exactly (no truncation error), which the stability models need for
// the gravity and ground-contact stiffness (Hessian of the potential energy).
// Fike & Alonso, AIAA 2011-886, "The development of hyper-dual numbers".

#include <cmath>

namespace mozzi::core::stability {

struct HyperDual {
  double a = 0.0;    // value
  double e1 = 0.0;   // d/dx1
  double e2 = 0.0;   // d/dx2
  double e12 = 0.0;  // d2/dx1dx2

  HyperDual() = default;
  HyperDual(double value) : a(value) {}  // NOLINT: implicit from a constant
  HyperDual(double value, double d1, double d2, double d12) : a(value), e1(d1), e2(d2), e12(d12) {}
};

inline HyperDual operator+(const HyperDual& x, const HyperDual& y) {
  return {x.a + y.a, x.e1 + y.e1, x.e2 + y.e2, x.e12 + y.e12};
}
inline HyperDual operator-(const HyperDual& x, const HyperDual& y) {
  return {x.a - y.a, x.e1 - y.e1, x.e2 - y.e2, x.e12 - y.e12};
}
inline HyperDual operator-(const HyperDual& x) {
  return {-x.a, -x.e1, -x.e2, -x.e12};
}
inline HyperDual operator*(const HyperDual& x, const HyperDual& y) {
  return {x.a * y.a, x.a * y.e1 + x.e1 * y.a, x.a * y.e2 + x.e2 * y.a,
          x.a * y.e12 + x.e1 * y.e2 + x.e2 * y.e1 + x.e12 * y.a};
}
// Chain rule for a scalar function with value f0, slope f1 and curvature f2 at x.a.
inline HyperDual applyScalar(const HyperDual& x, double f0, double f1, double f2) {
  return {f0, f1 * x.e1, f1 * x.e2, f1 * x.e12 + f2 * x.e1 * x.e2};
}
inline HyperDual sin(const HyperDual& x) {
  return applyScalar(x, std::sin(x.a), std::cos(x.a), -std::sin(x.a));
}
inline HyperDual cos(const HyperDual& x) {
  return applyScalar(x, std::cos(x.a), -std::sin(x.a), -std::cos(x.a));
}
// sqrt needs x.a > 0; callers evaluate it only near 1 (cosine of a small tilt).
inline HyperDual sqrt(const HyperDual& x) {
  const double s = std::sqrt(x.a);
  return applyScalar(x, s, 0.5 / s, -0.25 / (s * x.a));
}

}  // namespace mozzi::core::stability
