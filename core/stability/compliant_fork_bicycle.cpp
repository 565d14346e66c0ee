#include "core/stability/compliant_fork_bicycle.h"

#include <cmath>

namespace mozzi::core::stability {

ForkBending thesisSteelForkBending() {
  return {5635.0, 0.8, 0.21};
}  // thesis §6.5, Figure 51
ForkTorsion thesisSteelForkTorsion() {
  return {1938.0, 0.3, 0.0};
}  // thesis §6.4, eq. 54-55

Result<VehicleTopology> bicycleTopology(const BenchmarkParameters& p, ForkJoint joint, double jointGeometry) {
  MOZZI_TRY(validate(p));
  if (!std::isfinite(jointGeometry)) {
    return makeError(ErrorCode::InvalidArgument, "joint position is not finite", "fork joint");
  }
  const double sl = std::sin(p.lambda), cl = std::cos(p.lambda);
  const Vector3 steerAxis(sl, 0.0, cl);  // pointing down and forward; tilted back by lambda
  const Vector3 bendAxis(cl, 0.0, -sl);  // x_F of eq. 62: perpendicular to the steer axis, in the plane
  const Vector3 frontCentre(p.w, 0.0, -p.rF);

  VehicleTopology t;
  t.g = p.g;
  t.coordinates = {"roll", "steer"};
  t.joints.push_back({"roll", Vector3::Zero(), Vector3::UnitX(), 0});             // about the rear ground line
  t.joints.push_back({"pitch", Vector3(0.0, 0.0, -p.rR), Vector3::UnitY(), -1});  // rear frame pitch (2nd order)
  t.joints.push_back(
      {"steer", Vector3(p.w + p.c, 0.0, 0.0), steerAxis, 1});  // steer axis meets the ground c ahead of Q
  std::vector<int> frontChain = {0, 1, 2};
  if (joint == ForkJoint::Bending) {
    // eq. 64: the wheel centre moves by -h_W beta laterally; axis h_W up the fork.
    t.coordinates.push_back("bend");
    t.joints.push_back({"bend", frontCentre - jointGeometry * steerAxis, bendAxis, 2});
    frontChain.push_back(3);
  } else if (joint == ForkJoint::Torsion) {
    t.coordinates.push_back("torsion");
    const Vector3 onSteerAxis(p.w + p.c, 0.0, 0.0);
    t.joints.push_back({"torsion", onSteerAxis + jointGeometry * bendAxis, steerAxis, 2});
    frontChain.push_back(3);
  }
  auto planar = [](double xx, double xz, double yy, double zz) {
    Matrix3 I;
    I << xx, 0.0, xz, 0.0, yy, 0.0, xz, 0.0, zz;
    return I;
  };
  Body R{"rear wheel", p.mR, Vector3(0.0, 0.0, -p.rR), planar(p.IRxx, 0.0, p.IRyy, p.IRxx), p.IRyy, p.rR, {0, 1}};
  Body B{"rear frame", p.mB, Vector3(p.xB, 0.0, p.zB), planar(p.IBxx, p.IBxz, p.IByy, p.IBzz), 0.0, 0.0, {0, 1}};
  Body H{"front frame", p.mH, Vector3(p.xH, 0.0, p.zH), planar(p.IHxx, p.IHxz, p.IHyy, p.IHzz), 0.0, 0.0, {0, 1, 2}};
  Body F{"front wheel", p.mF, frontCentre, planar(p.IFxx, 0.0, p.IFyy, p.IFxx), p.IFyy, p.rF, frontChain};
  t.bodies = {R, B, H, F};
  t.rearWheel = 0;
  t.frontWheel = 3;
  return t;
}

Result<BicycleModel> whippleFromBodies(const BenchmarkParameters& p) {
  MOZZI_TRY_ASSIGN(auto t, bicycleTopology(p, ForkJoint::None, 0.0));
  return rollingBicycleModel(t);
}

namespace {

Result<BicycleModel> withJoint(const BenchmarkParameters& p, ForkJoint joint, double geometry, double k, double c,
                               const char* what) {
  if (!(k > 0.0) || !std::isfinite(k)) {
    return makeError(ErrorCode::InvalidArgument, "stiffness must be positive and finite", std::string(what) + " k");
  }
  if (!(c >= 0.0) || !std::isfinite(c)) {
    return makeError(ErrorCode::InvalidArgument, "damping must be non-negative and finite", std::string(what) + " c");
  }
  MOZZI_TRY_ASSIGN(auto t, bicycleTopology(p, joint, geometry));
  auto m = rollingBicycleModel(t);
  if (!m) return m.error();
  m->K(2, 2) = k;  // eq. 65, [K^B]
  m->C(2, 2) = c;  // eq. 65, [C^B]
  return m;
}

}  // namespace

Result<BicycleModel> forkBendingModel(const BenchmarkParameters& p, const ForkBending& fork) {
  if (!std::isfinite(fork.hW)) return makeError(ErrorCode::InvalidArgument, "h_W is not finite", "fork bending hW");
  return withJoint(p, ForkJoint::Bending, fork.hW, fork.stiffness, fork.damping, "fork bending");
}

Result<BicycleModel> forkTorsionModel(const BenchmarkParameters& p, const ForkTorsion& fork) {
  return withJoint(p, ForkJoint::Torsion, fork.axisOffset, fork.stiffness, fork.damping, "fork torsion");
}

}  // namespace mozzi::core::stability
