#pragma once
// Test sequences of the tyre tester, the Mototiremeter (thesis §1.8, §1.9,
// §5.1, appendix 2): a rotating disk under the tyre, a yaw (side-slip) servo
// and a camber servo on the arm, load cells for F_y, M_z and M_y, a rate gyro
// on the fork.
//
// Set-points are checked before anything moves: the disk speed against the
// machine's 50 km/h, side-slip and yaw amplitude against its +/-10 deg and
// camber against its +/-55 deg (appendix 2; §1.8 prints 54 deg), then against
// the working limits the operator set (by default +/-6 deg and +/-45 deg, §1.8:
// "in order to avoid dangerous oscillations of the whole arm"). A refusal names
// the set-point, its value and the limit.
//
// Relaxation test (§1.9, §5.1): the harmonic yaw programme (1.5 deg, a list of
// frequencies, about 10 cycles each, 5 km/h); each frequency's record is
// committed as soon as the next one starts; after a settling cycle the yaw rate
// and the lateral force are fitted with sines, the lag of the force behind the
// yaw angle gives the relaxation length at that frequency (core/tire/
// relaxation_length.h, eq. 28 corrected), and the mean over 0.84..1.68 Hz is
// the test's result (§5.4).
//
// Steady-state test (appendix 2): a side-slip sweep at zero camber and a
// camber sweep at zero side-slip, one held set-point per step (settle, then
// average F_y, M_z, M_y); at the end the characteristics (cornering, aligning,
// camber and twisting-torque stiffness as slopes at the origin,
// core/tire/steady_state.h) and the Magic Formula fit of F_y and M_z
// (core/tire/magic_formula.h), all with standard uncertainties.
//
// Storage: a rig set-up and a tyre test (kind "relaxation" or
// "steady-state", status Running) first; each step commits its record, its
// measured point (steady state) and its parameters in one transaction; the end
// stores the whole-test parameters and the status.

#include <string>
#include <vector>

#include "core/tire/magic_formula.h"
#include "devices/common/driver.h"
#include "devices/rigtests/rig_sequence.h"

namespace mozzi::devices::rigtests {

// The machine's limits (thesis §1.8, appendix 2).
inline constexpr double kMachineMaxSlipDeg = 10.0;
inline constexpr double kMachineMaxCamberDeg = 55.0;
inline constexpr double kMachineMaxSpeedKmh = 50.0;

struct TyreRigSetup {
  std::string rigName = "Mototiremeter";
  ChannelConfig yawRate;         // rate gyro on the fork [rad/s]
  ChannelConfig lateralForce;    // F_y [N]
  ChannelConfig aligningMoment;  // M_z [N m]
  ChannelConfig spinMoment;      // M_y [N m]
  ChannelConfig yawAngle;        // yaw servo's angle [rad]
  ChannelConfig camberAngle;     // camber servo's angle [rad]
  double sampleRateHz = 200.0;
  ParameterMap daqParameters;  // rig parameters (a simulated tester: tyre, pressure, load, seed, realtime)
  // Working limits the operator allows (§1.8: +/-6 deg side-slip, +/-45 deg
  // camber by default), at most the machine's.
  double slipLimitDeg = 6.0;
  double camberLimitDeg = 45.0;
  // Operating condition and the tyre's contact half-length a (Table 17), for
  // eq. 28 and the Magic Formula.
  double verticalLoadN = 1500.0;
  double pressurePa = 2e5;
  double halfLengthM = 0.0;
  double unloadedRadiusM = 0.3;
};

struct RelaxationSettings {
  double speedKmh = 5.0;                                            // §1.9
  std::vector<double> frequenciesHz{0.42, 0.84, 1.26, 1.68, 2.10};  // §5.1
  double yawAmplitudeDeg = 1.5;                                     // §1.9
  int cycles = 10;                                                  // per frequency (§5.1: about 10)
  int settleCycles = 1;                        // dropped at the start of each frequency (the lag's transient)
  double bandLowHz = 0.84, bandHighHz = 1.68;  // averaging band (§5.4)
};

struct SteadyStateSettings {
  double speedKmh = 5.0;
  std::vector<double> slipDeg{-6, -5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 6};  // at zero camber
  std::vector<double> camberDeg{-45, -40, -35, -30, -25, -20, -15, -10, -5, 0,
                                5,   10,  15,  20,  25,  30,  35,  40,  45};  // at zero side-slip
  double settleS = 2.0;           // after each set-point (appendix 2 holds 10 s)
  double holdS = 3.0;             // averaged
  double slipWindowDeg = 3.0;     // slope at the origin: cubic over +/- this (linear range, §7.1)
  double camberWindowDeg = 10.0;  // straight line over +/- this
  bool fitMagicFormula = true;
};

struct RelaxationOutcome : Outcome {};

struct SteadyStatePoint {
  double slipRad = 0.0, camberRad = 0.0;
  double force = 0.0, forceSe = 0.0;    // F_y [N]
  double torque = 0.0, torqueSe = 0.0;  // M_z [N m]
  double spinMoment = 0.0;              // M_y [N m]
  bool slipSweep = true;                // false: a camber-sweep point
};

struct SteadyStateOutcome : Outcome {
  std::vector<SteadyStatePoint> points;
  std::optional<core::tire::MfLateralFit> lateral;
  std::optional<core::tire::MfAligningFit> aligning;
};

// The checks done before anything moves (exposed for forms that validate as
// the operator types). The error names the set-point, its value and the limit.
core::Result<void> checkRelaxationSettings(const TyreRigSetup& setup, const RelaxationSettings& settings);
core::Result<void> checkSteadyStateSettings(const TyreRigSetup& setup, const SteadyStateSettings& settings);

// Errors: set-points refused (nothing was sent), the device refusing the
// first step, or the project refusing the test; otherwise an Outcome.
core::Result<RelaxationOutcome> runRelaxationTest(Device& daq, const TyreRigSetup& setup,
                                                  const RelaxationSettings& settings, const StoreTarget& target,
                                                  const Callbacks& callbacks = {}, const CancelFlag* cancel = nullptr);
core::Result<SteadyStateOutcome> runSteadyStateTest(Device& daq, const TyreRigSetup& setup,
                                                    const SteadyStateSettings& settings, const StoreTarget& target,
                                                    const Callbacks& callbacks = {},
                                                    const CancelFlag* cancel = nullptr);

// The set-up of the simulated tester (sim-tyre-tester) on a thesis tyre at a
// pressure: gyro, load cells and servo angles on inputs 0 to 5, the thesis
// load, Table 17's half-length at the pressure.
core::Result<TyreRigSetup> simulatedTyreSetup(const std::string& tyreKey, double pressureBar, std::uint64_t seed,
                                              bool realtime);

}  // namespace mozzi::devices::rigtests
