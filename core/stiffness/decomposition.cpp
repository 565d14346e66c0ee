#include "core/stiffness/decomposition.h"

#include "core/common/text.h"

#include <cmath>
#include <sstream>

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool finite(std::initializer_list<double> v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

Result<Decomposition> decomposeStiffness(const DecompositionInput& in) {
  const std::string where = "stiffness decomposition (eq. 24, 27)";
  if (!finite({in.twistStiffness, in.twistArm, in.twistBeta, in.bendArm, in.bendBeta, in.torsArm, in.torsBeta})) {
    return makeError(ErrorCode::InvalidArgument, "non-finite input", where);
  }
  if (!(in.twistStiffness > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "twist stiffness must be > 0, got " + formatNumber(in.twistStiffness),
                     where);
  }
  if (in.twistArm == 0.0 || in.bendArm == 0.0 || in.torsArm == 0.0) {
    return makeError(ErrorCode::InvalidArgument,
                     "an arm is zero: the load point lies on an axis, so that stiffness cannot be seen by the "
                     "load-point displacement",
                     where);
  }
  const double sb = std::sin(in.bendBeta - in.twistBeta), st = std::sin(in.torsBeta - in.twistBeta);
  const double cb = std::cos(in.bendBeta - in.twistBeta), ct = std::cos(in.torsBeta - in.twistBeta);
  const double rhs = in.twistArm * in.twistArm / in.twistStiffness;  // a_tw^2 / k_tw [m^2/(Nm)]
  // [a_b a_t; sb st] [A; B] = [rhs; 0]
  const double det = in.bendArm * st - in.torsArm * sb;
  const double scale = std::abs(in.bendArm) + std::abs(in.torsArm);
  if (std::abs(det) < 1e-9 * scale) {
    return makeError(ErrorCode::NumericalFailure,
                     "singular decomposition: a_bend sin(beta_tors - beta) = a_tors sin(beta_bend - beta), so eq. 24 "
                     "and eq. 27 do not separate the bending and torsion stiffness",
                     where);
  }
  if (std::abs(sb) < 1e-9 || std::abs(st) < 1e-9) {
    return makeError(ErrorCode::NumericalFailure,
                     std::string("the static twist axis is parallel to the ") +
                         (std::abs(sb) < 1e-9 ? "bending" : "torsion") +
                         " axis: the other component does not contribute and its stiffness is not identifiable",
                     where);
  }
  const double a = rhs * st / det;
  const double b = -rhs * sb / det;
  Decomposition out;
  out.bendCompliancePerArm = a;
  out.torsCompliancePerArm = b;
  out.determinant = det;
  out.bendStiffness = in.bendArm / a;
  out.torsStiffness = in.torsArm / b;
  if (!(out.bendStiffness > 0.0) || !(out.torsStiffness > 0.0)) {
    return makeError(ErrorCode::NumericalFailure,
                     "non-physical decomposition (k_bend = " + formatNumber(out.bendStiffness) +
                         ", k_tors = " + formatNumber(out.torsStiffness) +
                         " Nm/rad): the static axis does not lie between the bending and torsion axes with these "
                         "arms and directions",
                     where);
  }
  const double back = in.bendArm * in.bendArm / out.bendStiffness + in.torsArm * in.torsArm / out.torsStiffness;
  out.balanceResidual = (rhs - back) / rhs;
  const double rot = in.twistArm / in.twistStiffness;  // theta_tw / F
  out.rotationResidual = (a * cb + b * ct - rot) / rot;
  // Conditioning: relative error amplification of the 2x2 system.
  const double cond = (std::abs(in.bendArm) + std::abs(in.torsArm)) * (std::abs(sb) + std::abs(st)) / std::abs(det);
  if (cond > 100.0) {
    out.lowConfidence = true;
    out.note = "ill-conditioned decomposition (error amplification " + formatNumber(cond) + ")";
  }
  if (std::abs(out.rotationResidual) > 0.2) {
    out.lowConfidence = true;
    out.note += std::string(out.note.empty() ? "" : "; ") + "rotation magnitude (eq. 25/26) misses by " +
                formatNumber(100 * out.rotationResidual) + "%: axes or arms inconsistent";
  }
  return out;
}

Result<Decomposition> decomposeStiffness(double twistStiffness, const PlateAxis& twist, const PlateAxis& bend,
                                         const PlateAxis& tors, const Vector2& loadPoint) {
  // A rotation theta about a directed axis moves the load point by theta s with
  // s the signed arm; the direction angle (not modulo pi) enters eq. 25/26.
  auto angle = [](const PlateAxis& ax) { return std::atan2(ax.direction(0), ax.direction(1)); };
  DecompositionInput in;
  in.twistStiffness = twistStiffness;
  in.twistArm = twist.signedArm(loadPoint);
  in.twistBeta = angle(twist);
  in.bendArm = bend.signedArm(loadPoint);
  in.bendBeta = angle(bend);
  in.torsArm = tors.signedArm(loadPoint);
  in.torsBeta = angle(tors);
  return decomposeStiffness(in);
}

Result<Decomposition> decomposeForkStiffness(const ForkDecompositionInput& in) {
  const std::string where = "fork stiffness decomposition (eq. 35, 36)";
  if (!finite({in.twistStiffness, in.twistArm, in.bendArm, in.torsArm, in.alpha})) {
    return makeError(ErrorCode::InvalidArgument, "non-finite input", where);
  }
  if (!(in.twistStiffness > 0.0) || !(in.twistArm > 0.0) || !(in.bendArm > 0.0) || !(in.torsArm > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "stiffness and arms must be > 0", where);
  }
  if (!(in.alpha > 1e-6) || !(in.alpha < kPi / 2 - 1e-6)) {
    return makeError(ErrorCode::NumericalFailure,
                     "twist-axis inclination " + formatNumber(in.alpha * 180 / kPi) +
                         " deg: at 0 the twist axis is the bending axis (no torsion seen), at 90 deg it is the "
                         "torsion axis (no bending seen); the decomposition is singular",
                     where);
  }
  const double t = std::tan(in.alpha);
  const double rhs = in.twistArm * in.twistArm / in.twistStiffness;
  Decomposition out;
  out.bendStiffness = (in.bendArm * in.bendArm + in.torsArm * in.bendArm * t) / rhs;  // from eq. 35 + 36
  out.torsStiffness = out.bendStiffness * in.torsArm / (in.bendArm * t);              // eq. 36
  out.bendCompliancePerArm = in.bendArm / out.bendStiffness;
  out.torsCompliancePerArm = in.torsArm / out.torsStiffness;
  out.determinant = in.bendArm * std::cos(in.alpha) + in.torsArm * std::sin(in.alpha);
  const double back = in.bendArm * in.bendArm / out.bendStiffness + in.torsArm * in.torsArm / out.torsStiffness;
  out.balanceResidual = (rhs - back) / rhs;
  const double rot = in.twistArm / in.twistStiffness;
  out.rotationResidual =
      (out.bendCompliancePerArm * std::cos(in.alpha) + out.torsCompliancePerArm * std::sin(in.alpha) - rot) / rot;
  return out;
}

}  // namespace mozzi::core::stiffness
