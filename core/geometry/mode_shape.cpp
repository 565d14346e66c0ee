#include "core/geometry/mode_shape.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <queue>
#include <unordered_map>

#include "core/common/text.h"
#include "core/geometry/mesh_placement.h"
#include "core/modal/shape_tools.h"

namespace mozzi::core::geometry {
namespace {

using io::StoredCoordinateSystem;

// Columns: the unit local axes of the node's displacement system at global
// point p, in global coordinates.
Matrix3 localAxes(const StoredCoordinateSystem* cs, const Vector3& p) {
  if (!cs) return Matrix3::Identity();
  const Matrix3& r = cs->rotation;
  if (cs->kind == StoredCoordinateSystem::Kind::Cartesian) return r;
  const Vector3 q = r.transpose() * (p - cs->origin);  // r is orthonormal: inverse = transpose
  const double phi = std::atan2(q.y(), q.x());
  Matrix3 local;
  if (cs->kind == StoredCoordinateSystem::Kind::Cylindrical) {
    // radial, tangential, axial
    local.col(0) = Vector3(std::cos(phi), std::sin(phi), 0.0);
    local.col(1) = Vector3(-std::sin(phi), std::cos(phi), 0.0);
    local.col(2) = Vector3::UnitZ();
  } else {
    // radial, polar (theta from +z), azimuthal (phi from +x)
    const double rho = q.norm();
    const double theta = rho > 0.0 ? std::acos(std::clamp(q.z() / rho, -1.0, 1.0)) : 0.0;
    local.col(0) = Vector3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    local.col(1) = Vector3(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), -std::sin(theta));
    local.col(2) = Vector3(-std::sin(phi), std::cos(phi), 0.0);
  }
  return r * local;
}

int axisOf(const Dof& d) {
  return static_cast<int>(d.direction) - 1;
}  // 0..2 for X, Y, Z

struct Key {
  int node;
  int axis;
  bool operator<(const Key& o) const { return node != o.node ? node < o.node : axis < o.axis; }
};

}  // namespace

Result<NodePoints> nodePoints(const io::StoredMesh& mesh) {
  MOZZI_TRY_ASSIGN(auto global, globalNodePositions(mesh));
  NodePoints p(static_cast<Eigen::Index>(global.size()), 3);
  for (std::size_t i = 0; i < global.size(); ++i) p.row(static_cast<Eigen::Index>(i)) = global[i].transpose();
  return p;
}

Result<ShapeField> shapeField(const io::MeshDocument& document, const std::vector<Dof>& dofs,
                              const ComplexVectorRef& values, const FieldOptions& options) {
  if (static_cast<Eigen::Index>(dofs.size()) != values.size()) {
    return makeError(ErrorCode::InvalidArgument,
                     std::to_string(dofs.size()) + " DOFs but " + std::to_string(values.size()) + " shape values",
                     "mode shape");
  }
  for (Eigen::Index k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k].real()) || !std::isfinite(values[k].imag())) {
      return makeError(ErrorCode::InvalidArgument, "shape value is not finite", "DOF " + formatDof(dofs[k]));
    }
  }
  const auto& mesh = document.mesh;
  MOZZI_TRY_ASSIGN(auto points, nodePoints(mesh));
  const Eigen::Index n = static_cast<Eigen::Index>(mesh.nodes.size());
  std::unordered_map<int, Eigen::Index> row;
  for (Eigen::Index i = 0; i < n; ++i) row[mesh.nodes[i].label] = i;
  std::map<int, const StoredCoordinateSystem*> systems;
  for (const auto& cs : mesh.coordinateSystems) systems[cs.label] = &cs;

  ShapeField field;
  field.u = NodeDisplacements::Zero(n, 3);
  field.source.assign(static_cast<std::size_t>(n), NodeSource::Still);

  // Local translations known per (node, axis), positive sense.
  std::map<Key, Complex> known;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const Dof& d = dofs[k];
    if (d.isRotation() || !row.count(d.node)) {
      ++field.ignoredDofs;
      continue;
    }
    const Complex v = d.negative ? -values[static_cast<Eigen::Index>(k)] : values[static_cast<Eigen::Index>(k)];
    if (!known.emplace(Key{d.node, axisOf(d)}, v).second) ++field.ignoredDofs;  // first value of a direction wins
  }

  // Slaves, resolved recursively (rules are acyclic when validated; the depth
  // guard keeps an unvalidated cycle from recursing forever).
  std::map<Key, Complex> slaved;
  std::function<std::optional<Complex>(const Dof&, int)> valueOf = [&](const Dof& d,
                                                                       int depth) -> std::optional<Complex> {
    if (d.isRotation() || depth > 64) return std::nullopt;
    const double sign = d.negative ? -1.0 : 1.0;
    const Key key{d.node, axisOf(d)};
    if (auto it = known.find(key); it != known.end()) return sign * it->second;
    if (auto it = slaved.find(key); it != slaved.end()) return sign * it->second;
    // A rule may be written for +X or -X; find either.
    const io::SlavedDof* rule = nullptr;
    for (bool neg : {false, true}) {
      for (const auto& s : document.slaves)
        if (s.slave.node == d.node && s.slave.direction == d.direction && s.slave.negative == neg) rule = &s;
      if (rule) break;
    }
    if (!rule) return std::nullopt;
    Complex sum = 0.0;
    for (const auto& [master, weight] : rule->masters) {
      const auto mv = valueOf(master, depth + 1);
      if (!mv) return std::nullopt;
      sum += weight * *mv;
    }
    const Complex positive = rule->slave.negative ? -sum : sum;
    slaved[key] = positive;
    return sign * positive;
  };
  for (const auto& s : document.slaves) {
    if (s.slave.isRotation() || !row.count(s.slave.node)) continue;
    valueOf(Dof{s.slave.node, s.slave.direction, false}, 0);
  }

  // Node vectors in global axes.
  const auto globalRow = [&](Eigen::Index i) { return Vector3(points(i, 0), points(i, 1), points(i, 2)); };
  std::vector<bool> fixed(static_cast<std::size_t>(n), false);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& node = mesh.nodes[static_cast<std::size_t>(i)];
    Eigen::Matrix<Complex, 3, 1> local = Eigen::Matrix<Complex, 3, 1>::Zero();
    bool any = false, anySlaved = false;
    for (int axis = 0; axis < 3; ++axis) {
      const Key key{node.label, axis};
      if (auto it = known.find(key); it != known.end()) {
        local[axis] = it->second;
        any = true;
      } else if (auto jt = slaved.find(key); jt != slaved.end()) {
        local[axis] = jt->second;
        anySlaved = true;
      }
    }
    if (!any && !anySlaved) continue;
    const auto cs = systems.find(node.displacementCs);
    const Matrix3 axes = localAxes(cs == systems.end() ? nullptr : cs->second, globalRow(i));
    field.u.row(i) = (axes.cast<Complex>() * local).transpose();
    field.source[static_cast<std::size_t>(i)] = any ? NodeSource::Measured : NodeSource::Slaved;
    fixed[static_cast<std::size_t>(i)] = true;
  }

  if (options.interpolate) {
    // Graph of trace lines and face edges, weight 1/length.
    double diag = 0.0;
    if (n > 0) diag = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
    const double minLength = std::max(diag * 1e-9, 1e-15);
    std::vector<std::vector<std::pair<Eigen::Index, double>>> adjacent(static_cast<std::size_t>(n));
    auto connect = [&](int a, int b) {
      const auto ia = row.find(a), ib = row.find(b);
      if (ia == row.end() || ib == row.end() || ia->second == ib->second) return;
      const double length = (globalRow(ia->second) - globalRow(ib->second)).norm();
      const double w = 1.0 / std::max(length, minLength);
      adjacent[static_cast<std::size_t>(ia->second)].push_back({ib->second, w});
      adjacent[static_cast<std::size_t>(ib->second)].push_back({ia->second, w});
    };
    for (const auto& l : mesh.lines) connect(l.nodeA, l.nodeB);
    for (const auto& f : mesh.faces) {
      std::vector<int> ring = {f.nodeA, f.nodeB, f.nodeC};
      if (f.nodeD != 0) ring.push_back(f.nodeD);
      for (std::size_t k = 0; k < ring.size(); ++k) connect(ring[k], ring[(k + 1) % ring.size()]);
    }
    // Free nodes reachable from a fixed one.
    std::vector<Eigen::Index> unknownIndex(static_cast<std::size_t>(n), -1);
    std::vector<Eigen::Index> unknowns;
    std::queue<Eigen::Index> queue;
    for (Eigen::Index i = 0; i < n; ++i)
      if (fixed[static_cast<std::size_t>(i)]) queue.push(i);
    while (!queue.empty()) {
      const Eigen::Index i = queue.front();
      queue.pop();
      for (const auto& [j, w] : adjacent[static_cast<std::size_t>(i)]) {
        if (fixed[static_cast<std::size_t>(j)] || unknownIndex[static_cast<std::size_t>(j)] >= 0) continue;
        unknownIndex[static_cast<std::size_t>(j)] = static_cast<Eigen::Index>(unknowns.size());
        unknowns.push_back(j);
        queue.push(j);
      }
    }
    if (!unknowns.empty()) {
      const Eigen::Index m = static_cast<Eigen::Index>(unknowns.size());
      std::vector<Eigen::Triplet<double>> triplets;
      Matrix rhs = Matrix::Zero(m, 6);  // Re x, y, z; Im x, y, z
      for (Eigen::Index k = 0; k < m; ++k) {
        const Eigen::Index i = unknowns[static_cast<std::size_t>(k)];
        double diagonal = 0.0;
        for (const auto& [j, w] : adjacent[static_cast<std::size_t>(i)]) {
          diagonal += w;
          const Eigen::Index uj = unknownIndex[static_cast<std::size_t>(j)];
          if (uj >= 0) {
            triplets.emplace_back(k, uj, -w);
          } else if (fixed[static_cast<std::size_t>(j)]) {
            for (int c = 0; c < 3; ++c) {
              rhs(k, c) += w * field.u(j, c).real();
              rhs(k, 3 + c) += w * field.u(j, c).imag();
            }
          }
        }
        triplets.emplace_back(k, k, diagonal);
      }
      Eigen::SparseMatrix<double> laplacian(m, m);
      laplacian.setFromTriplets(triplets.begin(), triplets.end());
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
      if (solver.info() != Eigen::Success) {
        return makeError(ErrorCode::NumericalFailure, "the interpolation over the trace lines could not be solved",
                         "mode shape interpolation");
      }
      const Matrix x = solver.solve(rhs);
      if (solver.info() != Eigen::Success || !x.allFinite()) {
        return makeError(ErrorCode::NumericalFailure, "the interpolation over the trace lines could not be solved",
                         "mode shape interpolation");
      }
      for (Eigen::Index k = 0; k < m; ++k) {
        const Eigen::Index i = unknowns[static_cast<std::size_t>(k)];
        for (int c = 0; c < 3; ++c) field.u(i, c) = Complex(x(k, c), x(k, 3 + c));
        field.source[static_cast<std::size_t>(i)] = NodeSource::Interpolated;
      }
    }
  }
  for (const auto s : field.source) {
    switch (s) {
      case NodeSource::Measured: ++field.measuredNodes; break;
      case NodeSource::Slaved: ++field.slavedNodes; break;
      case NodeSource::Interpolated: ++field.interpolatedNodes; break;
      case NodeSource::Still: ++field.stillNodes; break;
    }
  }
  return field;
}

Result<ShapeReadings> shapeReadings(const io::MeshDocument& document, const std::vector<Dof>& dofs,
                                    const ComplexVectorRef& values) {
  if (static_cast<Eigen::Index>(dofs.size()) != values.size()) {
    return makeError(ErrorCode::InvalidArgument,
                     std::to_string(dofs.size()) + " DOFs but " + std::to_string(values.size()) + " shape values",
                     "mode shape");
  }
  const auto& mesh = document.mesh;
  auto points = nodePoints(mesh);
  if (!points) return points.error();
  std::unordered_map<int, Eigen::Index> row;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(mesh.nodes.size()); ++i) row[mesh.nodes[i].label] = i;
  std::map<int, const StoredCoordinateSystem*> systems;
  for (const auto& cs : mesh.coordinateSystems) systems[cs.label] = &cs;
  ShapeReadings out;
  std::vector<Vector3> at, along;
  std::vector<Complex> v;
  std::map<Key, bool> seen;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const Dof& d = dofs[k];
    const auto it = row.find(d.node);
    if (d.isRotation() || it == row.end() || !seen.emplace(Key{d.node, axisOf(d)}, true).second) continue;
    const Complex value = values[static_cast<Eigen::Index>(k)];
    if (!std::isfinite(value.real()) || !std::isfinite(value.imag()))
      return makeError(ErrorCode::InvalidArgument, "shape value is not finite", "DOF " + formatDof(d));
    const Vector3 p = points->row(it->second).transpose();
    const auto& node = mesh.nodes[static_cast<std::size_t>(it->second)];
    const auto cs = systems.find(node.displacementCs);
    const Matrix3 axes = localAxes(cs == systems.end() ? nullptr : cs->second, p);
    out.dofs.push_back(d);
    at.push_back(p);
    along.push_back(axes.col(axisOf(d)));
    v.push_back(d.negative ? -value : value);
  }
  const auto m = static_cast<Eigen::Index>(at.size());
  out.points.resize(m, 3);
  out.directions.resize(m, 3);
  out.values.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    out.points.row(k) = at[static_cast<std::size_t>(k)].transpose();
    out.directions.row(k) = along[static_cast<std::size_t>(k)].transpose();
    out.values(k) = v[static_cast<std::size_t>(k)];
  }
  return out;
}

Vector peakMagnitudes(const NodeDisplacements& u) {
  Vector peak(u.rows());
  for (Eigen::Index i = 0; i < u.rows(); ++i) {
    const Vector3 a = u.row(i).real().transpose();
    const Vector3 b = u.row(i).imag().transpose();
    const double aa = a.squaredNorm(), bb = b.squaredNorm(), ab = a.dot(b);
    const double half = 0.5 * (aa - bb);
    peak[i] = std::sqrt(std::max(0.0, 0.5 * (aa + bb) + std::sqrt(half * half + ab * ab)));
  }
  return peak;
}

Result<SharedMac> macOnCommonDofs(const std::vector<Dof>& dofsA, const ComplexVectorRef& a,
                                  const std::vector<Dof>& dofsB, const ComplexVectorRef& b) {
  if (static_cast<Eigen::Index>(dofsA.size()) != a.size() || static_cast<Eigen::Index>(dofsB.size()) != b.size()) {
    return makeError(ErrorCode::InvalidArgument, "each shape needs one value per DOF", "MAC");
  }
  std::map<std::pair<int, Direction>, std::pair<Eigen::Index, bool>> inB;
  for (std::size_t k = 0; k < dofsB.size(); ++k)
    inB.emplace(std::make_pair(dofsB[k].node, dofsB[k].direction),
                std::make_pair(static_cast<Eigen::Index>(k), dofsB[k].negative));
  std::vector<Complex> va, vb;
  for (std::size_t k = 0; k < dofsA.size(); ++k) {
    const auto it = inB.find({dofsA[k].node, dofsA[k].direction});
    if (it == inB.end()) continue;
    va.push_back(a[static_cast<Eigen::Index>(k)]);
    const double sign = it->second.second == dofsA[k].negative ? 1.0 : -1.0;  // -Z against +Z
    vb.push_back(sign * b[it->second.first]);
  }
  if (va.empty()) return makeError(ErrorCode::NotFound, "the two shapes share no DOF", "MAC");
  const Eigen::Map<const ComplexVector> ma(va.data(), static_cast<Eigen::Index>(va.size()));
  const Eigen::Map<const ComplexVector> mb(vb.data(), static_cast<Eigen::Index>(vb.size()));
  return SharedMac{modal::mac(ma, mb), static_cast<int>(va.size())};
}

Result<Ods> operatingDeflectionShape(const FrfMatrix& frf, double frequencyHz, Eigen::Index drivenIndex) {
  if (frf.lineCount() == 0) return makeError(ErrorCode::InvalidArgument, "the FRF set has no lines", "ODS");
  if (frf.h.size() != frf.references.size()) {
    return makeError(ErrorCode::InvalidArgument, "FRF blocks do not match the references", "ODS");
  }
  const bool alongReferences = frf.referenceCount() > frf.responseCount();
  const Eigen::Index heldCount = alongReferences ? frf.responseCount() : frf.referenceCount();
  if (drivenIndex < 0 || drivenIndex >= heldCount) {
    return makeError(ErrorCode::NotFound,
                     std::string("the FRF set has no ") + (alongReferences ? "response " : "reference ") +
                         std::to_string(drivenIndex + 1),
                     "ODS");
  }
  if (!std::isfinite(frequencyHz)) return makeError(ErrorCode::InvalidArgument, "frequency is not finite", "ODS");
  const auto& f = frf.frequencyHz;
  const double* begin = f.data();
  const double* end = f.data() + f.size();
  const double* it = std::lower_bound(begin, end, frequencyHz);
  Eigen::Index line = static_cast<Eigen::Index>(it - begin);
  if (line == f.size()) {
    line = f.size() - 1;
  } else if (line > 0 && frequencyHz - f[line - 1] <= f[line] - frequencyHz) {
    --line;
  }
  for (const ComplexMatrix& h : frf.h) {
    if (h.rows() != frf.lineCount() || h.cols() != frf.responseCount()) {
      return makeError(ErrorCode::InvalidArgument, "FRF block size does not match the set", "ODS");
    }
  }
  Ods ods;
  ods.alongReferences = alongReferences;
  ods.lineHz = f[line];
  ods.line = line;
  const auto held = static_cast<std::size_t>(drivenIndex);
  if (alongReferences) {
    ods.dofs = frf.references;
    ods.drivenAt = frf.responses[held];
    ods.values.resize(frf.referenceCount());
    for (std::size_t i = 0; i < frf.h.size(); ++i)
      ods.values[static_cast<Eigen::Index>(i)] = frf.h[i](line, drivenIndex);
  } else {
    ods.dofs = frf.responses;
    ods.drivenAt = frf.references[held];
    ods.values = frf.h[held].row(line).transpose();
  }
  return ods;
}

}  // namespace mozzi::core::geometry
