#include "core/tire/steady_state.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

namespace mozzi::core::tire {

Result<SlopeEstimate> slopeAtOrigin(const VectorRef& x, const VectorRef& y, double halfWindow, int degree) {
  const char* where = "slope at the origin (local regression)";
  if (x.size() != y.size()) return makeError(ErrorCode::InvalidArgument, "angle and value counts differ", where);
  if (degree < 1 || degree > 3)
    return makeError(ErrorCode::InvalidArgument, "polynomial degree must be 1, 2 or 3", where);
  if (!std::isfinite(halfWindow) || halfWindow <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "regression window must be positive", where);
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      return makeError(ErrorCode::InvalidArgument, "angle or value is NaN or infinite",
                       std::string(where) + ", point " + std::to_string(i + 1));
  if (x.size() >= 2) {
    const bool up = x[1] > x[0];
    for (Eigen::Index i = 1; i < x.size(); ++i) {
      if (up ? !(x[i] > x[i - 1]) : !(x[i] < x[i - 1])) {
        std::ostringstream m;
        m << "sweep angle is not strictly monotonic: " << x[i - 1] << " then " << x[i] << " rad";
        return makeError(ErrorCode::InvalidArgument, m.str(), std::string(where) + ", point " + std::to_string(i + 1));
      }
    }
  }
  std::vector<Eigen::Index> use;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (std::abs(x[i]) <= halfWindow) {
      use.push_back(i);
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
  const int n = static_cast<int>(use.size());
  if (n < degree + 2) {
    std::ostringstream m;
    m << n << " points within +-" << halfWindow << " rad of zero; a degree-" << degree << " fit needs " << degree + 2;
    return makeError(ErrorCode::InvalidArgument, m.str(), where);
  }
  // Points only far from zero would make c_1 an extrapolation: require the
  // window's data to start within 10% of the window from zero.
  if (lo > 0.1 * halfWindow || hi < -0.1 * halfWindow)
    return makeError(ErrorCode::InvalidArgument,
                     "the sweep does not reach zero angle: the slope at the origin would be extrapolated", where);
  Matrix X(n, degree + 1);
  Vector b(n);
  for (int r = 0; r < n; ++r) {
    const double xi = x[use[r]];
    double p = 1.0;
    for (int j = 0; j <= degree; ++j, p *= xi) X(r, j) = p;
    b[r] = y[use[r]];
  }
  Eigen::ColPivHouseholderQR<Matrix> qr(X);
  if (qr.rank() < degree + 1) return makeError(ErrorCode::NumericalFailure, "regression matrix is singular", where);
  const Vector c = qr.solve(b);
  const double rss = (X * c - b).squaredNorm();
  const double s2 = n > degree + 1 ? rss / (n - degree - 1) : 0.0;
  const Matrix cov = s2 * (X.transpose() * X).inverse();
  SlopeEstimate e;
  e.slope = c[1];
  e.slopeStdError = std::sqrt(std::max(0.0, cov(1, 1)));
  e.intercept = c[0];
  e.points = n;
  e.degree = degree;
  return e;
}

Result<SweepCharacteristics> characteriseSweep(const SteadyStateSweep& s, double halfWindow, int degree) {
  const char* where = "steady-state sweep (thesis appendix 2)";
  if (s.angle.size() != s.force.size() || s.angle.size() != s.torque.size())
    return makeError(ErrorCode::InvalidArgument, "angle, force and torque counts differ", where);
  if (!std::isfinite(s.verticalLoad) || s.verticalLoad <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "vertical load must be positive (normalised forces divide by it)",
                     where);
  SweepCharacteristics c;
  auto f = slopeAtOrigin(s.angle, s.force, halfWindow, degree);
  if (!f) return makeError(f.error().code, f.error().message, std::string(where) + ", force: " + f.error().where);
  auto t = slopeAtOrigin(s.angle, s.torque, halfWindow, degree);
  if (!t) return makeError(t.error().code, t.error().message, std::string(where) + ", torque: " + t.error().where);
  c.forceSlope = *f;
  c.torqueSlope = *t;
  c.normalisedForce = s.force / s.verticalLoad;    // F/F_z, Fig. 53
  c.normalisedTorque = s.torque / s.verticalLoad;  // M/F_z [m]
  c.normalisedForceSlope = f->slope / s.verticalLoad;
  return c;
}

}  // namespace mozzi::core::tire
