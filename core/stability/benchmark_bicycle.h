#pragma once
// Whipple-Carvallo benchmark bicycle: J.P. Meijaard, J.M. Papadopoulos,
// A. Ruina, A.L. Schwab, "Linearized dynamics equations for the balance and
// steer of a bicycle: a benchmark and review", Proc. R. Soc. A 463 (2007)
// 1955-1982. The 25 parameters of Table 1 and the matrices M, C1, K0, K2 of
// eq. (5.1) built with the formulas of the paper's Appendix A (thesis §6.6 uses
// the same bicycle, "CWBM", as its reference).

#include <string>

#include "core/common/result.h"
#include "core/stability/bicycle_model.h"

namespace mozzi::core::stability {

// Coordinates: x forward, y right, z down, origin at the rear contact point.
// Lengths m, masses kg, inertias kg m^2 about the body's centre of mass.
struct BenchmarkParameters {
  double w = 0, c = 0, lambda = 0, g = 0;     // wheel base, trail, steer axis tilt, gravity
  double rR = 0, mR = 0, IRxx = 0, IRyy = 0;  // rear wheel R
  double xB = 0, zB = 0, mB = 0;              // rear body and frame B
  double IBxx = 0, IBxz = 0, IByy = 0, IBzz = 0;
  double xH = 0, zH = 0, mH = 0;  // front handlebar and fork H
  double IHxx = 0, IHxz = 0, IHyy = 0, IHzz = 0;
  double rF = 0, mF = 0, IFxx = 0, IFyy = 0;  // front wheel F
};

// Table 1 of Meijaard et al. (2007), typed from the paper.
BenchmarkParameters meijaard2007Parameters();

// Reads name,value rows (lines starting with '#' are comments), e.g.
// shared/data/benchmark-bicycle/parameters.csv. Every one of the 25 names and g
// must be present; an error names the first missing or malformed one.
Result<BenchmarkParameters> loadBenchmarkParameters(const std::string& path);

// Physical plausibility: positive masses, radii and wheel base, |lambda| < pi/2,
// wheel radii below the heights, inertia tensors positive definite.
Result<void> validate(const BenchmarkParameters& p);

// M, C1, K0, K2 of eq. (5.1), Meijaard et al. (2007) Appendix A;
// C = K = 0. Coordinates {"roll", "steer"}.
Result<BicycleModel> benchmarkModel(const BenchmarkParameters& p);

}  // namespace mozzi::core::stability
