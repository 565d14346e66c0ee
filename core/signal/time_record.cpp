#include "core/signal/time_record.h"

#include <cmath>

#include "core/common/enum_names.h"
#include "core/signal/sample_scan.h"

namespace mozzi::core::signal {

namespace {
constexpr EnumEntry<TransducerKind, const char*> kTransducerKindEntries[] = {
    {TransducerKind::Force, "force"},
    {TransducerKind::Acceleration, "acceleration"},
    {TransducerKind::Velocity, "velocity"},
    {TransducerKind::Displacement, "displacement"},
    {TransducerKind::AngularRate, "angular rate"},
    {TransducerKind::Other, "other"}};
constexpr auto kTransducerKindNames = enumTable(kTransducerKindEntries, "other");
}  // namespace

const char* transducerKindName(TransducerKind kind) {
  return kTransducerKindNames.of(kind);
}

namespace {
std::string channelLabel(const TimeRecord& r, Eigen::Index c) {
  const auto& ch = r.channels[static_cast<std::size_t>(c)];
  std::string s = "channel " + std::to_string(c);
  if (!ch.name.empty()) s += " '" + ch.name + "'";
  return s + " (" + formatDof(ch.dof) + ")";
}
}  // namespace

namespace {
// What validate() and validateLayout() check before the channels.
Result<void> checkRecord(const TimeRecord& r) {
  const std::string where = "time record";
  if (!std::isfinite(r.sampleRateHz) || r.sampleRateHz <= 0.0) {
    return makeError(ErrorCode::InvalidArgument,
                     "sample rate must be finite and positive, got " + std::to_string(r.sampleRateHz) + " Hz", where);
  }
  if (r.channels.empty()) return makeError(ErrorCode::InvalidArgument, "record has no channels", where);
  if (r.samples.cols() != r.channelCount()) {
    return makeError(ErrorCode::InvalidArgument,
                     "sample matrix has " + std::to_string(r.samples.cols()) + " columns for " +
                         std::to_string(r.channelCount()) + " channels (mismatched lengths)",
                     where);
  }
  if (r.samples.rows() < 2) {
    return makeError(ErrorCode::InvalidArgument,
                     "record is empty or too short (" + std::to_string(r.samples.rows()) + " samples, need 2)", where);
  }
  if (r.preTriggerSamples < 0 || r.preTriggerSamples >= r.samples.rows()) {
    return makeError(ErrorCode::InvalidArgument,
                     "pre-trigger of " + std::to_string(r.preTriggerSamples) + " samples lies outside the record of " +
                         std::to_string(r.samples.rows()),
                     where);
  }
  return {};
}

Result<void> checkSensitivity(const TimeRecord& r, Eigen::Index c) {
  const auto& t = r.channels[static_cast<std::size_t>(c)].transducer;
  if (!std::isfinite(t.sensitivityMvPerUnit) || t.sensitivityMvPerUnit <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "transducer sensitivity must be positive (mV per unit)",
                     "time record, " + channelLabel(r, c));
  }
  return {};
}
}  // namespace

Result<void> TimeRecord::validateLayout() const {
  MOZZI_TRY(checkRecord(*this));
  for (Eigen::Index c = 0; c < channelCount(); ++c) MOZZI_TRY(checkSensitivity(*this, c));
  return {};
}

Result<void> TimeRecord::validate() const {
  MOZZI_TRY(checkRecord(*this));
  // Channel by channel, its sensitivity then its samples: the first offender.
  for (Eigen::Index c = 0; c < channelCount(); ++c) {
    MOZZI_TRY(checkSensitivity(*this, c));
    if (scanSamples(samples.col(c).data(), samples.rows()).finite) continue;
    for (Eigen::Index i = 0; i < samples.rows(); ++i) {
      if (!std::isfinite(samples(i, c))) {
        return makeError(ErrorCode::InvalidArgument, "sample is NaN or infinite",
                         "time record, " + channelLabel(*this, c) + ", sample " + std::to_string(i));
      }
    }
  }
  return {};
}

Result<Vector> engineeringFromVolts(const VectorRef& volts, const Transducer& transducer) {
  if (!std::isfinite(transducer.sensitivityMvPerUnit) || transducer.sensitivityMvPerUnit <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "transducer sensitivity must be positive (mV per unit)",
                     "transducer " + transducer.model + " " + transducer.serial);
  }
  return Vector(volts * (1000.0 / transducer.sensitivityMvPerUnit));
}

Result<Eigen::Index> findForceChannel(const TimeRecord& record) {
  Eigen::Index found = -1;
  for (Eigen::Index c = 0; c < record.channelCount(); ++c) {
    if (record.channels[static_cast<std::size_t>(c)].transducer.kind != TransducerKind::Force) continue;
    if (found >= 0) {
      return makeError(ErrorCode::InvalidArgument, "more than one force channel; name the reference explicitly",
                       "time record, " + channelLabel(record, found) + " and " + channelLabel(record, c));
    }
    found = c;
  }
  if (found < 0) return makeError(ErrorCode::NotFound, "no force channel to use as reference", "time record");
  return found;
}

}  // namespace mozzi::core::signal
