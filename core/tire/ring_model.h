#pragma once
// Rigid/flexible ring modal model of a two-wheeled-vehicle tyre (thesis §5.3)
// and the yaw-input ring FRF of appendix 1 (thesis §5.4, Fig. 41).
//
// The belt is a ring of mass m = beltShare * tyre mass (Pacejka's 75% for car
// tyres raised to 80%, §5.3) on the rim through the carcass. Mode k has the
// lateral shape y(phi) = y_0k cos(k phi), normalised at the lowest point
// (point 100): k = 0 lateral, 1 camber, 2 C-shaped, 3 S-shaped.
//   modal mass      m_k = m/(2 pi) int_0^2pi cos^2(k phi) dphi     eq. 45
//                       = m (k = 0), m/2 (k >= 1)
//   modal stiffness C_k = m_k w_k^2   [N/m at the lowest point]     eq. 46
//   damping         c_k = 2 zeta_k sqrt(C_k m_k) = 2 zeta_k C_k/w_k [N s/m]
//                   (eq. 47 as printed, K_k = zeta_k 2 sqrt(C_k w_k), is not
//                   dimensionally consistent: reference/notes.md)
// Because C_1 refers to the lateral displacement of the lowest point, the
// rotational (camber) stiffness is C_xx = C_1 r^2 [N m/rad] and the camber term
// r^2/C_xx of eq. 48 is 1/C_1.

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::tire {

// (1/2pi) int_0^2pi cos^2(k phi) dphi: 1 for k = 0, 1/2 for k >= 1 (eq. 45).
double ringModalMassFactor(int k);

// Conventional names: "lateral", "camber", "C-shaped", "S-shaped", "k=<n>".
std::string ringModeName(int k);

struct RingModeInput {
  int k = 0;  // circumferential wave number, >= 0
  double naturalFrequencyHz = 0.0;
  double dampingRatio = 0.0;  // viscous zeta (not eta)
};

struct RingModelSettings {
  double tyreMass = 0.0;    // measured tyre mass [kg]
  double beltShare = 0.8;   // ring share of the tyre mass (§5.3: 80%)
  double ringRadius = 0.0;  // r [m], for C_xx = C_1 r^2 and C_zz
};

struct RingMode {
  int k = 0;
  std::string name;
  double naturalFrequencyHz = 0.0;
  double dampingRatio = 0.0;
  double modalMass = 0.0;           // m_k [kg], eq. 45
  double modalStiffness = 0.0;      // C_k [N/m], eq. 46
  double dampingCoefficient = 0.0;  // c_k [N s/m], corrected eq. 47
};

struct RingModel {
  double ringMass = 0.0;        // m [kg]
  double ringRadius = 0.0;      // r [m]
  std::vector<RingMode> modes;  // sorted by k, one per k

  const RingMode* mode(int k) const;
  // 1/C_yg = sum_k 1/C_k: the static lateral compliance at the contact point of
  // the modes in series (eq. 48: 1/C_y + r^2/C_xx + 1/C_res) [m/N].
  double staticLateralCompliance() const;
  // G(w) = sum_k 1/(C_k + i w c_k) [m/N]: the Kelvin-Voigt chain (appendix 1,
  // 1/(C_yg + i w K_yg) generalised to one spring-damper per mode).
  Complex lateralCompliance(double omega, bool withDamping) const;
};

// eq. 45 to 47 from identified natural frequencies and damping ratios.
// Errors: tyre mass, share or radius out of range, negative or repeated k,
// frequency not positive, zeta negative or NaN.
Result<RingModel> identifyRingModel(const std::vector<RingModeInput>& modes, const RingModelSettings& settings);

// A ring model from modal stiffnesses already identified (e.g. thesis Table
// 16, N/m) with the mass (for m_k, w_k and c_k) still from eq. 45. Pairs (k, C_k).
struct RingStiffnessInput {
  int k = 0;
  double modalStiffness = 0.0;  // [N/m]
  double dampingRatio = 0.0;
};
Result<RingModel> ringModelFromStiffness(const std::vector<RingStiffnessInput>& modes,
                                         const RingModelSettings& settings);

// ---- appendix 1: lateral force over enforced yaw angle ------------------------
enum class RingFrfVariant {
  Full,        // damping and trail
  NoTrail,     // damping, t_0 = 0
  FirstOrder,  // neither: C(V - i w a)/(V + i w (sigma_c + C/C_yg))
};

struct RingFrfInputs {
  double speed = 5.0 / 3.6;         // V [m/s]
  double halfLength = 0.0;          // a [m]
  double contactRelaxation = 0.0;   // sigma_c = a m [m] (eq. 48, 49)
  double corneringStiffness = 0.0;  // C_bFalpha [N/rad]
  double trail = 0.0;               // t_0 [m], pneumatic trail (M_z = -t_0 F_y)
};

// F_y/psi_a [N/rad], appendix 1:
//   H = (V - i w a) C / ( i w C G(w) + (V - i w a) C t_0/(C_zz + i w K_zz) + V + i w sigma_c )
// with C_zz = C_1 r^2, K_zz = c_1 r^2 (yaw mode = camber mode by axial
// symmetry, §5.4). Errors: V not positive, no camber mode while t_0 != 0,
// negative inputs.
Result<ComplexVector> ringFrf(const RingModel& ring, const RingFrfInputs& in, const VectorRef& omega,
                              RingFrfVariant variant);

// The relaxation length the phase of H implies at each w: eq. (1) of
// relaxation_length.h applied to lag = -arg H. Points whose lag is outside the
// first-order range have valid = false and sigma = 0 (flagged, not NaN).
struct ImpliedRelaxation {
  Vector omega;
  Vector phaseLag;  // [rad]
  Vector sigma;     // [m]
  std::vector<bool> valid;
};
Result<ImpliedRelaxation> impliedRelaxationLength(const RingModel& ring, const RingFrfInputs& in,
                                                  const VectorRef& omega, RingFrfVariant variant);

}  // namespace mozzi::core::tire
