#pragma once
// Mechanical models of the virtual specimens used by the simulated rigs, with
// the thesis values they reproduce.
//
// Modal models are spatial: each catalogue specimen lives on the measurement
// mesh of its thesis set-up (core/geometry/mesh_templates.h), and its mode
// shapes over that mesh's DOFs follow the thesis's description of each mode
// (devices/sim/mode_shapes.h: cantilever bending, torsion about the
// component's axis, rigid wheel motion, tyre ring modes). The natural
// frequencies and viscous damping ratios are exactly the tabulated ones.
//
// How the model is simulated. A mesh has more DOFs (up to 96) than the
// specimen has modes (2 to 7, plus 3 out-of-band completion modes), so
// Phi (dofs x modes, mass-normalised, full column rank) is not square and
// M = Phi^-T Phi^-1 does not exist. The model is the reduced one of thesis
// eq. 1-2 in modal coordinates q (x = Phi q):
//   q'' + diag(2 zeta_r w_r) q' + diag(w_r^2) q = Phi^T f,
// so H_ij(w) = sum_r phi_ir phi_jr / (w_r^2 - w^2 + 2 i zeta_r w_r w) (thesis
// eq. 21), symmetric (H_ij = H_ji). A hammer hit at DOF e is simulated exactly
// by core/signal's MDOF integration (mdof_simulation.h) on an equivalent
// square system (drivenSystem): coordinates y = T q with T = [phi_e^T;
// |phi_e| Q^T], Q an orthonormal basis of the complement of phi_e (rows of
// Phi are phi_j^T). Then y_0 = x_e, the hit is a force on y_0 alone
// (T^-T phi_e = e_0), M_y = T^-T T^-1 = I / |phi_e|^2, K_y = T^-T diag(w_r^2)
// T^-1, C_y = T^-T diag(2 zeta_r w_r) T^-1 (the same poles), and the response
// at every mesh DOF is x = Phi T^-1 y, a constant linear map that commutes
// with the anti-aliasing filter and the sampling of hit_synthesis.h. A DOF
// with phi_e = 0 (a node of every mode) gives no response.

#include <complex>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/signal/mdof_simulation.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::sim {

// A DOF of a specimen's mesh as a row of its shapes, with the sign of the
// label ("12:-Y" is the row of 12:+Y with sign -1).
struct DofRow {
  Eigen::Index row = 0;
  double sign = 1.0;
};

// The square system equivalent to the modal model for a force at one DOF
// (see the header comment): force on coordinate 0 only, x = output * y.
struct DrivenSystem {
  core::signal::LinearMdof system;  // modes x modes
  core::Matrix output;              // dofs x modes
  bool excited = true;              // false: the DOF is a node of every mode (no response)
};

struct ModalSpecimen {
  std::string key;  // "fork-a-without-wheel"
  std::string name;
  std::string source;                   // thesis table
  std::string meshTemplate;             // core/geometry mesh template key
  std::vector<double> frequencyHz;      // per mode: the tabulated ones, then the completion modes
  std::vector<double> zeta;             // viscous damping ratio per mode
  std::vector<std::string> modeShapes;  // what each mode does on the mesh
  std::size_t tabulatedModes = 0;       // the first tabulatedModes modes are the thesis's
  core::Matrix shapes;                  // dofs x modes, mass-normalised [1/sqrt(kg)]
  std::vector<core::Dof> dofs;          // measurement DOF of each row (the template's, in order)
  Eigen::Index excitedDof = 0;          // the driving point: the thesis's hammer / static load point (row)

  // The row of a DOF label such as "12:+Y" or "12:-Y"; an unknown or
  // malformed label is an error naming the label and the specimen.
  core::Result<DofRow> findDof(const std::string& label) const;
  core::Result<DofRow> findDof(const core::Dof& dof) const;

  // The model in modal coordinates: M = I, K = diag(w_r^2), C = diag(2 zeta_r w_r).
  core::signal::LinearMdof modalSystem() const;
  // The square system for a force at `drive` (sign -1: a force along the
  // negative direction of that row's DOF).
  DrivenSystem drivenSystem(Eigen::Index drive, double sign = 1.0) const;
  // Receptance H_ij(w) [m/N], sum_r phi_ir phi_jr / (w_r^2 - w^2 + 2 i zeta_r w_r w).
  std::complex<double> receptance(Eigen::Index i, Eigen::Index j, double omega) const;
  // Static compliance between DOFs i and j, sum_r phi_ir phi_jr / w_r^2 [m/N].
  double staticCompliance(Eigen::Index i, Eigen::Index j) const;
};

// The mesh template of a catalogue specimen (core/geometry/mesh_templates.h),
// "" for an unknown key: frames A, B -> motorcycle-frame-20, -26; frame C ->
// motorcycle-frame-22 (with engine: -22-engine-10); swing-arms A, B ->
// swing-arm-6, -18; forks -> motorcycle-fork-10 (with wheel: -10-wheel-8);
// tyres -> tyre-6; bicycles -> bicycle-9-12; bicycle forks -> bicycle-fork-9
// (with wheel: -9-wheel-8).
std::string meshTemplateKey(const std::string& specimenKey);

// The modal model of a catalogue specimen (specimen_catalogue.h) on its mesh
// template: its tabulated frequencies and damping (eta as zeta = eta / 2),
// shapes from mode_shapes.h, and three out-of-band completion modes (2.5, 2.75
// and 3 x the highest tabulated frequency, 5% damping) on the 3-D meshes.
// Modal masses (each shape scaled to a largest component of 1 first): for
// specimens with static data, equal masses chosen so that the static
// compliance at the driving point, sum_r phi_er^2 / w_r^2, is the tabulated
// 1/k_lat (thesis §1: the static compliance is the sum of the modal
// compliances; the driving point is the static load point); for tyres the ring
// masses m_k of eq. 45 (the shapes are then normalised at point 100, as in
// §5.3); otherwise the catalogue's assumed masses.
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
  // The same with the force at plate point q instead of the load point (a
  // set-up that loads elsewhere): each mode's rotation per newton scaled by
  // signedArm_r(q) / arm_r, i.e. theta_r = F signedArm_r(q) / k_r (eq. 23), so
  // w(p)/F(q) = w(q)/F(p) (reciprocity); at q = loadPoint it is receptance(p, f).
  std::complex<double> receptance(const core::Vector2& p, const core::Vector2& q, double frequencyHz) const;
  // Static: F signedArm(q) signedArm(p) / k_tw with k_tw = k_lat a_tw^2 (eq. 29-32).
  double displacementAt(const core::Vector2& p, const core::Vector2& q, double forceN) const;
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
