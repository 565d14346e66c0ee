#include "devices/common/trigger.h"

#include <cmath>

namespace mozzi::devices {

core::Result<SoftwareTrigger> SoftwareTrigger::create(const SoftwareTriggerConfig& config, int channelCount) {
  auto bad = [](const std::string& m) {
    return core::makeError(core::ErrorCode::InvalidArgument, m, "software trigger");
  };
  if (channelCount <= 0) return bad("the stream has no channels");
  if (config.channel < 0 || config.channel >= channelCount)
    return bad("trigger channel " + std::to_string(config.channel) + " does not exist");
  if (config.recordScans <= 0) return bad("the record length must be at least one scan");
  if (!(config.preTriggerFraction >= 0.0 && config.preTriggerFraction < 1.0))
    return bad("the pre-trigger fraction must be in [0, 1)");
  if (config.holdOffScans < 0) return bad("the hold-off must not be negative");
  if (!std::isfinite(config.level)) return bad("the trigger level must be finite");
  if (!config.fullScale.empty() && static_cast<int>(config.fullScale.size()) != channelCount)
    return bad("give one full-scale value per channel or none");
  return SoftwareTrigger(config, channelCount);
}

SoftwareTrigger::SoftwareTrigger(SoftwareTriggerConfig config, int channels)
    : config_(std::move(config)), channels_(channels) {
  pre_ = static_cast<std::int64_t>(std::llround(config_.preTriggerFraction * static_cast<double>(config_.recordScans)));
}

bool SoftwareTrigger::crossed(double previous, double current) const {
  const bool up = previous < config_.level && current >= config_.level;
  const bool down = previous > config_.level && current <= config_.level;
  switch (config_.slope) {
    case TriggerSlope::Rising: return up;
    case TriggerSlope::Falling: return down;
    case TriggerSlope::Either: return up || down;
  }
  return false;
}

std::vector<TriggeredRecord> SoftwareTrigger::feed(std::int64_t firstSample, const core::MatrixRef& block) {
  std::vector<TriggeredRecord> done;
  if (block.cols() != channels_) return done;
  if (nextSample_ >= 0 && firstSample != nextSample_) {
    // A gap (overrun, restart): the ring no longer holds the samples just before
    // the next ones, and a pending record cannot be completed honestly.
    ring_.clear();
    previous_.reset();
    pending_.reset();
  }
  nextSample_ = firstSample + block.rows();
  for (Eigen::Index r = 0; r < block.rows(); ++r) {
    const std::int64_t k = firstSample + r;
    const double x = block(r, config_.channel);
    if (pending_) {
      auto& rec = pending_->record;
      rec.samples.row(pending_->filled) = block.row(r);
      ++pending_->filled;
      if (pending_->filled == config_.recordScans) {
        if (!config_.fullScale.empty()) {
          for (int c = 0; c < channels_; ++c) {
            std::int64_t n = 0;
            for (Eigen::Index i = 0; i < rec.samples.rows(); ++i)
              if (std::abs(rec.samples(i, c)) >= config_.fullScale[static_cast<std::size_t>(c)]) ++n;
            rec.fullScaleCounts[static_cast<std::size_t>(c)] = n;
            if (n >= config_.overloadSamples) rec.overloaded = true;
          }
        }
        blockedUntil_ = rec.firstSample + config_.recordScans + config_.holdOffScans;
        done.push_back(std::move(rec));
        pending_.reset();
      }
    } else if (previous_ && crossed(*previous_, x)) {
      if (static_cast<std::int64_t>(ring_.size()) == pre_ && k >= blockedUntil_) {
        Pending p;
        p.record.triggerSample = k;
        p.record.preTriggerScans = pre_;
        p.record.firstSample = k - pre_;
        p.record.samples.resize(config_.recordScans, channels_);
        p.record.fullScaleCounts.assign(static_cast<std::size_t>(channels_), 0);
        Eigen::Index i = 0;
        for (const auto& scan : ring_) {
          for (int c = 0; c < channels_; ++c) p.record.samples(i, c) = scan[static_cast<std::size_t>(c)];
          ++i;
        }
        p.record.samples.row(i) = block.row(r);
        p.filled = pre_ + 1;
        ++accepted_;
        if (p.filled == config_.recordScans) {
          blockedUntil_ = p.record.firstSample + config_.recordScans + config_.holdOffScans;
          done.push_back(std::move(p.record));
        } else {
          pending_ = std::move(p);
        }
      } else {
        ++ignored_;
      }
    }
    previous_ = x;
    if (pre_ > 0) {
      std::vector<double> scan(static_cast<std::size_t>(channels_));
      for (int c = 0; c < channels_; ++c) scan[static_cast<std::size_t>(c)] = block(r, c);
      ring_.push_back(std::move(scan));
      if (static_cast<std::int64_t>(ring_.size()) > pre_) ring_.pop_front();
    }
  }
  return done;
}

}  // namespace mozzi::devices
