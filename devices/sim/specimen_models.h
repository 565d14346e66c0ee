#pragma once
// Mechanical models of the virtual specimens used by the simulated rigs, with
// the thesis values they reproduce. Modal models are built so that their
// natural frequencies and viscous damping ratios are exactly the tabulated
// ones: with mass-normalised shapes Phi (dofs x modes, invertible),
//   M = Phi^-T Phi^-1,  K = Phi^-T diag(w_r^2) Phi^-1,  C = Phi^-T diag(2 zeta_r w_r) Phi^-1
// so that Phi^T M Phi = I, Phi^T K Phi = diag(w_r^2) (thesis eq. 1, 2) and
// the damping is classical. Static models give the displacement normal to
// the reference plate as a rotation about the twist axis (thesis §1.2, eq. 29-32).

#include <complex>
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
// The plate's dynamic response to a sine force at the load point (the
// actuator band 1..45 Hz, thesis §1.3): the static rotation split into
// rotations about a bending and a torsion axis (thesis §1.7, eq. 22 to 27),
// each a single-degree-of-freedom oscillator at the specimen's lateral
// (bending) and torsional mode of the modal tables, so the dynamic twist axis
// starts at the static one and turns towards the bending axis as the
// frequency nears the bending mode (Fig. 29).
struct PlateMode {
  std::string name;                                   // "bending", "torsion", or "lateral" (no axes: whole plate)
  core::Vector2 point = core::Vector2::Zero();        // foot of the axis from the load point [m]
  core::Vector2 direction = core::Vector2(0.0, 1.0);  // unit; PlateAxis convention (plate_motion.h)
  double rotationPerN = 0.0;  // static rotation about the axis per newton at the load point [rad/N]
  double arm = 0.0;           // signed arm of the load point [m]
  double frequencyHz = 0.0;   // natural frequency of the mode [Hz]
  double zeta = 0.0;          // viscous damping ratio
  double stiffness() const { return arm / rotationPerN; }  // k = F a / theta [Nm/rad] (eq. 23)
};

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

  // Bending and torsion axes (both present or both absent), or one "lateral"
  // mode that scales the whole static field when the tables give no arms.
  std::vector<PlateMode> modes;
  bool hasAxes() const { return modes.size() == 2; }
  // Receptance w/F at plate point p and frequency f [m/N]:
  //   sum_r theta_r signedArm_r(p) / (1 - (f/f_r)^2 + 2 i zeta_r f/f_r);
  // at f = 0 it is displacementAt(p, 1).
  std::complex<double> receptance(const core::Vector2& p, double frequencyHz) const;
};

// The static model of a catalogue specimen with static data: k_lat and a_tw
// from its table, the twist axis inclined by the tabulated angle (forks,
// Tables 10, 13) or an assumed 30 degrees in the plate plane, load point at the
// plate origin, four lasers on a 200 mm x 150 mm plate around it.
// Its plate modes: where the table prints bending and torsion arms and
// stiffnesses (Tables 4, 7, 9, 10, 13), theta_b = a_bend / k_bend and
// theta_t = a_tors / k_tors per newton are laid out with the static
// theta_s = 1 / (k_lat a_tw) as a triangle of rotation vectors
// (theta_s = theta_b + theta_t, eq. 25, 26): the torsion axis on the side of
// the v axis (the fork's stems), the bending axis on the other; the torsion
// arm is the printed one and the bending arm closes eq. 22 at the load point
// (the printed arms balance eq. 24 only to 0.1..2%, reference/notes.md), so the
// model's static field is the tabulated twist exactly. Frequencies: the
// "Lateral"/"Bending" and "Torsional"/"Wheel" modes of the modal table. Without
// printed arms (Table 5) one "lateral" mode at the first natural frequency.
core::Result<StaticSpecimen> staticSpecimen(const std::string& key);

}  // namespace mozzi::devices::sim
