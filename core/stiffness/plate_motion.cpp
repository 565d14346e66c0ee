#include "core/stiffness/plate_motion.h"

#include "core/common/text.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

double cross2(const Vector2& a, const Vector2& b) {
  return a(0) * b(1) - a(1) * b(0);
}

}  // namespace

double PlateAxis::signedArm(const Vector2& p) const {
  return cross2(p - point, direction);
}

Result<Vector2> PlateAxis::pointAtV(double v) const {
  if (std::abs(direction(1)) < 1e-12) {
    return makeError(ErrorCode::NumericalFailure,
                     "the axis is parallel to the u axis, so it cannot be parametrised by v (eq. 13 divides by "
                     "dtheta_z)",
                     "PlateAxis::pointAtV");
  }
  const double t = (v - point(1)) / direction(1);
  return Vector2(point + t * direction);
}

Result<PlaneFit> fitPlane(const std::vector<Vector2>& points, const std::vector<double>& w,
                          const PlaneFitOptions& options) {
  const auto n = static_cast<Eigen::Index>(points.size());
  if (n < 3) {
    return makeError(ErrorCode::InvalidArgument,
                     "at least 3 sensor points are needed to define the plate plane, got " + std::to_string(n),
                     "twist axis: sensor points");
  }
  if (static_cast<Eigen::Index>(w.size()) != n) {
    return makeError(
        ErrorCode::InvalidArgument,
        std::to_string(points.size()) + " sensor points but " + std::to_string(w.size()) + " displacements",
        "twist axis: displacements");
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!points[i].allFinite() || !std::isfinite(w[i])) {
      return makeError(ErrorCode::InvalidArgument, "non-finite coordinate or displacement",
                       "twist axis: sensor " + std::to_string(i + 1));
    }
  }
  if (!(options.sigmaFloor >= 0.0) || !std::isfinite(options.sigmaFloor)) {
    return makeError(ErrorCode::InvalidArgument, "sensor sigma must be finite and >= 0", "twist axis: options");
  }
  // Centre and scale the layout so the conditioning check is unit-free.
  Vector2 c = Vector2::Zero();
  for (const auto& p : points) c += p;
  c /= static_cast<double>(n);
  double size = 0.0;
  for (const auto& p : points) size += (p - c).squaredNorm();
  size = std::sqrt(size / static_cast<double>(n));
  if (!(size > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "all sensor points coincide", "twist axis: sensor points");
  }
  Matrix a(n, 3);
  Vector b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = (points[i](0) - c(0)) / size;
    a(i, 2) = (points[i](1) - c(1)) / size;
    b(i) = w[i];
  }
  Eigen::JacobiSVD<Matrix> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  if (s(2) < 1e-6 * s(0)) {
    return makeError(ErrorCode::NumericalFailure,
                     "sensor points are collinear (or coincide): the plate plane is undetermined (smallest/largest "
                     "singular value " +
                         formatNumber(s(2) / s(0)) + ")",
                     "twist axis: sensor points");
  }
  const Vector xs = svd.solve(b);
  const Vector r = a * xs - b;
  const int redundancy = static_cast<int>(n) - 3;
  double sigma = options.sigmaFloor;
  if (redundancy > 0) sigma = std::max(sigma, std::sqrt(r.squaredNorm() / redundancy));
  // Cov(xs) = sigma^2 V S^-2 V^T
  const Matrix vs = svd.matrixV() * s.cwiseInverse().asDiagonal();
  const Matrix3 covScaled = sigma * sigma * vs * vs.transpose();
  // Back to physical coefficients: w = x0 + x1 (u - cu)/L + x2 (v - cv)/L
  // => gu = x1/L, gv = x2/L, w0 = x0 - gu cu - gv cv (linear map T).
  Matrix3 t;
  t << 1.0, -c(0) / size, -c(1) / size, 0.0, 1.0 / size, 0.0, 0.0, 0.0, 1.0 / size;
  PlaneFit fit;
  fit.coefficients = t * xs;
  fit.covariance = t * covScaled * t.transpose();
  fit.sigma = sigma;
  fit.rmsResidual = std::sqrt(r.squaredNorm() / static_cast<double>(n));
  fit.redundancy = redundancy;
  fit.layoutSize = size;
  return fit;
}

Result<TwistAxis> axisFromPlane(const PlaneFit& plane, const Vector2& reference, const PlaneFitOptions& options) {
  const double w0 = plane.coefficients(0), gu = plane.coefficients(1), gv = plane.coefficients(2);
  const double g2 = gu * gu + gv * gv;
  const double g = std::sqrt(g2);
  // sigma of |g| from the covariance of (gu, gv): J = (gu, gv)/|g|.
  double thetaSigma = 0.0;
  if (g > 0.0) {
    const Vector2 j(gu / g, gv / g);
    thetaSigma = std::sqrt(std::max(0.0, j.dot(plane.covariance.block<2, 2>(1, 1) * j)));
  } else {
    thetaSigma = std::sqrt(std::max(0.0, plane.covariance(1, 1) + plane.covariance(2, 2)));
  }
  if (!(g > options.minRotationSnr * thetaSigma) || g == 0.0) {
    return makeError(ErrorCode::NumericalFailure,
                     "the plate rotation (" + formatNumber(g) + ") is not resolved above its uncertainty (" +
                         formatNumber(thetaSigma) +
                         "): the loaded plane is parallel to the unloaded one within the sensor noise (pure "
                         "translation, displacements at the sensor resolution), so the twist axis is at infinity",
                     "twist axis: plane intersection (eq. 6)");
  }
  // Direction d = (-gv, gu)/|g| so that w = |g| cross2(p - q, d); then
  // normalise beta = atan2(d_u, d_v) into (-pi/2, pi/2] flipping d and theta.
  Vector2 d(-gv / g, gu / g);
  double theta = g;
  double beta = std::atan2(d(0), d(1));
  if (beta <= -kPi / 2 || beta > kPi / 2) {
    d = -d;
    theta = -theta;
    beta = std::atan2(d(0), d(1));
  }
  // Foot of the perpendicular from the reference point: the signed offset
  // e = w(ref)/|g| along the in-plane gradient direction n = g/|g|.
  const double e = (w0 + gu * reference(0) + gv * reference(1)) / g;
  const Vector2 nrm(gu / g, gv / g);
  TwistAxis out;
  out.plane = plane;
  out.axis.point = reference - e * nrm;
  out.axis.direction = d;
  out.axis.rotation = theta;
  out.axis.beta = beta;
  // Propagation (first order). beta = atan2(-gv, gu) up to pi:
  //   d beta/d gu = gv/g^2, d beta/d gv = -gu/g^2.
  // e = (w0 + gu ru + gv rv)/g:
  //   de/dw0 = 1/g, de/dgu = ru/g - e gu/g^2, de/dgv = rv/g - e gv/g^2.
  const Eigen::RowVector3d jb(0.0, gv / g2, -gu / g2);
  const Eigen::RowVector3d je(1.0 / g, reference(0) / g - e * gu / g2, reference(1) / g - e * gv / g2);
  out.axis.betaSigma = std::sqrt(std::max(0.0, (jb * plane.covariance * jb.transpose())(0, 0)));
  out.axis.offsetSigma = std::sqrt(std::max(0.0, (je * plane.covariance * je.transpose())(0, 0)));
  out.axis.rotationSigma = thetaSigma;
  std::string note;
  if (out.axis.betaSigma > options.maxBetaSigma) {
    note += "axis inclination uncertain (sigma " + formatNumber(out.axis.betaSigma * 180.0 / kPi) + " deg); ";
  }
  if (out.axis.offsetSigma > options.maxOffsetSigmaRelative * plane.layoutSize) {
    note += "axis position uncertain (sigma " + formatNumber(out.axis.offsetSigma * 1e3) +
            " mm at the reference point, " + formatNumber(out.axis.offsetSigma / plane.layoutSize) +
            " of the sensor layout size); ";
  }
  if (!note.empty()) {
    out.lowConfidence = true;
    note.resize(note.size() - 2);
    out.note = note;
  }
  return out;
}

Result<TwistAxis> staticTwistAxis(const std::vector<Vector2>& points, const std::vector<double>& displacements,
                                  const Vector2& reference, const PlaneFitOptions& options) {
  MOZZI_TRY_ASSIGN(auto plane, fitPlane(points, displacements, options));
  return axisFromPlane(plane, reference, options);
}

Result<PlanarMozzi> planarMozziAxis(const std::vector<Vector2>& pointsYZ, const std::vector<double>& dx,
                                    const Vector2& reference, const PlaneFitOptions& options) {
  MOZZI_TRY_ASSIGN(auto plane, fitPlane(pointsYZ, dx, options));
  PlanarMozzi m;
  // Eq. 16 with u = y, v = z: dx = dx_Q + (-dtheta_z) y + dtheta_y z.
  m.dxQ = plane.coefficients(0);
  m.dThetaZ = -plane.coefficients(1);
  m.dThetaY = plane.coefficients(2);
  MOZZI_TRY_ASSIGN(m.twist, axisFromPlane(plane, reference, options));
  return m;
}

Result<LinearRegression> linearRegression(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n != y.size()) return makeError(ErrorCode::InvalidArgument, "x and y lengths differ", "linear regression");
  if (n < 3) return makeError(ErrorCode::InvalidArgument, "at least 3 samples are needed", "linear regression");
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      return makeError(ErrorCode::InvalidArgument, "non-finite sample",
                       "linear regression: sample " + std::to_string(i + 1));
    }
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "the regressor does not vary (constant load)", "linear regression");
  }
  LinearRegression r;
  r.n = static_cast<int>(n);
  r.slope = sxy / sxx;
  r.intercept = my - r.slope * mx;
  double rss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = y[i] - r.intercept - r.slope * x[i];
    rss += e * e;
  }
  const double s2 = rss / static_cast<double>(n - 2);
  r.slopeSe = std::sqrt(s2 / sxx);
  r.interceptSe = std::sqrt(s2 * (1.0 / static_cast<double>(n) + mx * mx / sxx));
  r.rSquared = syy > 0.0 ? 1.0 - rss / syy : 1.0;
  r.residualRms = std::sqrt(rss / static_cast<double>(n));
  return r;
}

Result<StaticTwistResult> staticTwistTest(const std::vector<Vector2>& points, const Vector& force,
                                          const Matrix& displacements, const Vector2& loadPoint,
                                          const StaticTestOptions& options) {
  const auto ns = static_cast<Eigen::Index>(points.size());
  const Eigen::Index nk = force.size();
  if (displacements.rows() != nk || displacements.cols() != ns) {
    return makeError(ErrorCode::InvalidArgument,
                     "displacement table is " + std::to_string(displacements.rows()) + " x " +
                         std::to_string(displacements.cols()) + ", expected " + std::to_string(nk) + " samples x " +
                         std::to_string(ns) + " sensors",
                     "static twist test");
  }
  if (nk < 3) {
    return makeError(ErrorCode::InvalidArgument, "at least 3 load samples are needed for the regression",
                     "static twist test: force");
  }
  if (!force.allFinite() || !displacements.allFinite() || !loadPoint.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "non-finite force, displacement or load point", "static twist test");
  }
  const double fmax = force.cwiseAbs().maxCoeff();
  if (!(fmax > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "the load is zero in every sample", "static twist test: force");
  }
  if (!(force.maxCoeff() - force.minCoeff() > 1e-9 * fmax)) {
    return makeError(ErrorCode::InvalidArgument,
                     "the load does not vary, so no stiffness can be regressed (use the single-load form)",
                     "static twist test: force");
  }
  // 1. Per-sensor compliance c_i = d D_i / d F by regression (removes offsets).
  std::vector<double> fv(force.data(), force.data() + nk);
  std::vector<double> compliance(static_cast<std::size_t>(ns));
  double seMax = 0.0;
  for (Eigen::Index i = 0; i < ns; ++i) {
    std::vector<double> di(static_cast<std::size_t>(nk));
    for (Eigen::Index k = 0; k < nk; ++k) di[static_cast<std::size_t>(k)] = displacements(k, i);
    auto reg = linearRegression(fv, di);
    if (!reg)
      return makeError(reg.error().code, reg.error().message, "static twist test: sensor " + std::to_string(i + 1));
    compliance[static_cast<std::size_t>(i)] = reg->slope;
    seMax = std::max(seMax, reg->slopeSe);
  }
  // 2. Compliance plane: the twist axis per unit load (eq. 5, 6 by least squares).
  PlaneFitOptions po = options.plane;
  // A displacement resolution r gives a compliance resolution about r / (F range).
  po.sigmaFloor = std::max(seMax, options.plane.sigmaFloor / (force.maxCoeff() - force.minCoeff()));
  MOZZI_TRY_ASSIGN(const auto plane, fitPlane(points, compliance, po));
  MOZZI_TRY_ASSIGN(auto axis, axisFromPlane(plane, loadPoint, po));
  // 3. Load-point displacement per sample from each sample's plane (linear in the
  // sensor readings), regressed on the force: x_lat = F / k_lat (eq. 29).
  std::vector<double> xl(static_cast<std::size_t>(nk));
  for (Eigen::Index k = 0; k < nk; ++k) {
    std::vector<double> dk(static_cast<std::size_t>(ns));
    for (Eigen::Index i = 0; i < ns; ++i) dk[static_cast<std::size_t>(i)] = displacements(k, i);
    PlaneFitOptions raw = options.plane;
    MOZZI_TRY_ASSIGN(auto pk, fitPlane(points, dk, raw));
    xl[static_cast<std::size_t>(k)] = pk.evaluate(loadPoint);
  }
  MOZZI_TRY_ASSIGN(auto reg, linearRegression(fv, xl));
  StaticTwistResult out;
  out.loadPoint = reg;
  if (!(reg.slope > 0.0)) {
    return makeError(ErrorCode::NumericalFailure,
                     "the load point moves against the force (compliance " + formatNumber(reg.slope) +
                         " m/N): check the sign convention of the lasers and of the load cell",
                     "static twist test: load point");
  }
  if (reg.slope < 3.0 * reg.slopeSe) {
    return makeError(ErrorCode::NumericalFailure,
                     "the load-point displacement is not resolved above the noise (slope " + formatNumber(reg.slope) +
                         " +- " + formatNumber(reg.slopeSe) + " m/N)",
                     "static twist test: load point");
  }
  out.lateralStiffness = 1.0 / reg.slope;
  out.lateralStiffnessSe = reg.slopeSe / (reg.slope * reg.slope);
  out.axis = std::move(axis);
  // a_tw = x_lat / theta: the distance of the load point from the axis.
  const double arm = out.axis.axis.signedArm(loadPoint);
  out.twistArm = std::abs(arm);
  out.twistArmSigma = out.axis.axis.offsetSigma;
  out.twistStiffness = out.lateralStiffness * out.twistArm * out.twistArm;  // k_tw = k_lat a_tw^2, eq. 30/32
  const double relK = out.lateralStiffnessSe / out.lateralStiffness;
  const double relA = out.twistArm > 0 ? out.twistArmSigma / out.twistArm : 0.0;
  out.twistStiffnessSigma = out.twistStiffness * std::sqrt(relK * relK + 4.0 * relA * relA);
  // 4. Linearity: R^2 and agreement of the two load branches (a sign-changing
  // ramp with play in the rig shows different slopes on each side).
  std::string note;
  auto branch = [&](bool positive) -> double {
    std::vector<double> fx, xx;
    for (Eigen::Index k = 0; k < nk; ++k) {
      const double f = fv[static_cast<std::size_t>(k)];
      if ((positive && f > 0) || (!positive && f < 0)) {
        fx.push_back(f);
        xx.push_back(xl[static_cast<std::size_t>(k)]);
      }
    }
    if (fx.size() < 5) return 0.0;
    const double span = *std::max_element(fx.begin(), fx.end()) - *std::min_element(fx.begin(), fx.end());
    if (span < 0.2 * fmax) return 0.0;
    auto r = linearRegression(fx, xx);
    return (r && r->slope > 0.0) ? 1.0 / r->slope : 0.0;
  };
  out.positiveBranchStiffness = branch(true);
  out.negativeBranchStiffness = branch(false);
  if (reg.rSquared < options.minR2) {
    out.linear = false;
    note += "load-displacement not linear (R^2 = " + formatNumber(reg.rSquared) + "); ";
  }
  if (out.positiveBranchStiffness > 0 && out.negativeBranchStiffness > 0) {
    const double rel = std::abs(out.positiveBranchStiffness - out.negativeBranchStiffness) / out.lateralStiffness;
    if (rel > options.branchTolerance) {
      out.linear = false;
      note +=
          "positive and negative load branches differ by " + formatNumber(100 * rel) + "% (play or contact change); ";
    }
  }
  if (out.axis.lowConfidence) note += out.axis.note + "; ";
  if (!note.empty()) {
    out.lowConfidence = true;
    note.resize(note.size() - 2);
    out.note = note;
  }
  return out;
}

Result<StaticTwistResult> staticTwistSingleLoad(const std::vector<Vector2>& points,
                                                const std::vector<double>& displacements, double force,
                                                const Vector2& loadPoint, const PlaneFitOptions& options) {
  if (!std::isfinite(force) || force == 0.0) {
    return makeError(ErrorCode::InvalidArgument, "the load must be finite and non-zero", "static twist: force");
  }
  MOZZI_TRY_ASSIGN(auto axis, staticTwistAxis(points, displacements, loadPoint, options));
  StaticTwistResult out;
  const double xlat = axis.plane.evaluate(loadPoint);
  if (!(xlat / force > 0.0)) {
    return makeError(ErrorCode::NumericalFailure,
                     "the load point moves against the force (x_lat = " + formatNumber(xlat) +
                         " m, F = " + formatNumber(force) + " N): check the sign convention",
                     "static twist: load point");
  }
  out.lateralStiffness = force / xlat;  // eq. 29
  const double arm = axis.axis.signedArm(loadPoint);
  out.twistArm = std::abs(arm);
  out.twistArmSigma = axis.axis.offsetSigma;
  out.twistStiffness = out.lateralStiffness * out.twistArm * out.twistArm;  // eq. 30
  out.twistStiffnessSigma = out.twistArm > 0 ? 2.0 * out.twistStiffness * out.twistArmSigma / out.twistArm : 0.0;
  out.lowConfidence = axis.lowConfidence;
  out.note = axis.note;
  out.axis = std::move(axis);
  return out;
}

}  // namespace mozzi::core::stiffness
