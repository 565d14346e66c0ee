#include "core/tire/relaxation_length.h"

#include <cmath>
#include <sstream>

#include "core/signal/sine_fit.h"

namespace mozzi::core::tire {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool finite(double x) {
  return std::isfinite(x);
}

std::string hz(double f) {
  std::ostringstream s;
  s << f << " Hz";
  return s.str();
}

}  // namespace

double firstOrderPhaseLag(double sigma, double omega, double speed, double halfLength) {
  // lag = atan(w a/V) + atan(w sigma/V), appendix 1 first-order FRF
  return std::atan(omega * halfLength / speed) + std::atan(omega * sigma / speed);
}

Result<RelaxationFromPhase> relaxationLengthFromPhaseLag(double phaseLagRad, double omega, double speed,
                                                         double halfLength, double phaseLagStdError) {
  const char* where = "relaxation length from phase lag (thesis eq. 28)";
  if (!finite(phaseLagRad) || !finite(omega) || !finite(speed) || !finite(halfLength) || !finite(phaseLagStdError))
    return makeError(ErrorCode::InvalidArgument, "phase lag, frequency, speed and half-length must be finite", where);
  if (speed <= 0.0) return makeError(ErrorCode::InvalidArgument, "forward speed V must be positive", where);
  if (omega <= 0.0) return makeError(ErrorCode::InvalidArgument, "excitation frequency must be positive", where);
  if (halfLength < 0.0)
    return makeError(ErrorCode::InvalidArgument, "contact half-length a must not be negative", where);
  if (phaseLagStdError < 0.0) return makeError(ErrorCode::InvalidArgument, "phase standard error is negative", where);
  // theta = phi - atan(w a/V) is the carcass + contact lag atan(w sigma/V); it
  // must lie in (0, pi/2): at pi/2 the denominator of eq. 28 is zero.
  const double k = omega / speed;  // w/V [1/m]
  const double theta = phaseLagRad - std::atan(k * halfLength);
  constexpr double kMargin = 1e-9;
  if (theta <= 0.0) {
    std::ostringstream m;
    m << "phase lag " << phaseLagRad * 180.0 / kPi
      << " deg is not larger than the contact-patch lag atan(w a/V) = " << std::atan(k * halfLength) * 180.0 / kPi
      << " deg: no positive relaxation length explains it";
    return makeError(ErrorCode::NumericalFailure, m.str(), where);
  }
  if (theta >= kPi / 2.0 - kMargin) {
    std::ostringstream m;
    m << "phase lag " << phaseLagRad * 180.0 / kPi
      << " deg reaches atan(w a/V) + 90 deg: the denominator of eq. 28 a (w/V)^2 tan(phi) - w/V is zero or changes "
         "sign";
    return makeError(ErrorCode::NumericalFailure, m.str(), where);
  }
  const double t = std::tan(theta);
  RelaxationFromPhase r;
  r.sigma = t / k;                                         // sigma = (V/w) tan(phi - atan(w a/V))
  r.sigmaStdError = (1.0 + t * t) / k * phaseLagStdError;  // d sigma/d phi = (V/w) sec^2(theta)
  return r;
}

Result<HarmonicYawResult> relaxationFromHarmonicYaw(const std::vector<HarmonicYawRecord>& records,
                                                    const HarmonicYawSettings& s) {
  const char* where = "harmonic yaw test (thesis §1.9)";
  if (records.empty()) return makeError(ErrorCode::InvalidArgument, "no excitation frequency recorded", where);
  if (!finite(s.speed) || s.speed <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "forward speed V must be positive (V = 0 has no relaxation length)",
                     where);
  if (!finite(s.halfLength) || s.halfLength < 0.0)
    return makeError(ErrorCode::InvalidArgument, "contact half-length a must be finite and not negative", where);
  if (s.forceSign != 1.0 && s.forceSign != -1.0)
    return makeError(ErrorCode::InvalidArgument, "force sign must be +1 or -1", where);
  if (!finite(s.minCycles) || s.minCycles <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "minimum number of cycles must be positive", where);
  if (!(s.bandLowHz <= s.bandHighHz))
    return makeError(ErrorCode::InvalidArgument, "averaging band low edge above its high edge", where);

  HarmonicYawResult out;
  double sum = 0.0, sumVar = 0.0, sumSq = 0.0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const HarmonicYawRecord& rec = records[i];
    const std::string at = std::string(where) + ", record " + std::to_string(i + 1);
    if (rec.yawRate.size() != rec.lateralForce.size())
      return makeError(ErrorCode::InvalidArgument, "yaw rate and lateral force have different lengths", at);
    if (!finite(rec.sampleRateHz) || rec.sampleRateHz <= 0.0)
      return makeError(ErrorCode::InvalidArgument, "sample rate must be positive", at);
    Result<signal::SineFit> rateFit =
        rec.excitationFrequencyHz > 0.0
            ? signal::fitSineKnownFrequency(rec.yawRate, rec.sampleRateHz, rec.excitationFrequencyHz)
            : signal::fitSine(rec.yawRate, rec.sampleRateHz);
    if (!rateFit) return makeError(rateFit.error().code, "yaw-rate sine fit: " + rateFit.error().message, at);
    const double f = rateFit->frequencyHz;
    const double duration = static_cast<double>(rec.yawRate.size()) / rec.sampleRateHz;
    if (duration * f < s.minCycles) {
      std::ostringstream m;
      m << "only " << duration * f << " cycles at " << hz(f) << " (at least " << s.minCycles
        << " needed for a sine fit)";
      return makeError(ErrorCode::InvalidArgument, m.str(), at);
    }
    // The force is fitted at the yaw frequency (the excitation), §1.9.
    auto forceFit = signal::fitSineKnownFrequency(rec.lateralForce, rec.sampleRateHz, f);
    if (!forceFit) return makeError(forceFit.error().code, "lateral-force sine fit: " + forceFit.error().message, at);
    if (rateFit->amplitude <= 0.0 || forceFit->amplitude <= 0.0)
      return makeError(ErrorCode::NumericalFailure, "a fitted amplitude is zero: no phase can be read", at);

    signal::SineFit angle = *rateFit;  // yaw angle = rate shifted by -pi/2 (velocity leads by pi/2, §1.9)
    angle.phaseRad = signal::displacementPhaseFromVelocity(rateFit->phaseRad);
    signal::SineFit force = *forceFit;
    if (s.forceSign < 0.0) force.phaseRad = signal::wrapPhase(force.phaseRad + kPi);
    const signal::PhaseDifference lead = signal::phaseDifference(force, angle);

    RelaxationPoint p;
    p.frequencyHz = f;
    p.phaseLagRad = -lead.phaseRad;
    p.phaseLagStdError = lead.stdError;
    const double omega = 2.0 * kPi * f;
    p.yawAmplitude = rateFit->amplitude / omega;
    p.forceAmplitude = forceFit->amplitude;
    auto r = relaxationLengthFromPhaseLag(p.phaseLagRad, omega, s.speed, s.halfLength, p.phaseLagStdError);
    if (r) {
      p.valid = true;
      p.sigma = r->sigma;
      p.sigmaStdError = r->sigmaStdError;
    } else {
      p.note = r.error().message;
    }
    const bool inBand = f >= s.bandLowHz * (1.0 - 1e-6) && f <= s.bandHighHz * (1.0 + 1e-6);
    if (p.valid && inBand) {
      ++out.pointsInBand;
      sum += p.sigma;
      sumSq += p.sigma * p.sigma;
      sumVar += p.sigmaStdError * p.sigmaStdError;
    }
    out.points.push_back(std::move(p));
  }
  if (out.pointsInBand == 0) {
    std::ostringstream m;
    m << "no valid relaxation length between " << s.bandLowHz << " and " << s.bandHighHz << " Hz";
    for (const auto& p : out.points)
      if (!p.valid) m << "; " << hz(p.frequencyHz) << ": " << p.note;
    return makeError(ErrorCode::NumericalFailure, m.str(), where);
  }
  const double n = out.pointsInBand;
  out.meanSigma = sum / n;                        // thesis §5.4: average of the band
  out.meanSigmaStdError = std::sqrt(sumVar) / n;  // var(mean) = sum var_i / n^2
  out.bandScatter = n > 1 ? std::sqrt(std::max(0.0, (sumSq - n * out.meanSigma * out.meanSigma) / (n - 1))) : 0.0;
  return out;
}

}  // namespace mozzi::core::tire
