#pragma once
// Test sequences of the stiffness rig, the Motostiffmeter (thesis §1.1 to
// §1.3, §1.7): a component locked at one end, the actuator loading the other
// end through a load cell, four lasers on a reference plate at the loaded end.
//
// Static test (§1.2, §2.1, eq. 29 to 32): one slow triangular force ramp
// 0 -> +F -> -F -> 0 (the thesis uses +/-300 N, fork B +/-500 N); the load cell
// and the four lasers are recorded and core/stiffness's static twist test
// gives k_lat (regression of the load-point displacement on the force), the
// twist axis (least-squares plane of the four lasers: position and inclination
// beta from the plate's v axis), a_tw and k_tw = k_lat a_tw^2 with their
// standard uncertainties, and, when the set-up names the specimen's bending
// and torsion axes, the decomposition of eq. 22 to 27 into k_bend and k_tors.
//
// Dynamic test (§1.3, Fig. 29): for each frequency of a list (1 to 45 Hz, the
// actuator's band) a sine force, a settling time, then a record of whole
// cycles; each channel is fitted with a sine of the set frequency
// (core/signal/sine_fit.h) and the dynamic twist axis, the dynamic lateral and
// twist stiffness come from the fitted phasors (core/stiffness/dynamic_twist.h).
// A step whose lasers reach their range or whose stream lost data keeps its
// record and says so, and the sweep goes on.
//
// The actuator's set-point goes to a function-generator device when one is
// given (devices/funcgen, parameters mode, static.max_force, static.period_s,
// sine.frequency, sine.amplitude), else to the DAQ device when it drives the
// actuator itself (the simulated rig sim-stiffness: sine.amplitude_1hz).
// Set-points are checked against the actuator's limits (5000 N, 1..45 Hz,
// §1.1) and the load cell's range before anything is sent.
//
// Storage: a rig set-up (devices, channels, transducers, plate geometry) and
// a rig test (kind static or dynamic, status Running) are stored first; each
// step commits its raw record (load cell and lasers, SI units) and its results
// in one transaction; the end stores the whole-test results and the status
// (Complete, Interrupted with what is missing, Failed).

#include <optional>
#include <string>
#include <vector>

#include "core/stiffness/decomposition.h"
#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/plate_motion.h"
#include "devices/common/driver.h"
#include "devices/rigtests/rig_sequence.h"

namespace mozzi::devices::rigtests {

// Actuator and band of the Motostiffmeter (thesis §1.1).
inline constexpr double kActuatorMaxForceN = 5000.0;
inline constexpr double kActuatorMinFrequencyHz = 1.0;
inline constexpr double kActuatorMaxFrequencyHz = 45.0;

struct StiffnessRigSetup {
  std::string rigName = "Motostiffmeter";
  // The DAQ channels: the load cell (force along +w at the load point [N])
  // and one laser per plate point (displacement along +w [m]).
  ChannelConfig loadCell;
  std::vector<ChannelConfig> lasers;
  // Plate coordinates (core/stiffness/plate_motion.h): u = x, v = z, w = y (§1.2).
  std::vector<core::Vector2> laserPoints;  // one per laser [m]
  core::Vector2 loadPoint = core::Vector2::Zero();
  double sampleRateHz = 1000.0;  // per channel; >= 20 x the highest sine frequency
  ParameterMap daqParameters;    // rig parameters of the DAQ device (a simulated rig: specimen, seed, realtime)
  double loadCellFullScaleN = 200.0 * 9.80665;  // +/-200 kg (§1.1)
  // The specimen's bending and torsion axes (modal twist axes, §1.4, §1.7)
  // for the decomposition; both or neither.
  std::optional<core::stiffness::PlateAxis> bendAxis;
  std::optional<core::stiffness::PlateAxis> torsAxis;
  // The reference plate's outline and the constrained (locked) end of the
  // specimen, plate coordinates [m]; for the set-up's picture and check, and
  // stored with the geometry. Empty / none when not given.
  std::vector<core::Vector2> plateOutline;
  std::optional<core::Vector2> constrainedEnd;
};

struct StaticTestSettings {
  double peakForceN = 300.0;  // F of the ramp 0 -> +F -> -F -> 0
  double periodS = 20.0;      // duration of the ramp
};

struct DynamicTestSettings {
  std::vector<double> frequenciesHz{1, 2, 5, 10, 15};
  double amplitudeN = 300.0;  // sine set-point (the force falls with frequency, §1.1)
  double settleCycles = 3.0;  // discarded after the soft start; at least minSettleS
  double minSettleS = 1.0;
  double recordCycles = 10.0;  // fitted; at least minRecordS
  double minRecordS = 1.0;
};

struct StaticOutcome : Outcome {
  std::optional<core::stiffness::StaticTwistResult> twist;
  std::optional<core::stiffness::Decomposition> decomposition;
};

struct DynamicStep {
  double frequencyHz = 0.0;
  std::optional<core::stiffness::SweepAxis> axis;  // none when the step gave no axis
};

struct DynamicOutcome : Outcome {
  std::vector<DynamicStep> sweep;  // per frequency that ran
};

// The checks before a run: every laser at least 5 mm from the others and on
// the plate, the lasers not on one line (the twist axis needs the plate's
// plane: the laser farthest from the line through the others less than 5 mm
// off it is refused), the constrained end off the plate and away from the
// load point. The error's `where` is the key of the
// field to correct (setup.laser3_u, setup.constrained_u, ...).
core::Result<void> checkPlateGeometry(const StiffnessRigSetup& setup);
// The set-up form's key of laser `index`'s (0-based) coordinate `axis` ("u"
// or "v"): "setup.laser1_u"; the geometry check names its fields so.
std::string laserFieldKey(std::size_t index, const char* axis);

// Checks the settings against the actuator and the set-up (peak force within
// 5000 N and the load cell's range, frequencies within 1..45 Hz and below a
// twentieth of the sample rate, at least three lasers, as many points as
// lasers, the plate geometry of checkPlateGeometry). The error names the
// setting, its value and the limit.
core::Result<void> checkStaticSettings(const StiffnessRigSetup& setup, const StaticTestSettings& settings);
core::Result<void> checkDynamicSettings(const StiffnessRigSetup& setup, const DynamicTestSettings& settings);

// Runs the tests. `daq` records the load cell and lasers; `actuator` (may be
// null) is a function generator giving the actuator its set-point. Errors:
// settings refused (nothing was sent to a device), a device that refuses its
// configuration before the first step, or the project refusing the test.
// Everything after the first step has started ends in an Outcome.
core::Result<StaticOutcome> runStaticStiffnessTest(Device& daq, Device* actuator, const StiffnessRigSetup& setup,
                                                   const StaticTestSettings& settings, const StoreTarget& target,
                                                   const Callbacks& callbacks = {}, const CancelFlag* cancel = nullptr);
core::Result<DynamicOutcome> runDynamicStiffnessTest(Device& daq, Device* actuator, const StiffnessRigSetup& setup,
                                                     const DynamicTestSettings& settings, const StoreTarget& target,
                                                     const Callbacks& callbacks = {},
                                                     const CancelFlag* cancel = nullptr);

// The set-up of the simulated rig (sim-stiffness) on a virtual specimen with
// static data: load cell on input 0 (10 V / 200 kg), four lasers on inputs 1
// to 4 (1 V/mm, +/-10 V: the 20 mm range), the specimen's plate layout and its
// bending and torsion axes when it has them.
core::Result<StiffnessRigSetup> simulatedStiffnessSetup(const std::string& specimenKey, std::uint64_t seed,
                                                        bool realtime);

}  // namespace mozzi::devices::rigtests
