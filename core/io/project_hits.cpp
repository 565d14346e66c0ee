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

// --- campaigns and hits --------------------------------------------------------------

Result<std::int64_t> ProjectStore::addCampaign(const StoredCampaign& campaign,
                                               const std::vector<StoredCampaignPoint>& points) {
  const std::string where = path_ + ", campaign '" + campaign.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (campaign.name.empty()) return makeError(ErrorCode::InvalidArgument, "a campaign needs a name", where);
    sql::Statement stmt(db_,
                        "INSERT INTO campaign(specimen_id, rig_setup_id, name, kind, started_utc, notes, settings_json)"
                        " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
    stmt.bindAll(campaign.specimenId, campaign.rigSetupId, campaign.name, campaign.kind,
                 campaign.startedUtc.empty() ? sql::nowUtc() : campaign.startedUtc, campaign.notes,
                 campaign.settingsJson.empty() ? std::string("{}") : campaign.settingsJson);
    MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the campaign", where));
    MOZZI_TRY(sql::insertCampaignPoints(db_, id, points, where));
    return id;
  });
}

Result<std::vector<StoredCampaign>> ProjectStore::campaigns(std::int64_t specimenId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(
      db_, std::string("SELECT ") + sql::kCampaignColumns + " FROM campaign WHERE specimen_id = ?1 ORDER BY id");
  std::vector<StoredCampaign> out;
  MOZZI_TRY(stmt.bindAll(specimenId).forEachRow("cannot read campaigns", path_, [&](const sql::Row& r) {
    out.push_back(sql::campaignFromRow(r.get()));
  }));
  return out;
}

Result<std::int64_t> ProjectStore::commitHit(const StoredHit& hit) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  // Refused before the hit is checked: a read-only project says so first.
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

  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    sql::Statement stmt(db_,
                        "INSERT INTO hit(campaign_id, sequence, point_node, point_direction, recorded_utc,"
                        " sample_rate_hz, channel_count, sample_count, encoding, samples, samples_crc32, accepted,"
                        " quality_flags, quality_reasons)"
                        " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)");
    stmt.bindAll(hit.campaignId, hit.sequence, hit.point, hit.recordedUtc.empty() ? sql::nowUtc() : hit.recordedUtc,
                 hit.sampleRateHz, hit.channelCount(), hit.sampleCount(), hitEncoding_,
                 sql::Blob{blob.data(), blob.size()}, crc, hit.accepted, hit.qualityFlags, hit.qualityReasons);
    MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the hit", where));
    if (!hit.channels.empty()) {
      sql::Statement ch(db_,
                        "INSERT INTO hit_channel(hit_id, channel, quantity, unit, dof_node, dof_direction)"
                        " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
      for (std::size_t c = 0; c < hit.channels.size(); ++c) {
        MOZZI_TRY(ch.runWith("cannot store channel " + std::to_string(c), where, id, c, hit.channels[c].quantity,
                             hit.channels[c].unit, hit.channels[c].dof));
      }
    }
    return id;
  });
}

Result<StoredHit> ProjectStore::hit(std::int64_t hitId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = hitWhere(path_, hitId);
  sql::Statement head(db_,
                      "SELECT id, campaign_id, sequence, point_node, point_direction, recorded_utc, sample_rate_hz,"
                      " channel_count, sample_count, encoding, samples, samples_crc32, accepted, quality_flags,"
                      " quality_reasons FROM hit WHERE id = ?1");
  MOZZI_TRY(head.lookup(hitId, "hit", where));
  const sql::Row r(head.get());
  StoredHit h;
  h.id = r.int64(0);
  h.campaignId = r.int64(1);
  h.sequence = r.int32(2);
  MOZZI_TRY_ASSIGN(h.point, r.dof(3, 4, where));
  h.recordedUtc = r.text(5);
  h.sampleRateHz = r.real(6);
  if (!(h.sampleRateHz > 0.0) || !finite(h.sampleRateHz)) {
    return makeError(ErrorCode::Corrupt, "stored sample rate is not a positive number", where);
  }
  MOZZI_TRY_ASSIGN(h.samples, columnSamples(head.get(), 7, where));
  h.accepted = r.int32(12) != 0;
  h.qualityFlags = static_cast<std::uint32_t>(r.int64(13));
  h.qualityReasons = r.text(14);
  sql::Statement ch(db_,
                    "SELECT channel, quantity, unit, dof_node, dof_direction FROM hit_channel WHERE hit_id = ?1"
                    " ORDER BY channel");
  auto readChannel = [&](const sql::Row& c) -> Result<void> {
    const std::int64_t index = c.int64(0);
    if (index != static_cast<std::int64_t>(h.channels.size()) || index >= h.channelCount()) {
      return makeError(ErrorCode::Corrupt, "channel descriptions do not number 0..n-1", where);
    }
    h.channels.push_back({c.optionalDof(3, 4), c.text(1), c.text(2)});
    return {};
  };
  MOZZI_TRY(ch.bindAll(hitId).forEachRow("cannot read channel descriptions", where, readChannel));
  return h;
}

Result<std::vector<HitInfo>> ProjectStore::hits(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", campaign " + std::to_string(campaignId);
  sql::Statement stmt(db_,
                      "SELECT id, sequence, point_node, point_direction, recorded_utc, sample_rate_hz, channel_count,"
                      " sample_count, accepted, quality_flags, quality_reasons, length(samples) FROM hit"
                      " WHERE campaign_id = ?1 ORDER BY sequence");
  std::vector<HitInfo> out;
  MOZZI_TRY(stmt.bindAll(campaignId).forEachRow("cannot list hits", where, [&](const sql::Row& r) -> Result<void> {
    MOZZI_TRY_ASSIGN(const Dof point, r.dof(2, 3, hitWhere(path_, r.int64(0))));
    out.push_back({r.int64(0), r.int32(1), point, r.text(4), r.real(5), r.int32(6), r.int64(7), r.int32(8) != 0,
                   static_cast<std::uint32_t>(r.int64(9)), r.text(10), r.int64(11)});
    return {};
  }));
  return out;
}

Result<void> ProjectStore::setHitAcceptance(std::int64_t hitId, bool accepted, std::uint32_t qualityFlags,
                                            const std::string& reasons) {
  const std::string where = hitWhere(path_, hitId);
  return writeInTransaction(where, [&]() -> Result<void> {
    sql::Statement stmt(db_, "UPDATE hit SET accepted = ?2, quality_flags = ?3, quality_reasons = ?4 WHERE id = ?1");
    MOZZI_TRY(stmt.bindAll(hitId, accepted, qualityFlags, reasons).run("cannot update the hit", where));
    if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such hit", where);
    return {};
  });
}

}  // namespace mozzi::core::io
