#pragma once
// What a device can do, as data (STYLE 2): the GUI builds its acquisition
// forms from this, configure() validates against it.

#include <cstdint>
#include <string>
#include <vector>

#include "devices/common/parameters.h"

namespace mozzi::devices {

// One input range of an ADC: codes [0, 2^bits - 1] map linearly onto
// [minVolts, maxVolts]; offset binary for bipolar ranges.
struct InputRange {
  std::string label;      // e.g. "+/-10 V"
  std::uint8_t code = 0;  // the device's own range code (USB-1608FS-Plus: 0..7)
  double minVolts = -10.0;
  double maxVolts = 10.0;
};

enum class Coupling { Dc, Ac };
enum class TriggerKind { Immediate, Software, ExternalEdge, ExternalLevel };

const char* couplingName(Coupling coupling);
const char* triggerKindName(TriggerKind kind);

struct InputChannelSpec {
  std::string name;  // "AI0"
  std::vector<InputRange> ranges;
  std::vector<Coupling> couplings;  // supported at the device input (external conditioners add their own)
  bool iepeSupply = false;          // the device itself can power IEPE sensors
  int resolutionBits = 16;
};

struct OutputSpec {
  std::string name;  // "actuator set-point"
  std::string unit;  // "N"
  double min = 0.0;
  double max = 0.0;
};

// Sample-rate quantisation: the device divides a timebase by an integer,
// rate = timebaseHz / divisor, divisor in [minDivisor, maxDivisor].
struct RateSpec {
  double minHz = 0.0;           // per channel
  double maxHz = 0.0;           // per channel
  double maxAggregateHz = 0.0;  // sum over enabled channels
  double timebaseHz = 0.0;      // 0: any rate in [minHz, maxHz] is exact
  bool simultaneous = true;     // all channels sampled at the same instant
};

struct Capabilities {
  std::string model;
  std::vector<InputChannelSpec> inputs;
  std::vector<OutputSpec> outputs;
  RateSpec rates;
  std::vector<TriggerKind> triggers;
  std::int64_t fifoSamples = 0;           // on-board buffer, samples over all channels
  std::vector<ParameterSpec> parameters;  // rig-specific settings (faults, specimen, ...)
};

// The rate the hardware will actually run at for a requested rate: the nearest
// timebase / integer when a timebase is given. Errors: non-finite or outside
// [minHz, maxHz].
core::Result<double> quantiseRate(const RateSpec& spec, double requestedHz);

}  // namespace mozzi::devices
