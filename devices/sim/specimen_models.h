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
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::sim {

struct ModalSpecimen {
  std::string key;  // "fork-a-without-wheel"
  std::string name;
  std::string source;               // thesis table
  std::vector<double> frequencyHz;  // per mode
  std::vector<double> zeta;         // viscous damping ratio per mode
  core::Matrix shapes;              // dofs x modes, mass-normalised [1/sqrt(kg)]
  std::vector<core::Dof> dofs;      // measurement DOF of each row
  Eigen::Index excitedDof = 0;      // the hammer point (row of `shapes`)

  core::signal::LinearMdof toMdof() const;
  // Static compliance between DOFs i and j, sum_r phi_ir phi_jr / w_r^2 [m/N].
  double staticCompliance(Eigen::Index i, Eigen::Index j) const;
};

// The modal model of a catalogue specimen (specimen_catalogue.h): its
// tabulated frequencies and damping (eta as zeta = eta / 2) on a small mesh of
// max(3, modes) DOFs with generic, well-conditioned shapes (the thesis shows
// its shapes only as figures). DOF 0 is the hammer point and, for specimens
// with static data, the static load point: the modal masses are chosen so
// that the model's static compliance there, sum_r phi_0r^2 / w_r^2, is the
// tabulated 1/k_lat (thesis §1: the static compliance is the sum of the modal
// compliances). Others use the catalogue's modal masses.
core::Result<ModalSpecimen> modalSpecimen(const std::string& key);
std::vector<std::string> modalSpecimenKeys();  // every catalogue key

// Static behaviour under a lateral force F at the load point (plate coordinates
// (u, v), displacement w normal to the plate): rotation F / (k_lat a_tw) about
// the twist axis, so w(p) = F / (k_lat a_tw) * signedArm(p) and the load point
// (arm a_tw) moves F / k_lat.
struct StaticSpecimen {
  std::string key;
  std::string name;
  std::string source;
  double lateralStiffness = 0.0;                      // k_lat [N/m]
  double twistArm = 0.0;                              // a_tw [m]
  core::Vector2 loadPoint = core::Vector2::Zero();    // (u, v) [m]
  core::Vector2 axisDirection = core::Vector2(0, 1);  // unit, in the plate plane
  std::vector<core::Vector2> laserPoints;             // four lasers (u, v) [m]

  double displacementAt(const core::Vector2& p, double forceN) const;  // [m]
  double testForceN = 300.0;                                           // the thesis's ramp amplitude for this specimen
};

// The static model of a catalogue specimen with static data: k_lat and a_tw
// from its table, the twist axis inclined by the tabulated angle (forks,
// Tables 10, 13) or an assumed 30 degrees in the plate plane, load point at the
// plate origin, four lasers on a 200 mm x 150 mm plate around it.
core::Result<StaticSpecimen> staticSpecimen(const std::string& key);

}  // namespace mozzi::devices::sim
