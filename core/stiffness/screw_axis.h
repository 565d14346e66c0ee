#pragma once
// General 3-D Mozzi (instantaneous screw) axis of a small rigid motion (thesis
// §1.5, eq. 10 to 12; closed forms in reference/notes.md): from three or more
// non-collinear points with measured 3-D displacements d_i,
//   d_i = d_O + w x p_i                               (eq. 15, small rotations)
// solved by least squares for the rotation vector w and the displacement d_O of
// the origin; then
//   direction u = w/|w|, point nearest the origin p = (w x d_O)/|w|^2,
//   pitch h = (w . d_O)/|w|^2 [m/rad].

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::stiffness {

struct ScrewAxisOptions {
  double sigmaFloor = 0.0;        // displacement standard deviation floor [m]
  double minRotationSnr = 3.0;    // |w| below this many sigmas: pure translation, refused
  double maxCondition = 1e3;      // condition number of the scaled design above which the result is flagged
  double maxPhaseResidual = 0.1;  // phasor input: |Im| / |Re| after phase alignment above which it is flagged
};

struct ScrewAxis {
  Vector3 rotation = Vector3::Zero();     // w [rad]
  Vector3 translation = Vector3::Zero();  // d_O [m]
  Vector3 direction = Vector3::UnitZ();   // u = w/|w|
  Vector3 point = Vector3::Zero();        // p = (w x d_O)/|w|^2 [m]
  double pitch = 0.0;                     // h = (w . d_O)/|w|^2 [m/rad]
  double angle = 0.0;                     // |w| [rad]
  // First-order standard uncertainties.
  double directionSigma = 0.0;   // angular [rad]
  double pointSigma = 0.0;       // rms over the three coordinates of p [m]
  double pitchSigma = 0.0;       // [m/rad]
  Matrix covariance;             // 6x6 of (d_O, w)
  double sigma = 0.0;            // displacement standard deviation used [m]
  double conditionNumber = 0.0;  // of the centred, length-scaled design matrix
  double phaseResidual = 0.0;    // phasor input only
  bool lowConfidence = false;
  std::string note;
  // Distance of a point from the axis [m].
  double distance(const Vector3& q) const;
};

// The stretch of the axis drawn through a body centred at `centre`: from
// p0 - halfLength u to p0 + halfLength u, p0 the axis point nearest `centre`.
struct AxisEnds {
  Vector3 from = Vector3::Zero();
  Vector3 to = Vector3::Zero();
};
AxisEnds axisSegment(const ScrewAxis& axis, const Vector3& centre, double halfLength);

// points: n x 3 [m]; displacements: n x 3 [m]. Errors: fewer than 3 points,
// shape mismatch, non-finite values, collinear or coincident points (the
// rotation about their line is unobservable), rotation not resolved.
Result<ScrewAxis> screwAxis(const Matrix& points, const Matrix& displacements, const ScrewAxisOptions& options = {});

// Same from complex displacement phasors (triaxial FRFs at one frequency,
// n x 3): the common phase that maximises the real part is removed and the
// real part is used; the remaining imaginary part is reported as phaseResidual.
Result<ScrewAxis> screwAxisFromPhasors(const Matrix& points, const ComplexMatrix& phasors,
                                       const ScrewAxisOptions& options = {});

// The rigid twist fitted to scalar readings, each the displacement of point
// p_k along the unit direction e_k (a mode shape's translational DOFs: one
// accelerometer axis at a node), v_k = e_k . (d_O + w x p_k), eq. 15 projected
// on e_k; least squares over the m >= 6 readings. points, directions: m x 3
// (directions are normalised); values: m. Errors: sizes, non-finite values, a
// zero direction, readings that leave a rotation or translation unseen
// (collinear points, too few directions), rotation not resolved.
Result<ScrewAxis> screwAxisFromReadings(const Matrix& points, const Matrix& directions, const Vector& values,
                                        const ScrewAxisOptions& options = {});

// Same from complex readings (a complex mode shape): the common phase is
// removed as in screwAxisFromPhasors and the rest reported as phaseResidual.
Result<ScrewAxis> screwAxisFromReadingPhasors(const Matrix& points, const Matrix& directions,
                                              const ComplexVector& values, const ScrewAxisOptions& options = {});

}  // namespace mozzi::core::stiffness
