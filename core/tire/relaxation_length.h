#pragma once
// Tyre relaxation length from the harmonic yaw test on the Mototiremeter
// (thesis §1.8, §1.9, §5.1, §5.4).
//
// The yaw servomotor swings the fork harmonically (1.5 deg, 0.42..2.10 Hz) at
// a forward speed V (5 km/h); a rate gyro gives the yaw rate, the arm load
// cell the lateral force. Both are fitted with sines (core/signal/sine_fit.h);
// the yaw-angle phase is the yaw-rate phase minus pi/2 and the phase lag phi of
// the force behind the yaw angle gives sigma.
//
// First-order tyre (appendix 1, last FRF, with sigma = sigma_c + C/C_yg):
//   F/psi = C (V - i w a) / (V + i w sigma),
//   lag phi = atan(w a / V) + atan(w sigma / V), hence
//   sigma = (V/w) tan(phi - atan(w a / V))
//         = (tan phi - a w/V) / (w/V + a (w/V)^2 tan phi).                  (1)
// This is thesis eq. 28 with the phase counted as force minus yaw angle
// (phi_eq28 = -lag). Eq. 28 as printed also multiplies by the cornering
// stiffness C_bFalpha, which makes it N m instead of m; the phase of the
// first-order FRF does not depend on C, so (1) has no such factor (see
// docs/validation/tire.md). The denominator vanishes when
// phi - atan(w a/V) = pi/2 (reference/notes.md, eq. 28); lags outside
// (atan(w a/V), atan(w a/V) + pi/2) have no positive sigma and are reported,
// never divided through.

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::tire {

struct RelaxationFromPhase {
  double sigma = 0.0;          // [m], eq. (1)
  double sigmaStdError = 0.0;  // [m], first-order propagation of the phase error
};

// sigma from the lag of the lateral force behind the yaw angle [rad] at the
// excitation angular frequency omega [rad/s], forward speed V [m/s] and contact
// half-length a [m]; phaseLagStdError [rad] is propagated with
// d sigma / d phi = (V/w) (1 + (w sigma/V)^2).
// Errors: V, omega not positive, a negative, a NaN input, or a lag outside the
// model's range (denominator of eq. 28 at or through zero).
Result<RelaxationFromPhase> relaxationLengthFromPhaseLag(double phaseLagRad, double omega, double speed,
                                                         double halfLength, double phaseLagStdError = 0.0);

// The inverse: the lag a first-order tyre with relaxation length sigma shows.
double firstOrderPhaseLag(double sigma, double omega, double speed, double halfLength);

// One excitation frequency of the harmonic yaw test.
struct HarmonicYawRecord {
  double excitationFrequencyHz = 0.0;  // the commanded frequency; <= 0: estimated from the yaw rate
  double sampleRateHz = 0.0;
  Vector yawRate;       // gyro [rad/s] (any consistent unit; only the phase is used)
  Vector lateralForce;  // load cell [N]
};

struct HarmonicYawSettings {
  double speed = 5.0 / 3.6;  // V [m/s]; thesis §1.9: 5 km/h
  double halfLength = 0.0;   // a [m], contact patch half-length (Table 17)
  double forceSign = 1.0;    // -1 when the load cell reads positive for a negative F_y
  double minCycles = 2.0;    // fewer cycles in a record: error (a sine fit needs them)
  double bandLowHz = 0.84;   // averaging band, thesis §5.4 (0.84, 1.26, 1.68 Hz)
  double bandHighHz = 1.68;
};

struct RelaxationPoint {
  double frequencyHz = 0.0;
  double phaseLagRad = 0.0;       // force behind yaw angle
  double phaseLagStdError = 0.0;  // sqrt(se_force^2 + se_yawrate^2)
  double yawAmplitude = 0.0;      // fitted yaw-angle amplitude = rate amplitude / w [rad]
  double forceAmplitude = 0.0;    // [N]
  bool valid = false;             // false: lag outside the model range; sigma not computed
  double sigma = 0.0;             // [m]
  double sigmaStdError = 0.0;     // [m]
  std::string note;               // why the point is flagged
};

struct HarmonicYawResult {
  std::vector<RelaxationPoint> points;  // one per record, in input order
  double meanSigma = 0.0;               // plain mean over the valid points in the band (thesis §5.4)
  double meanSigmaStdError = 0.0;       // sqrt(sum se_i^2)/n, fits independent
  double bandScatter = 0.0;             // sample standard deviation of sigma in the band (0 for n = 1)
  int pointsInBand = 0;
};

// Fits every record, computes sigma per frequency and the band average.
// Errors: settings out of range, a record that cannot be fitted (too few
// cycles, NaN, length mismatch), or no valid point in the band.
Result<HarmonicYawResult> relaxationFromHarmonicYaw(const std::vector<HarmonicYawRecord>& records,
                                                    const HarmonicYawSettings& settings);

}  // namespace mozzi::core::tire
