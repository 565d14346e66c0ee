#include "devices/rigtests/session.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <variant>

namespace mozzi::devices::rigtests {

const Quantity* findQuantity(const std::vector<Quantity>& quantities, const std::string& key) {
  for (const auto& q : quantities)
    if (q.key == key) return &q;
  return nullptr;
}

std::string missingStepsNote(const std::string& cause, int failedStep, const std::vector<std::string>& labels) {
  std::ostringstream s;
  s << cause;
  const int n = static_cast<int>(labels.size());
  if (failedStep >= 0 && failedStep < n) {
    s << " during step " << failedStep << " (" << labels[static_cast<std::size_t>(failedStep)] << "); ";
    if (failedStep == n - 1)
      s << "step " << failedStep << " is missing";
    else
      s << "steps " << failedStep << " to " << n - 1 << " are missing";
    s << " (";
    for (int k = failedStep; k < n; ++k) s << (k > failedStep ? ", " : "") << labels[static_cast<std::size_t>(k)];
    s << "); the steps before it are stored";
  }
  return s.str();
}

std::string cutShortNote(int committed, const std::vector<std::string>& labels) {
  const std::string cause = "running; if no program is running it, it was cut short (crash or power loss)";
  if (committed >= static_cast<int>(labels.size()))
    return cause + " after all " + std::to_string(labels.size()) + " steps were stored, before the whole-test results";
  return missingStepsNote(cause, committed, labels);
}

namespace detail {

namespace {

// Events of both devices, in arrival order, tagged with their source.
class EventQueue {
 public:
  StreamSink sink(int source) {
    return [this, source](StreamEvent&& e) {
      {
        std::lock_guard<std::mutex> l(mutex_);
        events_.push_back({source, std::move(e)});
      }
      cv_.notify_one();
    };
  }
  // The next event, or nullopt after `timeout` without one.
  std::optional<std::pair<int, StreamEvent>> pop(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> l(mutex_);
    if (!cv_.wait_for(l, timeout, [this] { return !events_.empty(); })) return std::nullopt;
    auto e = std::move(events_.front());
    events_.pop_front();
    return e;
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<std::pair<int, StreamEvent>> events_;
};

constexpr int kDaq = 0;
constexpr double kLiveBlockS = 0.025;
constexpr int kActuator = 1;

core::Result<void> openAndConfigure(Device& dev, const AcquisitionConfig& cfg, AcquisitionConfig* applied) {
  if (dev.state() == DeviceState::Closed) {
    if (auto r = dev.open(); !r) return r.error();
  }
  auto a = dev.configure(cfg);
  if (!a) return a.error();
  if (applied) *applied = *a;
  return {};
}

}  // namespace

std::int64_t scansFor(double seconds, double sampleRateHz) {
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(seconds * sampleRateHz - 1e-9)));
}

int channelIndex(const StreamHeader& header, const std::string& name) {
  for (std::size_t c = 0; c < header.channels.size(); ++c)
    if (header.channels[c].name == name) return static_cast<int>(c);
  return -1;
}

std::string endCause(const StreamEnd& end) {
  switch (end.reason) {
    case EndReason::Completed: return "completed";
    case EndReason::Stopped: return "stopped";
    case EndReason::Disconnected: return "the device was unplugged (" + end.message + ")";
    case EndReason::Timeout: return "the device stopped sending data (" + end.message + ")";
    case EndReason::Overrun: return "the device lost data it could not recover (" + end.message + ")";
    case EndReason::Error: return "the device reported an error (" + end.message + ")";
  }
  return end.message;
}

core::Result<SessionData> runSession(Device& daq, Device* actuator, const SessionPlan& plan, const Callbacks& callbacks,
                                     const CancelFlag* cancel, const SessionHooks& hooks) {
  EventQueue queue;
  SessionData data;
  if (actuator && plan.actuatorConfig) {
    if (auto r = openAndConfigure(*actuator, *plan.actuatorConfig, nullptr); !r) return r.error();
  }
  // A simulated rig re-seeds its noise at each configuration: give every step
  // its own seed (seed * 1009 + step), so the steps' noise is independent as on
  // a real rig, and the whole test still repeats bit for bit with the seed.
  AcquisitionConfig daqConfig = plan.daqConfig;
  // Blocks of 25 ms of data: live readouts at 40 per second in real time.
  if (daqConfig.blockScans == 0)
    daqConfig.blockScans = std::max<std::int64_t>(1, std::llround(daqConfig.sampleRateHz * kLiveBlockS));
  if (auto it = daqConfig.parameters.find("sim.seed"); it != daqConfig.parameters.end() && plan.step > 0)
    if (const auto* seed = std::get_if<std::int64_t>(&it->second))
      it->second = static_cast<std::int64_t>(
          (static_cast<std::uint64_t>(*seed) * 1009u + static_cast<std::uint64_t>(plan.step)) % 4294967296u);
  if (auto r = openAndConfigure(daq, daqConfig, nullptr); !r) return r.error();
  // The actuator first: its output (the set-point) runs before the DAQ records.
  const bool useActuator = actuator && plan.actuatorConfig;
  if (useActuator) {
    if (auto r = actuator->start(queue.sink(kActuator)); !r) return r.error();
  }
  if (auto r = daq.start(queue.sink(kDaq)); !r) {
    if (useActuator) actuator->stop();
    return r.error();
  }
  Eigen::Index rows = 0;
  bool daqEnded = false, stopping = false;
  auto silentSince = std::chrono::steady_clock::now();
  auto stopAll = [&] {
    if (stopping) return;
    stopping = true;
    daq.stop();  // joins the acquisition thread; its end event is queued
    if (useActuator) actuator->stop();
  };
  while (!daqEnded) {
    if (cancel && cancel->cancelled() && !stopping) {
      data.cancelled = true;
      stopAll();
    }
    auto ev = queue.pop(std::chrono::milliseconds(50));
    if (!ev) {
      if (std::chrono::steady_clock::now() - silentSince > plan.silence && !stopping) {
        stopAll();
        data.end = StreamEnd{EndReason::Timeout, rows, "no data for " + std::to_string(plan.silence.count()) + " ms"};
      }
      if (stopping && std::chrono::steady_clock::now() - silentSince > plan.silence * 2) {
        daqEnded = true;  // a stopped device that never sent its end: give up waiting
        if (data.end.message.empty()) data.end = StreamEnd{EndReason::Timeout, rows, "the device never ended"};
      }
      continue;
    }
    silentSince = std::chrono::steady_clock::now();
    auto& [source, event] = *ev;
    if (source == kActuator) {
      if (auto* end = std::get_if<StreamEnd>(&event); end && !stopping) {
        data.actuatorEnded = true;
        data.actuatorEnd = *end;
        stopAll();
      }
      continue;
    }
    if (auto* h = std::get_if<StreamHeader>(&event)) {
      data.header = *h;
      data.values.resize(0, static_cast<Eigen::Index>(h->channels.size()));
    } else if (auto* b = std::get_if<DataBlock>(&event)) {
      const Eigen::Index n = b->scanCount();
      if (rows + n > data.values.rows()) {
        // Grow by doubling: amortised O(1) per scan.
        data.values.conservativeResize(std::max<Eigen::Index>(rows + n, 2 * data.values.rows() + 1024),
                                       Eigen::NoChange);
      }
      data.values.middleRows(rows, n) = b->values;
      const Eigen::Index first = rows;
      rows += n;
      if (callbacks.live) {
        LiveReadout live;
        live.step = plan.step;
        live.stepLabel = plan.stepLabel;
        live.sampleRateHz = data.header.sampleRateHz;
        live.time = static_cast<double>(rows) / data.header.sampleRateHz;
        for (const auto& c : data.header.channels) {
          live.channels.push_back(c.name);
          live.units.push_back(c.transducer.unit);
        }
        live.block = b->values;
        if (hooks.derived) {
          live.derived = hooks.derived(b->values);
          live.derivedLabel = hooks.derivedLabel;
        }
        callbacks.live(live);
      }
      data.rows = rows;
      if (hooks.block) hooks.block(data, first, n);
    } else if (auto* t = std::get_if<TriggerEvent>(&event)) {
      data.triggers.push_back(*t);
      if (hooks.trigger) hooks.trigger(data, *t);
    } else if (auto* o = std::get_if<OverloadEvent>(&event)) {
      data.overloads.push_back(*o);
    } else if (auto* o = std::get_if<OverrunEvent>(&event)) {
      data.overruns.push_back(*o);
    } else if (auto* e = std::get_if<StreamEnd>(&event)) {
      if (data.end.message.empty() || e->reason != EndReason::Stopped) data.end = *e;
      daqEnded = true;
    }
  }
  stopAll();
  data.values.conservativeResize(rows, Eigen::NoChange);
  data.rows = rows;
  if (data.actuatorEnded && data.end.reason == EndReason::Stopped) data.end = data.actuatorEnd;
  return data;
}

}  // namespace detail
}  // namespace mozzi::devices::rigtests
