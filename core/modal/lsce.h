#pragma once
// Least-squares complex exponential (LSCE; Brown, Allemang, Zimmerman and
// Mergeay, SAE 790221, 1979), polyreference form (Vold et al., SAE 820194,
// 1982): the second multi-mode method of issue 5, a time-domain counterpart
// of pLSCF (plscf.h) with the same stabilization diagram, automatic selection
// and LSFD shapes.
//
// 1. Impulse responses h_o(k) (1 x ni rows, all references) by inverse real
//    FFT of the FRFs from 0 Hz to the band's upper edge f_N: dt = 1/(2 f_N).
//    LSCE needs baseband FRFs: the grid must be even and aligned with 0 Hz;
//    lines missing below the first line (exporters often drop DC) are taken as
//    zero when the first line is at most min(band low, 5% of f_N). A zoom band
//    far from 0 Hz is refused: use pLSCF, which fits any band.
// 2. Every pole z_r = exp(lambda_r dt) of a sum of damped exponentials
//    satisfies the matrix AR (Prony) recurrence of order p:
//      h_o(k) = sum_{j=1}^{p} h_o(k - j) theta_j   (theta_j ni x ni),
//    fitted in least squares over all outputs and samples k of a window. With
//    the regressors ordered by lag, the order-p problem uses the leading
//    columns of the order-pmax one: one Gram matrix and one Cholesky factor
//    give every order (forward substitution is nested, one back substitution
//    per order).
// 3. A(z) = z^p I - sum_j z^{p-j} theta_j; its p ni roots are the poles
//    (stabilization.h), the left null vectors of A(z_r) the participation
//    vectors and N_o(1/z_r) v_r (Prony numerator, right null vector) the
//    shape used by the stability check.
// 4. Automatic selection and LSFD exactly as for pLSCF.

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/plscf.h"

namespace mozzi::core::modal {

struct LsceOptions : PlscfOptions {
  // First impulse-response sample of the fit. Sample 0 holds the impulse of
  // the FRF's high-frequency asymptote (accelerance: mass line) and the first
  // few samples the time aliasing of the band-limited FRF.
  int firstSample = 2;
  // Samples per impulse response in the fit window; 0 chooses the window
  // automatically: up to where the response envelope falls to the noise
  // floor, at most half the period (the second half holds the wrapped
  // non-causal part).
  int sampleCount = 0;
};

// Stabilization diagram of LSCE over the orders of `options`; the poles kept
// are those in the band. Errors: FRFs not on a baseband grid, too few samples
// for the highest order, order range too small, singular normal equations.
// More references than responses: fitted transposed, as plscfStabilization.
Result<StabilizationDiagram> lsceStabilization(const FrfMatrix& frf, const LsceOptions& options);

// Diagram, automatic selection, LSFD over the band (lower and upper residuals).
Result<PlscfResult> identifyLsce(const FrfMatrix& frf, const LsceOptions& options);

}  // namespace mozzi::core::modal
