// The campaign's roving schedule and redo (schema 2, issue 15): separate from
// project_hits.cpp so the campaign engine's storage stays in one place.
#include <sqlite3.h>

#include <set>

#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using sql::sqliteError;

namespace {
std::string campaignWhere(const std::string& path, std::int64_t campaignId) {
  return path + ", campaign " + std::to_string(campaignId);
}
}  // namespace

Result<StoredCampaign> ProjectStore::campaign(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = campaignWhere(path_, campaignId);
  sql::Statement stmt(db_, (std::string("SELECT ") + sql::kCampaignColumns + " FROM campaign WHERE id = ?1").c_str());
  if (!stmt.ok()) return sqliteError(db_, "cannot read the campaign", where);
  stmt.bind(1, campaignId);
  const int rc = stmt.step();
  if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such campaign", where);
  if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the campaign", where);
  return sql::campaignFromRow(stmt.get());
}

StoredCampaign sql::campaignFromRow(sqlite3_stmt* row) {
  StoredCampaign c;
  c.id = sqlite3_column_int64(row, 0);
  c.specimenId = sqlite3_column_int64(row, 1);
  if (sqlite3_column_type(row, 2) != SQLITE_NULL) c.rigSetupId = sqlite3_column_int64(row, 2);
  c.name = columnText(row, 3);
  c.kind = columnText(row, 4);
  c.notes = columnText(row, 5);
  c.startedUtc = columnText(row, 6);
  c.settingsJson = columnText(row, 7);
  return c;
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
    ins.reset();
    ins.bind(1, campaignId).bind(2, p.position).bind(3, p.dof.node).bind(4, p.dof.uffCode());
    ins.bind(5, p.skipped ? 1 : 0).bind(6, p.skipReason);
    if (ins.step() != SQLITE_DONE) return sqliteError(db, "cannot store point " + formatDof(p.dof), where);
  }
  return {};
}

Result<void> ProjectStore::setCampaignPoints(std::int64_t campaignId, const std::vector<StoredCampaignPoint>& points) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r;
  const std::string where = campaignWhere(path_, campaignId) + ", schedule";
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun();
  sql::Statement del(db_, "DELETE FROM campaign_point WHERE campaign_id = ?1");
  del.bind(1, campaignId);
  if (del.step() != SQLITE_DONE) return sqliteError(db_, "cannot replace the schedule", where);
  if (auto r = sql::insertCampaignPoints(db_, campaignId, points, where); !r) return r;
  return tx.commit();
}

Result<std::vector<StoredCampaignPoint>> ProjectStore::campaignPoints(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = campaignWhere(path_, campaignId) + ", schedule";
  sql::Statement stmt(db_,
                      "SELECT position, node, direction, skipped, skip_reason FROM campaign_point"
                      " WHERE campaign_id = ?1 ORDER BY position");
  if (!stmt.ok()) return sqliteError(db_, "cannot read the schedule", where);
  stmt.bind(1, campaignId);
  std::vector<StoredCampaignPoint> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    StoredCampaignPoint p;
    p.position = sqlite3_column_int(stmt.get(), 0);
    if (p.position != static_cast<int>(out.size()))
      return makeError(ErrorCode::Corrupt, "schedule positions do not number 0..n-1", where);
    auto dof = sql::columnDof(stmt.get(), 1, 2, where);
    if (!dof) return dof.error();
    p.dof = *dof;
    p.skipped = sqlite3_column_int(stmt.get(), 3) != 0;
    p.skipReason = sql::columnText(stmt.get(), 4);
    out.push_back(std::move(p));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read the schedule", where);
  return out;
}

Result<void> ProjectStore::setCampaignPointSkipped(std::int64_t campaignId, int position, bool skipped,
                                                   const std::string& reason) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r;
  const std::string where = campaignWhere(path_, campaignId) + ", point " + std::to_string(position);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun();
  sql::Statement stmt(
      db_, "UPDATE campaign_point SET skipped = ?3, skip_reason = ?4 WHERE campaign_id = ?1 AND position = ?2");
  stmt.bind(1, campaignId).bind(2, position).bind(3, skipped ? 1 : 0).bind(4, skipped ? reason : std::string());
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot update the point", where);
  if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such point in the schedule", where);
  return tx.commit();
}

Result<int> ProjectStore::redoCampaignPoint(std::int64_t campaignId, int position, const std::string& reason) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = campaignWhere(path_, campaignId) + ", point " + std::to_string(position);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement point(db_, "SELECT node, direction FROM campaign_point WHERE campaign_id = ?1 AND position = ?2");
  point.bind(1, campaignId).bind(2, position);
  const int rc = point.step();
  if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such point in the schedule", where);
  if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the point", where);
  const std::int64_t node = sqlite3_column_int64(point.get(), 0);
  const std::int64_t direction = sqlite3_column_int64(point.get(), 1);
  sql::Statement hits(db_,
                      "UPDATE hit SET accepted = 0, quality_flags = quality_flags | ?4,"
                      " quality_reasons = CASE quality_reasons WHEN '' THEN ?5 ELSE quality_reasons || '; ' || ?5 END"
                      " WHERE campaign_id = ?1 AND point_node = ?2 AND point_direction = ?3 AND accepted = 1");
  hits.bind(1, campaignId).bind(2, node).bind(3, direction);
  hits.bind(4, static_cast<std::int64_t>(kHitManualReject)).bind(5, reason);
  if (hits.step() != SQLITE_DONE) return sqliteError(db_, "cannot set the point's hits aside", where);
  const int changed = sqlite3_changes(db_);
  sql::Statement unskip(
      db_, "UPDATE campaign_point SET skipped = 0, skip_reason = '' WHERE campaign_id = ?1 AND position = ?2");
  unskip.bind(1, campaignId).bind(2, position);
  if (unskip.step() != SQLITE_DONE) return sqliteError(db_, "cannot update the point", where);
  if (auto r = tx.commit(); !r) return r.error();
  return changed;
}

Result<std::vector<std::int64_t>> ProjectStore::frfSetHits(std::int64_t frfSetId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", FRF set " + std::to_string(frfSetId);
  sql::Statement stmt(db_, "SELECT hit_id FROM frf_hit WHERE frf_set_id = ?1 ORDER BY hit_id");
  if (!stmt.ok()) return sqliteError(db_, "cannot read the FRF set's hits", where);
  stmt.bind(1, frfSetId);
  std::vector<std::int64_t> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) out.push_back(sqlite3_column_int64(stmt.get(), 0));
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read the FRF set's hits", where);
  return out;
}

}  // namespace mozzi::core::io
