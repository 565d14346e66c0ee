#pragma once
// Distribution functions and multiple-testing helpers for the gap diagnosis
// (shared/GAP.md steps 1, 2 and 5). Self-contained: no Boost dependency.

#include <vector>

#include "core/gap/gap_problem.h"

namespace mozzi::core::gap {

// Chi-square distribution with `dof` degrees of freedom (dof > 0, may be
// fractional): P(X > x) and the quantile x with P(X <= x) = p.
double chiSquareSurvival(double x, double dof);
double chiSquareQuantile(double p, double dof);

// Standard normal: two-sided p-value of a z-score, and the quantile.
double normalTwoSidedP(double z);
double normalQuantile(double p);

// Empirical quantile (linear interpolation between order statistics, the
// "type 7" definition of Hyndman and Fan 1996) of `values` at probability p.
double empiricalQuantile(std::vector<double> values, double p);

// Holm (1979) step-down correction: flags[i] is true when p-value i is
// rejected at family-wise level alpha.
std::vector<bool> holmReject(const std::vector<double>& pValues, double alpha);

// Flags the rows of `metrics` by Holm's correction over the rows of each kind,
// with normal p-values from their z-scores (one-sided upper tail for rows
// marked oneSided, else two-sided). Rows with z == 0 (no uncertainty
// available) are not tested and keep the flag the problem gave; rows with a
// non-finite z are never flagged. The one rule for "where": the engine applies
// it with the user's alpha to gap_before and every gap_after.
void applyHolmFlags(GapMetrics& metrics, double alpha);

}  // namespace mozzi::core::gap
