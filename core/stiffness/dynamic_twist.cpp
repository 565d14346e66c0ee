#include "core/stiffness/dynamic_twist.h"

#include "core/common/text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/common/frf_type.h"

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Distance of an angle from the nearest of {0, pi} (mod 2 pi), in [0, pi/2].
double distanceFromZeroOrPi(double a) {
  double r = std::fmod(std::abs(a), kPi);
  return std::min(r, kPi - r);
}

}  // namespace

const char* phasorAxisCaseName(PhasorAxisCase c) {
  return c == PhasorAxisCase::InPhase ? "in-phase" : "three-instant";
}

Result<PhasorAxis> phasorTwistAxis(const std::vector<Vector2>& points, const ComplexVector& phasors,
                                   const Vector2& reference, const PhasorAxisOptions& options) {
  const auto n = static_cast<Eigen::Index>(points.size());
  if (phasors.size() != n) {
    return makeError(ErrorCode::InvalidArgument,
                     std::to_string(n) + " sensor points but " + std::to_string(phasors.size()) + " phasors",
                     "dynamic twist axis");
  }
  if (!phasors.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "non-finite phasor", "dynamic twist axis");
  }
  Eigen::Index iref = 0;
  phasors.cwiseAbs().maxCoeff(&iref);
  const double aref = std::abs(phasors(iref));
  if (!(aref > 0.0)) {
    return makeError(ErrorCode::NumericalFailure, "all sensor amplitudes are zero", "dynamic twist axis");
  }
  const double phiRef = std::arg(phasors(iref));
  // Phase check (§1.4): sensors whose amplitude is below the noise carry no
  // phase information and are left out of the check.
  PhasorAxis out;
  const double noise = 3.0 * options.plane.sigmaFloor;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (std::abs(phasors(i)) <= noise) continue;
    out.maxPhaseDeviation = std::max(out.maxPhaseDeviation, distanceFromZeroOrPi(std::arg(phasors(i)) - phiRef));
  }
  if (out.maxPhaseDeviation <= options.phaseTolerance) {
    // Eq. 9 at the instant omega t = -phi_ref: y_i = |Y_i| cos(phi_i - phi_ref),
    // taken as |Y_i| sign(cos(.)) (the thesis's maximum displacements).
    std::vector<double> w(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      const double c = std::cos(std::arg(phasors(i)) - phiRef);
      w[static_cast<std::size_t>(i)] = std::abs(phasors(i)) * (c >= 0 ? 1.0 : -1.0);
    }
    MOZZI_TRY_ASSIGN(out.axis, staticTwistAxis(points, w, reference, options.plane));
    out.method = PhasorAxisCase::InPhase;
    out.lowConfidence = out.axis.lowConfidence;
    out.note = out.axis.note;
    return out;
  }
  // Three-instant method (§1.4): at the instant omega t_j = -phi_j sensor j is
  // at its maximum; the plate is then y_i = |Y_i| cos(phi_i - phi_j).
  out.method = PhasorAxisCase::ThreeInstant;
  std::vector<TwistAxis> axes;
  std::string failures;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (std::abs(phasors(j)) <= noise) continue;
    std::vector<double> w(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      w[static_cast<std::size_t>(i)] = std::abs(phasors(i)) * std::cos(std::arg(phasors(i)) - std::arg(phasors(j)));
    }
    auto axis = staticTwistAxis(points, w, reference, options.plane);
    if (axis) {
      axes.push_back(std::move(*axis));
    } else {
      failures += "instant of sensor " + std::to_string(j + 1) + ": " + axis.error().message + "; ";
    }
  }
  if (axes.empty()) {
    return makeError(ErrorCode::NumericalFailure, "no instant gives a defined axis: " + failures,
                     "dynamic twist axis (three-instant method)");
  }
  // Average inclination: beta is defined modulo pi, so average the doubled
  // angle; average position: the mean of the feet of the perpendiculars from
  // the reference point (the "intercept" of §1.4, taken where it is measured).
  double s2 = 0, c2 = 0;
  Vector2 foot = Vector2::Zero();
  for (const auto& a : axes) {
    s2 += std::sin(2 * a.axis.beta);
    c2 += std::cos(2 * a.axis.beta);
    foot += a.axis.point;
    out.instantAxes.push_back(a.axis);
  }
  foot /= static_cast<double>(axes.size());
  const double beta = 0.5 * std::atan2(s2, c2);
  TwistAxis mean = axes.front();
  mean.axis.beta = beta;
  mean.axis.direction = Vector2(std::sin(beta), std::cos(beta));
  mean.axis.point = foot;
  for (const auto& a : axes) {
    double db = std::abs(a.axis.beta - beta);
    db = std::min(db, kPi - db);
    out.betaSpread = std::max(out.betaSpread, db);
    out.offsetSpread = std::max(out.offsetSpread, (a.axis.point - foot).norm());
  }
  // The spread of the instant axes is the honest uncertainty of the average.
  mean.axis.betaSigma = std::max(mean.axis.betaSigma, out.betaSpread);
  mean.axis.offsetSigma = std::max(mean.axis.offsetSigma, out.offsetSpread);
  double rot = 0;
  for (const auto& a : axes) rot += std::abs(a.axis.rotation);
  mean.axis.rotation = rot / static_cast<double>(axes.size());
  out.axis = mean;
  out.lowConfidence = true;
  out.note = "phases deviate up to " + formatNumber(out.maxPhaseDeviation * 180 / kPi) +
             " deg from 0/pi: the axis moves during the cycle; averaged over " + std::to_string(axes.size()) +
             " instants (inclination spread " + formatNumber(out.betaSpread * 180 / kPi) + " deg, position spread " +
             formatNumber(out.offsetSpread * 1e3) + " mm)";
  if (!failures.empty()) out.note += "; skipped " + failures.substr(0, failures.size() - 2);
  return out;
}

Result<std::vector<SweepAxis>> dynamicTwistSweep(const std::vector<Vector2>& points,
                                                 const std::vector<SweepPoint>& sweep, const Vector2& loadPoint,
                                                 const PhasorAxisOptions& options) {
  std::vector<SweepAxis> out;
  const auto n = static_cast<Eigen::Index>(points.size());
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    const auto& s = sweep[k];
    if (s.amplitude.size() != n || s.phase.size() != n) {
      return makeError(ErrorCode::InvalidArgument,
                       "amplitude/phase count differs from the " + std::to_string(n) + " sensors",
                       "dynamic twist sweep: frequency " + formatNumber(s.frequencyHz) + " Hz");
    }
    SweepAxis r;
    r.frequencyHz = s.frequencyHz;
    if (!std::isfinite(s.frequencyHz) || s.frequencyHz <= 0.0 || (s.amplitude.array() < 0.0).any()) {
      r.axis = makeError(ErrorCode::InvalidArgument, "frequency must be > 0 and amplitudes >= 0",
                         "dynamic twist sweep: row " + std::to_string(k + 1));
      out.push_back(std::move(r));
      continue;
    }
    ComplexVector y(n);
    for (Eigen::Index i = 0; i < n; ++i) y(i) = std::polar(s.amplitude(i), s.phase(i));
    r.axis = phasorTwistAxis(points, y, loadPoint, options);
    if (r.axis && s.forceAmplitude > 0.0) {
      // Dynamic compliance at the load point from the in-phase plane, referred to
      // the force phasor: x_lat / F.
      const auto& ax = r.axis->axis;
      const double xlat = std::abs(ax.plane.evaluate(loadPoint));
      r.twistArm = std::abs(ax.axis.signedArm(loadPoint));
      if (xlat > 0.0) {
        r.dynamicLateralStiffness = s.forceAmplitude / xlat;
        r.dynamicTwistStiffness = r.dynamicLateralStiffness * r.twistArm * r.twistArm;
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

Result<ModalAxis> modalTwistAxis(const FrfMatrix& frf, const std::vector<int>& responses, int reference,
                                 double frequencyHz, const std::vector<Vector2>& points, const Vector2& loadPoint,
                                 const PhasorAxisOptions& options) {
  MOZZI_TRY(frf.validate());
  if (reference < 0 || reference >= frf.referenceCount()) {
    return makeError(ErrorCode::NotFound, "reference index " + std::to_string(reference) + " out of range",
                     "modal twist axis");
  }
  if (responses.size() != points.size()) {
    return makeError(
        ErrorCode::InvalidArgument,
        std::to_string(responses.size()) + " FRF columns but " + std::to_string(points.size()) + " sensor points",
        "modal twist axis");
  }
  const auto nf = frf.lineCount();
  if (nf < 1 || !std::isfinite(frequencyHz) || frequencyHz <= 0.0 || frequencyHz < frf.frequencyHz(0) ||
      frequencyHz > frf.frequencyHz(nf - 1)) {
    return makeError(ErrorCode::InvalidArgument,
                     "frequency " + formatNumber(frequencyHz) + " Hz is outside the measured band or not positive",
                     "modal twist axis");
  }
  Eigen::Index k = 0;
  while (k + 1 < nf && frf.frequencyHz(k + 1) < frequencyHz) ++k;
  const Eigen::Index k1 = std::min<Eigen::Index>(k + 1, nf - 1);
  const double f0 = frf.frequencyHz(k), f1 = frf.frequencyHz(k1);
  const double t = (k1 == k || f1 == f0) ? 0.0 : (frequencyHz - f0) / (f1 - f0);
  const double omega = 2.0 * kPi * frequencyHz;
  // Eq. 7: receptance = accelerance / (-omega^2); general FrfType conversion.
  const Complex factor = frfConversionFactor(frf.type, FrfType::Receptance, omega);
  ModalAxis out;
  out.frequencyHz = frequencyHz;
  out.receptance.resize(static_cast<Eigen::Index>(responses.size()));
  const auto& h = frf.h[static_cast<std::size_t>(reference)];
  for (std::size_t i = 0; i < responses.size(); ++i) {
    const int c = responses[i];
    if (c < 0 || c >= h.cols()) {
      return makeError(ErrorCode::NotFound, "response index " + std::to_string(c) + " out of range",
                       "modal twist axis");
    }
    const Complex v = (1.0 - t) * h(k, c) + t * h(k1, c);
    out.receptance(static_cast<Eigen::Index>(i)) = v * factor;
  }
  // Receptances are small numbers [m/N]: compare the noise floor per unit force.
  PhasorAxisOptions o = options;
  o.plane.sigmaFloor = 0.0;
  auto axis = phasorTwistAxis(points, out.receptance, loadPoint, o);
  if (!axis)
    return makeError(axis.error().code, axis.error().message,
                     "modal twist axis at " + formatNumber(frequencyHz) + " Hz");
  out.axis = std::move(*axis);
  return out;
}

}  // namespace mozzi::core::stiffness
