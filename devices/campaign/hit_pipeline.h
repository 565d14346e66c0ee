#pragma once
// What happens to one hit between the trigger and the decision, without a
// device or a store (the engine runs it on its thread; the latency benchmark
// runs it alone): the record is rounded to the float32 the project stores (so
// that a live average and one rebuilt from the project on resume are the same
// numbers), checked by core/signal's hit quality, judged by the campaign's
// rejection rules, and, when a coherence rule is set, tried on a copy of the
// point's running average.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/signal/frf_estimator.h"
#include "core/signal/hit_quality.h"
#include "devices/campaign/campaign_definition.h"

namespace mozzi::devices::campaign {

struct HitVerdict {
  bool passed = false;               // every rule passed: accept unless the technician says otherwise
  std::vector<std::string> reasons;  // why it fails, in words (double hit, overload, force too low, poor coherence)
  std::vector<std::string> notes;    // remarks that do not reject
  std::uint32_t flags = 0;           // core::io::HitQualityFlag bits of the failed rules
  core::signal::HitQuality quality;
  std::optional<double> meanCoherence;  // of the point's average with this hit, when the rule ran
  std::string text() const;             // "accepted" or "rejected: reason; reason"
};

// The samples as the project stores them (float32) and back: a hit averaged
// live and the same hit read back from the project give the same spectra.
Eigen::MatrixXf storedSamples(const core::Matrix& samples);
core::Matrix samplesFromStored(const Eigen::MatrixXf& stored);

// The running average of one point (H1/H2/Hv with coherence, windows of the
// definition); FRFs cut to the stored band.
class PointAverage {
 public:
  explicit PointAverage(const CampaignDefinition& definition);
  core::Result<void> add(const core::signal::TimeRecord& record);
  int hits() const { return averager_ ? averager_->hitCount() : 0; }
  void reset() { averager_.reset(); }
  // Lines 0..storedBandHz of the estimator's FRF with coherence.
  core::Result<core::FrfMatrix> frf() const;
  // Mean coherence over the band of every response with `record` added (the
  // average itself is left as it is); nullopt when there is no hit yet.
  core::Result<std::optional<double>> coherenceWith(const core::signal::TimeRecord& record, double lowHz,
                                                    double highHz) const;

 private:
  const CampaignDefinition* definition_;
  std::optional<core::signal::SpectralAverager> averager_;
};

// Verdict of the rules on one record (already rounded with storedSamples).
// `average` (may be null) is the point's average before this hit, for the
// coherence rule. Errors only for a record the checks cannot read.
core::Result<HitVerdict> judgeHit(const CampaignDefinition& definition, const core::signal::TimeRecord& record,
                                  const PointAverage* average);

}  // namespace mozzi::devices::campaign
