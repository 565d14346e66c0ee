#include "devices/sim/sim_drivers.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <random>
#include <thread>

#include "core/signal/hit_synthesis.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::sim {

double hammerPulseWidthS(double hammerMassKg, double tipStiffnessNPerM) {
  return 3.14159265358979323846 * std::sqrt(hammerMassKg / tipStiffnessNPerM);
}

double actuatorSineAmplitude(double amplitudeAt1HzN, double frequencyHz) {
  return amplitudeAt1HzN * (1.0 - 0.8 * std::log(frequencyHz) / std::log(45.0));
}

namespace {

std::vector<ParameterSpec> commonParameters() {
  return {
      ParameterSpec{"sim.seed", "Random seed", ParameterType::Integer, "", 0.0, 4294967295.0, {}, std::int64_t{1},
                    "same seed, same data: noise, hit timing and faults are reproducible"},
      ParameterSpec{"sim.realtime", "Real-time pacing", ParameterType::Bool, "", std::nullopt, std::nullopt, {}, true,
                    "deliver data at the pace of the simulated clock; off = as fast as the consumer takes it"},
      ParameterSpec{"fault.overrun_probability", "Overrun probability per block", ParameterType::Real, "", 0.0, 1.0, {}, 0.0,
                    "each block is lost with this probability and reported as an overrun"},
      ParameterSpec{"fault.disconnect_after_s", "Disconnect after", ParameterType::Real, "s", 0.0, 1e6, {}, 0.0,
                    "unplug the simulated device after this much data (0 = never)"},
      ParameterSpec{"fault.timeout_after_s", "Time out after", ParameterType::Real, "s", 0.0, 1e6, {}, 0.0,
                    "stop sending data after this much data, as a stalled transfer (0 = never)"},
  };
}

// Physical values of the inputs for scans [first, first + n): n x inputs.
class SignalModel {
 public:
  virtual ~SignalModel() = default;
  virtual core::Result<void> prepare(const AcquisitionConfig& config) = 0;
  virtual void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out,
                        FaultCounters& counters) = 0;
};

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
    auto end = [&](EndReason r, const std::string& m) { endSession(r, delivered, m); };
    for (;;) {
      if (stopRequested()) return end(EndReason::Stopped, "stopped by the user");
      if (config_.scanCount > 0 && next >= config_.scanCount)
        return end(EndReason::Completed, std::to_string(config_.scanCount) + " scans acquired");
      if (disconnectS > 0.0 && static_cast<double>(next) >= disconnectS * fs) {
        std::lock_guard<std::mutex> l(countersMutex_);
        ++counters_.disconnects;
        return end(EndReason::Disconnected, "the simulated device was unplugged (fault injection); the data so far was kept");
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
        emit(StreamEvent(OverrunEvent{next, n, true, "simulated FIFO overrun (fault injection)"}));
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
          b.raw[static_cast<std::size_t>(s) * nc + c] = chains_[c].rawFromEngineering(physical(s, static_cast<Eigen::Index>(c)));
      next += n;
      delivered += n;
      if (realtime) paceTo(wallStart, static_cast<double>(next) / fs);
      emitBlock(std::move(b));
    }
  }

  std::unique_ptr<SignalModel> model_;
  mutable std::mutex countersMutex_;
  FaultCounters counters_;
};

InputChannelSpec simInput(const std::string& name, bool iepe) {
  InputChannelSpec in;
  in.name = name;
  in.ranges = mcc::ranges();  // the ranges of the USB-1608FS-Plus the rigs are wired to
  in.couplings = {Coupling::Dc, Coupling::Ac};
  in.iepeSupply = iepe;
  in.resolutionBits = 16;
  return in;
}

// ---------------------------------------------------------------- hammer station

struct Tip {
  const char* name;
  double stiffness;  // N/m
};
// Contact stiffnesses chosen to give the usual contact times of a 0.16 kg
// hammer (PCB 086C03): steel ~0.3 ms, plastic ~1 ms, rubber ~3 ms.
constexpr Tip kTips[] = {{"steel", 1.6e7}, {"plastic", 1.6e6}, {"rubber", 1.6e5}};
constexpr double kHammerMassKg = 0.16;

class HammerModel final : public SignalModel {
 public:
  core::Result<void> prepare(const AcquisitionConfig& config) override {
    auto spec = modalSpecimen(parameterText(config.parameters, "specimen", "fork-a-without-wheel"));
    if (!spec) return spec.error();
    specimen_ = *spec;
    system_ = specimen_.toMdof();
    fs_ = config.sampleRateHz;
    interval_ = std::max<std::int64_t>(16, static_cast<std::int64_t>(std::llround(parameterReal(config.parameters, "hammer.interval_s", 4.0) * fs_)));
    const std::string tip = parameterText(config.parameters, "hammer.tip", "plastic");
    double k = kTips[1].stiffness;
    for (const auto& t : kTips)
      if (tip == t.name) k = t.stiffness;
    pulseWidth_ = hammerPulseWidthS(kHammerMassKg, k);
    peak_ = parameterReal(config.parameters, "hammer.peak_force", 200.0);
    forceNoise_ = parameterReal(config.parameters, "noise.force_rms", 0.05);
    responseNoise_ = parameterReal(config.parameters, "noise.response_rms", 0.002);
    pDouble_ = parameterReal(config.parameters, "fault.double_hit_probability", 0.0);
    pOverload_ = parameterReal(config.parameters, "fault.overload_probability", 0.0);
    overloadFactor_ = parameterReal(config.parameters, "fault.overload_factor", 30.0);
    seed_ = static_cast<std::uint64_t>(parameterInteger(config.parameters, "sim.seed", 1));
    preHit_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::llround(0.25 * fs_)));
    segmentIndex_ = -1;
    return {};
  }

  void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out, FaultCounters& counters) override {
    for (Eigen::Index s = 0; s < n; ++s) {
      const std::int64_t k = first + s;
      const std::int64_t seg = k / interval_;
      if (seg != segmentIndex_) makeSegment(seg, counters);
      const Eigen::Index row = static_cast<Eigen::Index>(k - seg * interval_);
      for (std::size_t c = 0; c < inputs.size(); ++c) {
        const int in = inputs[c];
        out(s, static_cast<Eigen::Index>(c)) = in < segment_.cols() ? segment_(row, in) : 0.0;
      }
    }
  }

 private:
  void makeSegment(std::int64_t seg, FaultCounters& counters) {
    // Faults of hit `seg` from its own generator: the same hits whatever the block size.
    std::mt19937_64 rng(seed_ * 1000003u + static_cast<std::uint64_t>(seg));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const bool isDouble = u(rng) < pDouble_;
    const bool isOverload = u(rng) < pOverload_;
    core::signal::HammerHitSpec spec;
    spec.sampleRateHz = fs_;
    spec.sampleCount = static_cast<Eigen::Index>(interval_);
    spec.preTriggerSamples = static_cast<Eigen::Index>(preHit_);
    spec.oversampling = 8;
    spec.peakForceN = peak_ * (isOverload ? overloadFactor_ : 1.0) * (0.9 + 0.2 * u(rng));  // the hand varies +/-10%
    spec.pulseWidthS = pulseWidth_;
    spec.excitedDof = specimen_.excitedDof;
    spec.forceNoiseRms = forceNoise_;
    spec.responseNoiseRms = responseNoise_;
    spec.seed = seed_ * 7777u + static_cast<std::uint64_t>(seg) + 1u;
    spec.dofLabels = specimen_.dofs;
    if (isDouble) {
      spec.secondHitDelayS = 4.0 * pulseWidth_ + 0.004;  // a rebound a few ms after the first contact
      spec.secondHitFraction = 0.5;
    }
    auto rec = core::signal::synthesizeHammerHit(system_, spec);
    if (rec) segment_ = rec->samples;
    else segment_ = core::Matrix::Zero(static_cast<Eigen::Index>(interval_), specimen_.shapes.rows() + 1);
    segmentIndex_ = seg;
    ++counters.hits;
    if (isDouble) ++counters.doubleHits;
    if (isOverload) ++counters.overloadHits;
  }

  ModalSpecimen specimen_;
  core::signal::LinearMdof system_;
  double fs_ = 0.0, pulseWidth_ = 0.0, peak_ = 0.0, forceNoise_ = 0.0, responseNoise_ = 0.0;
  double pDouble_ = 0.0, pOverload_ = 0.0, overloadFactor_ = 30.0;
  std::int64_t interval_ = 1, preHit_ = 1;
  std::uint64_t seed_ = 1;
  std::int64_t segmentIndex_ = -1;
  core::Matrix segment_;
};

Capabilities hammerCapabilities() {
  Capabilities caps;
  caps.model = "Simulated impact hammer station";
  caps.inputs = {simInput("hammer", true), simInput("acc 1", true), simInput("acc 2", true), simInput("acc 3", true)};
  caps.rates = RateSpec{1.0, 51200.0, 204800.0, 0.0, true};
  caps.triggers = {TriggerKind::Immediate, TriggerKind::Software};
  caps.fifoSamples = mcc::kFifoSamples;
  caps.parameters = commonParameters();
  std::vector<ParameterSpec> own = {
      ParameterSpec{"specimen", "Specimen", ParameterType::Choice, "", std::nullopt, std::nullopt, modalSpecimenKeys(),
                    std::string("fork-a-without-wheel"), "virtual specimen with thesis modal parameters"},
      ParameterSpec{"hammer.tip", "Hammer tip", ParameterType::Choice, "", std::nullopt, std::nullopt, {"steel", "plastic", "rubber"},
                    std::string("plastic"), "contact time pi sqrt(m/k): steel 0.3 ms, plastic 1 ms, rubber 3 ms"},
      ParameterSpec{"hammer.peak_force", "Peak force", ParameterType::Real, "N", 1.0, 4000.0, {}, 200.0, "nominal peak of a hit (+/-10%)"},
      ParameterSpec{"hammer.interval_s", "Time between hits", ParameterType::Real, "s", 0.05, 60.0, {}, 4.0, "one hit every so many seconds"},
      ParameterSpec{"noise.force_rms", "Force noise", ParameterType::Real, "N", 0.0, 100.0, {}, 0.05, "white noise RMS on the hammer"},
      ParameterSpec{"noise.response_rms", "Response noise", ParameterType::Real, "m/s^2", 0.0, 100.0, {}, 0.002, "white noise RMS on each accelerometer"},
      ParameterSpec{"fault.double_hit_probability", "Double-hit probability", ParameterType::Real, "", 0.0, 1.0, {}, 0.0,
                    "a hit rebounds (second contact at half the peak) with this probability"},
      ParameterSpec{"fault.overload_probability", "Overload probability", ParameterType::Real, "", 0.0, 1.0, {}, 0.0,
                    "a hit is struck this many times harder than nominal with this probability"},
      ParameterSpec{"fault.overload_factor", "Overload factor", ParameterType::Real, "", 1.0, 1000.0, {}, 30.0, "peak multiplier of an overloaded hit"},
  };
  caps.parameters.insert(caps.parameters.end(), own.begin(), own.end());
  return caps;
}

// ---------------------------------------------------------------- stiffness rig

constexpr double kLoadCellFullScaleN = 200.0 * 9.80665;  // +/-200 kg (§1.1)
constexpr double kLaserRangeM = 0.020;                   // 20 mm (§1.1)
constexpr double kLaserResolutionM = 4e-6;               // 4 um (§1.1)

class StiffnessModel final : public SignalModel {
 public:
  core::Result<void> prepare(const AcquisitionConfig& config) override {
    auto spec = staticSpecimen(parameterText(config.parameters, "specimen", "frame-a-front-constrained"));
    if (!spec) return spec.error();
    specimen_ = *spec;
    fs_ = config.sampleRateHz;
    sine_ = parameterText(config.parameters, "mode", "static-ramp") == "sine";
    maxForce_ = parameterReal(config.parameters, "static.max_force", 1000.0);
    period_ = parameterReal(config.parameters, "static.period_s", 20.0);
    sineHz_ = parameterReal(config.parameters, "sine.frequency", 10.0);
    sineAmp_ = actuatorSineAmplitude(parameterReal(config.parameters, "sine.amplitude_1hz", 1000.0), sineHz_);
    forceNoise_ = parameterReal(config.parameters, "noise.force_rms", 0.5);
    rng_.seed(static_cast<std::uint64_t>(parameterInteger(config.parameters, "sim.seed", 1)) + 99u);
    return {};
  }

  // Actuator force at time t: triangle 0 -> +F -> -F -> 0 over one period, or
  // the sine of the set frequency and its amplitude.
  double force(double t) const {
    if (sine_) return sineAmp_ * std::sin(2.0 * 3.14159265358979323846 * sineHz_ * t);
    const double x = std::fmod(t / period_, 1.0);
    if (x < 0.25) return maxForce_ * 4.0 * x;
    if (x < 0.75) return maxForce_ * (2.0 - 4.0 * x);
    return maxForce_ * (4.0 * x - 4.0);
  }

  void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out, FaultCounters&) override {
    std::normal_distribution<double> noise(0.0, 1.0);
    for (Eigen::Index s = 0; s < n; ++s) {
      const double f = force(static_cast<double>(first + s) / fs_);
      for (std::size_t c = 0; c < inputs.size(); ++c) {
        const int in = inputs[c];
        double v = 0.0;
        if (in == 0) {
          v = f + forceNoise_ * noise(rng_);
        } else {
          // Quasi-static response (the sine band 1..45 Hz lies below the
          // specimens' first modes); each laser quantises to its 4 um
          // resolution and saturates at the ends of its 20 mm range.
          const double w = specimen_.displacementAt(specimen_.laserPoints[static_cast<std::size_t>(in - 1)], f);
          v = std::clamp(kLaserResolutionM * std::round(w / kLaserResolutionM), -kLaserRangeM / 2, kLaserRangeM / 2);
        }
        out(s, static_cast<Eigen::Index>(c)) = v;
      }
    }
  }

 private:
  StaticSpecimen specimen_;
  double fs_ = 0.0, maxForce_ = 0.0, period_ = 20.0, sineHz_ = 10.0, sineAmp_ = 0.0, forceNoise_ = 0.0;
  bool sine_ = false;
  std::mt19937_64 rng_;
};

Capabilities stiffnessCapabilities() {
  Capabilities caps;
  caps.model = "Simulated Motostiffmeter";
  caps.inputs = {simInput("load cell", false), simInput("laser 1", false), simInput("laser 2", false), simInput("laser 3", false),
                 simInput("laser 4", false)};
  caps.outputs = {OutputSpec{"actuator force set-point", "N", -5000.0, 5000.0}};
  caps.rates = RateSpec{1.0, 10000.0, 50000.0, 0.0, true};
  caps.triggers = {TriggerKind::Immediate};
  caps.fifoSamples = mcc::kFifoSamples;
  caps.parameters = commonParameters();
  std::vector<ParameterSpec> own = {
      ParameterSpec{"specimen", "Specimen", ParameterType::Choice, "", std::nullopt, std::nullopt, staticSpecimenKeys(),
                    std::string("frame-a-front-constrained"), "virtual specimen with thesis static stiffness and twist axis"},
      ParameterSpec{"mode", "Actuator mode", ParameterType::Choice, "", std::nullopt, std::nullopt, {"static-ramp", "sine"},
                    std::string("static-ramp"), "slow triangular ramp or sine excitation (§1.1)"},
      ParameterSpec{"static.max_force", "Ramp peak force", ParameterType::Real, "N", 1.0, 5000.0, {}, 1000.0,
                    "the actuator applies up to 5000 N statically (§1.1)"},
      ParameterSpec{"static.period_s", "Ramp period", ParameterType::Real, "s", 1.0, 3600.0, {}, 20.0, "0 -> +F -> -F -> 0"},
      ParameterSpec{"sine.frequency", "Sine frequency", ParameterType::Real, "Hz", 1.0, 45.0, {}, 10.0, "dynamic excitation up to 45 Hz (§1.1)"},
      ParameterSpec{"sine.amplitude_1hz", "Sine amplitude at 1 Hz", ParameterType::Real, "N", 1.0, 5000.0, {}, 1000.0,
                    "falls logarithmically with frequency to 20% at 45 Hz"},
      ParameterSpec{"noise.force_rms", "Load-cell noise", ParameterType::Real, "N", 0.0, 100.0, {}, 0.5, "white noise RMS on the load cell"},
  };
  caps.parameters.insert(caps.parameters.end(), own.begin(), own.end());
  return caps;
}

class SimDriver final : public Driver {
 public:
  using CapsFn = Capabilities (*)();
  using ModelFn = std::unique_ptr<SignalModel> (*)();
  SimDriver(std::string name, std::string description, std::string model, CapsFn caps, ModelFn makeModel)
      : name_(std::move(name)), description_(std::move(description)), model_(std::move(model)), caps_(caps), makeModel_(makeModel) {}
  std::string name() const override { return name_; }
  std::string description() const override { return description_; }
  bool simulated() const override { return true; }
  core::Result<std::vector<DeviceDescriptor>> scan() override {
    return std::vector<DeviceDescriptor>{DeviceDescriptor{name_, model_, 0, 0, "SIM-0001", "sim:0"}};
  }
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& d) override {
    if (d.driver != name_) return core::makeError(core::ErrorCode::InvalidArgument, "descriptor of another driver", d.driver);
    return std::unique_ptr<Device>(new SimDevice(d, caps_(), makeModel_()));
  }

 private:
  std::string name_, description_, model_;
  CapsFn caps_;
  ModelFn makeModel_;
};

}  // namespace

std::unique_ptr<Driver> makeHammerStationDriver() {
  return std::make_unique<SimDriver>("sim-hammer", "Simulated impact hammer station (virtual specimens, thesis §1.4, §1.6)",
                                     "Simulated impact hammer station", &hammerCapabilities,
                                     +[]() -> std::unique_ptr<SignalModel> { return std::make_unique<HammerModel>(); });
}

std::unique_ptr<Driver> makeStiffnessRigDriver() {
  return std::make_unique<SimDriver>("sim-stiffness", "Simulated Motostiffmeter: actuator, load cell, four lasers (thesis §1.1)",
                                     "Simulated Motostiffmeter", &stiffnessCapabilities,
                                     +[]() -> std::unique_ptr<SignalModel> { return std::make_unique<StiffnessModel>(); });
}

}  // namespace mozzi::devices::sim
