#include "core/tire/ring_model.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/tire/relaxation_length.h"

namespace mozzi::core::tire {
namespace {

constexpr double kPi = 3.14159265358979323846;

Result<void> checkSettings(const RingModelSettings& s, const char* where) {
  if (!std::isfinite(s.tyreMass) || s.tyreMass <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "tyre mass must be positive", where);
  if (!std::isfinite(s.beltShare) || s.beltShare <= 0.0 || s.beltShare > 1.0)
    return makeError(ErrorCode::InvalidArgument, "belt share must lie in (0, 1]", where);
  if (!std::isfinite(s.ringRadius) || s.ringRadius <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "ring radius must be positive", where);
  return {};
}

Result<void> checkK(int k, std::set<int>& seen, const std::string& where) {
  if (k < 0) return makeError(ErrorCode::InvalidArgument, "wave number k must not be negative", where);
  if (!seen.insert(k).second) return makeError(ErrorCode::InvalidArgument, "wave number k given twice", where);
  return {};
}

}  // namespace

double ringModalMassFactor(int k) {
  return k == 0 ? 1.0 : 0.5;
}

std::string ringModeName(int k) {
  switch (k) {
    case 0: return "lateral";
    case 1: return "camber";
    case 2: return "C-shaped";
    case 3: return "S-shaped";
    default: return "k=" + std::to_string(k);
  }
}

const RingMode* RingModel::mode(int k) const {
  for (const auto& m : modes)
    if (m.k == k) return &m;
  return nullptr;
}

double RingModel::staticLateralCompliance() const {
  double g = 0.0;
  for (const auto& m : modes) g += 1.0 / m.modalStiffness;  // springs in series, eq. 48
  return g;
}

Complex RingModel::lateralCompliance(double omega, bool withDamping) const {
  Complex g(0.0, 0.0);
  for (const auto& m : modes) g += 1.0 / Complex(m.modalStiffness, withDamping ? omega * m.dampingCoefficient : 0.0);
  return g;
}

namespace {

// The loop both constructors share: settings and k checked, ring mass from the
// belt share, modal mass by eq. 45; `complete` fills the modal stiffness and
// natural frequency (eq. 46, one way or the other) or says why the input is
// unusable; damping by the corrected eq. 47, c = 2 zeta sqrt(K m).
template <class Input, class Complete>
Result<RingModel> buildRingModel(const std::vector<Input>& in, const RingModelSettings& s, const char* where,
                                 Complete complete) {
  MOZZI_TRY(checkSettings(s, where));
  if (in.empty()) return makeError(ErrorCode::InvalidArgument, "no mode given", where);
  RingModel model;
  model.ringMass = s.beltShare * s.tyreMass;
  model.ringRadius = s.ringRadius;
  std::set<int> seen;
  for (const auto& mi : in) {
    const std::string at = std::string(where) + ", mode k=" + std::to_string(mi.k);
    MOZZI_TRY(checkK(mi.k, seen, at));
    if (!std::isfinite(mi.dampingRatio) || mi.dampingRatio < 0.0)
      return makeError(ErrorCode::InvalidArgument, "damping ratio must be finite and not negative", at);
    RingMode m;
    m.k = mi.k;
    m.name = ringModeName(mi.k);
    m.modalMass = model.ringMass * ringModalMassFactor(mi.k);  // eq. 45
    if (const char* problem = complete(mi, m)) return makeError(ErrorCode::InvalidArgument, problem, at);
    m.dampingRatio = mi.dampingRatio;
    m.dampingCoefficient = 2.0 * mi.dampingRatio * std::sqrt(m.modalStiffness * m.modalMass);  // eq. 47 corrected
    model.modes.push_back(m);
  }
  std::sort(model.modes.begin(), model.modes.end(), [](const RingMode& a, const RingMode& b) { return a.k < b.k; });
  return model;
}

}  // namespace

Result<RingModel> identifyRingModel(const std::vector<RingModeInput>& in, const RingModelSettings& s) {
  return buildRingModel(in, s, "ring modal model (thesis §5.3)",
                        [](const RingModeInput& mi, RingMode& m) -> const char* {
                          if (!std::isfinite(mi.naturalFrequencyHz) || mi.naturalFrequencyHz <= 0.0)
                            return "natural frequency must be positive";
                          const double w = 2.0 * kPi * mi.naturalFrequencyHz;
                          m.naturalFrequencyHz = mi.naturalFrequencyHz;
                          m.modalStiffness = m.modalMass * w * w;  // eq. 46
                          return nullptr;
                        });
}

Result<RingModel> ringModelFromStiffness(const std::vector<RingStiffnessInput>& in, const RingModelSettings& s) {
  return buildRingModel(in, s, "ring modal model from stiffnesses (thesis §5.3, Table 16)",
                        [](const RingStiffnessInput& mi, RingMode& m) -> const char* {
                          if (!std::isfinite(mi.modalStiffness) || mi.modalStiffness <= 0.0)
                            return "modal stiffness must be positive";
                          m.modalStiffness = mi.modalStiffness;
                          m.naturalFrequencyHz =
                              std::sqrt(m.modalStiffness / m.modalMass) / (2.0 * kPi);  // eq. 46 inverted
                          return nullptr;
                        });
}

Result<ComplexVector> ringFrf(const RingModel& ring, const RingFrfInputs& in, const VectorRef& omega,
                              RingFrfVariant variant) {
  const char* where = "ring-model FRF (thesis appendix 1)";
  if (!std::isfinite(in.speed) || in.speed <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "forward speed V must be positive", where);
  if (!std::isfinite(in.halfLength) || in.halfLength < 0.0 || !std::isfinite(in.contactRelaxation) ||
      in.contactRelaxation < 0.0)
    return makeError(ErrorCode::InvalidArgument, "half-length and contact relaxation length must not be negative",
                     where);
  if (!std::isfinite(in.corneringStiffness) || in.corneringStiffness <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "cornering stiffness must be positive", where);
  if (!std::isfinite(in.trail)) return makeError(ErrorCode::InvalidArgument, "trail must be finite", where);
  if (ring.modes.empty()) return makeError(ErrorCode::InvalidArgument, "ring model has no mode", where);
  const RingMode* camber = ring.mode(1);
  const bool useTrail = variant == RingFrfVariant::Full && in.trail != 0.0;
  if (useTrail && camber == nullptr)
    return makeError(ErrorCode::InvalidArgument, "the trail term needs the camber (k=1) mode for C_zz", where);
  const bool damped = variant != RingFrfVariant::FirstOrder;
  const double V = in.speed, a = in.halfLength, C = in.corneringStiffness;
  ComplexVector h(omega.size());
  for (Eigen::Index i = 0; i < omega.size(); ++i) {
    const double w = omega[i];
    if (!std::isfinite(w) || w < 0.0)
      return makeError(ErrorCode::InvalidArgument, "angular frequency must be finite and not negative",
                       std::string(where) + ", point " + std::to_string(i + 1));
    const Complex iw(0.0, w);
    const Complex num = (V - iw * a) * C;  // (V - i w a) C_bFalpha
    Complex den = iw * C * ring.lateralCompliance(w, damped) + V + in.contactRelaxation * iw;
    if (useTrail) {
      const double r2 = ring.ringRadius * ring.ringRadius;
      const Complex yaw(camber->modalStiffness * r2, w * camber->dampingCoefficient * r2);  // C_zz + i w K_zz
      den += num * in.trail / yaw;
    }
    h[i] = num / den;
  }
  return h;
}

Result<ImpliedRelaxation> impliedRelaxationLength(const RingModel& ring, const RingFrfInputs& in,
                                                  const VectorRef& omega, RingFrfVariant variant) {
  MOZZI_TRY_ASSIGN(auto h, ringFrf(ring, in, omega, variant));
  ImpliedRelaxation out;
  out.omega = omega;
  out.phaseLag.resize(omega.size());
  out.sigma = Vector::Zero(omega.size());
  out.valid.assign(static_cast<std::size_t>(omega.size()), false);
  for (Eigen::Index i = 0; i < omega.size(); ++i) {
    out.phaseLag[i] = -std::arg(h[i]);
    if (omega[i] <= 0.0) continue;
    auto s = relaxationLengthFromPhaseLag(out.phaseLag[i], omega[i], in.speed, in.halfLength);
    if (s) {
      out.sigma[i] = s->sigma;
      out.valid[static_cast<std::size_t>(i)] = true;
    }
  }
  return out;
}

}  // namespace mozzi::core::tire
