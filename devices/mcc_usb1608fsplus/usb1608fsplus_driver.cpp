#include "devices/mcc_usb1608fsplus/usb1608fsplus_driver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "devices/common/threaded_device.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/usb/usb_transport.h"

namespace mozzi::devices::mcc {

namespace {

constexpr const char* kDriverName = "mcc-usb1608fsplus";
constexpr const char* kModel = "MCC USB-1608FS-Plus";

Capabilities makeCapabilities() {
  Capabilities caps;
  caps.model = kModel;
  for (int c = 0; c < kChannelCount; ++c) {
    InputChannelSpec in;
    in.name = "AI" + std::to_string(c);
    in.ranges = ranges();
    in.couplings = {Coupling::Dc};  // AC coupling and IEPE come from the external conditioners
    in.iepeSupply = false;
    in.resolutionBits = 16;
    caps.inputs.push_back(in);
  }
  caps.rates.minHz = kTimebaseHz / 4294967296.0;  // pacer_period = 2^32 - 1
  caps.rates.maxHz = kMaxRatePerChannelHz;
  caps.rates.maxAggregateHz = kMaxAggregateHz;
  caps.rates.timebaseHz = kTimebaseHz;
  caps.rates.simultaneous = true;  // one ADC per channel
  caps.triggers = {TriggerKind::Immediate, TriggerKind::Software};
  caps.fifoSamples = kFifoSamples;
  caps.parameters = {
      ParameterSpec{"overrun.policy",
                    "On FIFO overrun",
                    ParameterType::Choice,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {"restart", "stop"},
                    std::string("restart"),
                    "restart: clear the FIFO, report the gap and scan on; stop: end the session"},
      ParameterSpec{
          "usb.transfer_timeout_ms",
          "Transfer timeout",
          ParameterType::Integer,
          "ms",
          10.0,
          60000.0,
          {},
          std::int64_t{2000},
          "a bulk transfer that brings no data for this long ends the session (at least twice its fill time)"},
      ParameterSpec{"usb.transfer_ms",
                    "Transfer length",
                    ParameterType::Integer,
                    "ms",
                    1.0,
                    1000.0,
                    {},
                    std::int64_t{100},
                    "data per bulk transfer; four are queued, so about 400 ms of data are buffered on the host"},
  };
  return caps;
}

struct Packet {
  usb::TransferStatus status;
  std::vector<std::uint8_t> bytes;
  bool stopRequest = false;
};

class Usb1608FsPlusDevice final : public ThreadedDevice {
 public:
  explicit Usb1608FsPlusDevice(DeviceDescriptor d) : ThreadedDevice(std::move(d), makeCapabilities()) {}
  ~Usb1608FsPlusDevice() override { close(); }

  core::Result<void> open() override {
    if (transport_) return {};
    auto t = usb::UsbTransport::open(kVendorId, kProductId, descriptor_.busPath);
    if (!t) return t.error();
    transport_ = std::move(*t);
    descriptor_.serial = transport_->info().serial;
    descriptor_.busPath = transport_->info().busPath();
    // Calibration table: 512 bytes at address 0, read 64 bytes at a time
    // (one full-speed control packet per request).
    std::vector<std::uint8_t> table;
    for (std::uint16_t a = 0; a < kCalTableBytes; a += 64) {
      auto chunk = transport_->controlIn(kCalMemory, a, 0, 64);
      if (!chunk) return fail(chunk.error());
      if (chunk->size() != 64)
        return fail(
            core::makeError(core::ErrorCode::IoError, "short calibration memory read", "address " + std::to_string(a)));
      table.insert(table.end(), chunk->begin(), chunk->end());
    }
    auto cal = parseCalibrationTable(table);
    if (!cal) return fail(cal.error());
    calibration_ = *cal;
    // A scan left running by another program would stall our requests.
    auto stop = transport_->controlOut(kAInScanStop, 0, 0, {});
    if (!stop) return fail(stop.error());
    setState(DeviceState::Open);
    return {};
  }

  void close() override {
    stop();
    if (transport_) transport_->setDisconnectCallback(nullptr);
    transport_.reset();
    setState(DeviceState::Closed);
  }

 protected:
  core::Result<void> prepareConfig(AcquisitionConfig& applied) override {
    auto period = pacerPeriodFor(applied.sampleRateHz, static_cast<int>(applied.channels.size()));
    if (!period) return period.error();
    applied.sampleRateHz = rateForPacerPeriod(*period);
    pacerPeriod_ = *period;
    return {};
  }

  void calibrateChains(std::vector<ChannelChain>& chains) override {
    for (std::size_t i = 0; i < chains.size(); ++i)
      chains[i].calibration =
          calibration_[config_.channels[i].rangeCode][static_cast<std::size_t>(config_.channels[i].input)];
  }

  core::Result<void> beginSession() override {
    {
      std::lock_guard<std::mutex> l(queueMutex_);
      queue_.clear();
    }
    auto ok = startScan(config_.scanCount);
    if (!ok) return ok;
    delivered_ = 0;
    pending_.clear();
    pendingScans_ = 0;
    transport_->setDisconnectCallback([this] { push(Packet{usb::TransferStatus::NoDevice, {}, false}); });
    return {};
  }

  void interruptSession() override { push(Packet{usb::TransferStatus::Cancelled, {}, true}); }

 private:
  core::Result<void> fail(core::Error e) {
    transport_.reset();
    return e;
  }

  core::Result<void> startScan(std::int64_t scans) {
    std::array<std::uint8_t, 8> codes{};
    for (const auto& ch : config_.channels) codes[static_cast<std::size_t>(ch.input)] = ch.rangeCode;
    std::uint8_t mask = 0;
    for (const auto& ch : config_.channels) mask = static_cast<std::uint8_t>(mask | (1u << ch.input));
    const auto cfg = encodeRangeConfig(codes);
    auto r = transport_->controlOut(kAInConfig, 0, 0, std::vector<std::uint8_t>(cfg.begin(), cfg.end()));
    if (!r) return r;
    if (!(r = transport_->controlOut(kAInScanStop, 0, 0, {}))) return r;
    if (!(r = transport_->controlOut(kAInClearFifo, 0, 0, {}))) return r;
    ScanRequest req;
    req.scanCount = static_cast<std::uint32_t>(scans);
    req.pacerPeriod = pacerPeriod_;
    req.channelMask = mask;
    req.options = 0;  // block transfer mode, no hardware trigger, stall on overrun
    const auto start = encodeScanStart(req);
    if (!(r = transport_->controlOut(kAInScanStart, 0, 0, std::vector<std::uint8_t>(start.begin(), start.end()))))
      return r;
    assembler_ = std::make_unique<ScanAssembler>(static_cast<int>(config_.channels.size()));
    // Transfer size from the rate: "usb.transfer_ms" of data (100 ms by
    // default), rounded up to whole 64-byte packets; four transfers in flight.
    const double bytesPerS = config_.sampleRateHz * static_cast<double>(config_.channels.size()) * 2.0;
    const double ms = static_cast<double>(parameterInteger(config_.parameters, "usb.transfer_ms", 100));
    const int packets = std::max(1, static_cast<int>(std::ceil(bytesPerS * ms / 1000.0 / kPacketBytes)));
    const int transferBytes = packets * kPacketBytes;
    const double fillMs = 1000.0 * transferBytes / bytesPerS;
    const auto timeout = static_cast<unsigned>(std::max<double>(
        static_cast<double>(parameterInteger(config_.parameters, "usb.transfer_timeout_ms", 2000)), 2.0 * fillMs));
    return transport_->startBulkIn(
        kBulkInEndpoint, transferBytes, 4, timeout, [this](usb::TransferStatus s, const std::uint8_t* d, int n) {
          push(Packet{s, d && n > 0 ? std::vector<std::uint8_t>(d, d + n) : std::vector<std::uint8_t>{}, false});
        });
  }

  void push(Packet p) {
    {
      std::lock_guard<std::mutex> l(queueMutex_);
      queue_.push_back(std::move(p));
    }
    queueCv_.notify_one();
  }

  Packet pop() {
    std::unique_lock<std::mutex> l(queueMutex_);
    queueCv_.wait(l, [&] { return !queue_.empty(); });
    Packet p = std::move(queue_.front());
    queue_.pop_front();
    return p;
  }

  // Emits full blocks; with `flush`, also the partial one.
  void emitBlocks(bool flush) {
    const std::size_t nc = chains_.size();
    while (pendingScans_ > 0 && (pendingScans_ >= config_.blockScans || flush)) {
      const std::int64_t n = std::min(pendingScans_, config_.blockScans);
      DataBlock b;
      b.firstSample = delivered_;
      b.raw.assign(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n * static_cast<std::int64_t>(nc)));
      pending_.erase(pending_.begin(),
                     pending_.begin() + static_cast<std::ptrdiff_t>(n * static_cast<std::int64_t>(nc)));
      pendingScans_ -= n;
      delivered_ += n;
      emitBlock(std::move(b));
    }
  }

  // Appends the scans of a packet; true when the requested count is reached.
  bool absorb(const Packet& p) {
    if (p.bytes.empty()) return false;
    pendingScans_ += assembler_->append(p.bytes.data(), static_cast<int>(p.bytes.size()), pending_);
    if (config_.scanCount > 0 && delivered_ + pendingScans_ >= config_.scanCount) {
      const std::int64_t keep = config_.scanCount - delivered_;
      pending_.resize(static_cast<std::size_t>(keep) * chains_.size());
      pendingScans_ = keep;
      return true;
    }
    return false;
  }

  void finish(EndReason reason, const std::string& message) {
    transport_->stopBulkIn();
    if (!transport_->disconnected()) (void)transport_->controlOut(kAInScanStop, 0, 0, {});
    // Every transfer is back now; data that completed before the end (e.g.
    // reaped after an unplug was first noticed) is handed on, in order.
    std::deque<Packet> rest;
    {
      std::lock_guard<std::mutex> l(queueMutex_);
      rest.swap(queue_);
    }
    bool full = config_.scanCount > 0 && delivered_ + pendingScans_ >= config_.scanCount;
    for (const auto& p : rest)
      if (!full && !p.stopRequest) full = absorb(p);
    emitBlocks(true);
    endSession(reason, delivered_, message);
  }

  void runSession() override {
    for (;;) {
      Packet p = pop();
      if (p.stopRequest) return finish(EndReason::Stopped, "stopped by the user");
      // A failed transfer may carry the data of the packets that arrived
      // before the failure: keep it.
      if (p.status != usb::TransferStatus::Completed && absorb(p))
        return finish(EndReason::Completed, std::to_string(config_.scanCount) + " scans acquired");
      switch (p.status) {
        case usb::TransferStatus::Completed: {
          if (p.bytes.empty()) break;  // zero-length packet after an exact multiple of 64 bytes
          if (absorb(p)) return finish(EndReason::Completed, std::to_string(config_.scanCount) + " scans acquired");
          emitBlocks(false);
          break;
        }
        case usb::TransferStatus::Stall: {
          if (!recoverFromOverrun()) return;
          break;
        }
        case usb::TransferStatus::NoDevice:
          return finish(EndReason::Disconnected,
                        "the USB-1608FS-Plus was unplugged or lost power; the data received so far was kept");
        case usb::TransferStatus::TimedOut:
          return finish(EndReason::Timeout,
                        "no data from the USB-1608FS-Plus within the transfer timeout (pacer or cable fault)");
        case usb::TransferStatus::Overflow:
          return finish(EndReason::Error, "the device sent more data than requested (USB overflow)");
        case usb::TransferStatus::Cancelled:
          if (stopRequested()) return finish(EndReason::Stopped, "stopped by the user");
          break;  // a sibling transfer cancelled during recovery
        case usb::TransferStatus::Error:
          if (transport_->disconnected())
            return finish(EndReason::Disconnected,
                          "the USB-1608FS-Plus was unplugged or lost power; the data received so far was kept");
          return finish(EndReason::Error, "USB transfer error");
      }
    }
  }

  // Overrun: the FIFO filled and the device stalled the bulk endpoint. Read
  // the status, stop the scan, clear the halt and the FIFO, report the gap,
  // then restart (default) or end the session.
  bool recoverFromOverrun() {
    transport_->stopBulkIn();
    {
      std::lock_guard<std::mutex> l(queueMutex_);  // completions of the cancelled ring carry no data
      queue_.erase(std::remove_if(queue_.begin(), queue_.end(),
                                  [](const Packet& p) {
                                    return !p.stopRequest && (p.status == usb::TransferStatus::Stall ||
                                                              p.status == usb::TransferStatus::Cancelled);
                                  }),
                   queue_.end());
    }
    if (transport_->disconnected()) {
      finish(EndReason::Disconnected, "the device disappeared during overrun recovery");
      return false;
    }
    auto status = transport_->controlIn(kStatus, 0, 0, 2);
    std::string detail = "bulk endpoint stalled";
    if (status) {
      auto bits = parseStatus(*status);
      if (bits && (*bits & kStatusScanOverrun))
        detail = "FIFO overrun (status 0x" + std::to_string(*bits) + "): the host did not read fast enough";
    }
    (void)transport_->controlOut(kAInScanStop, 0, 0, {});
    auto halt = transport_->clearHalt(kBulkInEndpoint);
    auto fifo = transport_->controlOut(kAInClearFifo, 0, 0, {});
    emitBlocks(true);  // hand on every complete scan before the gap
    const bool restart =
        parameterText(config_.parameters, "overrun.policy", "restart") == "restart" && halt && fifo && !stopRequested();
    publish(StreamEvent(OverrunEvent{delivered_, -1, restart, detail}));
    if (!restart) {
      finish(EndReason::Overrun, detail);
      return false;
    }
    assembler_->reset();
    const std::int64_t remaining = config_.scanCount > 0 ? config_.scanCount - delivered_ : 0;
    auto ok = startScan(remaining);
    if (!ok) {
      finish(transport_->disconnected() ? EndReason::Disconnected : EndReason::Error,
             "restart after overrun failed: " + ok.error().describe());
      return false;
    }
    return true;
  }

  std::unique_ptr<usb::UsbTransport> transport_;
  CalibrationTable calibration_{};
  std::uint32_t pacerPeriod_ = 0;
  std::mutex queueMutex_;
  std::condition_variable queueCv_;
  std::deque<Packet> queue_;
  std::unique_ptr<ScanAssembler> assembler_;
  std::vector<std::int32_t> pending_;
  std::int64_t pendingScans_ = 0;
  std::int64_t delivered_ = 0;
};

class Usb1608FsPlusDriver final : public Driver {
 public:
  std::string name() const override { return kDriverName; }
  std::string description() const override {
    return "Measurement Computing USB-1608FS-Plus, 8 x 16 bit simultaneous, 100 kS/s per channel (libusb)";
  }
  bool simulated() const override { return false; }
  core::Result<std::vector<DeviceDescriptor>> scan() override {
    auto found = usb::UsbTransport::enumerate(kVendorId, kProductId);
    if (!found) return found.error();
    std::vector<DeviceDescriptor> out;
    for (const auto& f : *found)
      out.push_back(DeviceDescriptor{kDriverName, kModel, f.vendorId, f.productId, f.serial, f.busPath()});
    return out;
  }
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& d) override {
    if (d.driver != kDriverName)
      return core::makeError(core::ErrorCode::InvalidArgument, "descriptor of another driver", d.driver);
    return std::unique_ptr<Device>(new Usb1608FsPlusDevice(d));
  }
};

}  // namespace

std::unique_ptr<Driver> makeUsb1608FsPlusDriver() {
  return std::make_unique<Usb1608FsPlusDriver>();
}

}  // namespace mozzi::devices::mcc
