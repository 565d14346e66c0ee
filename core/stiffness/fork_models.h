#pragma once
// Lumped 1-DOF fork models (thesis §4.2, Table 12) and the torsion and bending
// stiffness and damping of bicycle forks from modal data (thesis §6.4, §6.5).
// Damping: viscous ratio zeta inside (DESIGN); Tables 19/20 give hysteretic
// eta = 2 zeta (§6.4: "half of the hysteretic damping").

#include <string>

#include "core/common/result.h"

namespace mozzi::core::stiffness {

// ---- §4.2: motorcycle fork lumped models --------------------------------
struct ForkLumpedInput {
  double staticBendStiffness = 0.0;  // k from the static test and decomposition [Nm/rad] (Table 10: 28 kNm/rad)
  double staticAxisArm = 0.0;        // L1: static twist axis on the fork axis, from the contact point [m] (0.670)
  double dynamicAxisArm = 0.0;       // L2: modal twist axis on the fork axis, from the contact point [m] (0.846)
  double wheelCentreHeight = 0.0;    // wheel centre from the contact point [m] (0.670 - 0.405 = 0.265)
  double vibratingMass = 0.0;        // wheel + unsprung mass at the wheel centre [kg] (8 + 3)
  double wheelInertia = 0.0;         // wheel diametrical moment of inertia [kg m^2] (0.278)
  double measuredFrequencyHz = 0.0;  // lateral mode with the wheel [Hz] (Table 11: 22.3)
  double zeta = 0.0;                 // viscous damping ratio of that mode (Table 11: 2.4 %)
};
struct LumpedModel {
  double stiffness = 0.0;    // k_i [Nm/rad]
  double arm = 0.0;          // L_i from the contact point [m]
  double inertia = 0.0;      // J_i about the bending axis [kg m^2]
  double pureMoment = 0.0;   // added pure moment of inertia (model 3: J3 - (J_w + M d^2)) [kg m^2]
  double frequencyHz = 0.0;  // f_n = sqrt(k/J) / (2 pi)
  double damping = 0.0;      // c = 2 zeta sqrt(k J) [Nms/rad]
  double zeta = 0.0;
};
struct ForkLumpedModels {
  LumpedModel model1;  // static k at L1, measured inertia at L1 -> f_n computed
  LumpedModel model2;  // measured inertia at L2, k tuned to the measured f_n
  LumpedModel model3;  // static k at L1, inertia tuned to the measured f_n
};
Result<ForkLumpedModels> forkLumpedModels(const ForkLumpedInput& in);

// ---- §6.4, §6.5: bicycle forks ------------------------------------------
struct BicycleForkParameters {
  double forkMass = 0.0;      // m_fork [kg]
  double wheelMass = 0.0;     // m_F [kg]
  double wheelRadius = 0.0;   // r_F [m]
  double hubMass = 0.0;       // fake hub of the fork-alone test [kg]
  double hubRadius = 0.0;     // [m]
  double hubLength = 0.0;     // [m]
  double tipDistance = 0.0;   // d: blade tips to the torsion (steering) axis [m]
  double maxBendArm = 0.460;  // h_W range upper end: the lower jaw fixing point [m] (§6.5)
};

// Inertias about the torsion (steering) axis:
//  with wheel  I = 2 (m_fork/6) d^2 + m_F r_F^2 / 2          (eq. 52, see below)
//  fork alone  I = 2 (m_fork/6) d^2 + m_hub (3 r_hub^2 + l_hub^2) / 12   (eq. 53)
// Eq. 52 prints the wheel term as m_F r_F^2 (ring about its spin axis); the
// steering axis is a diameter of the wheel, whose ring inertia is m_F r_F^2 / 2,
// and only that reproduces the thesis's 1208 and 2901 Nm/rad (validation).
double torsionInertiaWithWheel(const BicycleForkParameters& p);
double torsionInertiaForkAlone(const BicycleForkParameters& p);
// Inertias about the bending axis at distance h from the blade tips:
//  with wheel  I = 2 (m_fork/6) h^2 + m_F h^2 + m_F r_F^2 / 2           (eq. 58)
//  fork alone  I = 2 (m_fork/6) h^2 + m_hub h^2 + m_hub (3 r^2 + l^2) / 12
// (eq. 59 prints the hub's own term with 1/2; the cylinder about a diameter is
// 1/12, as in eq. 53, which is what is used here).
double bendInertiaWithWheel(const BicycleForkParameters& p, double h);
double bendInertiaForkAlone(const BicycleForkParameters& p, double h);

// k = (2 pi f)^2 I (eq. 51, 57).
double modalStiffness(double frequencyHz, double inertia);
// Series combination of two close modes (eq. 54): 1 / (1/k1 + 1/k2).
Result<double> seriesStiffness(double k1, double k2);
// c = zeta c_c, c_c = 2 sqrt(k I) (eq. 55, 56, 60); zeta = eta / 2.
Result<double> modalDamping(double stiffness, double inertia, double zeta);

struct BicycleTorsion {
  double inertiaWithWheel = 0.0, inertiaAlone = 0.0;  // [kg m^2]
  double stiffnessWithWheel = 0.0;                    // [Nm/rad]
  double stiffnessAlone = 0.0;                        // [Nm/rad] (series of the modes when two are given)
  double stiffnessAloneMode1 = 0.0, stiffnessAloneMode2 = 0.0;
  double damping = 0.0;  // from the with-wheel data [Nms/rad]
};
// fAlone2Hz <= 0 when the fork alone shows a single torsion mode.
Result<BicycleTorsion> bicycleForkTorsion(const BicycleForkParameters& p, double fWithWheelHz, double etaWithWheel,
                                          double fAloneHz, double fAlone2Hz = 0.0);

struct BicycleBending {
  double bendArm = 0.0;    // h_W where the two stiffness curves meet [m]
  double stiffness = 0.0;  // k_beta at h_W [Nm/rad]
  double inertiaWithWheel = 0.0;
  double damping = 0.0;        // from the with-wheel lateral mode [Nms/rad]
  double crossingAngle = 0.0;  // relative slope difference of the curves at h_W (small: ill-conditioned)
};
// Errors when the curves do not meet inside [0, maxBendArm].
Result<BicycleBending> bicycleForkBending(const BicycleForkParameters& p, double fWithWheelHz, double etaWithWheel,
                                          double fAloneHz);

}  // namespace mozzi::core::stiffness
