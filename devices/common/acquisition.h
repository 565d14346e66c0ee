#pragma once
// Acquisition configuration and the typed stream every device produces:
// a header (actual rate, channels, units, start time), data blocks (raw codes
// and scaled values with the index of their first sample), overload, overrun
// or dropout, trigger, and one end event with its reason. Events reach a sink
// on the device's acquisition thread, in order; the end event is always last.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "devices/common/calibration.h"

namespace mozzi::devices {

struct ChannelConfig {
  int input = 0;               // device input index (AI0 = 0)
  std::string name;            // "hammer", "acc 21:+Z"
  std::uint8_t rangeCode = 0;  // one of the input's ranges (InputRange::code)
  Coupling coupling = Coupling::Dc;
  bool iepe = false;             // ask the device for IEPE supply (only where it has one)
  double conditionerGain = 1.0;  // external conditioner gain, V/V
  core::signal::Transducer transducer;
  core::Dof dof;
};

struct AcquisitionConfig {
  double sampleRateHz = 0.0;  // per channel; configure() returns the quantised rate
  std::vector<ChannelConfig> channels;
  std::int64_t blockScans = 0;  // scans per data block; 0 = driver default (~50 ms)
  std::int64_t scanCount = 0;   // total scans; 0 = continuous until stop()
  ParameterMap parameters;      // rig-specific, validated against Capabilities::parameters
};

// Checks a configuration against capabilities: at least one channel, inputs
// exist and are unique, range codes exist, coupling and IEPE available, rate
// quantised within per-channel and aggregate limits, parameters valid. Returns
// the applied configuration (rate quantised, parameters completed).
core::Result<AcquisitionConfig> validateConfig(const Capabilities& caps, const AcquisitionConfig& requested);

// The calibration chain of each configured channel (identity device
// calibration); drivers overwrite the calibration with the device's own.
std::vector<ChannelChain> chainsFor(const Capabilities& caps, const AcquisitionConfig& config);

struct StreamHeader {
  double sampleRateHz = 0.0;                    // actual rate per channel
  std::vector<core::signal::Channel> channels;  // name, transducer (unit), DOF, full scale [EU]
  std::chrono::system_clock::time_point startTime;
  std::string device;  // descriptor label
};

struct DataBlock {
  std::int64_t firstSample = 0;   // index of the first scan since start
  std::vector<std::int32_t> raw;  // scans x channels, scan-interleaved, codes as sent
  core::Matrix values;            // scans x channels [EU] after the calibration pipeline
  Eigen::Index scanCount() const { return values.rows(); }
};

struct OverloadEvent {
  std::int64_t firstSample = 0;         // block in which it happened
  int channel = 0;                      // index into the header's channels
  std::int64_t samplesAtFullScale = 0;  // >= 3 in this block
};

struct OverrunEvent {
  std::int64_t atSample = 0;    // next sample index expected when it happened
  std::int64_t lostScans = -1;  // -1 = unknown (the device cleared its FIFO)
  bool recovered = false;       // the driver restarted the scan
  std::string detail;
};

struct TriggerEvent {
  std::int64_t sample = 0;  // sample index of the trigger instant
  int channel = 0;
  double level = 0.0;  // [EU]
};

enum class EndReason { Completed, Stopped, Disconnected, Timeout, Overrun, Error };
const char* endReasonName(EndReason reason);

struct StreamEnd {
  EndReason reason = EndReason::Completed;
  std::int64_t samplesDelivered = 0;  // scans handed on before the end
  std::string message;
};

using StreamEvent = std::variant<StreamHeader, DataBlock, OverloadEvent, OverrunEvent, TriggerEvent, StreamEnd>;
using StreamSink = std::function<void(StreamEvent&&)>;

// Counts samples at full scale per channel in a block and reports an overload
// when a channel has at least `threshold` (common practice: 3) such samples.
std::vector<OverloadEvent> detectOverloads(const DataBlock& block, const std::vector<ChannelChain>& chains,
                                           std::int64_t threshold = 3);

// A thread-safe sink that keeps every event, for tests, the CLI and simple
// consumers: waitForEnd() blocks until the end event or a timeout.
class StreamCollector {
 public:
  StreamSink sink();
  bool waitForEnd(std::chrono::milliseconds timeout);
  bool waitForScans(std::int64_t scans, std::chrono::milliseconds timeout);

  std::optional<StreamHeader> header() const;
  std::optional<StreamEnd> end() const;
  std::vector<OverrunEvent> overruns() const;
  std::vector<OverloadEvent> overloads() const;
  std::vector<TriggerEvent> triggers() const;
  std::int64_t scans() const;
  // Every block concatenated: scans x channels [EU], and the raw codes.
  core::Matrix values() const;
  std::vector<std::int32_t> raw() const;
  std::vector<std::int64_t> blockStarts() const;
  bool orderedAndContiguous() const;  // each block starts where the previous ended

 private:
  void push(StreamEvent&& e);
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::optional<StreamHeader> header_;
  std::optional<StreamEnd> end_;
  std::vector<DataBlock> blocks_;
  std::vector<OverrunEvent> overruns_;
  std::vector<OverloadEvent> overloads_;
  std::vector<TriggerEvent> triggers_;
  std::int64_t scans_ = 0;
  bool eventAfterEnd_ = false;
};

}  // namespace mozzi::devices
