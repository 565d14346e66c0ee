#pragma once
// Assignment of one set of items to another at minimum total cost (the
// linear assignment problem), and its use in modal correlation: pairing two
// sets of mode shapes by MAC (model against test, run against run).

#include <vector>

#include "core/common/eigen_types.h"

namespace mozzi::core::modal {

// Hungarian assignment (Kuhn-Munkres with potentials, O(n^2 m)) of the rows of
// a cost matrix to its columns at minimum total cost, each column used at most
// once; result[row] = column, or -1 for the rows left over when there are more
// rows than columns.
std::vector<int> hungarianAssignment(const Matrix& cost);

// Pairs measured modes (columns of `measured`) with model modes (columns of
// `model`) on the same DOFs by Hungarian assignment on 1 - MAC; a pair with
// MAC below `minMac` is left unpaired. result[model mode] = measured mode or -1.
// With frequencies given, 0.01 |ln(f_model / f_measured)| is added to the cost:
// it only breaks ties (with one or two DOFs every MAC is near 1) and never
// outweighs a MAC difference of 0.01 below a 2.7x frequency ratio.
std::vector<int> pairModesByMac(const ComplexMatrix& model, const ComplexMatrix& measured, double minMac,
                                const Vector& modelHz = Vector(), const Vector& measuredHz = Vector());

}  // namespace mozzi::core::modal
