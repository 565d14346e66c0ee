#include "devices/sim/sim_device.h"

#include <algorithm>
#include <mutex>
#include <random>

#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"

namespace mozzi::devices::sim {

ParameterSpec realtimeParameter() {
  return ParameterSpec{"sim.realtime",
                       "Real-time pacing",
                       ParameterType::Bool,
                       "",
                       std::nullopt,
                       std::nullopt,
                       {},
                       true,
                       "deliver data at the pace of the (simulated or recorded) clock; off = as fast as the consumer "
                       "takes it"};
}

std::vector<ParameterSpec> commonSimParameters() {
  return {
      ParameterSpec{"sim.seed",
                    "Random seed",
                    ParameterType::Integer,
                    "",
                    0.0,
                    4294967295.0,
                    {},
                    std::int64_t{1},
                    "same seed, same data: noise, hit timing and faults are reproducible"},
      realtimeParameter(),
      ParameterSpec{"fault.overrun_probability",
                    "Overrun probability per block",
                    ParameterType::Real,
                    "",
                    0.0,
                    1.0,
                    {},
                    0.0,
                    "each block is lost with this probability and reported as an overrun"},
      ParameterSpec{"fault.disconnect_after_s",
                    "Disconnect after",
                    ParameterType::Real,
                    "s",
                    0.0,
                    1e6,
                    {},
                    0.0,
                    "unplug the simulated device after this much data (0 = never)"},
      ParameterSpec{"fault.timeout_after_s",
                    "Time out after",
                    ParameterType::Real,
                    "s",
                    0.0,
                    1e6,
                    {},
                    0.0,
                    "stop sending data after this much data, as a stalled transfer (0 = never)"},
  };
}

InputChannelSpec simInput(const std::string& name, bool iepe) {
  InputChannelSpec in;
  in.name = name;
  in.ranges = mcc::ranges();  // the ranges of the USB-1608FS-Plus the rigs are wired to
  in.couplings = {Coupling::Dc, Coupling::Ac};
  in.iepeSupply = iepe;
  in.resolutionBits = 16;
  return in;
}

namespace {

class SimDevice final : public SimulatedRig {
 public:
  SimDevice(DeviceDescriptor d, Capabilities caps, std::unique_ptr<SignalModel> model)
      : SimulatedRig(std::move(d), std::move(caps)), model_(std::move(model)) {}
  ~SimDevice() override { close(); }

  FaultCounters counters() const override {
    std::lock_guard<std::mutex> l(countersMutex_);
    return counters_;
  }

  core::Result<void> open() override {
    if (state() == DeviceState::Closed) setState(DeviceState::Open);
    return {};
  }
  void close() override {
    stop();
    setState(DeviceState::Closed);
  }

 protected:
  core::Result<void> prepareConfig(AcquisitionConfig& applied) override { return model_->prepare(applied); }

  // A fixed, slightly non-ideal device calibration so that the simulated
  // codes exercise the whole pipeline (slope and intercept as a real
  // USB-1608FS-Plus table would hold them).
  void calibrateChains(std::vector<ChannelChain>& chains) override {
    for (auto& c : chains) c.calibration = DeviceCalibration{1.0002, -3.0};
  }

  core::Result<void> beginSession() override {
    std::lock_guard<std::mutex> l(countersMutex_);
    counters_ = FaultCounters{};
    return {};
  }

 private:
  void runSession() override {
    const double fs = config_.sampleRateHz;
    const bool realtime = parameterBool(config_.parameters, "sim.realtime", true);
    const double pOverrun = parameterReal(config_.parameters, "fault.overrun_probability", 0.0);
    const double disconnectS = parameterReal(config_.parameters, "fault.disconnect_after_s", 0.0);
    const double timeoutS = parameterReal(config_.parameters, "fault.timeout_after_s", 0.0);
    std::mt19937_64 rng(static_cast<std::uint64_t>(parameterInteger(config_.parameters, "sim.seed", 1)) * 7919u + 17u);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<int> inputs;
    for (const auto& c : config_.channels) inputs.push_back(c.input);
    const auto wallStart = std::chrono::steady_clock::now();
    std::int64_t next = 0;       // sample index of the simulated clock
    std::int64_t delivered = 0;  // scans handed on
    core::Matrix physical;
    std::vector<TriggerEvent> marks;
    auto end = [&](EndReason r, const std::string& m) { endSession(r, delivered, m); };
    for (;;) {
      if (stopRequested()) return end(EndReason::Stopped, "stopped by the user");
      if (config_.scanCount > 0 && next >= config_.scanCount)
        return end(EndReason::Completed, std::to_string(config_.scanCount) + " scans acquired");
      if (disconnectS > 0.0 && static_cast<double>(next) >= disconnectS * fs) {
        std::lock_guard<std::mutex> l(countersMutex_);
        ++counters_.disconnects;
        return end(EndReason::Disconnected,
                   "the simulated device was unplugged (fault injection); the data so far was kept");
      }
      if (timeoutS > 0.0 && static_cast<double>(next) >= timeoutS * fs) {
        std::lock_guard<std::mutex> l(countersMutex_);
        ++counters_.timeouts;
        return end(EndReason::Timeout, "no data within the transfer timeout (fault injection)");
      }
      std::int64_t n = config_.blockScans;
      if (config_.scanCount > 0) n = std::min(n, config_.scanCount - next);
      if (pOverrun > 0.0 && uniform(rng) < pOverrun) {
        // The block is lost: report it and skip it on the simulated clock.
        publish(StreamEvent(OverrunEvent{next, n, true, "simulated FIFO overrun (fault injection)"}));
        std::lock_guard<std::mutex> l(countersMutex_);
        ++counters_.overruns;
        counters_.lostScans += n;
        next += n;
        continue;
      }
      physical.resize(n, static_cast<Eigen::Index>(inputs.size()));
      {
        FaultCounters local;
        model_->generate(next, static_cast<Eigen::Index>(n), inputs, physical, local);
        std::lock_guard<std::mutex> l(countersMutex_);
        counters_.hits += local.hits;
        counters_.doubleHits += local.doubleHits;
        counters_.overloadHits += local.overloadHits;
        counters_.scansGenerated += n;
      }
      DataBlock b;
      b.firstSample = next;
      const std::size_t nc = chains_.size();
      b.raw.resize(static_cast<std::size_t>(n) * nc);
      for (std::int64_t s = 0; s < n; ++s)
        for (std::size_t c = 0; c < nc; ++c)
          b.raw[static_cast<std::size_t>(s) * nc + c] =
              chains_[c].rawFromEngineering(physical(s, static_cast<Eigen::Index>(c)));
      next += n;
      delivered += n;
      if (realtime) paceTo(wallStart, static_cast<double>(next) / fs);
      marks.clear();
      model_->marks(b.firstSample, static_cast<Eigen::Index>(n), marks);
      emitBlock(std::move(b));
      for (auto& m : marks) publish(StreamEvent(m));
    }
  }

  std::unique_ptr<SignalModel> model_;
  mutable std::mutex countersMutex_;
  FaultCounters counters_;
};

class SimDriver final : public Driver {
 public:
  SimDriver(std::string name, std::string description, std::string model, CapsFn caps, ModelFn makeModel)
      : name_(std::move(name)),
        description_(std::move(description)),
        model_(std::move(model)),
        caps_(caps),
        makeModel_(makeModel) {}
  std::string name() const override { return name_; }
  std::string description() const override { return description_; }
  bool simulated() const override { return true; }
  core::Result<std::vector<DeviceDescriptor>> scan() override {
    return std::vector<DeviceDescriptor>{DeviceDescriptor{name_, model_, 0, 0, "SIM-0001", "sim:0"}};
  }
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& d) override {
    if (d.driver != name_)
      return core::makeError(core::ErrorCode::InvalidArgument, "descriptor of another driver", d.driver);
    return std::unique_ptr<Device>(new SimDevice(d, caps_(), makeModel_()));
  }

 private:
  std::string name_, description_, model_;
  CapsFn caps_;
  ModelFn makeModel_;
};

}  // namespace

std::unique_ptr<Driver> makeSimDriver(std::string name, std::string description, std::string model, CapsFn caps,
                                      ModelFn makeModel) {
  return std::make_unique<SimDriver>(std::move(name), std::move(description), std::move(model), caps, makeModel);
}

}  // namespace mozzi::devices::sim
