#pragma once
// Modal model of a linear structure and its links to the spatial and response
// models (thesis §1 intro, eq. 1 and 2; Ewins, "Modal testing", ch. 2).
//
// Viscous modal model, receptance [m/N], one conjugate pair per mode r:
//   H_{o,i}(omega) = sum_r [ R_{r,oi} / (i omega - lambda_r) + conj(R_{r,oi}) / (i omega - conj(lambda_r)) ]
//                    + U_{oi} - L_{oi} / omega^2
// lambda_r = -zeta_r omega_r + i omega_r sqrt(1 - zeta_r^2) (upper half plane),
// U = upper residual (modes above the band, stiffness-like, m/N),
// L = lower residual (modes below the band incl. rigid-body, 1/kg: -L/omega^2 is
// the receptance of a mass 1/L). Mobility and accelerance multiply the whole sum
// by (i omega) and (i omega)^2.
//
// Hysteretic modal model (thesis eq. 1): [Phi]^T [M] [Phi] = I,
// [Phi]^T ([K] + i[D]) [Phi] = diag(omega_r^2 (1 + i eta_r)), receptance
// H(omega) = Phi diag(1 / (omega_r^2 (1 + i eta_r) - omega^2)) Phi^T.
// Damping: viscous ratio zeta inside; loss factor eta = 2 zeta where the thesis
// reports it (Tables 6, 8, 18, 19, 20 give eta; 11 and 14 give zeta).

#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/frf_type.h"
#include "core/common/result.h"

namespace mozzi::core::modal {

// lambda = -zeta wn + i wn sqrt(1 - zeta^2) from natural frequency [Hz] and zeta.
Complex poleFromFrequencyDamping(double frequencyHz, double zeta);
// Undamped natural frequency |lambda| / (2 pi) [Hz].
double poleFrequencyHz(Complex pole);
// Viscous damping ratio -Re(lambda) / |lambda|.
double poleZeta(Complex pole);
// Equivalent hysteretic loss factor eta = 2 zeta (thesis §6.4 uses zeta = eta / 2).
inline double lossFactorFromZeta(double zeta) {
  return 2.0 * zeta;
}
inline double zetaFromLossFactor(double eta) {
  return 0.5 * eta;
}

struct Mode {
  Complex pole;                 // lambda_r [rad/s], Im > 0
  ComplexMatrix residue;        // no x ni receptance residues R_{r,oi} [m/N * rad/s]
  ComplexVector participation;  // ni-vector from the estimator (may be empty)

  double frequencyHz() const { return poleFrequencyHz(pole); }
  double zeta() const { return poleZeta(pole); }
  double eta() const { return lossFactorFromZeta(zeta()); }
};

struct ModalModel {
  std::vector<Dof> responses;   // no
  std::vector<Dof> references;  // ni
  std::vector<Mode> modes;
  ComplexMatrix lowerResidual;  // no x ni, L in -L / omega^2 [1/kg]; empty = none
  ComplexMatrix upperResidual;  // no x ni, U [m/N]; empty = none

  Eigen::Index responseCount() const { return static_cast<Eigen::Index>(responses.size()); }
  Eigen::Index referenceCount() const { return static_cast<Eigen::Index>(references.size()); }

  // Sizes of residues and residual terms agree with the DOF lists, poles are
  // finite, in the upper half plane and stable (Re < 0).
  Result<void> validate() const;
};

// Value of one FRF of the model at angular frequency omega [rad/s], of `type`.
// omega = 0 with a lower residual present is an error in receptance (division).
Complex synthesize(const ModalModel& model, Eigen::Index response, Eigen::Index reference, double omega, FrfType type);

// All FRFs of the model on the given frequency lines [Hz], as a FrfMatrix of `type`.
Result<FrfMatrix> synthesizeFrf(const ModalModel& model, const VectorRef& frequencyHz, FrfType type);

// --- Complete models: spatial (M, C, K) <-> modal <-> response ---------------

// Viscous spatial model -> modal model over all N DOFs (state-space
// eigenproblem, A = [0 I; -M^-1 K, -M^-1 C]). Residue of mode r:
// R_r = psi_r psi_r^T / (psi_r^T (2 lambda_r M + C) psi_r). Only underdamped
// modes are supported (an overdamped real pole is an Unsupported error).
// `dofs` names the N coordinates (responses = references = dofs).
Result<ModalModel> modalFromSpatial(const MatrixRef& m, const MatrixRef& c, const MatrixRef& k,
                                    const std::vector<Dof>& dofs);

struct SpatialModel {
  Matrix m, c, k;  // N x N [kg, N s/m, N/m]
};

// Complete viscous modal model (no = ni = N, all N modes, residues full N x N)
// -> (M, C, K) through the state-space orthogonality with A-normalised vectors:
// M^-1 = sum_r 2 Re(lambda_r R_r), K^-1 = -sum_r 2 Re(R_r / lambda_r),
// C = -M [sum_r 2 Re(lambda_r^2 R_r)] M.
Result<SpatialModel> spatialFromModal(const ModalModel& model);

struct HystereticModalModel {
  Vector omega2;      // omega_r^2 [rad^2/s^2]
  Vector eta;         // loss factors eta_r
  ComplexMatrix phi;  // N x N mass-normalised mode shapes (complex for non-proportional D)
};

// Thesis eq. 1: solve (K + i D) phi = lambda^2 M phi, lambda_r^2 = omega_r^2 (1 + i eta_r),
// scaled so phi^T M phi = I (unconjugated transpose).
Result<HystereticModalModel> hystereticModalFromSpatial(const MatrixRef& m, const MatrixRef& k, const MatrixRef& d);

struct HystereticSpatialModel {
  Matrix m, k, d;  // [kg, N/m, N/m]
};

// Thesis eq. 2 (misprint: its first line must read [Phi]^-T [Phi]^-1 = [M]):
// M = Phi^-T Phi^-1, K + i D = Phi^-T diag(lambda_r^2) Phi^-1.
Result<HystereticSpatialModel> spatialFromHystereticModal(const HystereticModalModel& model);

// Receptance of the hysteretic model: Phi diag(1 / (lambda_r^2 - omega^2)) Phi^T.
ComplexMatrix hystereticReceptance(const HystereticModalModel& model, double omega);

// Receptance of the spatial viscous model: (K - omega^2 M + i omega C)^-1 (thesis eq. 19,
// in the usual sign convention, see reference/notes.md).
ComplexMatrix spatialReceptance(const MatrixRef& m, const MatrixRef& c, const MatrixRef& k, double omega);

}  // namespace mozzi::core::modal
