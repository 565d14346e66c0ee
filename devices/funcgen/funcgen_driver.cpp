#include "devices/funcgen/funcgen_driver.h"

#include <atomic>
#include <mutex>

#include "core/common/text.h"
#include "devices/funcgen/function_generator.h"
#include "devices/usbtmc/usbtmc_transport.h"

namespace mozzi::devices::funcgen {

std::vector<ParameterSpec> setPointParameters(int channels) {
  return {
      ParameterSpec{"mode",
                    "Actuator mode",
                    ParameterType::Choice,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {"static-ramp", "sine"},
                    std::string("static-ramp"),
                    "slow triangular ramp or sine excitation (§1.1)"},
      ParameterSpec{"static.max_force",
                    "Ramp peak force",
                    ParameterType::Real,
                    "N",
                    1.0,
                    5000.0,
                    {},
                    1000.0,
                    "the actuator applies up to 5000 N statically (§1.1)"},
      ParameterSpec{"static.period_s",
                    "Ramp period",
                    ParameterType::Real,
                    "s",
                    1.0,
                    3600.0,
                    {},
                    20.0,
                    "one triangle -F -> +F -> -F; the generator's RAMP at 50% symmetry"},
      ParameterSpec{"sine.frequency",
                    "Sine frequency",
                    ParameterType::Real,
                    "Hz",
                    1.0,
                    45.0,
                    {},
                    10.0,
                    "dynamic excitation from 1 to 45 Hz (§1.1)"},
      ParameterSpec{"sine.amplitude",
                    "Sine force amplitude",
                    ParameterType::Real,
                    "N",
                    1.0,
                    5000.0,
                    {},
                    1000.0,
                    "set-point amplitude; the actuator's achievable amplitude falls with frequency (§1.1)"},
      ParameterSpec{"actuator.newtons_per_volt",
                    "Set-point scale",
                    ParameterType::Real,
                    "N/V",
                    1.0,
                    1e5,
                    {},
                    500.0,
                    "input scale of the actuator controller: 500 N/V maps +/-10 V onto +/-5000 N"},
      ParameterSpec{"channel",
                    "Generator channel",
                    ParameterType::Integer,
                    "",
                    1.0,
                    static_cast<double>(channels),
                    {},
                    std::int64_t{1},
                    "output wired to the actuator controller's set-point input"},
  };
}

namespace {

constexpr const char* kDriverName = "usbtmc-funcgen";
constexpr unsigned kProbeTimeoutMs = 1000;  // a generator answers SOUR1:FUNC? in milliseconds

Capabilities deviceCapabilities(const GeneratorCapabilities& g) {
  Capabilities caps;
  caps.model = g.model;
  caps.outputs = {OutputSpec{"actuator force set-point", "N", -5000.0, 5000.0}};
  for (int c = 1; c <= g.channels; ++c)
    caps.outputs.push_back(OutputSpec{"CH" + std::to_string(c) + " voltage", "V", -g.maxPeakV, g.maxPeakV});
  caps.triggers = {TriggerKind::Immediate};
  caps.parameters = setPointParameters(g.channels);
  return caps;
}

// The generator setting for the rig parameters (applied map, complete).
OutputSetting settingFor(const ParameterMap& p) {
  const double k = parameterReal(p, "actuator.newtons_per_volt", 500.0);
  OutputSetting s;
  s.channel = static_cast<int>(parameterInteger(p, "channel", 1));
  s.offsetV = 0.0;
  if (parameterText(p, "mode", "static-ramp") == "sine") {
    s.waveform = Waveform::Sine;
    s.frequencyHz = parameterReal(p, "sine.frequency", 10.0);
    s.amplitudeVpp = 2.0 * parameterReal(p, "sine.amplitude", 1000.0) / k;
  } else {
    s.waveform = Waveform::Ramp;
    s.symmetryPercent = 50.0;
    s.frequencyHz = 1.0 / parameterReal(p, "static.period_s", 20.0);
    s.amplitudeVpp = 2.0 * parameterReal(p, "static.max_force", 1000.0) / k;
  }
  return s;
}

// The rig parameters a read-back setting stands for.
void writeBack(const OutputSetting& s, ParameterMap& p) {
  const double k = parameterReal(p, "actuator.newtons_per_volt", 500.0);
  if (s.waveform == Waveform::Sine) {
    p["sine.frequency"] = s.frequencyHz;
    p["sine.amplitude"] = s.amplitudeVpp * k / 2.0;
  } else {
    p["static.period_s"] = 1.0 / s.frequencyHz;
    p["static.max_force"] = s.amplitudeVpp * k / 2.0;
  }
}

class FunctionGeneratorDevice final : public Device {
 public:
  explicit FunctionGeneratorDevice(DeviceDescriptor d) : descriptor_(std::move(d)), genCaps_(genericCapabilities()) {}
  ~FunctionGeneratorDevice() override { close(); }

  const DeviceDescriptor& descriptor() const override { return descriptor_; }
  Capabilities capabilities() const override { return deviceCapabilities(genCaps_); }
  DeviceState state() const override { return state_.load(); }

  core::Result<void> open() override {
    if (transport_) return {};
    auto r = openSession();
    if (!r) {
      // Nothing half-open stays behind: a later open() starts from scratch.
      generator_.reset();
      session_.reset();
      transport_.reset();
      genCaps_ = genericCapabilities();
    }
    return r;
  }

  void close() override {
    if (!transport_) return;
    if (state_ == DeviceState::Running) stop();
    if (!transport_->disconnected())
      for (int c = 1; c <= genCaps_.channels; ++c) (void)generator_->setOutput(c, false);
    generator_.reset();
    session_.reset();
    transport_.reset();
    state_ = DeviceState::Closed;
  }

  core::Result<AcquisitionConfig> configure(const AcquisitionConfig& requested) override {
    if (!requested.channels.empty())
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "the function generator has no input channels: acquire the rig's signals with a DAQ",
                             "channels");
    if (state_ == DeviceState::Running)
      return core::makeError(core::ErrorCode::InvalidArgument, "stop the output before configuring",
                             descriptor_.label());
    const Capabilities caps = capabilities();
    auto params = applyParameters(caps.parameters, requested.parameters);
    if (!params) return params.error();
    const OutputSetting wanted = settingFor(*params);
    auto valid = validateSetting(genCaps_, wanted);
    if (!valid) {
      // Name the rig parameter behind the generator field.
      const bool sine = wanted.waveform == Waveform::Sine;
      const std::string& field = valid.error().where;
      const std::string key = field == "channel"     ? "channel"
                              : field == "frequency" ? (sine ? "sine.frequency" : "static.period_s")
                                                     : (sine ? "sine.amplitude" : "static.max_force");
      return core::makeError(valid.error().code,
                             valid.error().message + " (" + key + " at " +
                                 core::formatNumber(parameterReal(*params, "actuator.newtons_per_volt", 500.0)) +
                                 " N/V)",
                             "parameter " + key);  // as applyParameters names them
    }
    AcquisitionConfig applied;
    applied.parameters = *params;
    if (!generator_)
      return core::makeError(core::ErrorCode::InvalidArgument, "open the device first", descriptor_.label());
    auto setting = generator_->configure(*valid);
    if (!setting) return fail(setting.error());
    writeBack(*setting, applied.parameters);
    channel_ = setting->channel;
    state_ = DeviceState::Configured;
    return applied;
  }

  core::Result<void> start(StreamSink sink) override {
    if (state_ != DeviceState::Configured)
      return core::makeError(core::ErrorCode::InvalidArgument, "configure the generator before starting it",
                             descriptor_.label());
    if (auto r = generator_->setOutput(channel_, true); !r) return fail(r.error());
    std::lock_guard<std::mutex> l(streamMutex_);
    sink_ = std::move(sink);
    StreamHeader h;
    h.startTime = std::chrono::system_clock::now();
    h.device = descriptor_.label();
    if (sink_) sink_(std::move(h));
    state_ = DeviceState::Running;
    return {};
  }

  void stop() override {
    if (state_ != DeviceState::Running) return;
    StreamEnd end;
    end.reason = EndReason::Stopped;
    if (auto r = generator_->setOutput(channel_, false); !r) {
      end.reason = transport_->disconnected() ? EndReason::Disconnected : EndReason::Error;
      end.message = r.error().describe();
    }
    endStream(std::move(end));
    state_ = transport_->disconnected() ? DeviceState::Open : DeviceState::Configured;
  }

 private:
  core::Result<void> openSession() {
    auto t = usbtmc::UsbtmcTransport::open(descriptor_.busPath);
    if (!t) return t.error();
    transport_ = std::move(*t);
    // Event thread: an unplug while the output runs (no traffic) ends the stream at once.
    transport_->setDisconnectCallback([this] { onUnplug(); });
    session_ = std::make_unique<usbtmc::ScpiSession>(*transport_);
    descriptor_.busPath = transport_->info().usb.busPath();
    descriptor_.serial = transport_->info().usb.serial;
    auto id = session_->identify();
    if (!id) return id.error();
    genCaps_ = capabilitiesFor(*id);
    descriptor_.model = id->manufacturer + " " + id->model;
    // *CLS empties an error queue left by an earlier program, so the first
    // checked command is not blamed for it.
    if (auto r = session_->clearStatus(); !r) return r.error();
    generator_ = std::make_unique<FunctionGenerator>(*session_, genCaps_);
    // A USBTMC instrument that does not know SOUR1:FUNC? is no generator: it
    // queues -113 "Undefined header" and sends nothing, so the query times out.
    auto func = session_->query("SOUR1:FUNC?", kProbeTimeoutMs);
    auto errors = session_->drainErrors();
    if (!errors) return errors.error();
    if (!errors->empty())
      return core::makeError(core::ErrorCode::Unsupported,
                             descriptor_.model + " does not know SOUR1:FUNC?: not a function generator (" +
                                 std::to_string(errors->front().code) + ", " + errors->front().message + ")",
                             transport_->where());
    if (!func) return func.error();
    for (int c = 1; c <= genCaps_.channels; ++c)
      if (auto r = generator_->setOutput(c, false); !r) return r.error();
    state_ = DeviceState::Open;
    return {};
  }

  // The one end event of a stream; later calls do nothing. The lock is never
  // held across I/O, so the event thread cannot wait on a transfer.
  void endStream(StreamEnd end) {
    std::lock_guard<std::mutex> l(streamMutex_);
    if (!sink_) return;
    sink_(std::move(end));
    sink_ = nullptr;
  }

  void onUnplug() {
    if (state_ != DeviceState::Running) return;
    StreamEnd end;
    end.reason = EndReason::Disconnected;
    end.message = "the instrument was unplugged (" + descriptor_.label() + ")";
    endStream(std::move(end));
    state_ = DeviceState::Open;
  }

  core::Error fail(const core::Error& e) {
    if (transport_ && transport_->disconnected()) state_ = DeviceState::Open;
    return e;
  }

  DeviceDescriptor descriptor_;
  GeneratorCapabilities genCaps_;
  std::unique_ptr<usbtmc::UsbtmcTransport> transport_;
  std::unique_ptr<usbtmc::ScpiSession> session_;
  std::unique_ptr<FunctionGenerator> generator_;
  std::mutex streamMutex_;
  StreamSink sink_;
  int channel_ = 1;
  std::atomic<DeviceState> state_{DeviceState::Closed};
};

class FunctionGeneratorDriver final : public Driver {
 public:
  std::string name() const override { return kDriverName; }
  std::string description() const override {
    return "SCPI function generator on USBTMC (Keysight 33500B, Rigol DG1000Z, ...): stiffness rig actuator set-point";
  }
  bool simulated() const override { return false; }
  core::Result<std::vector<DeviceDescriptor>> scan() override {
    auto found = usbtmc::UsbtmcTransport::enumerate();
    if (!found) return found.error();
    std::vector<DeviceDescriptor> out;
    for (const auto& i : *found) {
      DeviceDescriptor d;
      d.driver = kDriverName;
      d.model = i.manufacturer.empty() && i.product.empty() ? "USBTMC instrument" : i.manufacturer + " " + i.product;
      d.vendorId = i.usb.vendorId;
      d.productId = i.usb.productId;
      d.serial = i.usb.serial;
      d.busPath = i.usb.busPath();
      out.push_back(d);
    }
    return out;
  }
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& descriptor) override {
    return std::unique_ptr<Device>(std::make_unique<FunctionGeneratorDevice>(descriptor));
  }
};

}  // namespace

std::unique_ptr<Driver> makeFunctionGeneratorDriver() {
  return std::make_unique<FunctionGeneratorDriver>();
}

}  // namespace mozzi::devices::funcgen
