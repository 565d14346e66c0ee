#pragma once
// Linearised bicycle models in the form of Meijaard et al. (2007) eq. (5.1) and
// of the thesis's appendix 3, eq. 65:
//   M q'' + (v C1 + C) q' + (g K0 + v^2 K2 + K) q = 0,
// q = [roll phi, steer delta] (benchmark) or [phi, delta, beta|gamma] (fork
// bending or torsion compliance). C and K are the "true" damping and stiffness
// of the fork joint (zero for the benchmark).

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::stability {

struct BicycleModel {
  Matrix M;                              // mass matrix [kg m^2]
  Matrix C1;                             // velocity-proportional damping-like matrix [kg m]
  Matrix K0;                             // gravity stiffness, multiplied by g [kg m]
  Matrix K2;                             // velocity-squared stiffness [kg]
  Matrix C;                              // structural damping of the compliant joint [N m s/rad]
  Matrix K;                              // structural stiffness of the compliant joint [N m/rad]
  double g = 9.81;                       // gravity [m/s^2]
  std::vector<std::string> coordinates;  // "roll", "steer", "bend", "torsion"

  int size() const { return static_cast<int>(M.rows()); }

  // First-order state matrix A(v) of x = [q; q'], x' = A x.
  Result<Matrix> stateMatrix(double v) const;
  // Eigenvalues of A(v) (2n of them, unsorted), no eigenvectors: the fast path.
  Result<ComplexVector> eigenvalues(double v) const;
};

// Checks sizes, finiteness and that M is symmetric positive definite; the
// error names the offending matrix.
Result<void> validate(const BicycleModel& model);

}  // namespace mozzi::core::stability
