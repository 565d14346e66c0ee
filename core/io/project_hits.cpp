// ProjectStore: campaigns and their hits (time records with channel
// descriptions and acceptance).

#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::checkSamples;
using data::columnSamples;
using data::finite;
using data::hitWhere;
using sql::sqliteError;

// --- campaigns and hits --------------------------------------------------------------

Result<std::int64_t> ProjectStore::addCampaign(const StoredCampaign& campaign,
                                               const std::vector<StoredCampaignPoint>& points) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", campaign '" + campaign.name + "'";
  if (campaign.name.empty()) return makeError(ErrorCode::InvalidArgument, "a campaign needs a name", where);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO campaign(specimen_id, rig_setup_id, name, kind, started_utc, notes, settings_json)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  stmt.bind(1, campaign.specimenId).bind(2, campaign.rigSetupId).bind(3, campaign.name).bind(4, campaign.kind);
  stmt.bind(5, campaign.startedUtc.empty() ? sql::nowUtc() : campaign.startedUtc).bind(6, campaign.notes);
  stmt.bind(7, campaign.settingsJson.empty() ? std::string("{}") : campaign.settingsJson);
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the campaign", where));
  MOZZI_TRY(sql::insertCampaignPoints(db_, id, points, where));
  MOZZI_TRY(tx.commit());
  return id;
}

Result<std::vector<StoredCampaign>> ProjectStore::campaigns(std::int64_t specimenId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(
      db_,
      (std::string("SELECT ") + sql::kCampaignColumns + " FROM campaign WHERE specimen_id = ?1 ORDER BY id").c_str());
  stmt.bind(1, specimenId);
  std::vector<StoredCampaign> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    out.push_back(sql::campaignFromRow(stmt.get()));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read campaigns", path_);
  return out;
}

Result<std::int64_t> ProjectStore::commitHit(const StoredHit& hit) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where =
      path_ + ", campaign " + std::to_string(hit.campaignId) + ", hit " + std::to_string(hit.sequence);
  if (hit.sequence <= 0) return makeError(ErrorCode::InvalidArgument, "hit sequence numbers start at 1", where);
  MOZZI_TRY(checkSamples(hit.samples, hit.sampleRateHz, where));
  if (!hit.channels.empty() && static_cast<Eigen::Index>(hit.channels.size()) != hit.channelCount()) {
    return makeError(ErrorCode::InvalidArgument,
                     std::to_string(hit.channels.size()) + " channel descriptions for " +
                         std::to_string(hit.channelCount()) + " channels of samples",
                     where);
  }
  // Encode before the transaction so the write lock is held only for the
  // insert and the fsync.
  const std::size_t count = static_cast<std::size_t>(hit.samples.size());
  MOZZI_TRY_ASSIGN(auto blob, encodeSamples(hit.samples.data(), count, hitEncoding_));
  const std::uint32_t crc =
      sampleCrc32(reinterpret_cast<const std::uint8_t*>(hit.samples.data()), count * sizeof(float));

  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO hit(campaign_id, sequence, point_node, point_direction, recorded_utc,"
                      " sample_rate_hz, channel_count, sample_count, encoding, samples, samples_crc32, accepted,"
                      " quality_flags, quality_reasons)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)");
  stmt.bind(1, hit.campaignId).bind(2, hit.sequence).bind(3, hit.point.node).bind(4, hit.point.uffCode());
  stmt.bind(5, hit.recordedUtc.empty() ? sql::nowUtc() : hit.recordedUtc).bind(6, hit.sampleRateHz);
  stmt.bind(7, static_cast<std::int64_t>(hit.channelCount())).bind(8, static_cast<std::int64_t>(hit.sampleCount()));
  stmt.bind(9, static_cast<int>(hitEncoding_)).bindBlob(10, blob.data(), blob.size());
  stmt.bind(11, static_cast<std::int64_t>(crc)).bind(12, hit.accepted ? 1 : 0);
  stmt.bind(13, static_cast<std::int64_t>(hit.qualityFlags)).bind(14, hit.qualityReasons);
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the hit", where));
  if (!hit.channels.empty()) {
    sql::Statement ch(db_,
                      "INSERT INTO hit_channel(hit_id, channel, quantity, unit, dof_node, dof_direction)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    for (std::size_t c = 0; c < hit.channels.size(); ++c) {
      ch.reset();
      ch.bind(1, id).bind(2, static_cast<std::int64_t>(c)).bind(3, hit.channels[c].quantity);
      ch.bind(4, hit.channels[c].unit).bindDof(5, hit.channels[c].dof);
      MOZZI_TRY(ch.run("cannot store channel " + std::to_string(c), where));
    }
  }
  MOZZI_TRY(tx.commit());
  return id;
}

Result<StoredHit> ProjectStore::hit(std::int64_t hitId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = hitWhere(path_, hitId);
  StoredHit h;
  {
    sql::Statement stmt(db_,
                        "SELECT id, campaign_id, sequence, point_node, point_direction, recorded_utc, sample_rate_hz,"
                        " channel_count, sample_count, encoding, samples, samples_crc32, accepted, quality_flags,"
                        " quality_reasons FROM hit WHERE id = ?1");
    if (!stmt.ok()) return sqliteError(db_, "cannot read the hit", where);
    stmt.bind(1, hitId);
    MOZZI_TRY(stmt.single("cannot read the hit", "no such hit", where));
    h.id = sqlite3_column_int64(stmt.get(), 0);
    h.campaignId = sqlite3_column_int64(stmt.get(), 1);
    h.sequence = sqlite3_column_int(stmt.get(), 2);
    MOZZI_TRY_ASSIGN(auto point, sql::columnDof(stmt.get(), 3, 4, where));
    h.point = point;
    h.recordedUtc = sql::columnText(stmt.get(), 5);
    h.sampleRateHz = sqlite3_column_double(stmt.get(), 6);
    if (!(h.sampleRateHz > 0.0) || !finite(h.sampleRateHz)) {
      return makeError(ErrorCode::Corrupt, "stored sample rate is not a positive number", where);
    }
    MOZZI_TRY_ASSIGN(auto samples, columnSamples(stmt.get(), 7, where));
    h.samples = std::move(samples);
    h.accepted = sqlite3_column_int(stmt.get(), 12) != 0;
    h.qualityFlags = static_cast<std::uint32_t>(sqlite3_column_int64(stmt.get(), 13));
    h.qualityReasons = sql::columnText(stmt.get(), 14);
  }
  sql::Statement ch(db_,
                    "SELECT channel, quantity, unit, dof_node, dof_direction FROM hit_channel WHERE hit_id = ?1"
                    " ORDER BY channel");
  ch.bind(1, hitId);
  int rc;
  while ((rc = ch.step()) == SQLITE_ROW) {
    const std::int64_t index = sqlite3_column_int64(ch.get(), 0);
    if (index != static_cast<std::int64_t>(h.channels.size()) || index >= h.channelCount()) {
      return makeError(ErrorCode::Corrupt, "channel descriptions do not number 0..n-1", where);
    }
    StoredHitChannel c;
    c.quantity = sql::columnText(ch.get(), 1);
    c.unit = sql::columnText(ch.get(), 2);
    c.dof = sql::columnOptionalDof(ch.get(), 3, 4);
    h.channels.push_back(std::move(c));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read channel descriptions", where);
  return h;
}

Result<std::vector<HitInfo>> ProjectStore::hits(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", campaign " + std::to_string(campaignId);
  sql::Statement stmt(db_,
                      "SELECT id, sequence, point_node, point_direction, recorded_utc, sample_rate_hz, channel_count,"
                      " sample_count, accepted, quality_flags, quality_reasons, length(samples) FROM hit"
                      " WHERE campaign_id = ?1 ORDER BY sequence");
  stmt.bind(1, campaignId);
  std::vector<HitInfo> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    HitInfo h;
    h.id = sqlite3_column_int64(stmt.get(), 0);
    h.sequence = sqlite3_column_int(stmt.get(), 1);
    MOZZI_TRY_ASSIGN(auto point, sql::columnDof(stmt.get(), 2, 3, hitWhere(path_, h.id)));
    h.point = point;
    h.recordedUtc = sql::columnText(stmt.get(), 4);
    h.sampleRateHz = sqlite3_column_double(stmt.get(), 5);
    h.channelCount = sqlite3_column_int(stmt.get(), 6);
    h.sampleCount = sqlite3_column_int64(stmt.get(), 7);
    h.accepted = sqlite3_column_int(stmt.get(), 8) != 0;
    h.qualityFlags = static_cast<std::uint32_t>(sqlite3_column_int64(stmt.get(), 9));
    h.qualityReasons = sql::columnText(stmt.get(), 10);
    h.storedBytes = sqlite3_column_int64(stmt.get(), 11);
    out.push_back(std::move(h));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot list hits", where);
  return out;
}

Result<void> ProjectStore::setHitAcceptance(std::int64_t hitId, bool accepted, std::uint32_t qualityFlags,
                                            const std::string& reasons) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = hitWhere(path_, hitId);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_, "UPDATE hit SET accepted = ?2, quality_flags = ?3, quality_reasons = ?4 WHERE id = ?1");
  stmt.bind(1, hitId).bind(2, accepted ? 1 : 0).bind(3, static_cast<std::int64_t>(qualityFlags)).bind(4, reasons);
  MOZZI_TRY(stmt.run("cannot update the hit", where));
  if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such hit", where);
  return tx.commit();
}

}  // namespace mozzi::core::io
