#pragma once
// Nonlinear refinement of a modal model against the measured FRFs: the
// frequency and damping of every mode are fitted in least squares together
// with the complex residues and the lower/upper residual terms of every FRF.
// Variable projection (varpro.h): for each trial of the poles the residues and
// residual terms are the LSFD least-squares solution, eliminated exactly, and
// Levenberg-Marquardt moves the poles with the exact gradient of the
// projected functional and Kaufman's approximation J_K^T J_K of its
// Gauss-Newton matrix (Kaufman, BIT 15, 1975: the Golub-Pereyra term dropped;
// Ruhe and Wedin, SIAM Rev. 22, 1980: the same asymptotic rate; on the
// benchmark sets and the tests' six-mode system the same iterations and the
// same results to the printed digits), evaluated analytically: per
// evaluation the LSFD's pass over the data (Q^T Y, 2 nm + 4 columns) and
// one of 2 nm columns (Y X^T on the modes' rows; E^T Y had 4 nm), no numeric
// differences. The last step, when the observed linear rate predicts
// convergence, is evaluated without the second pass (varpro.h, Derivatives).
// Residual: H - H_model over the band's lines (or the lines carrying the
// modes, below), every response and reference.
// Standard errors: Cov(f, zeta) = s^2 (J_K^T J_K)^-1 with Kaufman's Jacobian
// J_K at the solution (J_K^T J_K is the Schur complement of the full
// problem's Gauss-Newton matrix on the nonlinear block, so the uncertainty of
// the residues and residual terms is accounted for), s^2 = SSR / (N - P), N
// real residuals, P every real parameter (nonlinear and linear).
//
// Lines carrying the modes: when the band holds more than `maxLines` lines,
// the poles are fitted on the lines within a few half-power half-widths
// (zeta f) of each mode, 3 to 8 as the budget allows (3 hold 98.6% of the
// information on an isolated mode's frequency and damping: the integral of
// |dH/d sigma|^2), plus blocks of 16 lines spread evenly over the rest of
// the band, within `maxLines` unless the modes' own windows need more. The
// lines are chosen around the start's poles, then again around the refined
// ones, and the fit repeated on those when they differ (window edges on a
// grid of 16 lines make that rare), so the result does not depend on the
// start beyond the convergence tolerance. The residues and residual terms of the result are then those of an LSFD over
// every line of the band at the refined poles (one LSFD more), and s^2 of
// the standard errors is that LSFD's: the standard errors are those of the
// thinned fit (its J_K^T J_K) on the noise estimate of the whole band
// (refine.cpp says why). RefineResult says how many lines were fitted.

#include <functional>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/lsfd.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

// The band and the residual terms are those of the LSFD that the fit
// eliminates (lsfd.h); the rest steers the iteration.
struct RefineOptions : LsfdOptions {
  int maxIterations = 50;
  // More lines than this in the band: fit on the lines carrying the modes
  // (see above). 0 = every line of the band.
  Eigen::Index maxLines = 0;
  // Called before each iteration with its number and the current relative
  // error; returning false cancels (ErrorCode::Cancelled).
  std::function<bool(int iteration, double relativeError)> progress;
};

struct RefineResult {
  ModalModel model;                    // refined poles, residues and residual terms (over the band)
  ModalModel startModel;               // LSFD at the initial poles on the fitted lines (the first evaluation;
                                       // the band's LSFD when fittedLines == bandLines)
  std::vector<double> frequencyStdHz;  // one standard error per mode [Hz]
  std::vector<double> zetaStd;         // one standard error per mode (zeta; eta's is twice)
  double initialRelativeError = 0.0;   // sqrt(SSR / sum |H|^2) of the fit over its fitted lines, before
  double finalRelativeError = 0.0;     // and after
  int iterations = 0;                  // Levenberg-Marquardt iterations
  int evaluations = 0;                 // evaluations of the projected residual
  Eigen::Index bandLines = 0;          // lines in the band (DC excluded)
  Eigen::Index fittedLines = 0;        // lines the fit used (= bandLines unless thinned)
};

// Errors: no modes, band with too few lines, a step that leaves every trial
// inadmissible, singular J^T J, Cancelled from the progress callback.
Result<RefineResult> refineModalModel(const FrfMatrix& frf, const ModalModel& initial, const RefineOptions& options);

}  // namespace mozzi::core::modal
