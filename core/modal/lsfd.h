#pragma once
// Least-squares frequency-domain estimation of residues for known poles (LSFD,
// the second step of PolyMAX; Peeters et al. 2004). For each FRF of type T
// (power n of i omega over receptance), linear in the unknowns:
//   H_T(omega) = (i omega)^n [ sum_r R_r/(i omega - lambda_r) + conj(R_r)/(i omega - conj(lambda_r)) + U ]
//                + L (i omega)^(n-2)
// (modal_model.h convention: U upper residual, -L/omega^2 lower residual in
// receptance). All FRFs share the poles, so one QR of the basis serves every
// response and reference column (computed by the variable-projection code of
// varpro.h at fixed poles).

#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

struct LsfdOptions {
  double bandLowHz = 0.0;
  double bandHighHz = 0.0;
  bool lowerResidual = true;
  bool upperResidual = true;
};

// Residues (and residual terms) of every FRF for the given poles (Im > 0,
// Re < 0). Errors: no poles, band with too few lines for the unknowns,
// singular basis (two identical poles).
Result<ModalModel> lsfd(const FrfMatrix& frf, const std::vector<Complex>& poles, const LsfdOptions& options);

// Relative RMS misfit sqrt(sum |H - H_model|^2 / sum |H|^2) over the band.
Result<double> relativeFitError(const FrfMatrix& frf, const ModalModel& model, double bandLowHz, double bandHighHz);

}  // namespace mozzi::core::modal
