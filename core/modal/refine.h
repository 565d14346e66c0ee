#pragma once
// Nonlinear refinement of a modal model against the measured FRFs with Ceres.
// Variable projection (Golub-Pereyra): Ceres moves the frequency and damping
// of every mode; for each trial the complex residues and the lower/upper
// residual terms are the LSFD least-squares solution (lsfd.h), so all of them
// are refined together. Residual vector: [Re; Im] of (H - H_model) over the
// band's lines, every response and reference, divided by the data RMS.
// Standard errors: Cov(f, zeta) = s^2 (J^T J)^-1 with the final Jacobian J
// of the projected residual (Kaufman; J^T J is the Schur complement of the
// full problem's normal matrix on the nonlinear block, so the linear
// parameters' uncertainty is accounted for), s^2 = SSR / (N - P), P counting
// every real parameter (nonlinear and linear).

#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

struct RefineOptions {
  double bandLowHz = 0.0;
  double bandHighHz = 0.0;
  bool lowerResidual = true;
  bool upperResidual = true;
  int maxIterations = 50;
};

struct RefineResult {
  ModalModel model;                    // refined poles, residues and residual terms
  std::vector<double> frequencyStdHz;  // one standard error per mode [Hz]
  std::vector<double> zetaStd;         // one standard error per mode (zeta; eta's is twice)
  double initialRelativeError = 0.0;   // sqrt(SSR / sum |H|^2) before
  double finalRelativeError = 0.0;     // and after
  int iterations = 0;
};

// Errors: no modes, band with too few lines, Ceres failure, singular J^T J.
Result<RefineResult> refineModalModel(const FrfMatrix& frf, const ModalModel& initial, const RefineOptions& options);

}  // namespace mozzi::core::modal
