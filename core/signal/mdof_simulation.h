#pragma once
// Time simulation of a linear MDOF system M q'' + C q' + K q = f(t) (thesis
// eq. 18) by exact discretisation of the state equation: with x = [q; q'],
//   x' = A x + B f,  A = [0 I; -M^-1 K  -M^-1 C],  B = [0; M^-1],
// and the force held between samples, the state transition over one step T is
// exact: x_{k+1} = Ad x_k + B0 f_k + B1 f_{k+1} with Ad = exp(A T) and the
// input matrices from the exponential of an augmented matrix (Van Loan 1978):
//   zero-order hold  (force constant on [t_k, t_k+1)):  B0 = int_0^T e^{As} ds B, B1 = 0
//   first-order hold (force linear between samples):     B0 = G0 - G1, B1 = G1,
//     G0 = int_0^T e^{As} ds B, G1 = (1/T) int_0^T e^{A(T-s)} s ds B.
// The first-order hold is exact for piecewise-linear forces and has no half-
// sample delay, so it is the one to use for synthesising sampled measurements.

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::signal {

enum class ForceHold { ZeroOrder, FirstOrder };

struct LinearMdof {
  Matrix mass;       // M [kg] (or kg m^2), n x n, symmetric positive definite
  Matrix damping;    // C [N s/m], n x n
  Matrix stiffness;  // K [N/m], n x n
  Eigen::Index dofCount() const { return mass.rows(); }
};

struct MdofResponse {
  Matrix displacement;  // samples x dofs [m]
  Matrix velocity;      // [m/s]
  Matrix acceleration;  // [m/s^2], M^-1 (f_k - C v_k - K q_k) at each sample
};

// force: samples x dofs [N], sampled at sampleRateHz from t = 0; the system
// starts at rest (or from q0, v0 when given with the right size).
// Errors: shapes, non-finite values, M not positive definite, rate <= 0.
Result<MdofResponse> simulateMdof(const LinearMdof& system, const MatrixRef& force, double sampleRateHz,
                                  ForceHold hold = ForceHold::ZeroOrder, const Vector& q0 = Vector(),
                                  const Vector& v0 = Vector());

}  // namespace mozzi::core::signal
