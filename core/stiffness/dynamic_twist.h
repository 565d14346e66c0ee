#pragma once
// Dynamic twist axes from harmonic displacement phasors of the plate sensors:
//  - actuator excitation (thesis §1.3): sine-fitted laser amplitudes and phases
//    per excitation frequency (the sine fit itself lives in core/signal), the
//    axis at each frequency and its evolution over 1 to 45 Hz (Fig. 29);
//  - hammer excitation (thesis §1.4): three accelerometer FRFs, receptance at a
//    chosen frequency (eq. 7, division by -omega^2), the phase check (eq. 8, 9)
//    and, when the phases are not close to 0 or pi, the three-instant method
//    with averaging.
// Plate coordinates as in plate_motion.h (u = x, v = z, w = y for §1.3/§1.4).

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/stiffness/plate_motion.h"

namespace mozzi::core::stiffness {

enum class PhasorAxisCase {
  InPhase,       // all phases within the tolerance of 0 or pi: one time-independent axis
  ThreeInstant,  // general phase shift: axes at the instants of each sensor's maximum, averaged (§1.4)
};
const char* phasorAxisCaseName(PhasorAxisCase c);  // "in-phase", "three-instant"

struct PhasorAxisOptions {
  PlaneFitOptions plane;
  double phaseTolerance = 0.1745;  // 10 degrees from 0 or pi
};

struct PhasorAxis {
  PhasorAxisCase method = PhasorAxisCase::InPhase;
  TwistAxis axis;                      // in-phase axis, or the averaged one
  double maxPhaseDeviation = 0.0;      // largest distance of a relative phase from {0, pi} [rad]
  std::vector<PlateAxis> instantAxes;  // three-instant case: the axis at each sensor's maximum
  double betaSpread = 0.0;             // three-instant case: max |beta_j - beta_mean| [rad]
  double offsetSpread = 0.0;           // three-instant case: max distance of the instant feet from the mean [m]
  bool lowConfidence = false;
  std::string note;
};

// Axis from complex displacement phasors Y_i = |Y_i| e^{i phi_i} [m] (or per
// unit force) of the sensors. Signed amplitudes |Y_i| sign(cos(phi_i - phi_ref))
// with phi_ref the phase of the largest phasor define the in-phase plane (eq. 9
// at the instant of maximum displacement).
Result<PhasorAxis> phasorTwistAxis(const std::vector<Vector2>& points, const ComplexVector& phasors,
                                   const Vector2& reference, const PhasorAxisOptions& options = {});

// One excitation frequency of an actuator sweep (§1.3): laser amplitudes [m] and
// phases [rad] from the sine fit; optionally the load-cell amplitude [N] and phase.
struct SweepPoint {
  double frequencyHz = 0.0;
  Vector amplitude;             // per laser [m]
  Vector phase;                 // per laser [rad]
  double forceAmplitude = 0.0;  // [N]; 0 when unknown
  double forcePhase = 0.0;      // [rad]
};
struct SweepAxis {
  double frequencyHz = 0.0;
  Result<PhasorAxis> axis = Error{};
  // |F| / |x_lat| and k_lat a_tw^2 at this frequency, 0 when no force is given.
  double dynamicLateralStiffness = 0.0;
  double dynamicTwistStiffness = 0.0;
  double twistArm = 0.0;
};
// The axis at every frequency; a frequency whose axis cannot be found keeps its
// error in SweepAxis::axis and does not stop the sweep. Errors only for bad
// shapes (amplitude and phase lengths differing from the sensor count).
Result<std::vector<SweepAxis>> dynamicTwistSweep(const std::vector<Vector2>& points,
                                                 const std::vector<SweepPoint>& sweep, const Vector2& loadPoint,
                                                 const PhasorAxisOptions& options = {});

// Modal twist axis (§1.4): three (or more) accelerometer FRFs of `frf` (response
// columns `responses`, reference column `reference`) at `frequencyHz`
// (interpolated linearly between lines), converted to receptance.
struct ModalAxis {
  double frequencyHz = 0.0;
  ComplexVector receptance;  // [m/N] per sensor
  PhasorAxis axis;
};
Result<ModalAxis> modalTwistAxis(const FrfMatrix& frf, const std::vector<int>& responses, int reference,
                                 double frequencyHz, const std::vector<Vector2>& points, const Vector2& loadPoint,
                                 const PhasorAxisOptions& options = {});

}  // namespace mozzi::core::stiffness
