#pragma once
// A mode shape (or an operating deflection shape) spread over every node of a
// measurement mesh, in global axes, ready to animate.
//
// DOF values are in each node's displacement system (UFF 15/2411 field 3):
// translations +/-X, Y, Z along that system's local axes at the node
// (cartesian: the rotation columns; cylindrical: radial, tangential, axial;
// spherical: radial, polar, azimuthal). Rotational DOFs are not drawn.
//
// Nodes without a measured DOF get their displacement, in this order:
//  1. from slave rules, u(slave) = sum_k w_k u(master_k) (MeshDocument::slaves);
//  2. by interpolation over the trace lines and face edges: the harmonic
//     interpolant with edge weights 1/length, sum_j w_ij (u_i - u_j) = 0 for
//     every free node i, which is linear interpolation by arc length along a
//     chain between two measured nodes;
//  3. nodes with no path to a measured node stay still (counted).

#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/io/mesh_document.h"

namespace mozzi::core::geometry {

// Per node (rows in mesh.nodes order) a complex displacement (x, y, z) in
// global axes, in the shape's own unit (unscaled).
using NodeDisplacements = Eigen::Matrix<Complex, Eigen::Dynamic, 3>;
// Per node (rows) a real (x, y, z) [m].
using NodePoints = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

enum class NodeSource { Measured, Slaved, Interpolated, Still };

struct ShapeField {
  NodeDisplacements u;             // n x 3
  std::vector<NodeSource> source;  // n
  int measuredNodes = 0;
  int slavedNodes = 0;
  int interpolatedNodes = 0;
  int stillNodes = 0;   // no measured neighbour reachable
  int ignoredDofs = 0;  // rotations, DOFs on nodes the mesh lacks
};

struct FieldOptions {
  bool interpolate = true;  // step 2 above (off: unmeasured nodes stay still)
};

// Global node positions as NodePoints (rows in mesh.nodes order).
Result<NodePoints> nodePoints(const io::StoredMesh& mesh);

// Spreads `values` (one per `dofs` entry) over the mesh of `document`.
Result<ShapeField> shapeField(const io::MeshDocument& document, const std::vector<Dof>& dofs,
                              const ComplexVectorRef& values, const FieldOptions& options = {});

// The measured translations of a shape, one reading per DOF, for a rigid-twist
// fit (core/stiffness/screw_axis.h, screwAxisFromReadingPhasors; thesis §1.5):
// the node's global position, the global unit direction of the DOF's positive
// sense in the node's displacement system, and the value (sign of a negative
// DOF folded in). Rotations, slaved and interpolated values and DOFs on nodes
// the mesh lacks are left out; of two values of one direction the first is kept.
struct ShapeReadings {
  std::vector<Dof> dofs;  // the DOF each reading came from
  Matrix points;          // m x 3 [m]
  Matrix directions;      // m x 3, unit
  ComplexVector values;   // m
};
Result<ShapeReadings> shapeReadings(const io::MeshDocument& document, const std::vector<Dof>& dofs,
                                    const ComplexVectorRef& values);

// Largest displacement magnitude of each node over a cycle:
// max_theta |Re(u) sin(theta) + Im(u) cos(theta)|; with a = Re u, b = Im u,
// = sqrt((|a|^2 + |b|^2)/2 + sqrt(((|a|^2 - |b|^2)/2)^2 + (a.b)^2)).
Vector peakMagnitudes(const NodeDisplacements& u);

// MAC of two shapes over the DOFs they share (modal::mac on the common DOFs,
// in the order of `dofsA`). Errors when they share none.
struct SharedMac {
  double mac = 0.0;
  int commonDofs = 0;
};
Result<SharedMac> macOnCommonDofs(const std::vector<Dof>& dofsA, const ComplexVectorRef& a,
                                  const std::vector<Dof>& dofsB, const ComplexVectorRef& b);

// Operating deflection shape at the line nearest `frequencyHz`: how the
// measured DOFs move under a harmonic force at one DOF, `drivenAt`.
// With at least as many responses as references (accelerometers roved or
// many, a shaker or a fixed hammer) it is the column of the responses to
// reference `drivenIndex`. With more references than responses (a roving
// hammer read by a few fixed accelerometers) the set's shapes lie along the
// references, and the ODS is the row of response `drivenIndex` over them: by
// Maxwell-Betti reciprocity H_{o,i} = H_{i,o}, the response at each hammer DOF
// i to a force at the accelerometer's DOF o.
struct Ods {
  std::vector<Dof> dofs;         // the DOFs that move: the responses, or the references
  ComplexVector values;          // H(f_line) per DOF, in the set's FRF type
  Dof drivenAt;                  // the reference (column) or the response (row) held
  bool alongReferences = false;  // true for the row over the references
  double lineHz = 0.0;           // the line used
  Eigen::Index line = 0;
};
Result<Ods> operatingDeflectionShape(const FrfMatrix& frf, double frequencyHz, Eigen::Index drivenIndex = 0);

}  // namespace mozzi::core::geometry
