#pragma once
// Internal to devices/rigtests: one acquisition session of a sequence step.
// The devices' stream events are queued by their sinks (acquisition threads)
// and handled here on the sequence's thread, which also calls the live
// callback, so front ends see every callback on one thread (rig_sequence.h).

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "devices/common/driver.h"
#include "devices/rigtests/rig_sequence.h"

namespace mozzi::devices::rigtests::detail {

// Scans of one session, as they arrived.
struct SessionData {
  StreamHeader header;
  // Columns as the header's channels [EU]; while the session runs only the
  // first `rows` rows are data (the rest is capacity), at its end rows() == rows.
  core::Matrix values;
  Eigen::Index rows = 0;
  std::vector<TriggerEvent> triggers;
  std::vector<OverloadEvent> overloads;
  std::vector<OverrunEvent> overruns;
  StreamEnd end;
  bool cancelled = false;      // the sequence's cancel flag stopped it
  bool actuatorEnded = false;  // the actuator's stream ended first (unplugged, error)
  StreamEnd actuatorEnd;
  Eigen::Index scans() const { return rows; }
};

struct SessionHooks {
  // After each block is appended (first row of the block, its row count).
  std::function<void(const SessionData&, Eigen::Index first, Eigen::Index rows)> block;
  // For each trigger mark the DAQ sends.
  std::function<void(const SessionData&, const TriggerEvent&)> trigger;
  // Per scan of a block: the derived quantity for the live readout (or empty).
  std::function<core::Vector(const core::Matrix& block)> derived;
  std::string derivedLabel;
};

struct SessionPlan {
  AcquisitionConfig daqConfig;                      // validated by the caller
  std::optional<AcquisitionConfig> actuatorConfig;  // when an actuator device is used
  int step = 0;  // also varies a simulated rig's "sim.seed" per step (seed * 1009 + step)
  std::string stepLabel;
  // A session that delivers no event for this long is stopped and ends as a
  // timeout (drivers end stalled streams themselves; this is the backstop).
  std::chrono::milliseconds silence{15000};
};

// Opens (if needed), configures and starts the actuator then the DAQ, pumps
// their events until the DAQ's stream ends, the actuator's ends, or `cancel`
// is set; stops both. An error only when a device refuses to open, configure
// or start (nothing of this session ran); an unplug mid-session is data with
// end.reason Disconnected.
core::Result<SessionData> runSession(Device& daq, Device* actuator, const SessionPlan& plan, const Callbacks& callbacks,
                                     const CancelFlag* cancel, const SessionHooks& hooks);

// Seconds of data -> scans at fs (rounded up, at least 1).
std::int64_t scansFor(double seconds, double sampleRateHz);

// Index of the channel named `name` in a header; -1 when absent.
int channelIndex(const StreamHeader& header, const std::string& name);

// A sentence for why a stream ended early ("the device was unplugged").
std::string endCause(const StreamEnd& end);

}  // namespace mozzi::devices::rigtests::detail
