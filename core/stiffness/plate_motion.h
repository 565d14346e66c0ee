#pragma once
// Twist axis of a reference plate from out-of-plane displacements (thesis §1.2,
// §1.5): the static twist axis (eq. 3 to 6, least-squares plane with 4 lasers),
// the planar Mozzi axis (eq. 13 to 16, solved directly for any layout, see
// reference/notes.md on eq. 17) and the static test with a force ramp
// (lateral stiffness by regression, twist arm, k_tw = k_lat a_tw^2, eq. 29 to 32).
//
// Plate coordinates: the reference plate lies in the plane of two in-plane axes
// (u, v); every sensor measures the displacement w normal to the plate.
//   thesis §1.2 and §1.4 (Fig. 3, 5): u = x, v = z, w = y (lasers/accelerometers)
//   thesis §1.5 (Fig. 7):             u = y, v = z, w = x (lateral displacement)
// A small rigid motion of the plate seen out of plane is the plane
//   w(u, v) = w0 + gu u + gv v                                  [m]
// (the loaded plane of eq. 5 with y = w; intersection with w = 0 is eq. 6).
// It is a rotation theta = |g| [rad] about the line w(u, v) = 0 (the twist axis,
// which coincides with the Mozzi axis of eq. 13 when the plate has no in-plane
// motion) plus a translation along w that is zero on that line.

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::stiffness {

// Laser sensor resolution of the Motostiffmeter, 4 um (thesis §1.1).
inline constexpr double kLaserResolution = 4e-6;

// A directed line in the plate plane. Convention (used throughout this module
// and by the decomposition): a rotation `rotation` about `direction` moves a
// point p out of plane by  w = rotation * signedArm(p),
//   signedArm(p) = cross2(p - point, direction) = (p_u - q_u) d_v - (p_v - q_v) d_u.
struct PlateAxis {
  Vector2 point = Vector2::Zero();    // foot of the perpendicular from the reference point [m]
  Vector2 direction = Vector2(0, 1);  // unit vector; normalised so beta is in (-pi/2, pi/2]
  double rotation = 0.0;              // signed rotation about `direction` [rad] (or rad/N per unit load)
  double beta = 0.0;                  // angle from the v (z) axis to the axis, towards u [rad] (§1.7 beta)
  double betaSigma = 0.0;             // standard uncertainty of beta [rad]
  double offsetSigma = 0.0;    // std. uncertainty of the axis position normal to itself at the reference point [m]
  double rotationSigma = 0.0;  // std. uncertainty of `rotation`
  double signedArm(const Vector2& p) const;
  // Point of the axis at in-plane coordinate v (eq. 13 parametrises the Mozzi
  // axis by z_P); an error when the axis is parallel to the u axis.
  Result<Vector2> pointAtV(double v) const;
};

struct PlaneFitOptions {
  // Standard deviation floor of one displacement [m]. Default: the 4 um laser
  // resolution as a uniform quantisation error, 4e-6 / sqrt(12).
  double sigmaFloor = kLaserResolution / 3.4641016151377544;
  // The rotation must exceed this many standard uncertainties, otherwise the
  // loaded and unloaded planes are parallel within the noise (pure translation:
  // the axis is at infinity) and the fit is refused.
  double minRotationSnr = 3.0;
  // Above these the result is returned but flagged low-confidence.
  double maxBetaSigma = 0.0873;          // 5 degrees
  double maxOffsetSigmaRelative = 0.10;  // of the sensor layout size (rms distance from centroid)
};

// Least-squares plane w = w0 + gu u + gv v through the sensor readings.
struct PlaneFit {
  Vector3 coefficients = Vector3::Zero();  // (w0, gu, gv) [m, rad, rad] (or per N)
  Matrix3 covariance = Matrix3::Zero();    // of the coefficients
  double sigma = 0.0;                      // displacement standard deviation used [m]
  double rmsResidual = 0.0;                // [m]; 0 with three sensors
  int redundancy = 0;                      // sensors - 3
  double layoutSize = 0.0;                 // rms distance of the sensors from their centroid [m]
  double evaluate(const Vector2& p) const { return coefficients(0) + coefficients(1) * p(0) + coefficients(2) * p(1); }
};

// Fits the plane; errors: fewer than 3 sensors, size mismatch, non-finite
// values, collinear or coincident sensor points.
Result<PlaneFit> fitPlane(const std::vector<Vector2>& points, const std::vector<double>& w,
                          const PlaneFitOptions& options = {});

// The axis of a fitted plane; `reference` fixes PlateAxis::point and the
// offset uncertainty (use the load point, or the sensor centroid).
struct TwistAxis {
  PlateAxis axis;
  PlaneFit plane;
  bool lowConfidence = false;
  std::string note;  // why the result is low-confidence, empty otherwise
};
Result<TwistAxis> axisFromPlane(const PlaneFit& plane, const Vector2& reference, const PlaneFitOptions& options = {});

// Static twist axis from one loaded reading of 3 or more lasers (eq. 3 to 6,
// least squares with 4 lasers, §1.2). `reference` as above.
Result<TwistAxis> staticTwistAxis(const std::vector<Vector2>& points, const std::vector<double>& displacements,
                                  const Vector2& reference, const PlaneFitOptions& options = {});

// Planar Mozzi axis (§1.5): lateral displacements dx_i of points (y_i, z_i) of
// the plate (u = y, v = z). Eq. 16, dx_i = dx_Q - dtheta_z y_i + dtheta_y z_i, is
// solved directly (least squares with more than three points); the axis is
// eq. 13, x_P = 0, y_P = dx_Q / dtheta_z + dtheta_y / dtheta_z z_P.
struct PlanarMozzi {
  double dxQ = 0.0;      // lateral displacement of the origin Q [m]
  double dThetaY = 0.0;  // [rad]
  double dThetaZ = 0.0;  // [rad]
  TwistAxis twist;       // the same axis in PlateAxis form
};
Result<PlanarMozzi> planarMozziAxis(const std::vector<Vector2>& pointsYZ, const std::vector<double>& dx,
                                    const Vector2& reference, const PlaneFitOptions& options = {});

// Ordinary least-squares line y = intercept + slope x with standard errors.
struct LinearRegression {
  double slope = 0.0, intercept = 0.0;
  double slopeSe = 0.0, interceptSe = 0.0;
  double rSquared = 0.0;
  double residualRms = 0.0;
  int n = 0;
};
Result<LinearRegression> linearRegression(const std::vector<double>& x, const std::vector<double>& y);

// Static test with a slowly varying force (§1.2, §2.1): force samples F_k [N]
// along +w at `loadPoint`, and the lasers' displacements D(k, i) [m] along +w.
struct StaticTestOptions {
  PlaneFitOptions plane;
  // Linearity check: the compliance fitted on the positive and on the negative
  // load branch may differ by at most this fraction, and R^2 must exceed minR2.
  double branchTolerance = 0.10;
  double minR2 = 0.98;
};
struct StaticTwistResult {
  TwistAxis axis;                 // axis of the compliance plane (rotation in rad/N)
  LinearRegression loadPoint;     // load-point displacement [m] against force [N]
  double lateralStiffness = 0.0;  // k_lat = F / x_lat [N/m] (eq. 29, 31)
  double lateralStiffnessSe = 0.0;
  double twistArm = 0.0;  // a_tw = |distance of the load point from the axis| [m]
  double twistArmSigma = 0.0;
  double twistStiffness = 0.0;  // k_tw = k_lat a_tw^2 [Nm/rad] (eq. 30, 32)
  double twistStiffnessSigma = 0.0;
  double positiveBranchStiffness = 0.0;  // 0 when that branch has too few samples
  double negativeBranchStiffness = 0.0;
  bool linear = true;
  bool lowConfidence = false;
  std::string note;
};
Result<StaticTwistResult> staticTwistTest(const std::vector<Vector2>& points, const Vector& force,
                                          const Matrix& displacements, const Vector2& loadPoint,
                                          const StaticTestOptions& options = {});

// Stiffness about the twist axis from one loaded state: k_lat = F / x_lat with
// x_lat the plane's displacement at the load point; zero load is an error.
Result<StaticTwistResult> staticTwistSingleLoad(const std::vector<Vector2>& points,
                                                const std::vector<double>& displacements, double force,
                                                const Vector2& loadPoint, const PlaneFitOptions& options = {});

}  // namespace mozzi::core::stiffness
