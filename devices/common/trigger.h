#pragma once
// Device-independent software trigger with a pre-trigger ring buffer, for
// impact-hammer hits (thesis §1.4, §1.6). Fed with consecutive blocks of
// scaled samples, it cuts records of `recordScans` scans of which
// round(preTriggerFraction * recordScans) lie before the trigger sample.
//
// Trigger sample: the first sample k of the trigger channel with
//   rising:  x[k-1] <  level <= x[k]
//   falling: x[k-1] >  level >= x[k]
//   either:  one of the two.
// A crossing is accepted only when the ring holds the full pre-trigger (so a
// record never lacks its beginning) and k >= the end of the previous record +
// holdOffScans (no re-trigger on the ringing of the last hit). Defaults are
// common practice: pre-trigger 10% of the record, overload when 3 or more
// samples of a channel sit at full scale.

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::devices {

enum class TriggerSlope { Rising, Falling, Either };

struct SoftwareTriggerConfig {
  int channel = 0;     // column of the blocks
  double level = 0.0;  // [EU]
  TriggerSlope slope = TriggerSlope::Rising;
  std::int64_t recordScans = 0;     // > 0
  double preTriggerFraction = 0.1;  // [0, 1)
  std::int64_t holdOffScans = 0;    // after the end of a record
  std::vector<double> fullScale;    // |EU| per channel (empty: no overload check)
  std::int64_t overloadSamples = 3;
};

struct TriggeredRecord {
  std::int64_t triggerSample = 0;  // absolute sample index of the trigger
  std::int64_t firstSample = 0;    // triggerSample - preTriggerScans
  std::int64_t preTriggerScans = 0;
  core::Matrix samples;                       // recordScans x channels [EU]
  std::vector<std::int64_t> fullScaleCounts;  // per channel: samples with |x| >= full scale
  bool overloaded = false;                    // any channel with >= overloadSamples at full scale
};

class SoftwareTrigger {
 public:
  static core::Result<SoftwareTrigger> create(const SoftwareTriggerConfig& config, int channelCount);

  // Feeds a block that starts at absolute sample `firstSample` (blocks must be
  // consecutive; a gap resets the ring and the armed state). Returns the
  // records completed by this block, in order.
  std::vector<TriggeredRecord> feed(std::int64_t firstSample, const core::MatrixRef& block);

  std::int64_t preTriggerScans() const { return pre_; }
  std::int64_t triggersAccepted() const { return accepted_; }
  std::int64_t crossingsIgnored() const { return ignored_; }

 private:
  SoftwareTrigger(SoftwareTriggerConfig config, int channels);
  bool crossed(double previous, double current) const;

  SoftwareTriggerConfig config_;
  int channels_ = 0;
  std::int64_t pre_ = 0;
  std::deque<std::vector<double>> ring_;  // last `pre_` scans
  std::optional<double> previous_;        // last sample of the trigger channel
  std::int64_t nextSample_ = -1;          // expected index of the next block
  std::int64_t blockedUntil_ = 0;         // crossings before this index are ignored
  struct Pending {
    TriggeredRecord record;
    std::int64_t filled = 0;
  };
  std::optional<Pending> pending_;
  std::int64_t accepted_ = 0;
  std::int64_t ignored_ = 0;
};

}  // namespace mozzi::devices
