#pragma once
// Mechanical models of the virtual specimens used by the simulated rigs, with
// the thesis values they reproduce. Modal models are built so that their
// natural frequencies and viscous damping ratios are exactly the tabulated
// ones: with mass-normalised shapes Phi (dofs x modes, invertible),
//   M = Phi^-T Phi^-1,  K = Phi^-T diag(w_r^2) Phi^-1,  C = Phi^-T diag(2 zeta_r w_r) Phi^-1
// so that Phi^T M Phi = I, Phi^T K Phi = diag(w_r^2) (thesis eq. 1, 2) and
// the damping is classical. Static models give the displacement normal to
// the reference plate as a rotation about the twist axis (thesis §1.2, eq. 29-32).

#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/signal/mdof_simulation.h"

namespace mozzi::devices::sim {

struct ModalSpecimen {
  std::string key;                  // "fork-a-without-wheel"
  std::string name;
  std::string source;               // thesis table
  std::vector<double> frequencyHz;  // per mode
  std::vector<double> zeta;         // viscous damping ratio per mode
  core::Matrix shapes;              // dofs x modes, mass-normalised [1/sqrt(kg)]
  std::vector<core::Dof> dofs;      // measurement DOF of each row
  Eigen::Index excitedDof = 0;      // the hammer point (row of `shapes`)

  core::signal::LinearMdof toMdof() const;
};

// Thesis Table 11 (left): fork A (enduro) without wheel, 38.6 Hz 2.2% lateral,
// 41.2 Hz 1.8% longitudinal, 67.1 Hz 3.6% torsional.
ModalSpecimen forkAWithoutWheel();
// Thesis Table 11 (right): fork A with wheel, 22.3 Hz 2.4%, 23.5 Hz 1.4%, 67.2 Hz 5.9%.
ModalSpecimen forkAWithWheel();
// Thesis §2.1: frame A front-constrained modes 26.5 Hz (lateral), 56.8 Hz
// (longitudinal), 77.0 Hz (torsional); damping not tabulated, 2% assumed.
ModalSpecimen frameAFrontConstrainedModal();

core::Result<ModalSpecimen> modalSpecimen(const std::string& key);
std::vector<std::string> modalSpecimenKeys();

// Static behaviour under a lateral force F at the load point (plate coordinates
// (u, v), displacement w normal to the plate): rotation F / (k_lat a_tw) about
// the twist axis, so w(p) = F / (k_lat a_tw) * signedArm(p) and the load point
// (arm a_tw) moves F / k_lat.
struct StaticSpecimen {
  std::string key;
  std::string name;
  std::string source;
  double lateralStiffness = 0.0;    // k_lat [N/m]
  double twistArm = 0.0;            // a_tw [m]
  core::Vector2 loadPoint = core::Vector2::Zero();   // (u, v) [m]
  core::Vector2 axisDirection = core::Vector2(0, 1); // unit, in the plate plane
  std::vector<core::Vector2> laserPoints;            // four lasers (u, v) [m]

  double displacementAt(const core::Vector2& p, double forceN) const;  // [m]
};

// Thesis Table 3: frame A front-constrained, 167 kN/m, twist arm 0.551 m
// (rotational stiffness 50.8 kNm/rad = 167e3 x 0.551^2).
StaticSpecimen frameAFrontConstrainedStatic();
core::Result<StaticSpecimen> staticSpecimen(const std::string& key);
std::vector<std::string> staticSpecimenKeys();

}  // namespace mozzi::devices::sim
