#include "devices/campaign/campaign_store.h"

#include <algorithm>
#include <set>

namespace mozzi::devices::campaign {

using core::ErrorCode;
using core::makeError;

core::Result<std::int64_t> createCampaign(core::io::ProjectStore& store, std::int64_t specimenId,
                                          const std::string& name, const CampaignDefinition& definition,
                                          const std::string& notes) {
  if (auto v = definition.validate(); !v) return v.error();
  core::io::StoredCampaign c;
  c.specimenId = specimenId;
  c.name = name;
  c.kind = excitationKindName(definition.excitation);
  c.notes = notes;
  c.settingsJson = definitionToJson(definition).dump();
  // Campaign and schedule in one transaction: a crash never leaves a campaign
  // without its points.
  std::vector<core::io::StoredCampaignPoint> points;
  for (std::size_t i = 0; i < definition.points.size(); ++i)
    points.push_back({static_cast<int>(i), definition.points[i], false, {}});
  return store.addCampaign(c, points);
}

namespace {

core::Result<LoadedCampaign> loadFrom(const core::io::ProjectStore& store, core::io::StoredCampaign stored) {
  const std::string where = store.path() + ", campaign " + std::to_string(stored.id) + " '" + stored.name + "'";
  if (stored.settingsJson.empty() || stored.settingsJson == "{}")
    return makeError(ErrorCode::Unsupported, "the campaign has no definition (made outside the campaign engine)",
                     where);
  auto def = parseDefinition(stored.settingsJson);
  if (!def) return makeError(def.error().code, def.error().message, where + ", " + def.error().where);
  LoadedCampaign l;
  l.campaign = std::move(stored);
  l.definition = std::move(*def);
  auto points = store.campaignPoints(l.campaign.id);
  if (!points) return points.error();
  if (points->size() != l.definition.points.size())
    return makeError(ErrorCode::Corrupt, "the stored schedule and the definition list different points", where);
  l.schedule = RovingSchedule(*points, l.definition.hitsPerPoint);
  auto hits = store.hits(l.campaign.id);
  if (!hits) return hits.error();
  l.hits = std::move(*hits);
  l.schedule.replay(l.hits);
  for (const auto& h : l.hits) l.nextSequence = std::max(l.nextSequence, h.sequence + 1);
  auto sets = store.frfSets();
  if (!sets) return sets.error();
  for (const auto& s : *sets)
    if (s.campaignId && *s.campaignId == l.campaign.id) l.frfSetId = s.id;
  if (l.frfSetId) {
    auto tied = store.frfSetHits(*l.frfSetId);
    if (!tied) return tied.error();
    l.frfSetCurrent = *tied == l.acceptedHitIds();
  }
  return l;
}

}  // namespace

std::vector<std::int64_t> LoadedCampaign::acceptedHitIds() const {
  std::vector<std::int64_t> ids;
  for (const auto& h : hits) {
    if (!h.accepted) continue;
    const auto pos = schedule.positionOf(h.point);
    if (!pos) continue;
    const auto& p = schedule.point(*pos);
    if (p.done && !p.skipped) ids.push_back(h.id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

core::Result<LoadedCampaign> loadCampaign(const core::io::ProjectStore& store, std::int64_t campaignId) {
  const std::lock_guard<std::recursive_mutex> lock(store.mutex());
  auto c = store.campaign(campaignId);
  if (!c) return c.error();
  return loadFrom(store, std::move(*c));
}

core::Result<std::vector<LoadedCampaign>> loadCampaigns(const core::io::ProjectStore& store, std::int64_t specimenId) {
  const std::lock_guard<std::recursive_mutex> lock(store.mutex());
  auto all = store.campaigns(specimenId);
  if (!all) return all.error();
  std::vector<LoadedCampaign> out;
  for (auto& c : *all) {
    if (c.settingsJson.empty() || c.settingsJson == "{}") continue;
    auto l = loadFrom(store, std::move(c));
    if (!l) return l.error();
    out.push_back(std::move(*l));
  }
  return out;
}

core::Result<PointHits> pointHits(const core::io::ProjectStore& store, const LoadedCampaign& campaign, int position) {
  PointHits out;
  const auto& p = campaign.schedule.point(position);
  for (const auto& info : campaign.hits) {
    if (!info.accepted || info.point != p.dof) continue;
    auto h = store.hit(info.id);
    if (!h) return h.error();
    if (h->channelCount() != static_cast<Eigen::Index>(campaign.definition.channels.size()))
      return makeError(ErrorCode::Corrupt,
                       "hit has " + std::to_string(h->channelCount()) + " channels, the campaign defines " +
                           std::to_string(campaign.definition.channels.size()),
                       store.path() + ", hit " + std::to_string(info.id));
    out.records.push_back(
        timeRecordFor(campaign.definition, p.dof, h->sampleRateHz, {}, samplesFromStored(h->samples)));
    out.hitIds.push_back(info.id);
  }
  return out;
}

core::Result<void> rebuildPointAverage(const core::io::ProjectStore& store, const LoadedCampaign& campaign,
                                       int position, PointAverage& average) {
  average.reset();
  const auto& p = campaign.schedule.point(position);
  for (const auto& info : campaign.hits) {
    if (!info.accepted || info.point != p.dof) continue;
    auto h = store.hit(info.id);
    if (!h) return h.error();
    auto r = timeRecordFor(campaign.definition, p.dof, h->sampleRateHz, {}, samplesFromStored(h->samples));
    if (auto a = average.add(r); !a)
      return makeError(a.error().code, a.error().message, store.path() + ", hit " + std::to_string(info.id));
  }
  return {};
}

core::Result<CampaignFrf> computeCampaignFrf(const core::io::ProjectStore& store, const LoadedCampaign& campaign) {
  const auto& def = campaign.definition;
  const std::string where = store.path() + ", campaign " + std::to_string(campaign.campaign.id);
  CampaignFrf out;
  bool first = true;
  PointAverage average(def);
  for (const auto& p : campaign.schedule.points()) {
    if (p.skipped || !p.done) continue;
    // One hit in memory at a time: read, add, drop.
    average.reset();
    for (const auto& info : campaign.hits) {
      if (!info.accepted || info.point != p.dof) continue;
      auto h = store.hit(info.id);
      if (!h) return h.error();
      auto r = timeRecordFor(def, p.dof, h->sampleRateHz, {}, samplesFromStored(h->samples));
      if (auto a = average.add(r); !a)
        return makeError(a.error().code, a.error().message, store.path() + ", hit " + std::to_string(info.id));
      out.hitIds.push_back(info.id);
    }
    auto f = average.frf();
    if (!f) return makeError(f.error().code, f.error().message, where + ", point " + core::formatDof(p.dof));
    if (first) {
      out.frf.frequencyHz = f->frequencyHz;
      out.frf.type = f->type;
    } else if (f->lineCount() != out.frf.lineCount() || f->type != out.frf.type) {
      return makeError(ErrorCode::InvalidArgument, "the point's FRF lines differ from the first point's",
                       where + ", point " + core::formatDof(p.dof));
    }
    if (def.excitation == ExcitationKind::RovingHammer) {
      if (first) out.frf.responses = f->responses;
      out.frf.references.push_back(f->references.at(0));
      out.frf.h.push_back(f->h.at(0));
      out.frf.coherence.push_back(f->coherence.at(0));
    } else {
      if (first) {
        out.frf.references = f->references;
        out.frf.h.assign(1, core::ComplexMatrix(f->lineCount(), 0));
        out.frf.coherence.assign(1, core::Matrix(f->lineCount(), 0));
      }
      // Columns to take: the roving channels always, fixed ones at the first point.
      std::set<core::Dof> have(out.frf.responses.begin(), out.frf.responses.end());
      std::vector<Eigen::Index> cols;
      for (Eigen::Index o = 0; o < f->responseCount(); ++o)
        if (!have.count(f->responses[static_cast<std::size_t>(o)])) cols.push_back(o);
      auto& h = out.frf.h[0];
      auto& c = out.frf.coherence[0];
      const Eigen::Index base = h.cols();
      h.conservativeResize(Eigen::NoChange, base + static_cast<Eigen::Index>(cols.size()));
      c.conservativeResize(Eigen::NoChange, base + static_cast<Eigen::Index>(cols.size()));
      for (std::size_t k = 0; k < cols.size(); ++k) {
        h.col(base + static_cast<Eigen::Index>(k)) = f->h[0].col(cols[k]);
        c.col(base + static_cast<Eigen::Index>(k)) = f->coherence[0].col(cols[k]);
        out.frf.responses.push_back(f->responses[static_cast<std::size_t>(cols[k])]);
      }
    }
    first = false;
  }
  if (first) return makeError(ErrorCode::InvalidArgument, "no point of the campaign is done", where);
  return out;
}

core::Result<std::int64_t> storeCampaignFrf(core::io::ProjectStore& store, const LoadedCampaign& campaign) {
  auto f = computeCampaignFrf(store, campaign);
  if (!f) return f.error();
  const std::lock_guard<std::recursive_mutex> lock(store.mutex());
  auto sets = store.frfSets();
  if (!sets) return sets.error();
  std::set<std::string> names;
  for (const auto& s : *sets)
    if (s.specimenId == campaign.campaign.specimenId) names.insert(s.name);
  core::io::FrfSetInfo info;
  info.specimenId = campaign.campaign.specimenId;
  info.campaignId = campaign.campaign.id;
  info.name = campaign.campaign.name + " FRFs";
  for (int n = 2; names.count(info.name); ++n) info.name = campaign.campaign.name + " FRFs " + std::to_string(n);
  const auto& def = campaign.definition;
  info.source = "measured: campaign '" + campaign.campaign.name + "', " + excitationKindName(def.excitation) + ", " +
                std::to_string(def.hitsPerPoint) + " hits per point";
  if (def.windows.exponentialTauS > 0.0)
    info.source += ", exponential window tau " + std::to_string(def.windows.exponentialTauS) + " s";
  info.estimator = core::signal::frfEstimatorName(def.estimator);
  return store.addFrfSet(info, f->frf, f->hitIds);
}

std::uint64_t hitSeed(std::uint64_t campaignSeed, int position, int attempt) {
  // splitmix64 of the three, folded into the 32 bits sim.seed takes.
  std::uint64_t z = campaignSeed * 0x9E3779B97F4A7C15ull +
                    static_cast<std::uint64_t>(position) * 0xBF58476D1CE4E5B9ull +
                    static_cast<std::uint64_t>(attempt) * 0x94D049BB133111EBull + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return z & 0xFFFFFFFFull;
}

}  // namespace mozzi::devices::campaign
