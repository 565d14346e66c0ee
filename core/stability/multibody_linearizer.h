#pragma once
// Linearised equations of a two-wheeled vehicle built from its bodies and
// joints, about straight upright running at constant speed v. Used for the
// models the benchmark formulas do not cover: the thesis's fork bending and
// torsion joints (appendix 3, eq. 61-65) and the motorcycle with tyre forces
// and lumped fork models (§4.2, Sharp 1971).
//
// Method (Kane's equations, linearised): coordinates z = [y_P, psi, q] with y_P
// the lateral position of the rear contact, psi the yaw of the rear frame and
// q = [phi (roll), delta (steer), further joint angles]. To first order every
// body's mass centre moves laterally by V_i z and rotates by W_i z (V_i, W_i
// 3xN), so
//   generalised inertia forces  = Mfull z'' + v Gfull z'
//   Mfull = sum_i m_i V_i^T V_i + W_i^T I_i W_i
//   Gfull = sum_i (J_i / r_i) W_i^T [e_y]x W_i     (wheel spin -v/r_i about +y,
//           thesis eq. 61: d/dt of J (-v/r) axle = (J v / r) e_y x omega)
// The potential energy of gravity, with the rear-frame pitch chi fixed by the
// front wheel touching the ground (a second-order holonomic constraint), gives
//   g K0 = Hess_q V - (dV/dchi / dz_Q/dchi) Hess_q z_Q,
// evaluated exactly with hyper-dual numbers. Contact kinematics (lateral
// displacement, heading and camber rows of each wheel's contact point) give the
// rolling constraints (bicycle) or the tyre slip and force arms (motorcycle).
// Axes: x forward, y right, z down, origin at the rear contact (benchmark
// convention).

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::stability {

// Revolute joint about `axis` (unit) through `point`, angle = q[coordinate];
// coordinate -1 marks the rear-frame pitch joint (second order only).
struct Joint {
  std::string name;
  Vector3 point = Vector3::Zero();
  Vector3 axis = Vector3::UnitX();
  int coordinate = -1;
};

struct Body {
  std::string name;
  double mass = 0.0;                  // [kg]
  Vector3 com = Vector3::Zero();      // mass centre in the reference configuration [m]
  Matrix3 inertia = Matrix3::Zero();  // inertia tensor about the mass centre, x y z axes [kg m^2]
  double spinInertia = 0.0;           // polar inertia of a rolling wheel about its axle (+y) [kg m^2]
  double rollingRadius = 0.0;         // wheel radius (spin rate -v/r) [m]; 0: no spin
  std::vector<int> joints;            // joints from the ground outwards (indices into the joint list)
};

struct VehicleTopology {
  std::vector<Joint> joints;
  std::vector<Body> bodies;
  std::vector<std::string> coordinates;  // names of q, e.g. {"roll", "steer", "bend"}
  int rearWheel = -1;                    // body index of the rear wheel (its contact is y_P)
  int frontWheel = -1;                   // body index of the front wheel (contact Q)
  double g = 9.81;
};

// Contact kinematics of one wheel, rows over z = [y_P, psi, q]:
struct ContactRows {
  Vector lateral;  // first-order lateral displacement of the contact point [m per unit]
  Vector heading;  // heading of the wheel's line of contact (yaw) [rad per unit]
  Vector camber;   // camber (lean of the wheel plane, positive to the right) [rad per unit]
  double x = 0.0;  // forward position of the contact point [m]
};

struct Linearization {
  Matrix Mfull;            // N x N, N = 2 + n
  Matrix Gfull;            // N x N, multiply by v
  Matrix K0;               // n x n gravity stiffness / g on q (includes the ground reaction)
  double frontLoad = 0.0;  // static vertical ground force on the front wheel [N]
  ContactRows rear, front;
  int n = 0;
};

// Checks indices, axes and masses; errors name the body or joint.
Result<Linearization> linearize(const VehicleTopology& topology);

// Whipple-type bicycle: both contacts roll without slip (Meijaard et al. 2007,
// eq. of the front contact: w psi' = v heading_Q - lateral_Q . q'); reduces the
// linearization to M, C1, K0, K2 on q. C, K are set to zero.
struct BicycleModel;
Result<BicycleModel> rollingBicycleModel(const VehicleTopology& topology);

}  // namespace mozzi::core::stability
