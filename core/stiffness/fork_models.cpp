#include "core/stiffness/fork_models.h"

#include "core/common/text.h"

#include <cmath>
#include <initializer_list>
#include <sstream>
#include <utility>

namespace mozzi::core::stiffness {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

bool positiveFinite(double v) {
  return std::isfinite(v) && v > 0.0;
}

Result<void> checkParameters(const BicycleForkParameters& p) {
  const struct {
    const char* name;
    double v;
  } items[] = {{"fork mass", p.forkMass},       {"wheel mass", p.wheelMass},   {"wheel radius", p.wheelRadius},
               {"hub mass", p.hubMass},         {"hub radius", p.hubRadius},   {"hub length", p.hubLength},
               {"tip distance", p.tipDistance}, {"max bend arm", p.maxBendArm}};
  for (const auto& it : items) {
    if (!positiveFinite(it.v)) {
      return makeError(ErrorCode::InvalidArgument, std::string(it.name) + " must be > 0, got " + formatNumber(it.v),
                       "bicycle fork parameters (Table 21)");
    }
  }
  return {};
}

// Error naming the first quantity that is not a finite positive number.
Result<void> requireFinitePositive(std::initializer_list<std::pair<const char*, double>> values,
                                   const std::string& where) {
  for (const auto& [name, v] : values) {
    if (!positiveFinite(v)) {
      return makeError(ErrorCode::NumericalFailure,
                       std::string(name) + " is " + formatNumber(v) +
                           ": out of the representable range (inputs far too large or too small)",
                       where);
    }
  }
  return {};
}

}  // namespace

Result<ForkLumpedModels> forkLumpedModels(const ForkLumpedInput& in) {
  const std::string where = "fork lumped models (§4.2, Table 12)";
  if (!positiveFinite(in.staticBendStiffness) || !positiveFinite(in.vibratingMass) ||
      !positiveFinite(in.measuredFrequencyHz) || !(in.wheelInertia >= 0.0) || !(in.zeta >= 0.0) ||
      !std::isfinite(in.staticAxisArm) || !std::isfinite(in.dynamicAxisArm) || !std::isfinite(in.wheelCentreHeight) ||
      !std::isfinite(in.zeta) || !std::isfinite(in.wheelInertia)) {
    return makeError(ErrorCode::InvalidArgument,
                     "stiffness, mass and frequency must be > 0, inertia and damping >= 0, arms finite", where);
  }
  const double omega = kTwoPi * in.measuredFrequencyHz;
  auto finish = [&](LumpedModel& m) {
    m.frequencyHz = std::sqrt(m.stiffness / m.inertia) / kTwoPi;
    m.zeta = in.zeta;
    m.damping = 2.0 * in.zeta * std::sqrt(m.stiffness * m.inertia);  // c = 2 zeta sqrt(k J), eq. 55/56
  };
  ForkLumpedModels out;
  // Model 1: J1 = J_wheel + M (L1 - h_c)^2 (0.278 + 11 x 0.405^2), k1 static.
  const double d1 = in.staticAxisArm - in.wheelCentreHeight;
  out.model1.stiffness = in.staticBendStiffness;
  out.model1.arm = in.staticAxisArm;
  out.model1.inertia = in.wheelInertia + in.vibratingMass * d1 * d1;
  finish(out.model1);
  // Model 2: J2 = J_wheel + M (L2 - h_c)^2, k2 = omega_n^2 J2.
  const double d2 = in.dynamicAxisArm - in.wheelCentreHeight;
  out.model2.arm = in.dynamicAxisArm;
  out.model2.inertia = in.wheelInertia + in.vibratingMass * d2 * d2;
  out.model2.stiffness = omega * omega * out.model2.inertia;
  finish(out.model2);
  // Model 3: k3 = k1 at L1, J3 = k / omega_n^2, pure moment J3 - J1.
  out.model3.stiffness = in.staticBendStiffness;
  out.model3.arm = in.staticAxisArm;
  out.model3.inertia = in.staticBendStiffness / (omega * omega);
  out.model3.pureMoment = out.model3.inertia - out.model1.inertia;
  finish(out.model3);
  if (!(out.model1.inertia > 0.0) || !(out.model2.inertia > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "vibrating inertia is zero (no mass off the axis)", where);
  }
  for (const auto* m : {&out.model1, &out.model2, &out.model3}) {
    if (!std::isfinite(m->stiffness) || !std::isfinite(m->inertia) || !std::isfinite(m->frequencyHz) ||
        !std::isfinite(m->damping) || !std::isfinite(m->pureMoment)) {
      return makeError(ErrorCode::NumericalFailure,
                       "a model quantity is out of the representable range (inputs far too large or too small)", where);
    }
  }
  return out;
}

double torsionInertiaWithWheel(const BicycleForkParameters& p) {
  // eq. 52 with the ring about a diameter: 2 (m/6) d^2 + m_F r_F^2 / 2
  return 2.0 * (p.forkMass / 6.0) * p.tipDistance * p.tipDistance + 0.5 * p.wheelMass * p.wheelRadius * p.wheelRadius;
}

double torsionInertiaForkAlone(const BicycleForkParameters& p) {
  // eq. 53: cylinder about a diameter, m (3 r^2 + l^2) / 12
  return 2.0 * (p.forkMass / 6.0) * p.tipDistance * p.tipDistance +
         p.hubMass * (3.0 * p.hubRadius * p.hubRadius + p.hubLength * p.hubLength) / 12.0;
}

double bendInertiaWithWheel(const BicycleForkParameters& p, double h) {
  // eq. 58
  return 2.0 * (p.forkMass / 6.0) * h * h + p.wheelMass * h * h + 0.5 * p.wheelMass * p.wheelRadius * p.wheelRadius;
}

double bendInertiaForkAlone(const BicycleForkParameters& p, double h) {
  // eq. 59 with the hub's own term as in eq. 53
  return 2.0 * (p.forkMass / 6.0) * h * h + p.hubMass * h * h +
         p.hubMass * (3.0 * p.hubRadius * p.hubRadius + p.hubLength * p.hubLength) / 12.0;
}

double modalStiffness(double frequencyHz, double inertia) {
  const double w = kTwoPi * frequencyHz;
  return w * w * inertia;  // eq. 51, 57
}

Result<double> seriesStiffness(double k1, double k2) {
  if (!positiveFinite(k1) || !positiveFinite(k2)) {
    return makeError(ErrorCode::InvalidArgument, "both stiffnesses must be > 0", "series stiffness (eq. 54)");
  }
  return 1.0 / (1.0 / k1 + 1.0 / k2);
}

Result<double> modalDamping(double stiffness, double inertia, double zeta) {
  if (!positiveFinite(stiffness) || !positiveFinite(inertia) || !(zeta >= 0.0) || !std::isfinite(zeta)) {
    return makeError(ErrorCode::InvalidArgument, "stiffness and inertia must be > 0 and zeta >= 0",
                     "modal damping (eq. 55, 56)");
  }
  return zeta * 2.0 * std::sqrt(stiffness * inertia);
}

Result<BicycleTorsion> bicycleForkTorsion(const BicycleForkParameters& p, double fWithWheelHz, double etaWithWheel,
                                          double fAloneHz, double fAlone2Hz) {
  MOZZI_TRY(checkParameters(p));
  if (!positiveFinite(fWithWheelHz) || !positiveFinite(fAloneHz) || !(etaWithWheel >= 0.0) ||
      !std::isfinite(fAlone2Hz) || !std::isfinite(etaWithWheel)) {
    return makeError(ErrorCode::InvalidArgument, "frequencies must be > 0 and the loss factor >= 0",
                     "bicycle fork torsion (§6.4)");
  }
  BicycleTorsion out;
  out.inertiaWithWheel = torsionInertiaWithWheel(p);
  out.inertiaAlone = torsionInertiaForkAlone(p);
  out.stiffnessWithWheel = modalStiffness(fWithWheelHz, out.inertiaWithWheel);
  out.stiffnessAloneMode1 = modalStiffness(fAloneHz, out.inertiaAlone);
  const std::string where = "bicycle fork torsion (§6.4)";
  // Every intermediate is checked: inputs near the double range (1e308) give
  // inf or 0 here, which must be an error and not a dereferenced failure.
  if (auto r = requireFinitePositive({{"inertia with wheel", out.inertiaWithWheel},
                                      {"inertia of the fork alone", out.inertiaAlone},
                                      {"stiffness with wheel", out.stiffnessWithWheel},
                                      {"stiffness of the fork alone (mode 1)", out.stiffnessAloneMode1}},
                                     where);
      !r) {
    return r.error();
  }
  if (fAlone2Hz > 0.0) {
    out.stiffnessAloneMode2 = modalStiffness(fAlone2Hz, out.inertiaAlone);
    auto series = seriesStiffness(out.stiffnessAloneMode1, out.stiffnessAloneMode2);  // eq. 54
    if (!series) return makeError(series.error().code, series.error().message, where);
    out.stiffnessAlone = *series;
  } else {
    out.stiffnessAlone = out.stiffnessAloneMode1;
  }
  // zeta = eta / 2 (§6.4), with-wheel stiffness and inertia.
  auto damping = modalDamping(out.stiffnessWithWheel, out.inertiaWithWheel, 0.5 * etaWithWheel);
  if (!damping || !std::isfinite(*damping)) {
    return makeError(ErrorCode::NumericalFailure, "the damping is out of the representable range", where);
  }
  out.damping = *damping;
  return out;
}

Result<BicycleBending> bicycleForkBending(const BicycleForkParameters& p, double fWithWheelHz, double etaWithWheel,
                                          double fAloneHz) {
  MOZZI_TRY(checkParameters(p));
  const std::string where = "bicycle fork bending (§6.5, eq. 57 to 59)";
  if (!positiveFinite(fWithWheelHz) || !positiveFinite(fAloneHz) || !(etaWithWheel >= 0.0) ||
      !std::isfinite(etaWithWheel)) {
    return makeError(ErrorCode::InvalidArgument, "frequencies must be > 0 and the loss factor >= 0", where);
  }
  // k_w(h) = ww^2 (Bw h^2 + Jw), k_a(h) = wa^2 (Ba h^2 + Ja): both of the form
  // alpha + beta h^2, so they meet where h^2 = (wa^2 Ja - ww^2 Jw) / (ww^2 Bw - wa^2 Ba).
  const double ww2 = std::pow(kTwoPi * fWithWheelHz, 2), wa2 = std::pow(kTwoPi * fAloneHz, 2);
  const double jw = bendInertiaWithWheel(p, 0.0), ja = bendInertiaForkAlone(p, 0.0);
  const double bw = bendInertiaWithWheel(p, 1.0) - jw, ba = bendInertiaForkAlone(p, 1.0) - ja;
  const double den = ww2 * bw - wa2 * ba;
  const double num = wa2 * ja - ww2 * jw;
  if (!std::isfinite(num) || !std::isfinite(den)) {
    return makeError(ErrorCode::NumericalFailure,
                     "the inputs overflow the stiffness curves (frequencies, masses or lengths far too large)", where);
  }
  if (den == 0.0 || !(num / den >= 0.0)) {
    return makeError(ErrorCode::NumericalFailure,
                     "the with-wheel and fork-alone stiffness curves do not meet for any real h_W", where);
  }
  const double h = std::sqrt(num / den);
  if (h > p.maxBendArm) {
    return makeError(ErrorCode::NumericalFailure,
                     "the stiffness curves meet at h_W = " + formatNumber(h) + " m, beyond the fixing point (" +
                         formatNumber(p.maxBendArm) + " m)",
                     where);
  }
  BicycleBending out;
  out.bendArm = h;
  out.inertiaWithWheel = bendInertiaWithWheel(p, h);
  out.stiffness = ww2 * out.inertiaWithWheel;
  if (auto r = requireFinitePositive(
          {{"inertia with wheel", out.inertiaWithWheel}, {"bending stiffness", out.stiffness}}, where);
      !r) {
    return r.error();
  }
  // Relative slope difference dk/dh of the two curves at h: small means a
  // grazing intersection where rounded inputs move h_W a lot.
  out.crossingAngle = std::abs(2.0 * h * den) / std::max(out.stiffness / std::max(h, 1e-9), 1e-30);
  auto damping = modalDamping(out.stiffness, out.inertiaWithWheel, 0.5 * etaWithWheel);
  if (!damping || !std::isfinite(*damping)) {
    return makeError(ErrorCode::NumericalFailure, "the damping is out of the representable range", where);
  }
  out.damping = *damping;
  return out;
}

}  // namespace mozzi::core::stiffness
