#pragma once
// The machinery every simulated rig shares (internal to devices/sim): a
// SignalModel produces the physical value of each input scan by scan; the
// simulated device runs it on the threaded-device base with the common
// parameters (seed, real-time pacing, injected overruns, disconnects and
// timeouts) and passes the values through the calibration pipeline of a
// 16-bit DAQ (physical value -> raw code -> volts -> engineering units).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::sim {

// Physical values of the inputs for scans [first, first + n): n x inputs.
// Scans are asked for in increasing order; a gap (a block lost to an injected
// overrun) means those scans were skipped on the simulated clock.
class SignalModel {
 public:
  virtual ~SignalModel() = default;
  virtual core::Result<void> prepare(const AcquisitionConfig& config) = 0;
  virtual void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out,
                        FaultCounters& counters) = 0;
  // Trigger marks the model puts in scans [first, first + n) (e.g. the start
  // of each excitation step); sent after the block that holds them.
  virtual void marks(std::int64_t first, Eigen::Index n, std::vector<TriggerEvent>& out) {
    (void)first;
    (void)n;
    (void)out;
  }
};

// "sim.realtime": pace the stream at its clock, or as fast as it is taken.
ParameterSpec realtimeParameter();
// "sim.seed", "sim.realtime" and the "fault.*" switches.
std::vector<ParameterSpec> commonSimParameters();
// An input wired to the USB-1608FS-Plus ranges, DC or AC coupled.
InputChannelSpec simInput(const std::string& name, bool iepe);

using CapsFn = Capabilities (*)();
using ModelFn = std::unique_ptr<SignalModel> (*)();
std::unique_ptr<Driver> makeSimDriver(std::string name, std::string description, std::string model, CapsFn caps,
                                      ModelFn makeModel);

}  // namespace mozzi::devices::sim
