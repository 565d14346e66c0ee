#pragma once
// Pieces shared by the stabilization diagrams of pLSCF (plscf.h) and LSCE
// (lsce.h): the roots of the monic denominator matrix polynomial of each order
// and the classification of its poles against the previous order.
//
// Both estimators end an order with real coefficients of
//   A(z) = z^m I + sum_{j<m} z^j alpha_j   (alpha_j ni x ni),
// whose m ni roots z_r are the discrete-time poles, lambda_r = ln(z_r) / dt.

#include <functional>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/plscf.h"

namespace mozzi::core::modal {

// Roots of successive orders of A(z). Ehrlich-Aberth iteration on det A(z)
// (Bini and Noferini, Linear Algebra Appl. 439, 2013: the Newton correction is
// 1 / tr(A(z)^-1 A'(z))), warm-started from the previous order's roots (the
// stable ones barely move; the ni new ones start on a circle). A sweep costs
// O((m ni)^2 + m ni m ni^2) against O((m ni)^3) for the QR iteration on the
// companion matrix; when it does not converge the companion matrix is used.
class MatrixPolynomialRoots {
 public:
  // alpha: (m + 1) ni x ni, rows [alpha_0; ...; alpha_{m-1}; I]. Errors:
  // NumericalFailure when even the companion eigenproblem fails.
  Result<ComplexVector> solve(const Matrix& alpha, Eigen::Index ni, const std::string& where);
  // Forget the warm start (next call starts from scratch).
  void reset() { warm_.clear(); }

 private:
  bool aberth(const Matrix& alpha, Eigen::Index ni);
  std::vector<Complex> warm_, roots_;
  std::vector<char> done_;
  ComplexMatrix a_, da_, x_;
};

// Shape of pole z_r at every output for the stability vector check:
// (z_r, right null vector v_r of A(z_r)) -> no-vector.
using PoleShapeFunction = std::function<ComplexVector(Complex z, const ComplexVector& v)>;

// Keeps the physical candidates among the roots z (in the band, 0 < zeta <=
// maxZeta), computes participation (left null vector of A(z_r)) and shape,
// classifies each against `previous` (nearest frequency) with the criteria and
// appends them, sorted by frequency, to the diagram. `previous` becomes this
// order's poles.
void appendOrderPoles(int order, const Matrix& alpha, Eigen::Index ni, const ComplexVector& z, double dt,
                      const PoleShapeFunction& shape, const PlscfOptions& options,
                      std::vector<StabilizationPole>& previous, StabilizationDiagram& diagram);

// Poles belong to the structure, not to the orientation of its FRF matrix.
// With more references than responses (a roving hammer over a mesh, a few
// fixed accelerometers) the denominator A(z) would be ni x ni while the data's
// rank is bounded by the responses: the reduced normal equations become
// singular and the cost grows with ni^3. The estimators therefore fit the
// transposed matrix (FrfMatrix::transposed) when ni > no; this gives the
// diagram of `estimate` on the orientation with fewer references, its
// participation and shape vectors exchanged back so that they refer to this
// FRF's references and responses (thesis §1.6: poles and residues of a
// reciprocal matrix, H^T = sum_r l_r psi_r^T / (i omega - lambda_r) + ...).
using StabilizationEstimator = std::function<Result<StabilizationDiagram>(const FrfMatrix&)>;
Result<StabilizationDiagram> stabilizationOnFewerReferences(const FrfMatrix& frf,
                                                            const StabilizationEstimator& estimate);

// Checks band and order range shared by both estimators; fills the order list.
Result<std::vector<int>> stabilizationOrders(const PlscfOptions& options, const std::string& where);

}  // namespace mozzi::core::modal
