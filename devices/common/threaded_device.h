#pragma once
// The session life cycle every streaming device shares: state machine
// (Closed -> Open -> Configured -> Running), configure() through
// validateConfig, the stream header, one acquisition thread per session, the
// end event, and the reaping of a session that ended by itself (completed,
// unplugged, timed out) so the device can be configured again. Drivers (real
// and simulated) implement only what differs: how a configuration is applied
// to the hardware, how a session starts, the acquisition loop, and how a
// blocked loop is woken by stop().

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "devices/common/driver.h"

namespace mozzi::devices {

class ThreadedDevice : public Device {
 public:
  ThreadedDevice(DeviceDescriptor descriptor, Capabilities caps);
  // Derived classes call stop() (or close()) in their own destructor: the
  // acquisition thread runs their virtual runSession().
  ~ThreadedDevice() override;

  const DeviceDescriptor& descriptor() const override { return descriptor_; }
  Capabilities capabilities() const override { return caps_; }
  DeviceState state() const override { return state_.load(); }

  // Validates against the capabilities, lets the driver adjust the applied
  // configuration (prepareConfig), builds the calibration chains and lets the
  // driver set their device calibration (calibrateChains).
  core::Result<AcquisitionConfig> configure(const AcquisitionConfig& requested) final;
  // Emits the header and runs runSession() on the acquisition thread.
  core::Result<void> start(StreamSink sink) final;
  // Asks the loop to end, wakes it (interruptSession) and joins; idempotent.
  void stop() final;

 protected:
  // Adjust `applied` (rate quantisation, model preparation); an error refuses it.
  virtual core::Result<void> prepareConfig(AcquisitionConfig& applied) = 0;
  // Device calibration of each configured channel; default: identity.
  virtual void calibrateChains(std::vector<ChannelChain>& chains) { (void)chains; }
  // Called by start() before the header is sent (start the scan, clear buffers).
  virtual core::Result<void> beginSession() { return {}; }
  // The acquisition loop; it must end through endSession() (exactly once).
  virtual void runSession() = 0;
  // Wakes a loop that waits for data; stopRequested() is already true.
  virtual void interruptSession() {}

  void setState(DeviceState s) { state_ = s; }
  bool stopRequested() const { return stopRequested_.load(); }
  void publish(StreamEvent&& event) { sink_(std::move(event)); }
  // The last event of a session: marks it ended (to be reaped) and sends it.
  void endSession(EndReason reason, std::int64_t delivered, const std::string& message);
  // Real-time pacing: sleeps until `seconds` of stream time after `wallStart`
  // (or until stop() is asked for), in slices short enough for stop to be prompt.
  void paceTo(std::chrono::steady_clock::time_point wallStart, double seconds) const;
  // Fills the values of a block from its raw codes (calibration pipeline)
  // unless they are set already, and sends it with the overloads it holds.
  void emitBlock(DataBlock&& block);

  DeviceDescriptor descriptor_;
  Capabilities caps_;
  AcquisitionConfig config_;
  std::vector<ChannelChain> chains_;

 private:
  void reapEndedSession();

  std::atomic<DeviceState> state_{DeviceState::Closed};
  std::atomic<bool> stopRequested_{false};
  std::atomic<bool> ended_{false};
  StreamSink sink_;
  std::thread worker_;
};

}  // namespace mozzi::devices
