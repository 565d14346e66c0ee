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

#include "devices/common/driver.h"
#include "devices/common/threaded_device.h"

namespace mozzi::devices::sim {

struct FaultCounters {
  std::int64_t scansGenerated = 0;
  std::int64_t hits = 0;            // hammer hits generated
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

// Impact hammer station: PCB 086C03 hammer (2.25 mV/N) and three
// accelerometers (10 mV/(m/s^2), PCB M352C65, thesis §1.4) on a virtual
// specimen simulated by core/signal's exact MDOF integration.
std::unique_ptr<Driver> makeHammerStationDriver();
// Motostiffmeter (thesis §1.1): actuator static ramp up to 5000 N or sine
// 1..45 Hz with amplitude falling logarithmically with frequency, load cell
// +/-200 kg, four lasers of 20 mm range and 4 um resolution.
std::unique_ptr<Driver> makeStiffnessRigDriver();

// Half-sine contact time of a hammer of mass m on a tip of stiffness k:
// T = pi sqrt(m / k) (linear contact spring, rigid specimen).
double hammerPulseWidthS(double hammerMassKg, double tipStiffnessNPerM);

// Actuator sine amplitude at f for the Motostiffmeter: A(f) = A1 [1 - 0.8 ln(f) / ln(45)]
// (f in Hz, A1 the amplitude at 1 Hz; falls to 0.2 A1 at 45 Hz, §1.1:
// "the amplitude of vibration decreases logarithmically").
double actuatorSineAmplitude(double amplitudeAt1HzN, double frequencyHz);

}  // namespace mozzi::devices::sim
