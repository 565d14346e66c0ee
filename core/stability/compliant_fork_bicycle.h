#pragma once
// The thesis's improved bicycle model (appendix 3, Figure 65, eq. 61-65): the
// benchmark bicycle with a compliant front fork, either
//  - a bending joint: revolute axis perpendicular to the steer axis in the
//    bicycle's plane of symmetry, at distance h_W above the front wheel centre
//    along the fork (parallel to the steer axis), angle beta, spring k_beta,
//    damper c_beta (Figure 65 b, eq. 62-64), or
//  - a torsion joint: revolute axis parallel to the steer axis, angle gamma,
//    spring k_gamma, damper c_gamma (Figure 65 c).
// Only the front wheel F moves with the joint (the Euler equation of the front
// wheel, eq. 61, is the fourth equation before the yaw and lateral force are
// eliminated). The result has the form of eq. 65 with q = [phi, delta, beta].

#include "core/common/result.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/bicycle_model.h"
#include "core/stability/multibody_linearizer.h"

namespace mozzi::core::stability {

struct ForkBending {
  double stiffness = 0.0;  // k_beta [N m/rad]
  double damping = 0.0;    // c_beta [N m s/rad]
  double hW = 0.0;         // distance from the wheel centre up to the bending axis [m]
};

struct ForkTorsion {
  double stiffness = 0.0;   // k_gamma [N m/rad]
  double damping = 0.0;     // c_gamma [N m s/rad]
  double axisOffset = 0.0;  // perpendicular distance of the torsion axis ahead of the steer axis [m];
                            // 0: on the steer axis, as §6.4 assumes by symmetry
};

// Steel fork of thesis §6.5/§6.6: k_beta = 5635 N m/rad, c_beta = 0.8 N m s/rad,
// h_W = 0.21 m (Figure 51).
ForkBending thesisSteelForkBending();
// Steel fork alone, thesis §6.4: k_gamma = 1938 N m/rad (eq. 54), c_gamma = 0.3
// N m s/rad (eq. 55, steel fork), axis on the steer axis.
ForkTorsion thesisSteelForkTorsion();

// Bodies and joints of the benchmark bicycle (rear wheel R, rear frame B, front
// frame H, front wheel F), optionally with one fork joint acting on F.
enum class ForkJoint { None, Bending, Torsion };
Result<VehicleTopology> bicycleTopology(const BenchmarkParameters& p, ForkJoint joint, double jointGeometry);

// The 2x2 benchmark matrices derived from the bodies (independent of the
// Appendix A formulas; the two must agree).
Result<BicycleModel> whippleFromBodies(const BenchmarkParameters& p);

// 3x3 models of eq. 65; C and K hold the joint damper and spring.
Result<BicycleModel> forkBendingModel(const BenchmarkParameters& p, const ForkBending& fork);
Result<BicycleModel> forkTorsionModel(const BenchmarkParameters& p, const ForkTorsion& fork);

}  // namespace mozzi::core::stability
