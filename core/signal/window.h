#pragma once
// Time windows for hammer and random excitation (thesis §1.6): rectangular,
// Hann, flat-top, force window and exponential window, plus the damping the
// exponential window adds to every pole and its correction.
//
// Time origin: t = (i - originSample) / fs [s], i.e. the trigger instant when the
// caller passes the record's pre-trigger length as originSample.

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::signal {

enum class WindowKind { Rectangular, Hann, FlatTop, Force, Exponential };

const char* windowKindName(WindowKind kind);

struct WindowSpec {
  WindowKind kind = WindowKind::Rectangular;
  // Force window: 1 for t <= forceWidthS (the pre-trigger included), then a
  // half-cosine taper to 0 over forceTaperS, then 0. Widths in seconds.
  double forceWidthS = 0.0;
  double forceTaperS = 0.0;
  // Exponential window: w(t) = exp(-t / tau) for t >= 0 and 1 before the
  // origin. When > 0 it also multiplies a Force window (the usual hammer
  // reference window is force x exponential).
  double exponentialTauS = 0.0;
};

// n samples at sample rate fs [Hz]. Hann and flat-top are the periodic
// (DFT-even) forms used for spectral analysis; flat-top uses the five-term
// coefficients a = (0.21557895, 0.41663158, 0.277263158, 0.083578947,
// 0.006947368) (Heinzel, Ruediger, Schilling 2002, "FTSRS"-type as in SciPy's
// 'flattop'). Errors: n < 1, fs not positive, widths negative, tau not positive.
Result<Vector> makeWindow(const WindowSpec& spec, Eigen::Index n, double sampleRateHz, Eigen::Index originSample = 0);

// The exponential window w(t) = exp(-t/tau) turns each modal decay
// exp(-sigma t) into exp(-(sigma + 1/tau) t): every pole lambda = -sigma + i omega_d
// moves to -(sigma + 1/tau) + i omega_d, so zeta_meas * omega_n,meas =
// zeta_true * omega_n + 1/tau with the damped frequency omega_d unchanged.
double exponentialWindowAddedDecayRate(double tauS);  // 1/tau [1/s]

struct PoleEstimate {
  double naturalFrequencyHz = 0.0;  // undamped natural frequency f_n [Hz]
  double zeta = 0.0;                // viscous damping ratio [-]
};

// Removes the decay added by an exponential window of time constant tau from an
// identified pole: sigma = zeta_m omega_m - 1/tau, omega_d = omega_m sqrt(1 -
// zeta_m^2), omega_n = sqrt(sigma^2 + omega_d^2), zeta = sigma / omega_n.
// Error when the identified decay is smaller than the window's own (the pole
// would become unstable: the identification or tau is wrong) or the inputs are
// outside 0 < zeta < 1, f > 0, tau > 0.
Result<PoleEstimate> correctExponentialWindowDamping(const PoleEstimate& measured, double tauS);

// The reverse: the pole an exponential window of time constant tau makes out of
// the true pole (used to report the bias and in tests).
Result<PoleEstimate> applyExponentialWindowDamping(const PoleEstimate& truePole, double tauS);

}  // namespace mozzi::core::signal
