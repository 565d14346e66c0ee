// The campaign's roving schedule and redo (schema 2, issue 15): separate from
// project_hits.cpp so the campaign engine's storage stays in one place.
#include <sqlite3.h>

#include <set>

#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

namespace {
std::string campaignWhere(const std::string& path, std::int64_t campaignId) {
  return path + ", campaign " + std::to_string(campaignId);
}
}  // namespace

Result<StoredCampaign> ProjectStore::campaign(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = campaignWhere(path_, campaignId);
  sql::Statement stmt(db_, std::string("SELECT ") + sql::kCampaignColumns + " FROM campaign WHERE id = ?1");
  MOZZI_TRY(stmt.lookup(campaignId, "campaign", where));
  return sql::campaignFromRow(stmt.get());
}

StoredCampaign sql::campaignFromRow(sqlite3_stmt* row) {
  const Row r(row);
  return {r.int64(0), r.int64(1), r.optionalInt64(2), r.text(3), r.text(4), r.text(5), r.text(6), r.text(7)};
}

Result<void> sql::insertCampaignPoints(sqlite3* db, std::int64_t campaignId,
                                       const std::vector<StoredCampaignPoint>& points, const std::string& where) {
  std::set<Dof> seen;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].position != static_cast<int>(i))
      return makeError(ErrorCode::InvalidArgument, "schedule positions must be 0..n-1 in order", where);
    if (!seen.insert(points[i].dof).second)
      return makeError(ErrorCode::InvalidArgument, "point " + formatDof(points[i].dof) + " is listed twice", where);
  }
  sql::Statement ins(db,
                     "INSERT INTO campaign_point(campaign_id, position, node, direction, skipped, skip_reason)"
                     " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (const auto& p : points) {
    MOZZI_TRY(ins.runWith("cannot store point " + formatDof(p.dof), where, campaignId, p.position, p.dof, p.skipped,
                          p.skipReason));
  }
  return {};
}

Result<void> ProjectStore::setCampaignPoints(std::int64_t campaignId, const std::vector<StoredCampaignPoint>& points) {
  const std::string where = campaignWhere(path_, campaignId) + ", schedule";
  return writeInTransaction(where, [&]() -> Result<void> {
    sql::Statement del(db_, "DELETE FROM campaign_point WHERE campaign_id = ?1");
    MOZZI_TRY(del.bindAll(campaignId).run("cannot replace the schedule", where));
    return sql::insertCampaignPoints(db_, campaignId, points, where);
  });
}

Result<std::vector<StoredCampaignPoint>> ProjectStore::campaignPoints(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = campaignWhere(path_, campaignId) + ", schedule";
  sql::Statement stmt(db_,
                      "SELECT position, node, direction, skipped, skip_reason FROM campaign_point"
                      " WHERE campaign_id = ?1 ORDER BY position");
  std::vector<StoredCampaignPoint> out;
  MOZZI_TRY(
      stmt.bindAll(campaignId).forEachRow("cannot read the schedule", where, [&](const sql::Row& r) -> Result<void> {
        if (r.int32(0) != static_cast<int>(out.size()))
          return makeError(ErrorCode::Corrupt, "schedule positions do not number 0..n-1", where);
        MOZZI_TRY_ASSIGN(const Dof dof, r.dof(1, 2, where));
        out.push_back({r.int32(0), dof, r.int32(3) != 0, r.text(4)});
        return {};
      }));
  return out;
}

Result<void> ProjectStore::setCampaignPointSkipped(std::int64_t campaignId, int position, bool skipped,
                                                   const std::string& reason) {
  const std::string where = campaignWhere(path_, campaignId) + ", point " + std::to_string(position);
  return writeInTransaction(where, [&]() -> Result<void> {
    sql::Statement stmt(
        db_, "UPDATE campaign_point SET skipped = ?3, skip_reason = ?4 WHERE campaign_id = ?1 AND position = ?2");
    stmt.bindAll(campaignId, position, skipped, skipped ? reason : std::string());
    MOZZI_TRY(stmt.run("cannot update the point", where));
    if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such point in the schedule", where);
    return {};
  });
}

Result<int> ProjectStore::redoCampaignPoint(std::int64_t campaignId, int position, const std::string& reason) {
  const std::string where = campaignWhere(path_, campaignId) + ", point " + std::to_string(position);
  int changed = 0;
  MOZZI_TRY(writeInTransaction(where, [&]() -> Result<void> {
    sql::Statement point(db_, "SELECT node, direction FROM campaign_point WHERE campaign_id = ?1 AND position = ?2");
    MOZZI_TRY(
        point.bindAll(campaignId, position).single("cannot read the point", "no such point in the schedule", where));
    const std::int64_t node = sqlite3_column_int64(point.get(), 0);
    const std::int64_t direction = sqlite3_column_int64(point.get(), 1);
    sql::Statement hits(db_,
                        "UPDATE hit SET accepted = 0, quality_flags = quality_flags | ?4,"
                        " quality_reasons = CASE quality_reasons WHEN '' THEN ?5 ELSE quality_reasons || '; ' || ?5 END"
                        " WHERE campaign_id = ?1 AND point_node = ?2 AND point_direction = ?3 AND accepted = 1");
    hits.bindAll(campaignId, node, direction, kHitManualReject, reason);
    MOZZI_TRY(hits.run("cannot set the point's hits aside", where));
    changed = sqlite3_changes(db_);
    sql::Statement unskip(
        db_, "UPDATE campaign_point SET skipped = 0, skip_reason = '' WHERE campaign_id = ?1 AND position = ?2");
    return unskip.bindAll(campaignId, position).run("cannot update the point", where);
  }));
  return changed;
}

Result<std::vector<std::int64_t>> ProjectStore::frfSetHits(std::int64_t frfSetId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", FRF set " + std::to_string(frfSetId);
  sql::Statement stmt(db_, "SELECT hit_id FROM frf_hit WHERE frf_set_id = ?1 ORDER BY hit_id");
  std::vector<std::int64_t> out;
  MOZZI_TRY(stmt.bindAll(frfSetId).forEachRow("cannot read the FRF set's hits", where,
                                              [&](const sql::Row& r) { out.push_back(r.int64(0)); }));
  return out;
}

}  // namespace mozzi::core::io
