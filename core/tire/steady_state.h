#pragma once
// Steady-state tyre characteristics from side-slip and camber sweeps (thesis
// appendix 2, §7.1): cornering stiffness dF_y/dalpha, camber stiffness
// dF_y/dgamma, self-aligning torque stiffness dM_z/dalpha and twisting torque
// stiffness dM_z/dgamma, each the slope at the origin of a local polynomial
// regression, and the normalised forces F/F_z [-] and torques M/F_z [m] of
// Figures 53 and 61-64.

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::tire {

// y = sum_{j=0..degree} c_j x^j fitted by least squares to the points with
// |x| <= halfWindow; slope = c_1, its standard error from s^2 (X'X)^-1,
// s^2 = RSS/(n - degree - 1).
struct SlopeEstimate {
  double slope = 0.0;
  double slopeStdError = 0.0;
  double intercept = 0.0;  // c_0: force or torque at zero angle (conicity, ply steer, offset)
  int points = 0;          // n used
  int degree = 0;
};

// Errors: sizes differ, NaN, the angle sequence not strictly monotonic in the
// order given (a sweep), fewer than degree + 2 points in the window, degree
// outside 1..3, a window that does not reach both sides of zero nor start at it.
Result<SlopeEstimate> slopeAtOrigin(const VectorRef& angle, const VectorRef& value, double halfWindow, int degree = 2);

// One steady-state sweep at fixed load, pressure and speed: angle in rad
// (side slip or camber), lateral force F_y [N] and yaw torque M_z [N m].
struct SteadyStateSweep {
  Vector angle;
  Vector force;
  Vector torque;
  double verticalLoad = 0.0;  // F_z [N]
  double pressure = 0.0;      // [Pa], metadata
  double speed = 0.0;         // [m/s], metadata
};

struct SweepCharacteristics {
  SlopeEstimate forceSlope;           // cornering stiffness [N/rad] (slip sweep) or camber stiffness (camber sweep)
  SlopeEstimate torqueSlope;          // aligning torque stiffness [N m/rad] or twisting torque stiffness
  Vector normalisedForce;             // F_y/F_z [-]
  Vector normalisedTorque;            // M_z/F_z [m]
  double normalisedForceSlope = 0.0;  // (dF_y/dangle)/F_z [1/rad]
};

// halfWindow [rad] is the regression window (3 deg by default: inside the
// linear range of §7.1, alpha < 1 deg for normal road use, saturation above 3 deg).
Result<SweepCharacteristics> characteriseSweep(const SteadyStateSweep& sweep, double halfWindow = 0.0523598775598,
                                               int degree = 2);

}  // namespace mozzi::core::tire
