#include "core/signal/window.h"

#include <cmath>
#include <string>

namespace mozzi::core::signal {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

const char* windowKindName(WindowKind kind) {
  switch (kind) {
    case WindowKind::Rectangular: return "rectangular";
    case WindowKind::Hann: return "Hann";
    case WindowKind::FlatTop: return "flat-top";
    case WindowKind::Force: return "force";
    case WindowKind::Exponential: return "exponential";
  }
  return "rectangular";
}

Result<Vector> makeWindow(const WindowSpec& spec, Eigen::Index n, double sampleRateHz, Eigen::Index originSample) {
  const std::string where = std::string(windowKindName(spec.kind)) + " window";
  if (n < 1) return makeError(ErrorCode::InvalidArgument, "window length must be at least 1 sample", where);
  if (!std::isfinite(sampleRateHz) || sampleRateHz <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be finite and positive", where);
  }
  if (!std::isfinite(spec.exponentialTauS) || spec.exponentialTauS < 0.0) {
    return makeError(ErrorCode::InvalidArgument, "exponential time constant must be positive", where + ", tau");
  }
  Vector w = Vector::Ones(n);
  const double nd = static_cast<double>(n);
  switch (spec.kind) {
    case WindowKind::Rectangular: break;
    case WindowKind::Hann:
      // w = 0.5 - 0.5 cos(2 pi i / n), periodic form
      for (Eigen::Index i = 0; i < n; ++i) w[i] = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / nd);
      break;
    case WindowKind::FlatTop: {
      const double a[5] = {0.21557895, 0.41663158, 0.277263158, 0.083578947, 0.006947368};
      for (Eigen::Index i = 0; i < n; ++i) {
        const double x = 2.0 * kPi * static_cast<double>(i) / nd;
        w[i] = a[0] - a[1] * std::cos(x) + a[2] * std::cos(2 * x) - a[3] * std::cos(3 * x) + a[4] * std::cos(4 * x);
      }
      break;
    }
    case WindowKind::Force: {
      if (!std::isfinite(spec.forceWidthS) || spec.forceWidthS <= 0.0) {
        return makeError(ErrorCode::InvalidArgument, "force window width must be positive", where + ", width");
      }
      if (spec.forceWidthS * sampleRateHz < 1.0) {
        // Narrower than a sample: the window keeps at most the sample at t = 0
        // and the FRF is noise (coherence near 0), not an error to hide.
        return makeError(ErrorCode::InvalidArgument,
                         "force window width " + std::to_string(spec.forceWidthS) +
                             " s is shorter than one sample (1/" + std::to_string(sampleRateHz) + " Hz)",
                         where + ", width");
      }
      if (!std::isfinite(spec.forceTaperS) || spec.forceTaperS < 0.0) {
        return makeError(ErrorCode::InvalidArgument, "force window taper must not be negative", where + ", taper");
      }
      for (Eigen::Index i = 0; i < n; ++i) {
        const double t = static_cast<double>(i - originSample) / sampleRateHz;
        if (t <= spec.forceWidthS) continue;
        const double u = t - spec.forceWidthS;
        // half-cosine taper: 0.5 (1 + cos(pi u / taper)) for 0 < u < taper
        w[i] =
            (spec.forceTaperS > 0.0 && u < spec.forceTaperS) ? 0.5 * (1.0 + std::cos(kPi * u / spec.forceTaperS)) : 0.0;
      }
      break;
    }
    case WindowKind::Exponential:
      if (spec.exponentialTauS <= 0.0) {
        return makeError(ErrorCode::InvalidArgument, "exponential time constant must be positive", where + ", tau");
      }
      break;
  }
  if (spec.exponentialTauS > 0.0) {
    // w(t) = exp(-t / tau) from the origin on
    for (Eigen::Index i = originSample < 0 ? 0 : originSample; i < n; ++i) {
      w[i] *= std::exp(-static_cast<double>(i - originSample) / sampleRateHz / spec.exponentialTauS);
    }
  }
  return w;
}

double exponentialWindowAddedDecayRate(double tauS) {
  return 1.0 / tauS;
}

namespace {
Result<void> checkPole(const PoleEstimate& p, double tauS, const char* where) {
  if (!std::isfinite(tauS) || tauS <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "exponential time constant must be positive", where);
  }
  if (!std::isfinite(p.naturalFrequencyHz) || p.naturalFrequencyHz <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "natural frequency must be positive", where);
  }
  if (!std::isfinite(p.zeta) || p.zeta < 0.0 || p.zeta >= 1.0) {
    return makeError(ErrorCode::InvalidArgument, "damping ratio must lie in [0, 1) (underdamped pole)", where);
  }
  return {};
}

PoleEstimate poleFrom(double sigma, double omegaD) {
  const double omegaN = std::hypot(sigma, omegaD);
  return PoleEstimate{omegaN / (2.0 * kPi), sigma / omegaN};
}
}  // namespace

Result<PoleEstimate> correctExponentialWindowDamping(const PoleEstimate& measured, double tauS) {
  const char* where = "exponential window damping correction";
  MOZZI_TRY(checkPole(measured, tauS, where));
  const double omegaM = 2.0 * kPi * measured.naturalFrequencyHz;
  const double sigma = measured.zeta * omegaM - exponentialWindowAddedDecayRate(tauS);  // sigma_true = sigma_m - 1/tau
  const double omegaD = omegaM * std::sqrt(1.0 - measured.zeta * measured.zeta);        // unchanged by the window
  if (sigma <= 0.0) {
    return makeError(ErrorCode::NumericalFailure,
                     "identified decay rate " + std::to_string(measured.zeta * omegaM) +
                         " 1/s is not larger than the window's 1/tau = " + std::to_string(1.0 / tauS) +
                         " 1/s; the damping cannot be corrected (check tau or the identification)",
                     where);
  }
  return poleFrom(sigma, omegaD);
}

Result<PoleEstimate> applyExponentialWindowDamping(const PoleEstimate& truePole, double tauS) {
  const char* where = "exponential window damping";
  MOZZI_TRY(checkPole(truePole, tauS, where));
  const double omegaN = 2.0 * kPi * truePole.naturalFrequencyHz;
  const double sigma = truePole.zeta * omegaN + exponentialWindowAddedDecayRate(tauS);
  const double omegaD = omegaN * std::sqrt(1.0 - truePole.zeta * truePole.zeta);
  return poleFrom(sigma, omegaD);
}

}  // namespace mozzi::core::signal
