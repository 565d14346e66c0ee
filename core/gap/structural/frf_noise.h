#pragma once
// Measurement noise of an FRF taken from the data (issue 16, GAP.md step 0).
//
// Model, per real and imaginary component of line k:
//   sigma_k^2 = s_b (relative^2 |H_k|^2 + floor^2)
// a relative part (calibration, force-level scatter) and an additive floor
// (sensor and converter noise: it dominates near antiresonances and at the low
// end of a hammer test), per FRF, with a scale s_b per band b where the data
// show one (otherwise s_b = 1).
//
// Estimated without a model of the structure: the noise of neighbouring lines
// is independent, the FRF is smooth on the scale of a few lines except at
// lightly damped peaks. A difference of order p (kernel c_j = (-1)^j binom(p, j))
// removes a polynomial of degree p - 1 and leaves, per line,
//   t_k = |sum_j c_j y_{k+j}|^2 / 2  ~  V_k Exp(1),
//   V_k = relative^2 sum_j c_j^2 |H_{k+j}|^2 + floor^2 sum_j c_j^2,
// where the peaks the difference cannot follow are outliers. The fit is robust
// in two stages: least absolute deviations of log t_k - log V_k (a median
// regression: up to half the lines may be outliers) over a grid of
// floor^2 / relative^2, then maximum likelihood on the lines with
// t_k / V_k below the 99% point of Exp(1) (the truncated mean corrected), twice.
// Repeated hits give t_k from their scatter instead (chi-square with 2 (R - 1)
// degrees of freedom per line); the same fit then smooths them.

#include <utility>
#include <vector>

#include "core/common/eigen_types.h"

namespace mozzi::core::gap::structural {

struct FrfNoiseBand {
  Eigen::Index first = 0, last = 0;  // lines [first, last)
  double scale = 1.0;                // s_b (a factor on sigma^2)
  int lines = 0;                     // inlier lines it was fitted on
};

struct FrfNoiseFit {
  bool ok = false;
  double relative = 0.0;  // per component, fraction of |H|
  double floor = 0.0;     // per component, unit of H
  int lines = 0;          // inlier lines of the fit
  int outliers = 0;       // lines left out (peaks the difference cannot follow)
  // Variance of log(sigma^2) from the estimate's own scatter (about 2 / lines
  // for the differences): the uncertainty of the noise level itself.
  double logVariance = 0.0;
  std::vector<FrfNoiseBand> bands;  // every band, scale 1 where the data show no difference

  // sigma of line k (per component) given |H_k|^2.
  double sigma(Eigen::Index k, double mag2) const;
};

// Noise of one FRF from its own lines. `y` is the FRF, or its difference from a
// smooth reference curve (the residual against a nominal model: smaller
// curvature, smaller bias); `mag2` holds |H_k|^2 for the relative part.
// `bandEdges` are line indices 0 = e_0 < e_1 < ... < e_m = n of the bands that
// may get their own scale. Fails (ok = false) with fewer than 16 usable lines.
FrfNoiseFit estimateFrfNoise(const ComplexVector& y, const Vector& mag2, const std::vector<Eigen::Index>& bandEdges,
                             int order = 3);

// The same FRF noise model with only its level refitted (the ratio of floor to
// relative part kept from `shape`): the cheap re-estimate on simulated data
// sets, where the level carries almost all of the estimate's error.
FrfNoiseFit rescaleFrfNoise(const FrfNoiseFit& shape, const ComplexVector& y, const Vector& mag2,
                            const std::vector<Eigen::Index>& bandEdges, int order = 3);

// Noise of the mean of R >= 2 repeated FRFs (hits) of one channel pair: t_k is
// the sample variance of the mean per component (chi-square, 2 (R - 1) dof),
// smoothed by the same relative + floor fit.
FrfNoiseFit replicateFrfNoise(const std::vector<ComplexVector>& hits, const std::vector<Eigen::Index>& bandEdges);

}  // namespace mozzi::core::gap::structural
