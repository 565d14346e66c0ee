#pragma once
// Magic Formula, Pacejka 2002 style (MF-Tyre 5.2 pure side slip with the
// inflation-pressure terms of MF 6.1), for the steady-state tests of thesis
// appendix 2 and chapter 7: lateral force F_y(alpha, gamma, F_z, p) and
// self-aligning torque M_z(alpha, gamma, F_z, p), fitted with Ceres
// (Levenberg-Marquardt, automatic derivatives) with parameter standard errors
// from the covariance s^2 (J'J)^-1, s^2 = RSS/(n - p_free).
//
// Sign convention: F_y positive for positive alpha (pKy1 > 0, pDy1 > 0); the
// ISO/TYDEX sets with pKy1 < 0 describe the same tyre with alpha mirrored.
// Angles in rad; dfz = (F_z - F_z0)/F_z0, dpi = (p - p0)/p0.
//
// Lateral force (Pacejka, Tyre and Vehicle Dynamics, 2nd ed., §4.3.2):
//   S_Hy = pHy1 + pHy2 dfz + pHy3 gamma
//   S_Vy = F_z (pVy1 + pVy2 dfz + (pVy3 + pVy4 dfz) gamma)
//   alpha_y = alpha + S_Hy
//   C_y = pCy1
//   mu_y = (pDy1 + pDy2 dfz)(1 + ppy3 dpi + ppy4 dpi^2)(1 - pDy3 gamma^2),  D_y = mu_y F_z
//   E_y = (pEy1 + pEy2 dfz)(1 - (pEy3 + pEy4 gamma) sgn(alpha_y))
//   K_ya = pKy1 F_z0 (1 + ppy1 dpi) sin(2 atan(F_z / (pKy2 F_z0 (1 + ppy2 dpi)))) (1 - pKy3 |gamma|)
//   B_y = K_ya/(C_y D_y)
//   F_y = D_y sin(C_y atan(B_y alpha_y - E_y (B_y alpha_y - atan(B_y alpha_y)))) + S_Vy
// Aligning torque (ibid. §4.3.2, pneumatic trail t and residual torque M_zr):
//   S_Ht = qHz1 + qHz2 dfz + (qHz3 + qHz4 dfz) gamma,  alpha_t = alpha + S_Ht
//   B_t = (qBz1 + qBz2 dfz + qBz3 dfz^2)(1 + qBz4 gamma + qBz5 |gamma|),  C_t = qCz1
//   D_t = F_z (R0/F_z0)(qDz1 + qDz2 dfz)(1 + ppz1 dpi)(1 + qDz3 gamma + qDz4 gamma^2)
//   E_t = (qEz1 + qEz2 dfz + qEz3 dfz^2)(1 + (qEz4 + qEz5 gamma)(2/pi) atan(B_t C_t alpha_t))
//   t = D_t cos(C_t atan(B_t alpha_t - E_t (B_t alpha_t - atan(B_t alpha_t)))) cos(alpha)
//   alpha_r = alpha + S_Hy + S_Vy/K_ya,  B_r = qBz9 + qBz10 B_y C_y
//   D_r = F_z R0 (qDz6 + qDz7 dfz + (qDz8 + qDz9 dfz)(1 + ppz2 dpi) gamma)
//   M_zr = D_r cos(atan(B_r alpha_r)) cos(alpha)
//   M_z = -t (F_y - S_Vy) + M_zr

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::tire {

inline constexpr int kMfLateralCount = 22;
inline constexpr int kMfAligningCount = 27;
using MfLateralCoefficients = std::array<double, kMfLateralCount>;
using MfAligningCoefficients = std::array<double, kMfAligningCount>;

// Names in array order: pCy1 pDy1 pDy2 pDy3 pEy1 pEy2 pEy3 pEy4 pKy1 pKy2 pKy3
// pHy1 pHy2 pHy3 pVy1 pVy2 pVy3 pVy4 ppy1 ppy2 ppy3 ppy4.
const std::array<std::string, kMfLateralCount>& mfLateralNames();
// qBz1 qBz2 qBz3 qBz4 qBz5 qBz9 qBz10 qCz1 qDz1 qDz2 qDz3 qDz4 qDz6 qDz7 qDz8
// qDz9 qEz1 qEz2 qEz3 qEz4 qEz5 qHz1 qHz2 qHz3 qHz4 ppz1 ppz2.
const std::array<std::string, kMfAligningCount>& mfAligningNames();

struct MfConstants {
  double nominalLoad = 1500.0;   // F_z0 [N]
  double nominalPressure = 2e5;  // p0 [Pa]
  double unloadedRadius = 0.3;   // R0 [m]
};

// A neutral starting/default set: zero shifts, zero load, camber and pressure
// sensitivities, pCy1 = 1.3, pDy1 = 1, pKy1 = 15, pKy2 = 2, pEy1 = -0.5.
MfLateralCoefficients mfLateralDefaults();
// qBz1 = 10, qCz1 = 1.2, qDz1 = 0.1, qEz1 = -1, qBz9 = 10, the rest zero.
MfAligningCoefficients mfAligningDefaults();

double mfLateralForce(const MfLateralCoefficients& p, const MfConstants& c, double alpha, double gamma, double load,
                      double pressure);
double mfAligningTorque(const MfAligningCoefficients& q, const MfLateralCoefficients& p, const MfConstants& c,
                        double alpha, double gamma, double load, double pressure);

struct SteadyStatePoint {
  double slip = 0.0;      // alpha [rad]
  double camber = 0.0;    // gamma [rad]
  double load = 0.0;      // F_z [N]
  double pressure = 0.0;  // [Pa]
  double force = 0.0;     // F_y [N]
  double torque = 0.0;    // M_z [N m]
};

struct MfFitOptions {
  std::set<std::string> fixed;  // names held at their start value
  // Also hold the parameters the data cannot determine: pressure terms with
  // one pressure, load terms with one load (quadratic ones with fewer than
  // three), camber terms with one camber, sgn/abs terms with one-sided data.
  bool autoFix = true;
  int maxIterations = 200;
};

template <std::size_t N>
struct MfFit {
  std::array<double, N> value{};
  std::array<double, N> stdError{};  // 0 for held parameters
  std::array<bool, N> free{};
  std::vector<std::string> heldByData;  // names auto-fixed, for the report
  double rmsResidual = 0.0;             // sqrt(RSS/n) [N] or [N m]
  int observations = 0;
  int freeParameters = 0;
  int iterations = 0;
};
using MfLateralFit = MfFit<kMfLateralCount>;
using MfAligningFit = MfFit<kMfAligningCount>;

// Errors: fewer points than free parameters + 1, a non-positive load or
// pressure, NaN, an unknown name in `fixed`, no convergence, a singular
// covariance (parameters the data cannot separate: hold some).
Result<MfLateralFit> fitMfLateral(const std::vector<SteadyStatePoint>& data, const MfConstants& c,
                                  const MfFitOptions& options = {},
                                  std::optional<MfLateralCoefficients> start = std::nullopt);
// The lateral coefficients are held (fit them first).
Result<MfAligningFit> fitMfAligning(const std::vector<SteadyStatePoint>& data, const MfConstants& c,
                                    const MfLateralCoefficients& lateral, const MfFitOptions& options = {},
                                    std::optional<MfAligningCoefficients> start = std::nullopt);

}  // namespace mozzi::core::tire
