// Replay driver: plays the time records of a Universal File (dataset 58,
// function type 1, through core/io/uff) back as a live acquisition, so a
// campaign can be re-run from a recording through the same trigger, FRF and
// identification code. The recording is named by the descriptor's bus path
// ("/path/to/hits.uff"); open() reads and checks it, and the capabilities then
// list its channels at its sample rate.
//
// The values handed on are the file's samples, bit for bit, in the file's
// engineering units; the raw codes of each block are those a 16-bit +/-10 V
// DAQ would have given (full scale twice the channel's peak), so overload
// detection and consumers of raw codes still work. The load cases (one hit
// each, as the hammer station and `mozzi-cli frf` write them) are played back
// to back, with a trigger mark at each recorded trigger instant.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "core/io/uff/uff.h"
#include "devices/common/threaded_device.h"
#include "devices/sim/sim_device.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::sim {

namespace {

namespace uff = core::io::uff;

constexpr const char* kDriverName = "sim-replay";
constexpr const char* kModel = "Replay of recorded time data (UFF 58)";

struct Recording {
  double sampleRateHz = 0.0;
  std::vector<core::signal::Channel> channels;
  core::Matrix samples;                // scans x channels, every load case in file order
  std::vector<std::int64_t> triggers;  // scan index of each load case's trigger instant
};

core::signal::TransducerKind kindFromUff(int specificDataType) {
  using K = core::signal::TransducerKind;
  switch (specificDataType) {
    case 8: return K::Displacement;
    case 11: return K::Velocity;
    case 12: return K::Acceleration;
    case 13: return K::Force;
    default: return K::Other;
  }
}

core::Result<Recording> loadRecording(const std::string& path) {
  if (path.empty())
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "no recording named: give the UFF file as the device's bus path", kDriverName);
  auto file = uff::readFile(path);
  if (!file) return file.error();
  std::vector<int> order;
  std::map<int, std::vector<const uff::Function58*>> byCase;
  for (const auto* f : file->all<uff::Function58>()) {
    if (f->functionType != uff::FunctionType::TimeResponse) continue;
    if (!byCase.count(f->loadCase)) order.push_back(f->loadCase);
    byCase[f->loadCase].push_back(f);
  }
  if (order.empty())
    return core::makeError(core::ErrorCode::NotFound, "no time records (dataset 58, function type 1) to replay", path);
  Recording rec;
  const uff::Function58& first = *byCase[order.front()].front();
  if (!first.evenSpacing || !(first.abscissaIncrement > 0.0) || !std::isfinite(first.abscissaIncrement))
    return core::makeError(core::ErrorCode::Unsupported, "time records must be evenly sampled with a positive step",
                           path + ", load case " + std::to_string(order.front()));
  rec.sampleRateHz = 1.0 / first.abscissaIncrement;
  // ASCII 58 records print the time step with six significant digits (E13.5):
  // a rate within 5e-6 of a whole number of hertz is that number.
  if (std::abs(rec.sampleRateHz - std::round(rec.sampleRateHz)) < 5e-6 * rec.sampleRateHz)
    rec.sampleRateHz = std::round(rec.sampleRateHz);
  Eigen::Index total = 0;
  for (int lc : order) total += byCase[lc].front()->pointCount();
  for (int lc : order) {
    const auto& recs = byCase[lc];
    const std::string where = path + ", load case " + std::to_string(lc);
    if (rec.channels.empty()) {
      for (const auto* f : recs) {
        auto dof = f->response.dof();
        if (!dof) return core::makeError(dof.error().code, dof.error().message, where);
        core::signal::Channel ch;
        ch.dof = *dof;
        ch.name = core::formatDof(*dof);
        ch.transducer.kind = kindFromUff(f->ordinateNumerator.specificDataType);
        ch.transducer.unit = f->ordinateNumerator.unitsLabel == "NONE" ? "" : f->ordinateNumerator.unitsLabel;
        rec.channels.push_back(ch);
      }
      rec.samples.resize(total, static_cast<Eigen::Index>(rec.channels.size()));
      total = 0;
    }
    if (recs.size() != rec.channels.size())
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "has " + std::to_string(recs.size()) + " channels, the first load case " +
                                 std::to_string(rec.channels.size()) + " (a replay needs the same channels throughout)",
                             where);
    const Eigen::Index n = recs.front()->pointCount();
    for (std::size_t c = 0; c < recs.size(); ++c) {
      const uff::Function58& f = *recs[c];
      const std::string cw = where + ", channel " + std::to_string(c + 1);
      if (uff::isComplex(f.ordinateType))
        return core::makeError(core::ErrorCode::Unsupported, "a time record with complex ordinates", cw);
      if (!f.evenSpacing || f.abscissaIncrement != first.abscissaIncrement || f.pointCount() != n)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "time step or length differs from the first record (one sample rate, equal channels)",
                               cw);
      auto dof = f.response.dof();
      if (!dof || *dof != rec.channels[c].dof)
        return core::makeError(
            core::ErrorCode::InvalidArgument,
            "the channel's DOF differs from the first load case's (" + core::formatDof(rec.channels[c].dof) + ")", cw);
      if (!f.real.allFinite())
        return core::makeError(core::ErrorCode::InvalidArgument, "a sample is not finite (NaN or infinite)", cw);
      rec.samples.block(total, static_cast<Eigen::Index>(c), n, 1) = f.real;
    }
    const double pre = recs.front()->abscissaMin < 0.0 ? -recs.front()->abscissaMin * rec.sampleRateHz : 0.0;
    rec.triggers.push_back(total + static_cast<std::int64_t>(std::llround(pre)));
    total += n;
  }
  if (total < 1) return core::makeError(core::ErrorCode::InvalidArgument, "the time records hold no samples", path);
  return rec;
}

// A nominal DAQ range for the raw codes: +/-10 V at a sensitivity that puts
// full scale at twice the channel's peak (or 1 EU for an all-zero channel).
constexpr double kFullScaleVolts = 10.0;

InputRange replayRange() {
  return InputRange{"recorded (+/-10 V nominal)", 0, -kFullScaleVolts, kFullScaleVolts};
}

Capabilities replayCapabilities(const Recording* rec) {
  Capabilities caps;
  caps.model = kModel;
  if (rec) {
    for (const auto& ch : rec->channels) {
      InputChannelSpec in;
      in.name = ch.name + (ch.transducer.unit.empty() ? "" : " [" + ch.transducer.unit + "]");
      in.ranges = {replayRange()};
      in.couplings = {Coupling::Dc};
      caps.inputs.push_back(in);
    }
    // Only the recorded rate; a relative 1e-5 lets a rate computed from the
    // file's rounded step through (configure applies the recording's own).
    caps.rates = RateSpec{rec->sampleRateHz * (1 - 1e-5), rec->sampleRateHz * (1 + 1e-5),
                          rec->sampleRateHz * static_cast<double>(rec->channels.size()) * (1 + 1e-5), 0.0, true};
  }
  caps.triggers = {TriggerKind::Immediate};
  caps.parameters = {
      realtimeParameter(),
      ParameterSpec{"replay.loop",
                    "Loop",
                    ParameterType::Bool,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {},
                    false,
                    "start again at the end of the recording (until stop or the scan count)"},
  };
  return caps;
}

class ReplayDevice final : public ThreadedDevice {
 public:
  explicit ReplayDevice(DeviceDescriptor d) : ThreadedDevice(std::move(d), replayCapabilities(nullptr)) {}
  ~ReplayDevice() override { close(); }

  core::Result<void> open() override {
    if (state() != DeviceState::Closed) return {};
    auto rec = loadRecording(descriptor_.busPath);
    if (!rec) return rec.error();
    recording_ = std::move(*rec);
    caps_ = replayCapabilities(&recording_);
    setState(DeviceState::Open);
    return {};
  }

  void close() override {
    stop();
    setState(DeviceState::Closed);
  }

 protected:
  core::Result<void> prepareConfig(AcquisitionConfig& applied) override {
    applied.sampleRateHz = recording_.sampleRateHz;
    for (auto& c : applied.channels) {
      const auto& rc = recording_.channels[static_cast<std::size_t>(c.input)];
      const double peak = recording_.samples.col(c.input).cwiseAbs().maxCoeff();
      if (c.name.empty()) c.name = rc.name;
      c.dof = rc.dof;
      c.transducer.kind = rc.transducer.kind;
      c.transducer.unit = rc.transducer.unit;
      c.transducer.model = "replay";
      c.transducer.sensitivityMvPerUnit = 1000.0 * kFullScaleVolts / (peak > 0.0 ? 2.0 * peak : 1.0);
      c.conditionerGain = 1.0;
      c.rangeCode = 0;
    }
    return {};
  }

  void runSession() override {
    const bool realtime = parameterBool(config_.parameters, "sim.realtime", true);
    const bool loop = parameterBool(config_.parameters, "replay.loop", false);
    const std::int64_t length = recording_.samples.rows();
    const std::int64_t total = config_.scanCount > 0 ? config_.scanCount : (loop ? -1 : length);
    const std::size_t nc = config_.channels.size();
    const auto wallStart = std::chrono::steady_clock::now();
    std::int64_t next = 0;
    for (;;) {
      if (stopRequested()) return endSession(EndReason::Stopped, next, "stopped by the user");
      if (total >= 0 && next >= total)
        return endSession(EndReason::Completed, next,
                          std::to_string(next) + " scans replayed from " + descriptor_.busPath);
      std::int64_t n = config_.blockScans;
      if (total >= 0) n = std::min(n, total - next);
      n = std::min(n, length - next % length);  // a block does not wrap around the end
      const std::int64_t at = next % length;
      DataBlock b;
      b.firstSample = next;
      b.values.resize(n, static_cast<Eigen::Index>(nc));
      b.raw.resize(static_cast<std::size_t>(n) * nc);
      for (std::size_t c = 0; c < nc; ++c) {
        const Eigen::Index col = config_.channels[c].input;
        b.values.col(static_cast<Eigen::Index>(c)) = recording_.samples.block(at, col, n, 1);
        for (std::int64_t s = 0; s < n; ++s)
          b.raw[static_cast<std::size_t>(s) * nc + c] =
              chains_[c].rawFromEngineering(b.values(s, static_cast<Eigen::Index>(c)));
      }
      std::vector<TriggerEvent> marks;
      for (std::int64_t t : recording_.triggers)
        if (t >= at && t < at + n) marks.push_back(TriggerEvent{next + (t - at), 0, 0.0});
      next += n;
      if (realtime) paceTo(wallStart, static_cast<double>(next) / config_.sampleRateHz);
      emitBlock(std::move(b));
      for (auto& m : marks) publish(StreamEvent(m));
    }
  }

 private:
  Recording recording_;
};

class ReplayDriver final : public Driver {
 public:
  std::string name() const override { return kDriverName; }
  std::string description() const override {
    return "Replay of recorded time data (UFF 58, function type 1) as a live acquisition; the bus path names the file";
  }
  bool simulated() const override { return true; }
  // Recordings are opened by path, not discovered.
  core::Result<std::vector<DeviceDescriptor>> scan() override { return std::vector<DeviceDescriptor>{}; }
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& d) override {
    if (d.driver != kDriverName)
      return core::makeError(core::ErrorCode::InvalidArgument, "descriptor of another driver", d.driver);
    DeviceDescriptor desc = d;
    if (desc.model.empty()) desc.model = kModel;
    return std::unique_ptr<Device>(new ReplayDevice(desc));
  }
};

}  // namespace

std::unique_ptr<Driver> makeReplayDriver() {
  return std::make_unique<ReplayDriver>();
}

}  // namespace mozzi::devices::sim
