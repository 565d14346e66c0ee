#pragma once
// Decomposition of the stiffness about the static twist axis into bending and
// torsion stiffness (thesis §1.7, eq. 22 to 27) and the fork variant with the
// torsion axis along the stems (thesis §4, eq. 33 to 36).
//
// With A = theta_bend / F = a_bend / k_bend and B = theta_tors / F = a_tors / k_tors
// (eq. 23), eq. 24 and eq. 27 are linear in (A, B):
//   a_bend A + a_tors B = a_tw^2 / k_tw                            (eq. 24)
//   A sin(beta_bend - beta) + B sin(beta_tors - beta) = 0            (eq. 27)
// (eq. 27 cross-multiplied), so k_bend = a_bend / A, k_tors = a_tors / B. Arms
// are signed (PlateAxis::signedArm) when the axes are directed; with the
// thesis's positive arms all three rotations are taken in the same sense.
// The magnitude part of eq. 25/26, which eq. 27 drops, is kept as a check:
//   A cos(beta_bend - beta) + B cos(beta_tors - beta) = a_tw / k_tw.

#include <string>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/stiffness/plate_motion.h"

namespace mozzi::core::stiffness {

struct DecompositionInput {
  double twistStiffness = 0.0;  // k_tw [Nm/rad]
  double twistArm = 0.0;        // a_tw [m]
  double twistBeta = 0.0;       // beta: angle from the z axis to the static twist axis [rad]
  double bendArm = 0.0;         // a_bend [m]
  double bendBeta = 0.0;        // beta_bend: bending modal twist axis [rad]
  double torsArm = 0.0;         // a_tors [m]
  double torsBeta = 0.0;        // beta_tors: torsion modal twist axis [rad]
};

struct Decomposition {
  double bendStiffness = 0.0;         // k_bend [Nm/rad]
  double torsStiffness = 0.0;         // k_tors [Nm/rad]
  double bendCompliancePerArm = 0.0;  // A = a_bend / k_bend [rad/(N m)... per unit force: rad/N]
  double torsCompliancePerArm = 0.0;  // B
  // eq. 24: a_tw^2/k_tw - (a_bend^2/k_bend + a_tors^2/k_tors), relative to a_tw^2/k_tw (0 by construction)
  double balanceResidual = 0.0;
  // Rotation magnitude check (eq. 25/26 without the ratio): relative residual.
  double rotationResidual = 0.0;
  double determinant = 0.0;  // of the 2x2 system, in m (a_bend sin(bt - b) - a_tors sin(bb - b))
  bool lowConfidence = false;
  std::string note;
};

// Errors: non-positive k_tw or zero arms, a singular system (bending and torsion
// axes parallel, or the static axis parallel to one of them so the other is
// not identifiable), or a non-physical (negative) stiffness.
Result<Decomposition> decomposeStiffness(const DecompositionInput& in);

// Same from directed axes in the plate plane (PlateAxis) and the load point;
// arms are signed, betas are the axes' betas with the directions kept.
Result<Decomposition> decomposeStiffness(double twistStiffness, const PlateAxis& twist, const PlateAxis& bend,
                                         const PlateAxis& tors, const Vector2& loadPoint);

// Fork variant (§4, eq. 35, 36): torsion axis along the stems, bending axis
// perpendicular; alpha is the inclination of the twist axis (Table 10, 13) with
//   tan(alpha) = (a_tors k_bend) / (k_tors a_bend)   (eq. 36)
//   a_tw^2 / k_tw = a_tors^2 / k_tors + a_bend^2 / k_bend   (eq. 35)
// => k_bend = (a_bend^2 + a_tors a_bend tan(alpha)) k_tw / a_tw^2,
//    k_tors = k_bend a_tors / (a_bend tan(alpha)).
struct ForkDecompositionInput {
  double twistStiffness = 0.0;  // [Nm/rad]
  double twistArm = 0.0;        // [m]
  double bendArm = 0.0;         // [m]
  double torsArm = 0.0;         // [m]
  double alpha = 0.0;           // [rad], in (0, pi/2)
};
Result<Decomposition> decomposeForkStiffness(const ForkDecompositionInput& in);

}  // namespace mozzi::core::stiffness
