#include "devices/common/acquisition.h"

#include <algorithm>
#include <set>

namespace mozzi::devices {

const char* endReasonName(EndReason reason) {
  switch (reason) {
    case EndReason::Completed: return "completed";
    case EndReason::Stopped: return "stopped";
    case EndReason::Disconnected: return "device disconnected";
    case EndReason::Timeout: return "transfer timeout";
    case EndReason::Overrun: return "overrun";
    case EndReason::Error: return "error";
  }
  return "unknown";
}

namespace {
const InputRange* findRange(const InputChannelSpec& spec, std::uint8_t code) {
  for (const auto& r : spec.ranges)
    if (r.code == code) return &r;
  return nullptr;
}
}  // namespace

core::Result<AcquisitionConfig> validateConfig(const Capabilities& caps, const AcquisitionConfig& requested) {
  AcquisitionConfig applied = requested;
  if (requested.channels.empty())
    return core::makeError(core::ErrorCode::InvalidArgument, "enable at least one input channel", "channels");
  std::set<int> seen;
  for (std::size_t i = 0; i < requested.channels.size(); ++i) {
    const auto& ch = requested.channels[i];
    const std::string where = "channel " + std::to_string(i) + (ch.name.empty() ? "" : " (" + ch.name + ")");
    if (ch.input < 0 || ch.input >= static_cast<int>(caps.inputs.size()))
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "input " + std::to_string(ch.input) + " does not exist on " + caps.model + " (it has " +
                                 std::to_string(caps.inputs.size()) + ")",
                             where);
    if (!seen.insert(ch.input).second)
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "input " + std::to_string(ch.input) + " is configured twice", where);
    const auto& spec = caps.inputs[static_cast<std::size_t>(ch.input)];
    if (!findRange(spec, ch.rangeCode))
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "range code " + std::to_string(ch.rangeCode) + " is not offered by " + spec.name, where);
    if (std::find(spec.couplings.begin(), spec.couplings.end(), ch.coupling) == spec.couplings.end())
      return core::makeError(core::ErrorCode::InvalidArgument,
                             std::string(couplingName(ch.coupling)) + " coupling is not available at " + spec.name +
                                 "; use an external conditioner and declare its gain",
                             where);
    if (ch.iepe && !spec.iepeSupply)
      return core::makeError(core::ErrorCode::InvalidArgument,
                             spec.name + " has no IEPE supply; power the sensor from an external conditioner", where);
    ChannelChain chain;
    chain.range = *findRange(spec, ch.rangeCode);
    chain.resolutionBits = spec.resolutionBits;
    chain.conditionerGain = ch.conditionerGain;
    chain.transducer = ch.transducer;
    auto ok = validateChain(chain, where);
    if (!ok) return ok.error();
  }
  auto rate = quantiseRate(caps.rates, requested.sampleRateHz);
  if (!rate) return rate.error();
  applied.sampleRateHz = *rate;
  const double aggregate = *rate * static_cast<double>(requested.channels.size());
  if (caps.rates.maxAggregateHz > 0.0 && aggregate > caps.rates.maxAggregateHz * (1.0 + 1e-12))
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "aggregate rate " + std::to_string(aggregate) + " S/s exceeds the device limit of " +
                               std::to_string(caps.rates.maxAggregateHz) + " S/s",
                           "sample rate");
  if (requested.blockScans < 0 || requested.scanCount < 0)
    return core::makeError(core::ErrorCode::InvalidArgument, "block size and scan count must not be negative",
                           "blocks");
  if (applied.blockScans == 0)  // about 50 ms of data per block, at least one scan
    applied.blockScans = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(0.05 * *rate)));
  auto params = applyParameters(caps.parameters, requested.parameters);
  if (!params) return params.error();
  applied.parameters = *params;
  // Inputs in ascending order: the order in which scanning devices send them.
  std::sort(applied.channels.begin(), applied.channels.end(),
            [](const ChannelConfig& a, const ChannelConfig& b) { return a.input < b.input; });
  return applied;
}

std::vector<ChannelChain> chainsFor(const Capabilities& caps, const AcquisitionConfig& config) {
  std::vector<ChannelChain> chains;
  for (const auto& ch : config.channels) {
    ChannelChain chain;
    const auto& spec = caps.inputs.at(static_cast<std::size_t>(ch.input));
    chain.range = *findRange(spec, ch.rangeCode);
    chain.resolutionBits = spec.resolutionBits;
    chain.conditionerGain = ch.conditionerGain;
    chain.transducer = ch.transducer;
    chains.push_back(chain);
  }
  return chains;
}

std::vector<OverloadEvent> detectOverloads(const DataBlock& block, const std::vector<ChannelChain>& chains,
                                           std::int64_t threshold) {
  std::vector<OverloadEvent> events;
  const std::size_t nc = chains.size();
  if (nc == 0) return events;
  const std::size_t scans = block.raw.size() / nc;
  for (std::size_t c = 0; c < nc; ++c) {
    std::int64_t count = 0;
    for (std::size_t s = 0; s < scans; ++s)
      if (chains[c].atFullScale(chains[c].correctedCode(block.raw[s * nc + c]))) ++count;
    if (count >= threshold) events.push_back(OverloadEvent{block.firstSample, static_cast<int>(c), count});
  }
  return events;
}

StreamSink StreamCollector::sink() {
  return [this](StreamEvent&& e) { push(std::move(e)); };
}

void StreamCollector::push(StreamEvent&& e) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (end_) eventAfterEnd_ = true;
    if (auto* h = std::get_if<StreamHeader>(&e))
      header_ = std::move(*h);
    else if (auto* b = std::get_if<DataBlock>(&e)) {
      scans_ += b->scanCount();
      blocks_.push_back(std::move(*b));
    } else if (auto* o = std::get_if<OverrunEvent>(&e))
      overruns_.push_back(*o);
    else if (auto* l = std::get_if<OverloadEvent>(&e))
      overloads_.push_back(*l);
    else if (auto* t = std::get_if<TriggerEvent>(&e))
      triggers_.push_back(*t);
    else if (auto* s = std::get_if<StreamEnd>(&e))
      end_ = *s;
  }
  cv_.notify_all();
}

bool StreamCollector::waitForEnd(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  return cv_.wait_for(lock, timeout, [&] { return end_.has_value(); });
}

bool StreamCollector::waitForScans(std::int64_t scans, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  return cv_.wait_for(lock, timeout, [&] { return scans_ >= scans || end_.has_value(); }) && scans_ >= scans;
}

std::optional<StreamHeader> StreamCollector::header() const {
  std::lock_guard<std::mutex> l(mutex_);
  return header_;
}
std::optional<StreamEnd> StreamCollector::end() const {
  std::lock_guard<std::mutex> l(mutex_);
  return end_;
}
std::vector<OverrunEvent> StreamCollector::overruns() const {
  std::lock_guard<std::mutex> l(mutex_);
  return overruns_;
}
std::vector<OverloadEvent> StreamCollector::overloads() const {
  std::lock_guard<std::mutex> l(mutex_);
  return overloads_;
}
std::vector<TriggerEvent> StreamCollector::triggers() const {
  std::lock_guard<std::mutex> l(mutex_);
  return triggers_;
}
std::int64_t StreamCollector::scans() const {
  std::lock_guard<std::mutex> l(mutex_);
  return scans_;
}

core::Matrix StreamCollector::values() const {
  std::lock_guard<std::mutex> l(mutex_);
  Eigen::Index cols = blocks_.empty() ? 0 : blocks_.front().values.cols();
  core::Matrix all(scans_, cols);
  Eigen::Index row = 0;
  for (const auto& b : blocks_) {
    all.middleRows(row, b.values.rows()) = b.values;
    row += b.values.rows();
  }
  return all;
}

std::vector<std::int32_t> StreamCollector::raw() const {
  std::lock_guard<std::mutex> l(mutex_);
  std::vector<std::int32_t> all;
  for (const auto& b : blocks_) all.insert(all.end(), b.raw.begin(), b.raw.end());
  return all;
}

std::vector<std::int64_t> StreamCollector::blockStarts() const {
  std::lock_guard<std::mutex> l(mutex_);
  std::vector<std::int64_t> s;
  for (const auto& b : blocks_) s.push_back(b.firstSample);
  return s;
}

bool StreamCollector::orderedAndContiguous() const {
  std::lock_guard<std::mutex> l(mutex_);
  if (eventAfterEnd_) return false;
  std::int64_t next = blocks_.empty() ? 0 : blocks_.front().firstSample;
  for (const auto& b : blocks_) {
    if (b.firstSample != next) return false;
    next += b.scanCount();
  }
  return true;
}

}  // namespace mozzi::devices
