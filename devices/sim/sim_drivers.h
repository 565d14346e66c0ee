#pragma once
// Simulated rigs registered as drivers (STYLE 3, after QGroundControl's
// MockLink and libsigrok's demo driver): seeded and deterministic, with
// switches for disconnect, timeout, overrun, double hit and overload, and
// counters tests can assert on. Their data pass through the same calibration
// pipeline as real hardware (physical value -> raw code of a 16-bit +/-range
// DAQ -> device calibration -> volts -> engineering units), so quantisation
// and full-scale clipping are those of the real chain.
//
// Common parameters: "sim.seed", "sim.realtime" (pace the stream at the
// wall clock; off = as fast as the consumer takes it), "fault.*".

#include <cstdint>
#include <memory>
#include <string>

#include "devices/common/driver.h"
#include "devices/common/threaded_device.h"

namespace mozzi::devices::sim {

struct FaultCounters {
  std::int64_t scansGenerated = 0;
  std::int64_t hits = 0;  // hammer hits generated
  std::int64_t doubleHits = 0;
  std::int64_t overloadHits = 0;
  std::int64_t overruns = 0;
  std::int64_t lostScans = 0;
  std::int64_t disconnects = 0;
  std::int64_t timeouts = 0;
};

// Every simulated device is a SimulatedRig; tests read its counters.
class SimulatedRig : public ThreadedDevice {
 public:
  using ThreadedDevice::ThreadedDevice;
  virtual FaultCounters counters() const = 0;
};

// Impact hammer station: PCB 086C03 hammer (2.25 mV/N) and up to seven
// accelerometers (10 mV/(m/s^2), PCB M352C65, thesis §1.4; hammer + 7 = the 8
// inputs of the MCC USB-1608FS-Plus) on a spatial virtual specimen
// (specimen_models.h) simulated by core/signal's exact MDOF integration.
// "hammer.point" (a DOF label of the specimen's mesh, empty = its driving
// point) is where the hammer strikes; "response.dofs" (comma-separated DOF
// labels, empty = the first DOFs of the mesh) are the accelerometers of inputs
// 1..7 in order; an input without a DOF reads noise only. An unknown label
// fails configure() with an error naming the label and the specimen.
std::unique_ptr<Driver> makeHammerStationDriver();
// Motostiffmeter (thesis §1.1): actuator static ramp up to 5000 N or sine
// 1..45 Hz with amplitude falling logarithmically with frequency (soft start
// over 0.5 s), load cell +/-200 kg, four lasers of 20 mm range and 4 um
// resolution; the plate answers a sine through the specimen's bending and
// torsion modes (StaticSpecimen::receptance), a ramp quasi-statically.
std::unique_ptr<Driver> makeStiffnessRigDriver();

// Simulated function generator "sim-funcgen" giving the simulated
// Motostiffmeter its actuator set-point, as usbtmc-funcgen gives the real
// one (docs/hardware.md): the same parameters (mode static-ramp | sine,
// static.max_force, static.period_s, sine.frequency, sine.amplitude,
// actuator.newtons_per_volt, channel) and the limits of a 33522B into high
// impedance (2 channels, 2 mVpp to 20 Vpp, 10 V peak, sine up to 30 MHz),
// checked by configure() before anything is set; no inputs. configure()
// programs the set-point, start() switches the output on, stop() and close()
// off. A sim-stiffness device configured with actuator.source =
// "sim-funcgen" takes its force from it (the ramp is the generator's
// triangle -F -> +F -> -F, the sine the set amplitude falling with frequency
// as the actuator's does, actuatorSineAmplitude) and refuses to configure
// when the generator has not been set; one simulated bench per process.
// counters(): configurations applied and outputs switched on.
struct FunctionGeneratorSimCounters {
  int configured = 0;
  int started = 0;
  std::string lastMode;
  double lastFrequencyHz = 0.0;
  double lastAmplitudeN = 0.0;  // sine amplitude or ramp peak set [N]
  double lastAmplitudeVpp = 0.0;
};
std::unique_ptr<Driver> makeFunctionGeneratorSimDriver();
FunctionGeneratorSimCounters functionGeneratorSimCounters();

// Mototiremeter (thesis §1.8, §1.9): rotating disk up to 50 km/h, yaw
// (+/-10 deg, +/-6 by default) and camber (+/-55 deg, appendix 2; §1.8 prints
// 54; +/-45 by default) servos, load cells for F_y, M_z and M_y, a rate gyro on
// the fork; a harmonic yaw test (trigger mark at each frequency step, its level
// the step's frequency [Hz]), steady side-slip and camber sweeps (triangles),
// or one held steady-state set-point (mode "steady-state": sweep.slip_deg and
// sweep.camber_deg held from the start) on one of the six thesis tyres.
inline constexpr double kTyreTesterMaxYawDeg = 10.0;     // side-slip servo range (§1.8, appendix 2)
inline constexpr double kTyreTesterMaxCamberDeg = 55.0;  // camber range (appendix 2; §1.8: 54)
inline constexpr double kTyreTesterMaxSpeedKmh = 50.0;   // disk speed (§1.8)
std::unique_ptr<Driver> makeTyreTesterDriver();

// Assumed normalised camber stiffness (dF_y/dgamma)/F_z [1/rad] of the
// simulated tyres (the thesis tabulates none for motorcycle tyres).
inline constexpr double kAssumedNormalisedCamberStiffness = 0.9;

// The tyre the tester simulates for a parameter map (defaults completed).
struct TyreTesterSetup {
  std::string tyre;  // catalogue key, "tyre-120-70-r17"
  double pressurePa = 2e5;
  double load = 0.0;                // F_z [N]
  double speed = 0.0;               // V [m/s]
  double halfLength = 0.0;          // a [m], Table 17 at the pressure
  double corneringStiffness = 0.0;  // C [N/rad]
  double camberStiffness = 0.0;     // [N/rad]
  double relaxationLength = 0.0;    // sigma [m] (eq. 48 unless set)
  double outerRadius = 0.0;         // [m]
};
core::Result<TyreTesterSetup> tyreTesterSetup(const ParameterMap& parameters);
// Table 17 contact half-length, linear in pressure between the tabulated ones.
double tyreHalfLengthAt(const std::string& tyreKey, double pressurePa);

// Plays time records back as a live acquisition (see replay_driver.cpp).
std::unique_ptr<Driver> makeReplayDriver();
// The capabilities a replay of `path` has (its channels and rate), from the
// 58 headers alone: the samples are skipped unread, so a recording of any size
// is summarised at a cost independent of its length. Errors name the file.
core::Result<Capabilities> replayRecordingCapabilities(const std::string& path);

// Half-sine contact time of a hammer of mass m on a tip of stiffness k:
// T = pi sqrt(m / k) (linear contact spring, rigid specimen).
double hammerPulseWidthS(double hammerMassKg, double tipStiffnessNPerM);

// Actuator sine amplitude at f for the Motostiffmeter: A(f) = A1 [1 - 0.8 ln(f) / ln(45)]
// (f in Hz, A1 the amplitude at 1 Hz; falls to 0.2 A1 at 45 Hz, §1.1:
// "the amplitude of vibration decreases logarithmically").
double actuatorSineAmplitude(double amplitudeAt1HzN, double frequencyHz);

}  // namespace mozzi::devices::sim
