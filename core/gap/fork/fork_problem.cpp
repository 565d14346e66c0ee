#include "core/gap/fork/fork_problem.h"

#include <cmath>
#include <limits>

#include "core/common/text.h"

namespace mozzi::core::gap {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
enum ForkEffect { kStiffnessLocation = 0, kBendingStiffness, kInertia, kResidualCompliance };

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}
}  // namespace

// ---- fork A lumped model (§4.2) ------------------------------------------------

Result<std::unique_ptr<ForkLumpedGapProblem>> ForkLumpedGapProblem::create(const ForkLumpedGapInput& in) {
  const char* where = "fork lumped gap problem (§4.2)";
  // forkLumpedModels validates the shared inputs (and model 1 is the baseline).
  MOZZI_TRY(stiffness::forkLumpedModels(in.fork));
  if (!positive(in.frequencySigmaHz))
    return makeError(ErrorCode::InvalidArgument, "the frequency uncertainty must be positive", where);
  if (!(in.torsionCompliance >= 0.0) || !std::isfinite(in.torsionCompliance))
    return makeError(ErrorCode::InvalidArgument, "the torsion compliance must be >= 0", where);
  if (!positive(in.unsprungMass) || !positive(in.unsprungMassSigma) || !(in.unsprungMass < in.fork.vibratingMass))
    return makeError(ErrorCode::InvalidArgument, "unsprung mass must be positive and part of the vibrating mass",
                     where);
  if (!(in.fork.dynamicAxisArm > in.fork.wheelCentreHeight) || !(in.fork.staticAxisArm > in.fork.wheelCentreHeight))
    return makeError(ErrorCode::InvalidArgument, "the bending axes must lie above the wheel centre", where);
  // One fold for all: a frequency and a static stiffness are different
  // quantities; fitting an effect on one cannot predict the other for every
  // candidate (an inertia change has no static signature), so no held-out split.
  std::vector<ConditionPoint> pts = {{"lateral mode [Hz]", 0.0, in.fork.measuredFrequencyHz, in.frequencySigmaHz, 0}};
  if (in.withStatic) {
    if (!positive(in.staticLateralStiffness) || !positive(in.staticSigma))
      return makeError(ErrorCode::InvalidArgument, "static lateral stiffness and its uncertainty must be positive",
                       where);
    pts.push_back({"static lateral stiffness [N/m]", 1.0, in.staticLateralStiffness, in.staticSigma, 0});
  }
  return std::unique_ptr<ForkLumpedGapProblem>(new ForkLumpedGapProblem(in, std::move(pts)));
}

std::vector<Parameter> ForkLumpedGapProblem::calibrationParameters() const {
  return {
      {"unsprung_mass", "kg", in_.unsprungMass, 0.5 * in_.unsprungMass, 1.5 * in_.unsprungMass, in_.unsprungMassSigma}};
}

std::vector<Candidate> ForkLumpedGapProblem::candidates() const {
  const std::string l2 = "bending axis at " + formatNumber(in_.fork.dynamicAxisArm, 3) + " m";
  const std::string l1 = "bending axis at " + formatNumber(in_.fork.staticAxisArm, 3) + " m";
  return {
      {"stiffness_location", {l2}, {{"stiffness_scale", "", 1.0, 0.2, 10.0, 0.0}}},
      {"bending_stiffness", {l1}, {{"stiffness_scale", "", 1.0, 0.2, 10.0, 0.0}}},
      {"inertia", {l1}, {{"pure_moment", "kg m^2", 0.0, -1.5, 1.5, 0.0}}},
      {"residual_compliance", {}, {{"static_share", "", 0.0, 0.0, 0.9, 0.0}}},
  };
}

std::vector<double> ForkLumpedGapProblem::predict(const ModelPoint& at) const {
  const auto& f = in_.fork;
  const double mass = f.vibratingMass + (at.theta ? at.theta[0] - in_.unsprungMass : 0.0);
  auto inertia = [&](double arm) {  // wheel + unsprung mass M at the wheel centre, J_wheel about its own diameter
    const double d = arm - f.wheelCentreHeight;
    return f.wheelInertia + mass * d * d;
  };
  double arm = f.staticAxisArm;            // where the spring and the rotation axis are
  double kModal = f.staticBendStiffness;   // the stiffness the mode deforms
  double kStatic = f.staticBendStiffness;  // the bending stiffness the static test sees at that arm
  double J = inertia(arm);
  switch (at.candidate) {
    case -1: break;
    case kStiffnessLocation:
      arm = f.dynamicAxisArm;
      kModal = kStatic = at.phi[0] * f.staticBendStiffness;
      J = inertia(arm);
      break;
    case kBendingStiffness: kModal = kStatic = at.phi[0] * f.staticBendStiffness; break;
    case kInertia: J += at.phi[0]; break;
    case kResidualCompliance: kModal = f.staticBendStiffness / (1.0 - at.phi[0]); break;
    default: return std::vector<double>(points_.size(), kNaN);
  }
  std::vector<double> out;
  out.push_back(J > 0.0 && kModal > 0.0 ? std::sqrt(kModal / J) / kTwoPi : kNaN);          // f_n = sqrt(k/J) / 2pi
  if (in_.withStatic) out.push_back(1.0 / (arm * arm / kStatic + in_.torsionCompliance));  // K_lat, series
  return out;
}

std::unique_ptr<GapProblem> ForkLumpedGapProblem::withPoints(std::vector<ConditionPoint> points) const {
  return std::unique_ptr<GapProblem>(new ForkLumpedGapProblem(in_, std::move(points)));
}

GapMetrics ForkLumpedGapProblem::metrics(const ModelPoint& at) const {
  auto m = ConditionSeriesProblem::metrics(at);
  m.entries[0].kind = "mode";  // the lateral mode; the static stiffness stays a "condition"
  return m;
}

// ---- estimates of one stiffness from several configurations (§6.4) -------------

Result<std::unique_ptr<StiffnessEstimatesGapProblem>> StiffnessEstimatesGapProblem::create(
    std::vector<StiffnessEstimate> estimates, std::string unit) {
  const char* where = "stiffness estimates gap problem";
  if (estimates.size() < 2)
    return makeError(ErrorCode::InvalidArgument, "at least two estimates are needed to compare", where);
  std::vector<ConditionPoint> pts;
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    const auto& e = estimates[i];
    if (!positive(e.value) || !positive(e.sigma))
      return makeError(ErrorCode::InvalidArgument, "estimate and uncertainty must be positive", e.configuration);
    for (const auto& p : pts)
      if (p.label == e.configuration)
        return makeError(ErrorCode::InvalidArgument, "configuration named twice", e.configuration);
    // One fold for all: each configuration's error acts on its own estimate
    // only, so holding one out leaves nothing to predict it from.
    pts.push_back({e.configuration, static_cast<double>(i), e.value, e.sigma, 0});
  }
  const double ref = estimates.front().value;
  return std::unique_ptr<StiffnessEstimatesGapProblem>(
      new StiffnessEstimatesGapProblem(std::move(pts), std::move(unit), ref));
}

std::vector<Parameter> StiffnessEstimatesGapProblem::calibrationParameters() const {
  return {{"stiffness_scale", "", 1.0, 0.2, 5.0, 0.0}};  // k / first estimate
}

std::vector<Candidate> StiffnessEstimatesGapProblem::candidates() const {
  std::vector<Candidate> c;
  for (const auto& p : points_) c.push_back({"inertia_error", {p.label}, {{"inertia_scale", "", 1.0, 0.5, 2.0, 0.0}}});
  c.push_back({"boundary_stiffness", {}, {{"compliance_ratio", "", 0.0, 0.0, 2.0, 0.0}}});
  return c;
}

std::vector<double> StiffnessEstimatesGapProblem::predict(const ModelPoint& at) const {
  const int n = static_cast<int>(points_.size());
  std::vector<double> out(points_.size(), at.theta[0] * reference_);
  if (at.candidate >= 0 && at.candidate < n) {
    // k_hat = (2 pi f)^2 I_assumed with (2 pi f)^2 = k / I_true: k / s.
    out[static_cast<std::size_t>(at.candidate)] /= at.phi[0];
  } else if (at.candidate == n) {
    for (auto& v : out) v /= 1.0 + at.phi[0];  // series clamp: 1/k_hat = 1/k + rho/k
  } else if (at.candidate != -1) {
    out.assign(points_.size(), kNaN);
  }
  return out;
}

std::unique_ptr<GapProblem> StiffnessEstimatesGapProblem::withPoints(std::vector<ConditionPoint> points) const {
  return std::unique_ptr<GapProblem>(new StiffnessEstimatesGapProblem(std::move(points), unit_, reference_));
}

}  // namespace mozzi::core::gap
