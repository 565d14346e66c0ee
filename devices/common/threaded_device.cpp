#include "devices/common/threaded_device.h"

#include <algorithm>

namespace mozzi::devices {

ThreadedDevice::ThreadedDevice(DeviceDescriptor descriptor, Capabilities caps)
    : descriptor_(std::move(descriptor)), caps_(std::move(caps)) {}

ThreadedDevice::~ThreadedDevice() {
  // Normally joined by the derived destructor; this is the last safety net
  // against std::terminate from a joinable thread.
  if (worker_.joinable()) {
    stopRequested_ = true;
    worker_.join();
  }
}

void ThreadedDevice::reapEndedSession() {
  if (state_ == DeviceState::Running && ended_ && worker_.joinable()) {
    worker_.join();
    state_ = DeviceState::Configured;
  }
}

core::Result<AcquisitionConfig> ThreadedDevice::configure(const AcquisitionConfig& requested) {
  reapEndedSession();
  if (state_ == DeviceState::Closed)
    return core::makeError(core::ErrorCode::InvalidArgument, "open the device first", descriptor_.label());
  if (state_ == DeviceState::Running)
    return core::makeError(core::ErrorCode::InvalidArgument, "stop the acquisition first", descriptor_.label());
  auto applied = validateConfig(caps_, requested);
  if (!applied) return applied.error();
  auto ok = prepareConfig(*applied);
  if (!ok) return ok.error();
  config_ = *applied;
  chains_ = chainsFor(caps_, config_);
  calibrateChains(chains_);
  state_ = DeviceState::Configured;
  return config_;
}

core::Result<void> ThreadedDevice::start(StreamSink sink) {
  reapEndedSession();
  if (state_ != DeviceState::Configured)
    return core::makeError(core::ErrorCode::InvalidArgument, "configure the device before starting",
                           descriptor_.label());
  sink_ = std::move(sink);
  stopRequested_ = false;
  ended_ = false;
  auto ok = beginSession();
  if (!ok) return ok;
  StreamHeader h;
  h.sampleRateHz = config_.sampleRateHz;
  h.startTime = std::chrono::system_clock::now();
  h.device = descriptor_.label();
  for (std::size_t i = 0; i < chains_.size(); ++i) {
    const auto& c = config_.channels[i];
    core::signal::Channel ch;
    ch.name = c.name.empty() ? caps_.inputs[static_cast<std::size_t>(c.input)].name : c.name;
    ch.transducer = c.transducer;
    ch.dof = c.dof;
    ch.fullScale = chains_[i].fullScaleEngineering();
    h.channels.push_back(ch);
  }
  sink_(StreamEvent(std::move(h)));
  state_ = DeviceState::Running;
  worker_ = std::thread([this] { runSession(); });
  return {};
}

void ThreadedDevice::stop() {
  stopRequested_ = true;
  if (worker_.joinable()) {
    interruptSession();
    worker_.join();
  }
  if (state_ == DeviceState::Running) state_ = DeviceState::Configured;
}

void ThreadedDevice::endSession(EndReason reason, std::int64_t delivered, const std::string& message) {
  ended_ = true;
  sink_(StreamEvent(StreamEnd{reason, delivered, message}));
}

void ThreadedDevice::paceTo(std::chrono::steady_clock::time_point wallStart, double seconds) const {
  using Clock = std::chrono::steady_clock;
  const auto due = wallStart + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  while (!stopRequested_ && Clock::now() < due)
    std::this_thread::sleep_for(std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(20)));
}

void ThreadedDevice::emitBlock(DataBlock&& block) {
  const std::size_t nc = chains_.size();
  if (block.values.size() == 0 && nc > 0) {
    const Eigen::Index n = static_cast<Eigen::Index>(block.raw.size() / nc);
    block.values.resize(n, static_cast<Eigen::Index>(nc));
    for (Eigen::Index s = 0; s < n; ++s)
      for (std::size_t c = 0; c < nc; ++c)
        block.values(s, static_cast<Eigen::Index>(c)) =
            chains_[c].engineeringFromRaw(block.raw[static_cast<std::size_t>(s) * nc + c]);
  }
  auto overloads = detectOverloads(block, chains_);
  sink_(StreamEvent(std::move(block)));
  for (auto& o : overloads) sink_(StreamEvent(o));
}

}  // namespace mozzi::devices
