#include "core/stability/motorcycle.h"

#include "core/stability/parameter_file.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace mozzi::core::stability {

Result<SharpParameters> loadSharpParameters(const std::string& path) {
  MOZZI_TRY_ASSIGN(auto file, readParameterFile(path, "motorcycle"));
  SharpParameters p;
  p.trust = file.comments;
  const std::vector<std::pair<const char*, double*>> fields = {
      {"Mf", &p.Mf},     {"Mr", &p.Mr},   {"Zf", &p.Zf},   {"Irx", &p.Irx}, {"Irz", &p.Irz},
      {"Crxz", &p.Crxz}, {"Ifx", &p.Ifx}, {"Ifz", &p.Ifz}, {"ify", &p.ify}, {"iry_plus_lambda_i", &p.iry},
      {"a", &p.a},       {"b", &p.b},     {"e", &p.e},     {"f", &p.f},     {"h", &p.h},
      {"Rf", &p.Rf},     {"Rr", &p.Rr},   {"t", &p.t},     {"eps", &p.eps}, {"Cf1", &p.Cf1},
      {"Cf2", &p.Cf2},   {"Cr1", &p.Cr1}, {"Cr2", &p.Cr2}, {"K", &p.K},     {"sigma", &p.sigma}};
  MOZZI_TRY(takeParameters(file, fields, path));
  const std::pair<const char*, double> positive[] = {
      {"Mf", p.Mf}, {"Mr", p.Mr}, {"Irx", p.Irx}, {"Irz", p.Irz}, {"Ifx", p.Ifx}, {"Ifz", p.Ifz},
      {"Rf", p.Rf}, {"Rr", p.Rr}, {"h", p.h},     {"Cf1", p.Cf1}, {"Cr1", p.Cr1}, {"sigma", p.sigma}};
  for (const auto& [name, x] : positive) {
    if (!(x > 0.0)) return makeError(ErrorCode::InvalidArgument, "must be positive", path + ": parameter " + name);
  }
  if (!(std::fabs(p.eps) < M_PI / 2.0))
    return makeError(ErrorCode::InvalidArgument, "caster out of range", path + ": eps");
  return p;
}

Result<LumpedForkModel> thesisLumpedForkModel(int model) {
  // Thesis §4.2, Table 12 (enduro fork); notes.md: J1 = 0.278 + 11 x 0.405^2,
  // J2 = 0.278 + 11 x (0.405 + 0.846 - 0.670)^2, model 3 with a pure moment of
  // -0.67 kg m^2; c = 2 zeta sqrt(k J), zeta = 2.4%.
  switch (model) {
    case 1: return LumpedForkModel{"model 1", 28e3, 11.6, 2.085, 11.0, 0.405, 0.670};
    case 2: return LumpedForkModel{"model 2", 78.4e3, 26.9, 3.995, 11.0, 0.405 + 0.846 - 0.670, 0.846};
    case 3: return LumpedForkModel{"model 3", 28e3, 9.6, 1.426, 11.0, 0.405, 0.670};
    default: return makeError(ErrorCode::InvalidArgument, "thesis Table 12 has fork models 1, 2 and 3", "fork model");
  }
}

namespace {

Matrix3 parallelAxis(const Vector3& r) {
  return r.squaredNorm() * Matrix3::Identity() - r * r.transpose();
}

}  // namespace

Result<MotorcycleModel> MotorcycleModel::build(const SharpParameters& p, const std::optional<LumpedForkModel>& fork) {
  const double se = std::sin(p.eps), ce = std::cos(p.eps);
  const Vector3 s(se, 0.0, ce);    // steer axis, down and forward
  const Vector3 e1(ce, 0.0, -se);  // normal to it, in the plane, forward and up
  // Ground point of the steer axis: the ground point below the rear mass centre
  // is a from the axis, perpendicular to it (Sharp Fig. 1).
  const double xs = p.b + p.a / ce;
  const double xQ = xs - p.t / ce;  // front contact, normal trail t behind the axis
  const Vector3 wheelF(xQ, 0.0, -p.Rf);
  // Front frame mass centre: (a + e) along e1, f down the steer axis, from the
  // ground point below the rear mass centre.
  const Vector3 comF = Vector3(p.b, 0.0, 0.0) + (p.a + p.e) * e1 + p.f * s;
  if (!(xQ > 0.0))
    return makeError(ErrorCode::InvalidArgument, "front contact is not ahead of the rear", "geometry a, b, t");
  Matrix3 IF = p.Ifx * e1 * e1.transpose() + p.Ifz * s * s.transpose();
  Matrix3 IR;
  IR << p.Irx, 0.0, p.Crxz, 0.0, 0.0, 0.0, p.Crxz, 0.0, p.Irz;

  VehicleTopology t;
  t.g = p.g;
  t.coordinates = {"roll", "steer"};
  t.joints.push_back({"roll", Vector3::Zero(), Vector3::UnitX(), 0});
  t.joints.push_back({"pitch", Vector3(0.0, 0.0, -p.Rr), Vector3::UnitY(), -1});
  t.joints.push_back({"steer", Vector3(xs, 0.0, 0.0), s, 1});
  std::vector<int> wheelChain = {0, 1, 2};
  MotorcycleModel m;
  m.p_ = p;
  Body front{"front frame", p.Mf, comF, IF, 0.0, 0.0, {0, 1, 2}};
  std::vector<Body> extra;
  if (fork) {
    const LumpedForkModel& k = *fork;
    if (!(k.stiffness > 0.0) || !(k.damping >= 0.0) || !(k.mass > 0.0) || !(k.mass < p.Mf) || !(k.massArm >= 0.0) ||
        !std::isfinite(k.inertia) || !std::isfinite(k.stiffness) || !std::isfinite(k.damping)) {
      return makeError(ErrorCode::InvalidArgument,
                       "lumped fork needs k > 0, c >= 0, 0 < M < front frame mass, arm >= 0, finite J",
                       "fork " + k.name);
    }
    t.coordinates.push_back("bend");
    t.joints.push_back({"bend", wheelF - k.massArm * s, e1, 2});
    wheelChain.push_back(3);
    // Vibrating body: mass M on the axle, own inertia J - M d^2 about the
    // bending direction (negative for model 3: the thesis's pure moment).
    const Matrix3 Iw = (k.inertia - k.mass * k.massArm * k.massArm) * e1 * e1.transpose();
    const double mRest = p.Mf - k.mass;
    const Vector3 comRest = (p.Mf * comF - k.mass * wheelF) / mRest;
    const Matrix3 IRest = IF - Iw - k.mass * parallelAxis(wheelF - comF) - mRest * parallelAxis(comRest - comF);
    front = Body{"front frame", mRest, comRest, IRest, 0.0, 0.0, {0, 1, 2}};
    extra.push_back(Body{"fork wheel and unsprung mass", k.mass, wheelF, Iw, 0.0, 0.0, wheelChain});
  }
  t.bodies.push_back(Body{"rear frame", p.Mr, Vector3(p.b, 0.0, -p.h), IR, 0.0, 0.0, {0, 1}});
  t.bodies.push_back(Body{"rear wheel spin", 0.0, Vector3(0.0, 0.0, -p.Rr), Matrix3::Zero(), p.iry, p.Rr, {0, 1}});
  t.bodies.push_back(front);
  t.bodies.push_back(Body{"front wheel spin", 0.0, wheelF, Matrix3::Zero(), p.ify, p.Rf, wheelChain});
  for (const Body& b : extra) t.bodies.push_back(b);
  t.rearWheel = 1;
  t.frontWheel = 3;
  MOZZI_TRY_ASSIGN(m.lin_, linearize(t));
  m.massLu_ = Eigen::PartialPivLU<Matrix>(m.lin_.Mfull);  // speed-free: factored once for every speed
  m.coordinates_ = t.coordinates;
  const int n = m.lin_.n, N = n + 2;
  m.jointDamping_ = Matrix::Zero(N, N);
  m.jointStiffness_ = Matrix::Zero(n, n);
  m.jointDamping_(3, 3) = p.K;  // steering damper on delta'
  if (fork) {
    m.jointDamping_(4, 4) = fork->damping;
    m.jointStiffness_(2, 2) = fork->stiffness;
  }
  return m;
}

Result<Matrix> MotorcycleModel::stateMatrix(double u) const {
  if (!(u > 0.0) || !std::isfinite(u)) {
    return makeError(ErrorCode::InvalidArgument, "the tyre model needs a positive finite speed", "u");
  }
  const int n = lin_.n, N = n + 2, S = 2 * n + 4;
  const int iq = 0, iw = n, iY = n + N;  // blocks of the state
  // Generalised forces on (y, psi, q) per state: F = Fx x.
  Matrix F = Matrix::Zero(N, S);
  F.block(2, iq, n, n) = -(p_.g * lin_.K0 + jointStiffness_);
  F.block(0, iw, N, N) = -(u * lin_.Gfull + jointDamping_);
  F.col(iw + 1) -= u * lin_.Mfull.col(0);           // y_P'' = v_lat' + u r
  F.col(iY) += lin_.front.lateral;                  // Y_f at the front contact
  F.col(iY + 1) += lin_.rear.lateral;               // Y_r at the rear contact
  const Eigen::PartialPivLU<Matrix>& lu = massLu_;  // the linearisation's mass matrix, factored in build()
  Matrix A = Matrix::Zero(S, S);
  A.block(iq, iw + 2, n, n).setIdentity();
  A.block(iw, 0, N, S) = lu.solve(F);
  // Tyres: Y' = (u/sigma)(C1 alpha + C2 gamma - Y), alpha = heading - lateral velocity / u.
  auto tyre = [&](const ContactRows& c, double C1, double C2, int row) {
    const double k = u / p_.sigma;
    for (int j = 0; j < n; ++j) A(row, iq + j) += k * (C1 * c.heading(2 + j) + C2 * c.camber(2 + j));
    A(row, iw) += -k * C1 * c.lateral(0) / u;      // v_lat
    A(row, iw + 1) += -k * C1 * c.lateral(1) / u;  // r: contact x times yaw rate
    for (int j = 0; j < n; ++j) A(row, iw + 2 + j) += -k * C1 * c.lateral(2 + j) / u;
    A(row, row) -= k;
  };
  tyre(lin_.front, p_.Cf1, p_.Cf2, iY);
  tyre(lin_.rear, p_.Cr1, p_.Cr2, iY + 1);
  return A;
}

StabilitySystem MotorcycleModel::system() const {
  StabilitySystem s;
  const MotorcycleModel copy = *this;
  s.stateMatrix = [copy](double u) { return copy.stateMatrix(u); };
  const int n = lin_.n;
  for (int j = 0; j < n; ++j) {
    s.shapeNames.push_back(coordinates_[j]);
    s.shapeRows.push_back(j);
    s.shapeIsRate.push_back(false);
  }
  s.shapeNames.push_back("yaw");
  s.shapeRows.push_back(n + 1);
  s.shapeIsRate.push_back(true);
  s.kind = VehicleKind::Motorcycle;
  return s;
}

}  // namespace mozzi::core::stability
