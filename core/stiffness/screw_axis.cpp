#include "core/stiffness/screw_axis.h"

#include "core/common/text.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace mozzi::core::stiffness {
namespace {

Matrix3 skew(const Vector3& a) {
  Matrix3 m;
  m << 0, -a(2), a(1), a(2), 0, -a(0), -a(1), a(0), 0;
  return m;
}

// (d_O, w) -> (u, p, h) as one 7-vector for numerical propagation.
Eigen::Matrix<double, 7, 1> screwParams(const Eigen::Matrix<double, 6, 1>& x) {
  const Vector3 d = x.head<3>(), w = x.tail<3>();
  const double w2 = w.squaredNorm();
  Eigen::Matrix<double, 7, 1> y;
  y.head<3>() = w / std::sqrt(w2);
  y.segment<3>(3) = w.cross(d) / w2;
  y(6) = w.dot(d) / w2;
  return y;
}

}  // namespace

double ScrewAxis::distance(const Vector3& q) const {
  return (q - point).cross(direction).norm();
}

AxisEnds axisSegment(const ScrewAxis& axis, const Vector3& centre, double halfLength) {
  const Vector3 p0 = axis.point + axis.direction * (centre - axis.point).dot(axis.direction);
  return {p0 - halfLength * axis.direction, p0 + halfLength * axis.direction};
}

namespace {

// The least-squares rigid twist of m scalar readings b_k = e_k . (d_O + w x p_k)
// (eq. 15; a full 3-D displacement is three readings along x, y, z):
// `at` m x 3 the points p_k, `along` m x 3 the unit directions e_k.
Result<ScrewAxis> fitScrew(const Matrix& at, const Matrix& along, const Vector& b, const ScrewAxisOptions& options,
                           const std::string& rankProblem) {
  const Eigen::Index m = at.rows();
  // Centre at the centroid c and scale lengths by L: d_i = d_c + (w L) x (p_i - c)/L.
  const Vector3 c = at.colwise().mean().transpose();
  double size = std::sqrt((at.rowwise() - c.transpose()).rowwise().squaredNorm().mean());
  if (!(size > 0.0)) return makeError(ErrorCode::InvalidArgument, "all points coincide", "screw axis: points");
  Matrix a = Matrix::Zero(m, 6);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Vector3 r = (at.row(k).transpose() - c) / size;
    const Vector3 e = along.row(k).transpose();
    a.block<1, 3>(k, 0) = e.transpose();
    a.block<1, 3>(k, 3) = -e.transpose() * skew(r);  // e . (w x r) = -e . (r x w)
  }
  Eigen::JacobiSVD<Matrix> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Vector& s = svd.singularValues();
  if (s.size() < 6 || !(s(5) > 1e-8 * s(0)))
    return makeError(ErrorCode::NumericalFailure, rankProblem, "screw axis: points");
  const double cond = s(0) / s(5);
  const Vector xs = svd.solve(b);
  const Vector res = a * xs - b;
  const Eigen::Index red = m - 6;
  double sigma = options.sigmaFloor;
  if (red > 0) sigma = std::max(sigma, std::sqrt(res.squaredNorm() / static_cast<double>(red)));
  const Matrix vs = svd.matrixV() * s.cwiseInverse().asDiagonal();
  const Matrix covScaled = sigma * sigma * vs * vs.transpose();
  // Physical (d_O, w): w = ws / L; d_O = d_c - w x c = d_c + c x w.
  Eigen::Matrix<double, 6, 6> t = Eigen::Matrix<double, 6, 6>::Zero();
  t.block<3, 3>(0, 0) = Matrix3::Identity();
  t.block<3, 3>(0, 3) = skew(c) / size;
  t.block<3, 3>(3, 3) = Matrix3::Identity() / size;
  const Eigen::Matrix<double, 6, 1> x = t * xs;
  const Eigen::Matrix<double, 6, 6> cov = t * covScaled * t.transpose();

  ScrewAxis out;
  out.translation = x.head<3>();
  out.rotation = x.tail<3>();
  out.angle = out.rotation.norm();
  out.covariance = cov;
  out.sigma = sigma;
  out.conditionNumber = cond;
  const Vector3 u0 = out.angle > 0 ? Vector3(out.rotation / out.angle) : Vector3::UnitZ();
  const double angleSigma = std::sqrt(std::max(0.0, (u0.transpose() * cov.block<3, 3>(3, 3) * u0)(0, 0)));
  if (!(out.angle > options.minRotationSnr * angleSigma) || out.angle == 0.0) {
    return makeError(ErrorCode::NumericalFailure,
                     "the rotation (" + formatNumber(out.angle) + " rad) is not resolved above its uncertainty (" +
                         formatNumber(angleSigma) + " rad): pure translation, the screw axis is at infinity",
                     "screw axis");
  }
  const auto y = screwParams(x);
  out.direction = y.head<3>();
  out.point = y.segment<3>(3);
  out.pitch = y(6);
  // Numerical Jacobian of (u, p, h) w.r.t. (d_O, w), central differences.
  Eigen::Matrix<double, 7, 6> jac;
  for (int k = 0; k < 6; ++k) {
    const double scale = k < 3 ? std::max(out.translation.norm(), 1e-12) : out.angle;
    const double hstep = 1e-6 * scale;
    Eigen::Matrix<double, 6, 1> xp = x, xm = x;
    xp(k) += hstep;
    xm(k) -= hstep;
    jac.col(k) = (screwParams(xp) - screwParams(xm)) / (2 * hstep);
  }
  const Eigen::Matrix<double, 7, 7> cy = jac * cov * jac.transpose();
  out.directionSigma = std::sqrt(std::max(0.0, cy.block<3, 3>(0, 0).trace()));
  out.pointSigma = std::sqrt(std::max(0.0, cy.block<3, 3>(3, 3).trace() / 3.0));
  out.pitchSigma = std::sqrt(std::max(0.0, cy(6, 6)));
  if (cond > options.maxCondition) {
    out.lowConfidence = true;
    out.note = "ill-conditioned point layout (condition number " + formatNumber(cond) + ")";
  }
  return out;
}

}  // namespace

Result<ScrewAxis> screwAxis(const Matrix& points, const Matrix& displacements, const ScrewAxisOptions& options) {
  const Eigen::Index n = points.rows();
  if (points.cols() != 3 || displacements.cols() != 3 || displacements.rows() != n) {
    return makeError(ErrorCode::InvalidArgument, "points and displacements must both be n x 3", "screw axis");
  }
  if (n < 3) {
    return makeError(ErrorCode::InvalidArgument, "at least 3 non-collinear points are needed, got " + std::to_string(n),
                     "screw axis");
  }
  if (!points.allFinite() || !displacements.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "non-finite coordinate or displacement", "screw axis");
  }
  Matrix at(3 * n, 3), along(3 * n, 3);
  Vector b(3 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      at.row(3 * i + k) = points.row(i);
      along.row(3 * i + k) = Vector3::Unit(k).transpose();
      b(3 * i + k) = displacements(i, k);
    }
  }
  return fitScrew(at, along, b, options,
                  "the points are collinear (or coincide): the rotation about their common line is unobservable");
}

Result<ScrewAxis> screwAxisFromReadings(const Matrix& points, const Matrix& directions, const Vector& values,
                                        const ScrewAxisOptions& options) {
  const Eigen::Index m = points.rows();
  if (points.cols() != 3 || directions.cols() != 3 || directions.rows() != m || values.size() != m) {
    return makeError(ErrorCode::InvalidArgument, "points and directions must be m x 3 with m values", "screw axis");
  }
  if (m < 6) {
    return makeError(ErrorCode::InvalidArgument,
                     "at least 6 readings are needed for the 6 components of a rigid motion, got " + std::to_string(m),
                     "screw axis");
  }
  if (!points.allFinite() || !directions.allFinite() || !values.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "non-finite point, direction or value", "screw axis");
  }
  Matrix along(m, 3);
  for (Eigen::Index k = 0; k < m; ++k) {
    const double norm = directions.row(k).norm();
    if (!(norm > 0.0)) {
      return makeError(ErrorCode::InvalidArgument, "reading " + std::to_string(k + 1) + " has no direction",
                       "screw axis");
    }
    along.row(k) = directions.row(k) / norm;
  }
  return fitScrew(points, along, values, options,
                  "the readings do not determine the rigid motion: the points are collinear, or the directions "
                  "measured leave a rotation or translation unseen");
}

namespace {

// The common phase that maximises |Re(e^{-i phi} D)|^2 = A cos^2 + B sin^2 +
// 2 C sin cos, with A = |Re D|^2, B = |Im D|^2, C = <Re D, Im D>:
// phi = atan2(2C, A - B) / 2; returns e^{-i phi} D.
template <class M>
M alignPhase(const M& d) {
  // Two declarations: real() and imag() are expressions of different types.
  const auto re = d.real();
  const auto im = d.imag();
  const double aa = re.squaredNorm(), bb = im.squaredNorm(), cc = (re.array() * im.array()).sum();
  const double phi = 0.5 * std::atan2(2 * cc, aa - bb);
  return d * std::polar(1.0, -phi);
}

void flagPhase(ScrewAxis& r, double residual, const ScrewAxisOptions& options) {
  r.phaseResidual = residual;
  if (r.phaseResidual > options.maxPhaseResidual) {
    r.lowConfidence = true;
    r.note += std::string(r.note.empty() ? "" : "; ") +
              "displacements are not in phase (|Im|/|Re| = " + formatNumber(r.phaseResidual) +
              "): the screw axis moves during the cycle";
  }
}

}  // namespace

Result<ScrewAxis> screwAxisFromPhasors(const Matrix& points, const ComplexMatrix& phasors,
                                       const ScrewAxisOptions& options) {
  if (!phasors.allFinite()) return makeError(ErrorCode::InvalidArgument, "non-finite phasor", "screw axis");
  const ComplexMatrix rot = alignPhase(phasors);
  const Matrix real = rot.real();
  const double rn = real.norm();
  if (!(rn > 0.0)) return makeError(ErrorCode::NumericalFailure, "all phasors are zero", "screw axis");
  auto r = screwAxis(points, real, options);
  if (r) flagPhase(*r, rot.imag().norm() / rn, options);
  return r;
}

Result<ScrewAxis> screwAxisFromReadingPhasors(const Matrix& points, const Matrix& directions,
                                              const ComplexVector& values, const ScrewAxisOptions& options) {
  if (!values.allFinite()) return makeError(ErrorCode::InvalidArgument, "non-finite phasor", "screw axis");
  const ComplexVector rot = alignPhase(values);
  const Vector real = rot.real();
  const double rn = real.norm();
  if (!(rn > 0.0)) return makeError(ErrorCode::NumericalFailure, "all phasors are zero", "screw axis");
  auto r = screwAxisFromReadings(points, directions, real, options);
  if (r) flagPhase(*r, rot.imag().norm() / rn, options);
  return r;
}

}  // namespace mozzi::core::stiffness
