#include "devices/campaign/roving_schedule.h"

#include <algorithm>

namespace mozzi::devices::campaign {

double ScheduleProgress::fraction() const {
  return pointCount > 0 ? static_cast<double>(pointsDone + pointsSkipped) / pointCount : 1.0;
}

RovingSchedule::RovingSchedule(const std::vector<core::io::StoredCampaignPoint>& points, int hitsPerPoint)
    : hitsPerPoint_(std::max(1, hitsPerPoint)) {
  for (const auto& p : points) {
    PointStatus s;
    s.position = p.position;
    s.dof = p.dof;
    s.skipped = p.skipped;
    s.skipReason = p.skipReason;
    points_.push_back(std::move(s));
  }
}

void RovingSchedule::replay(const std::vector<core::io::HitInfo>& hits) {
  for (const auto& h : hits) {
    const auto pos = positionOf(h.point);
    if (!pos) {
      ++ignored_;
      continue;
    }
    recordHit(*pos, h.accepted);
  }
}

void RovingSchedule::recordHit(int position, bool accepted) {
  auto& p = points_.at(static_cast<std::size_t>(position));
  ++p.attempts;
  if (accepted)
    ++p.accepted;
  else
    ++rejected_;
  p.done = p.accepted >= hitsPerPoint_;
}

void RovingSchedule::setSkipped(int position, bool skipped, const std::string& reason) {
  auto& p = points_.at(static_cast<std::size_t>(position));
  p.skipped = skipped;
  p.skipReason = skipped ? reason : std::string();
}

void RovingSchedule::redo(int position) {
  auto& p = points_.at(static_cast<std::size_t>(position));
  rejected_ += p.accepted;
  p.accepted = 0;
  p.done = false;
  p.skipped = false;
  p.skipReason.clear();
}

std::optional<int> RovingSchedule::positionOf(const core::Dof& dof) const {
  for (const auto& p : points_)
    if (p.dof == dof) return p.position;
  return std::nullopt;
}

std::optional<int> RovingSchedule::next() const {
  for (const auto& p : points_)
    if (!p.done && !p.skipped) return p.position;
  return std::nullopt;
}

ScheduleProgress RovingSchedule::progress() const {
  ScheduleProgress s;
  s.pointCount = static_cast<int>(points_.size());
  for (const auto& p : points_) {
    if (p.skipped)
      ++s.pointsSkipped;
    else if (p.done)
      ++s.pointsDone;
    s.acceptedHits += p.accepted;
  }
  s.rejectedHits = rejected_;
  s.next = next();
  return s;
}

}  // namespace mozzi::devices::campaign
