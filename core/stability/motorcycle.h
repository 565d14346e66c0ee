#pragma once
// Linear motorcycle model in the structure of R.S. Sharp, "The stability and
// control of motorcycles", J. Mech. Eng. Sci. 13(5):316-329, 1971: rear frame
// (with rider) and front frame joined at the steer axis, lateral, yaw, roll and
// steer freedoms, steering damper, tyre side forces with first-order lag
//   (sigma/u) Y' + Y = C1 alpha + C2 gamma,
// optionally with a front-fork lateral bending freedom represented by the lumped
// fork models of thesis §4.2 (Table 12): a 1-DOF rotation of the wheel and the
// unsprung mass about an axis perpendicular to the steer axis.
// Equations: built from the bodies by multibody_linearizer.h (Kane, linearised),
// with the tyre forces acting at the contact points.

#include <Eigen/LU>
#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/stability/mode_tracking.h"
#include "core/stability/multibody_linearizer.h"

namespace mozzi::core::stability {

// Sharp (1971) notation, SI. Geometry (paper Fig. 1 as transcribed): b = rear
// frame mass centre ahead of the rear contact, h its height; a = perpendicular
// distance from the steer axis of the ground point below the rear frame mass
// centre; e = front frame mass centre ahead of the steer axis (perpendicular);
// f = its distance down the steer axis from the foot of a; t = trail measured
// perpendicular to the steer axis (normal trail); eps = caster angle.
struct SharpParameters {
  double Mf = 0, Mr = 0, Zf = 0;              // masses [kg], front tyre load as tabulated [N]
  double Irx = 0, Irz = 0, Crxz = 0;          // rear frame inertias [kg m^2] (Crxz: x-z product, z down)
  double Ifx = 0, Ifz = 0;                    // front frame inertias normal to / along the steer axis
  double ify = 0, iry = 0;                    // wheel spin inertias (rear includes the engine)
  double a = 0, b = 0, e = 0, f = 0, h = 0;   // geometry [m]
  double Rf = 0, Rr = 0, t = 0, eps = 0;      // wheel radii, trail [m], caster [rad]
  double Cf1 = 0, Cf2 = 0, Cr1 = 0, Cr2 = 0;  // side-slip and camber stiffnesses [N/rad]
  double K = 0;                               // steering damper [N m s/rad]
  double sigma = 0;                           // relaxation length [m]
  double g = 9.81;
  std::string trust;  // the file's note on how far the values can be trusted
};

// Reads the name,value_si,... CSV of shared/data/motorcycle (comment lines
// starting with '#' are kept as the trust note). Errors name the missing or
// malformed parameter and the line.
Result<SharpParameters> loadSharpParameters(const std::string& path);

// The same "standard machine" built in (sharp1971.cpp): the value_si column of
// shared/data/motorcycle/sharp1971-parameters.csv, typed in, so the demo
// project and the report need no file (a test checks the two agree).
SharpParameters sharp1971Parameters();

// Thesis §4.2, Table 12: lumped model of the enduro fork's lateral bending.
struct LumpedForkModel {
  std::string name;
  double stiffness = 0.0;        // k_i [N m/rad]
  double damping = 0.0;          // c_i [N m s/rad]
  double inertia = 0.0;          // J_i, vibrating inertia about the bending axis [kg m^2]
  double mass = 0.0;             // M_i, wheel plus unsprung mass [kg]
  double massArm = 0.0;          // distance from the bending axis down to that mass [m]
  double axisFromContact = 0.0;  // L_i, bending axis distance from the contact point [m] (reported only)
};

// Models 1, 2, 3 of Table 12 (k, c, J, M, L as printed; mass arm 0.405 m for
// models 1 and 3 and 0.405 + 0.846 - 0.670 m for model 2, notes.md).
Result<LumpedForkModel> thesisLumpedForkModel(int model);

class MotorcycleModel {
 public:
  // fork: none for the rigid fork. The vibrating mass is taken out of the front
  // frame (total mass, mass centre and inertia of the front assembly unchanged)
  // and centred on the front wheel axle, bending axis massArm above it along
  // the fork.
  static Result<MotorcycleModel> build(const SharpParameters& p, const std::optional<LumpedForkModel>& fork);

  // x = [phi, delta(, beta), v_lat, r, phi', delta'(, beta'), Y_f, Y_r], u > 0 [m/s].
  Result<Matrix> stateMatrix(double u) const;
  StabilitySystem system() const;
  const std::vector<std::string>& coordinates() const { return coordinates_; }
  double frontLoad() const { return lin_.frontLoad; }  // static front ground force from the geometry [N]

 private:
  SharpParameters p_;
  Linearization lin_;
  Eigen::PartialPivLU<Matrix> massLu_;  // of lin_.Mfull, the same at every speed
  Matrix jointDamping_;                 // N x N on (y, psi, q)
  Matrix jointStiffness_;               // n x n on q
  std::vector<std::string> coordinates_;
};

}  // namespace mozzi::core::stability
