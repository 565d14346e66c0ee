#include "devices/campaign/hit_pipeline.h"

#include <cmath>
#include <cstdio>

#include "core/io/project_records.h"

namespace mozzi::devices::campaign {

std::string HitVerdict::text() const {
  if (passed) return "accepted";
  std::string s = "rejected: ";
  for (std::size_t i = 0; i < reasons.size(); ++i) s += (i ? "; " : "") + reasons[i];
  return s;
}

Eigen::MatrixXf storedSamples(const core::Matrix& samples) {
  return samples.cast<float>();
}

core::Matrix samplesFromStored(const Eigen::MatrixXf& stored) {
  return stored.cast<double>();
}

PointAverage::PointAverage(const CampaignDefinition& definition) : definition_(&definition) {}

core::Result<void> PointAverage::add(const core::signal::TimeRecord& record) {
  if (!averager_) {
    auto a = core::signal::SpectralAverager::create(record, definition_->frfOptions());
    if (!a) return a.error();
    averager_ = std::move(*a);
  }
  return averager_->add(record);
}

core::Result<core::FrfMatrix> PointAverage::frf() const {
  if (!averager_ || averager_->hitCount() == 0)
    return core::makeError(core::ErrorCode::InvalidArgument, "the point has no accepted hit yet", "running average");
  auto f = averager_->frf(definition_->estimator);
  if (!f) return f.error();
  return core::signal::selectBand(*f, 0.0, definition_->storedBandHz());
}

core::Result<std::optional<double>> PointAverage::coherenceWith(const core::signal::TimeRecord& record, double lowHz,
                                                                double highHz) const {
  if (!averager_ || averager_->hitCount() == 0) return std::optional<double>();
  core::signal::SpectralAverager trial = *averager_;
  if (auto r = trial.add(record); !r) return r.error();
  auto f = trial.frf(definition_->estimator);
  if (!f) return f.error();
  double sum = 0.0;
  std::int64_t n = 0;
  for (Eigen::Index k = 0; k < f->lineCount(); ++k) {
    const double hz = f->frequencyHz[k];
    if (hz < lowHz || hz > highHz) continue;
    for (const auto& c : f->coherence) {
      sum += c.row(k).sum();
      n += c.cols();
    }
  }
  if (n == 0) return std::optional<double>();
  return std::optional<double>(sum / static_cast<double>(n));
}

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

bool startsWith(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

}  // namespace

core::Result<HitVerdict> judgeHit(const CampaignDefinition& d, const core::signal::TimeRecord& record,
                                  const PointAverage* average) {
  namespace io = core::io;
  core::signal::HitQualityOptions opt;
  const int fc = d.forceChannel();
  if (fc >= 0) opt.referenceChannel = fc;
  opt.triggerLevel = d.acquisition.triggerLevel;
  opt.minForceSnrDb = d.rules.minForceSnrDb;
  auto q = core::signal::assessHit(record, opt);
  if (!q) return q.error();
  HitVerdict v;
  v.quality = *q;
  v.notes = q->notes;
  // Sort the checks' reasons into the campaign's rules; a rule switched off
  // turns its finding into a note.
  for (const auto& r : q->reasons) {
    if (startsWith(r, "double hit")) {
      (d.rules.doubleHit ? v.reasons : v.notes).push_back(r);
      if (d.rules.doubleHit) v.flags |= io::kHitDoubleHit;
    } else if (startsWith(r, "overload")) {
      (d.rules.overload ? v.reasons : v.notes).push_back(r);
      if (d.rules.overload) v.flags |= io::kHitOverload;
    } else if (startsWith(r, "hit too early")) {
      v.reasons.push_back(r);
      v.flags |= io::kHitTruncated;
    } else {
      v.reasons.push_back(r);  // no signal, never reaches the trigger, force weak against noise
      v.flags |= io::kHitLowSignal;
    }
  }
  if (d.rules.minPeakForceN > 0.0 && std::abs(q->peakForce) < d.rules.minPeakForceN) {
    v.reasons.push_back("force too low: peak " + fmt("%.1f", std::abs(q->peakForce)) + " N, " +
                        fmt("%.1f", d.rules.minPeakForceN) + " N needed");
    v.flags |= io::kHitLowSignal;
  }
  if (d.rules.minCoherence > 0.0 && average && v.reasons.empty()) {
    const double lo = d.rules.coherenceBandHighHz > 0.0 ? d.rules.coherenceBandLowHz : 0.0;
    const double hi = d.rules.coherenceBandHighHz > 0.0 ? d.rules.coherenceBandHighHz : d.storedBandHz();
    auto c = average->coherenceWith(record, lo, hi);
    if (!c) return c.error();
    v.meanCoherence = *c;
    if (*c && **c < d.rules.minCoherence) {
      v.reasons.push_back("poor coherence: mean " + fmt("%.3f", **c) + " over " + fmt("%.0f", lo) + ".." +
                          fmt("%.0f", hi) + " Hz with this hit, " + fmt("%.2f", d.rules.minCoherence) + " needed");
      v.flags |= io::kHitLowCoherence;
    }
  }
  v.passed = v.reasons.empty();
  return v;
}

}  // namespace mozzi::devices::campaign
