#pragma once
// Sine fitting of sampled signals (thesis §1.3: "a sine-wave fitting has been
// carried out on the laser outputs", half amplitude = fitted amplitude; §1.9:
// yaw rate and lateral force fitted with sine functions and their phase lag
// taken, velocity leading displacement by pi/2).
//
// Model: y(t) = offset + A cos(2 pi f t + phi), t = t0 + i / fs [s].
// Known f: linear least squares in (a, b, c) with y = c + a cos(wt) + b sin(wt),
// A = sqrt(a^2 + b^2), phi = atan2(-b, a). Unknown f: the same model with
// omega free, solved by Ceres (Levenberg-Marquardt) from an FFT-peak start.
// Standard errors from the least-squares covariance s^2 (J'J)^-1 with
// s^2 = RSS / (n - p), propagated to A and phi to first order; the 95%
// half-widths use Student's t with n - p degrees of freedom.

#include <optional>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::signal {

struct SineFit {
  double frequencyHz = 0.0;
  double amplitude = 0.0;    // A >= 0 [EU] (half the peak-to-peak of the fitted sine)
  double phaseRad = 0.0;     // phi in (-pi, pi] at t = 0
  double offset = 0.0;       // c [EU]
  double residualRms = 0.0;  // sqrt(RSS / n) [EU]
  double sigma = 0.0;        // sqrt(RSS / (n - p)), the noise estimate [EU]
  double amplitudeStdError = 0.0;
  double phaseStdError = 0.0;  // [rad]
  double offsetStdError = 0.0;
  double frequencyStdError = 0.0;  // [Hz], 0 for a known frequency
  Eigen::Index sampleCount = 0;
  int degreesOfFreedom = 0;  // n - p
  double tQuantile95 = 0.0;  // Student t(0.975, n - p)

  double amplitudeCi95() const { return tQuantile95 * amplitudeStdError; }  // half-widths
  double phaseCi95() const { return tQuantile95 * phaseStdError; }
};

// y sampled at fs [Hz] from t0 [s]. Errors: fewer than 4 samples, NaN samples,
// fs <= 0, f outside (0, fs/2), a singular design (f at 0 or Nyquist).
Result<SineFit> fitSineKnownFrequency(const VectorRef& y, double sampleRateHz, double frequencyHz, double t0 = 0.0);

// Frequency free. The start is the FFT peak (zero-padded, parabolic
// interpolation) unless a guess is given. Errors as above, plus no convergence.
Result<SineFit> fitSine(const VectorRef& y, double sampleRateHz, std::optional<double> frequencyGuessHz = std::nullopt,
                        double t0 = 0.0);

// phi wrapped into (-pi, pi].
double wrapPhase(double phiRad);

// Phase of a over b, wrapped: positive when a leads b (e.g. force against yaw
// angle in §1.9), with the standard error sqrt(se_a^2 + se_b^2) (independent fits).
struct PhaseDifference {
  double phaseRad = 0.0;
  double stdError = 0.0;
};
PhaseDifference phaseDifference(const SineFit& a, const SineFit& b);

// The displacement (angle) phase from a velocity (rate) fit: for
// x = X cos(wt + phi_x), x' = w X cos(wt + phi_x + pi/2), so phi_x = phi_v - pi/2.
double displacementPhaseFromVelocity(double velocityPhaseRad);

// Student t quantile t(0.975, dof) (Cornish-Fisher expansion about the normal
// 1.959964; relative error < 1e-4 for dof >= 3). dof < 1 gives 0.
double studentT975(int dof);

}  // namespace mozzi::core::signal
