#pragma once
// The roving schedule of a campaign: the points in roving order, how many
// hits each holds (accepted, and every attempt including rejected ones), skips
// with the technician's reason, and which point comes next. Pure bookkeeping,
// rebuilt from the project on resume (campaign_store.h): a point is done when
// it holds the definition's number of accepted hits.

#include <optional>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/io/project_records.h"

namespace mozzi::devices::campaign {

struct PointStatus {
  int position = 0;
  core::Dof dof;
  int accepted = 0;  // accepted hits (not set aside by a redo)
  int attempts = 0;  // every committed hit at the point, accepted or not
  bool skipped = false;
  std::string skipReason;
  bool done = false;  // accepted >= hits per point
};

struct ScheduleProgress {
  int pointCount = 0;
  int pointsDone = 0;
  int pointsSkipped = 0;
  int acceptedHits = 0;
  int rejectedHits = 0;     // every committed hit not accepted (includes those a redo set aside)
  std::optional<int> next;  // first point neither done nor skipped
  bool complete() const { return !next.has_value(); }
  double fraction() const;  // (done + skipped) / count
};

class RovingSchedule {
 public:
  RovingSchedule() = default;
  RovingSchedule(const std::vector<core::io::StoredCampaignPoint>& points, int hitsPerPoint);

  // Replays the stored hits (in sequence order) onto the schedule; hits at a
  // DOF that is not in the schedule are ignored (and counted).
  void replay(const std::vector<core::io::HitInfo>& hits);
  void recordHit(int position, bool accepted);
  void setSkipped(int position, bool skipped, const std::string& reason);
  void redo(int position);  // accepted hits set aside, skip cleared

  std::optional<int> positionOf(const core::Dof& dof) const;
  std::optional<int> next() const;
  const std::vector<PointStatus>& points() const { return points_; }
  const PointStatus& point(int position) const { return points_.at(static_cast<std::size_t>(position)); }
  int hitsPerPoint() const { return hitsPerPoint_; }
  int ignoredHits() const { return ignored_; }
  ScheduleProgress progress() const;

 private:
  std::vector<PointStatus> points_;
  int hitsPerPoint_ = 1;
  int rejected_ = 0;
  int ignored_ = 0;
};

}  // namespace mozzi::devices::campaign
