#include "core/stability/multibody_linearizer.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "core/stability/bicycle_model.h"
#include "core/stability/hyper_dual.h"

namespace mozzi::core::stability {

namespace {

using HD3 = std::array<HyperDual, 3>;

HD3 toHD(const Vector3& v) {
  return {HyperDual(v.x()), HyperDual(v.y()), HyperDual(v.z())};
}

// Rodrigues: R(u, theta) p = p cos + (u x p) sin + u (u . p)(1 - cos)
HD3 rotate(const Vector3& u, const HyperDual& theta, const HD3& p) {
  const HyperDual c = cos(theta), s = sin(theta);
  const HyperDual one_c = HyperDual(1.0) - c;
  const HD3 uxp = {u.y() * p[2] - u.z() * p[1], u.z() * p[0] - u.x() * p[2], u.x() * p[1] - u.y() * p[0]};
  const HyperDual udp = u.x() * p[0] + u.y() * p[1] + u.z() * p[2];
  HD3 r;
  for (int k = 0; k < 3; ++k) r[k] = p[k] * c + uxp[k] * s + u[k] * udp * one_c;
  return r;
}

// Exact placement of a body point and of the body's axle direction (+y) for
// joint angles qe = [q..., chi]; chi is the pitch joint's angle.
struct Placement {
  HD3 point;
  HD3 axle;
};

Placement place(const VehicleTopology& t, const Body& b, const Vector3& point, const std::vector<HyperDual>& qe) {
  HD3 p = toHD(point);
  HD3 a = toHD(Vector3::UnitY());
  for (auto it = b.joints.rbegin(); it != b.joints.rend(); ++it) {  // outermost joint first
    const Joint& j = t.joints[*it];
    const HyperDual angle = j.coordinate >= 0 ? qe[j.coordinate] : qe.back();
    HD3 rel = {p[0] - j.point.x(), p[1] - j.point.y(), p[2] - j.point.z()};
    rel = rotate(j.axis, angle, rel);
    p = {rel[0] + j.point.x(), rel[1] + j.point.y(), rel[2] + j.point.z()};
    a = rotate(j.axis, angle, a);
  }
  return {p, a};
}

// Potential energy V = -g sum m z (z down) and the height of the front contact
// point z_Q = z_C + r sqrt(1 - a_z^2) (lowest point of a knife-edge wheel with
// axle a and centre C).
std::pair<HyperDual, HyperDual> energyAndContact(const VehicleTopology& t, const std::vector<HyperDual>& qe) {
  HyperDual V(0.0);
  for (const Body& b : t.bodies) {
    if (b.mass == 0.0) continue;
    V = V - (t.g * b.mass) * place(t, b, b.com, qe).point[2];
  }
  const Body& f = t.bodies[t.frontWheel];
  const Placement pf = place(t, f, f.com, qe);
  const HyperDual zQ = pf.point[2] + f.rollingRadius * sqrt(HyperDual(1.0) - pf.axle[2] * pf.axle[2]);
  return {V, zQ};
}

Matrix3 skew(const Vector3& v) {
  Matrix3 s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

}  // namespace

Result<Linearization> linearize(const VehicleTopology& t) {
  const int n = static_cast<int>(t.coordinates.size());
  const int N = 2 + n;
  if (n < 1) return makeError(ErrorCode::InvalidArgument, "no coordinates", "vehicle topology");
  if (t.rearWheel < 0 || t.rearWheel >= static_cast<int>(t.bodies.size()) || t.frontWheel < 0 ||
      t.frontWheel >= static_cast<int>(t.bodies.size())) {
    return makeError(ErrorCode::InvalidArgument, "rear or front wheel index out of range", "vehicle topology");
  }
  if (!(t.g > 0.0)) return makeError(ErrorCode::InvalidArgument, "gravity must be positive", "vehicle topology g");
  for (const Joint& j : t.joints) {
    if (j.coordinate >= n || !j.point.allFinite() || !j.axis.allFinite() || std::fabs(j.axis.norm() - 1.0) > 1e-12) {
      return makeError(ErrorCode::InvalidArgument, "joint needs a unit axis, a finite point and a valid coordinate",
                       "joint " + j.name);
    }
  }
  for (const Body& b : t.bodies) {
    if (!std::isfinite(b.mass) || !b.com.allFinite() || !b.inertia.allFinite() || !std::isfinite(b.spinInertia) ||
        !(b.rollingRadius >= 0.0)) {
      return makeError(ErrorCode::InvalidArgument, "mass, position, inertia or radius not finite", "body " + b.name);
    }
    for (int j : b.joints) {
      if (j < 0 || j >= static_cast<int>(t.joints.size())) {
        return makeError(ErrorCode::InvalidArgument, "joint index out of range", "body " + b.name);
      }
    }
  }
  if (!(t.bodies[t.frontWheel].rollingRadius > 0.0) || !(t.bodies[t.rearWheel].rollingRadius > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "wheels need a positive rolling radius", "vehicle topology");
  }

  Linearization L;
  L.n = n;
  L.Mfull = Matrix::Zero(N, N);
  L.Gfull = Matrix::Zero(N, N);
  const Vector3 ey = Vector3::UnitY(), ez = Vector3::UnitZ();
  // First-order kinematics: translation V (3xN) and rotation W (3xN) of a body
  // point; yaw psi turns everything about the vertical through the rear contact.
  auto kinematics = [&](const Body& b, const Vector3& p, Eigen::Matrix<double, 3, Eigen::Dynamic>& V,
                        Eigen::Matrix<double, 3, Eigen::Dynamic>& W) {
    V = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, N);
    W = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, N);
    V.col(0) = ey;
    V.col(1) = ez.cross(p);
    W.col(1) = ez;
    for (int ji : b.joints) {
      const Joint& j = t.joints[ji];
      if (j.coordinate < 0) continue;  // pitch is second order
      V.col(2 + j.coordinate) += j.axis.cross(p - j.point);
      W.col(2 + j.coordinate) += j.axis;
    }
  };
  Eigen::Matrix<double, 3, Eigen::Dynamic> V, W;
  for (const Body& b : t.bodies) {
    kinematics(b, b.com, V, W);
    L.Mfull += b.mass * V.transpose() * V + W.transpose() * b.inertia * W;
    if (b.rollingRadius > 0.0 && b.spinInertia != 0.0) {
      L.Gfull += (b.spinInertia / b.rollingRadius) * W.transpose() * skew(ey) * W;
    }
  }
  // Contact rows: lateral_Q = y(C) - r theta_x, heading = theta_z, camber = theta_x.
  auto contact = [&](const Body& b) {
    kinematics(b, b.com, V, W);
    ContactRows c;
    c.lateral = V.row(1).transpose() - b.rollingRadius * W.row(0).transpose();
    c.heading = W.row(2).transpose();
    c.camber = W.row(0).transpose();
    c.x = b.com.x();
    return c;
  };
  L.rear = contact(t.bodies[t.rearWheel]);
  L.front = contact(t.bodies[t.frontWheel]);

  // Second order: Hessians of V and z_Q over q, first derivatives over chi.
  Matrix HV(n, n), HZ(n, n);
  for (int r = 0; r < n; ++r) {
    for (int s = r; s < n; ++s) {
      std::vector<HyperDual> qe(n + 1, HyperDual(0.0));
      qe[r].e1 = 1.0;
      qe[s].e2 = 1.0;
      const auto [Vh, zh] = energyAndContact(t, qe);
      HV(r, s) = HV(s, r) = Vh.e12;
      HZ(r, s) = HZ(s, r) = zh.e12;
    }
  }
  std::vector<HyperDual> qe(n + 1, HyperDual(0.0));
  qe[n].e1 = 1.0;
  const auto [Vc, zc] = energyAndContact(t, qe);
  if (std::fabs(zc.e1) < 1e-9) {
    return makeError(ErrorCode::NumericalFailure,
                     "rear-frame pitch does not lift the front wheel (degenerate geometry)", "vehicle topology");
  }
  // Lagrange multiplier of the front contact: the static front ground force.
  const double nu = Vc.e1 / zc.e1;
  L.frontLoad = nu;
  L.K0 = (HV - nu * HZ) / t.g;
  return L;
}

Result<BicycleModel> rollingBicycleModel(const VehicleTopology& topology) {
  MOZZI_TRY_ASSIGN(auto lin, linearize(topology));
  const Linearization& L = lin;
  const int n = L.n, N = n + 2;
  const double w = L.front.x - L.rear.x;
  if (!(w > 0.0)) return makeError(ErrorCode::InvalidArgument, "front contact must be ahead of the rear", "wheel base");
  // Rear contact: y_P' = v psi. Front contact: lateral velocity along the
  // heading, y_Q' = v heading_Q, with y_Q = y_P + w psi + l.q:
  //   psi' = (v h.q - l.q') / w.
  const Vector h = L.front.heading.tail(n) - L.rear.heading.tail(n);
  const Vector l = L.front.lateral.tail(n) - L.rear.lateral.tail(n);
  // z' = T q' + v S q, with T = [0; -l/w; I] and z'' = T q'' + v E q' + v^2 F q.
  Matrix T = Matrix::Zero(N, n), E = Matrix::Zero(N, n), F = Matrix::Zero(N, n), S = Matrix::Zero(N, n);
  T.row(1) = -l.transpose() / w;
  T.bottomRows(n).setIdentity();
  E.row(0) = -l.transpose() / w;  // y_P'' = v psi'
  E.row(1) = h.transpose() / w;   // psi'' = (v h.q' - l.q'')/w
  F.row(0) = h.transpose() / w;
  S.row(1) = h.transpose() / w;
  BicycleModel m;
  m.g = topology.g;
  m.coordinates = topology.coordinates;
  m.M = T.transpose() * L.Mfull * T;
  m.C1 = T.transpose() * (L.Mfull * E + L.Gfull * T);
  m.K2 = T.transpose() * (L.Mfull * F + L.Gfull * S);
  m.K0 = L.K0;
  m.C = Matrix::Zero(n, n);
  m.K = Matrix::Zero(n, n);
  return m;
}

}  // namespace mozzi::core::stability
