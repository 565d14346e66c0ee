#pragma once
// A campaign in the project (core/io ProjectStore): created with its
// definition (campaign.settings_json) and schedule (campaign_point), loaded
// back for a resume or a status, and turned into its FRF set. The FRF set is
// always computed from the stored hits (float32, in sequence order), so a
// campaign interrupted and resumed any number of times gives the same FRFs,
// bit for bit, as one run straight through with the same hits.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/io/project_store.h"
#include "devices/campaign/campaign_definition.h"
#include "devices/campaign/hit_pipeline.h"
#include "devices/campaign/roving_schedule.h"

namespace mozzi::devices::campaign {

// Adds the campaign with its definition and schedule (one point per
// definition.points entry, in order) and returns its id.
core::Result<std::int64_t> createCampaign(core::io::ProjectStore& store, std::int64_t specimenId,
                                          const std::string& name, const CampaignDefinition& definition,
                                          const std::string& notes = {});

struct LoadedCampaign {
  core::io::StoredCampaign campaign;
  CampaignDefinition definition;
  RovingSchedule schedule;               // hits replayed onto it
  std::vector<core::io::HitInfo> hits;   // in sequence order
  std::optional<std::int64_t> frfSetId;  // the latest FRF set tied to the campaign
  bool frfSetCurrent = false;            // it holds exactly the accepted hits of the done points
  int nextSequence = 1;

  // Finished: no point left to measure and its FRF set stored (a redo after
  // the end makes it unfinished until the new FRF set is stored).
  bool finished() const { return schedule.progress().complete() && frfSetCurrent; }
  // Accepted hit ids of the done, not skipped points, ascending.
  std::vector<std::int64_t> acceptedHitIds() const;
};

// Errors: no such campaign; a campaign without a definition (made by an older
// Mozzi or imported) is Unsupported, naming the campaign.
core::Result<LoadedCampaign> loadCampaign(const core::io::ProjectStore& store, std::int64_t campaignId);

// The campaigns of a specimen that have a definition, oldest first.
core::Result<std::vector<LoadedCampaign>> loadCampaigns(const core::io::ProjectStore& store, std::int64_t specimenId);

// The accepted hits of one point as time records, in sequence order (with
// their ids), as the averaging reads them.
struct PointHits {
  std::vector<core::signal::TimeRecord> records;
  std::vector<std::int64_t> hitIds;
};
core::Result<PointHits> pointHits(const core::io::ProjectStore& store, const LoadedCampaign& campaign, int position);

// The running average of one point rebuilt from its accepted hits.
core::Result<void> rebuildPointAverage(const core::io::ProjectStore& store, const LoadedCampaign& campaign,
                                       int position, PointAverage& average);

// The campaign's FRFs over every done point (skipped ones left out), one hit
// read at a time. Roving hammer: references = the points, responses = the
// fixed accelerometers. Roving accelerometer: reference = the fixed hammer
// point, responses = the roving channels at every point, then the fixed
// response channels as measured at the first point.
struct CampaignFrf {
  core::FrfMatrix frf;
  std::vector<std::int64_t> hitIds;  // every accepted hit that went into it
};
core::Result<CampaignFrf> computeCampaignFrf(const core::io::ProjectStore& store, const LoadedCampaign& campaign);

// Computes and stores the FRF set tied to the campaign and its hits; returns its id.
core::Result<std::int64_t> storeCampaignFrf(core::io::ProjectStore& store, const LoadedCampaign& campaign);

// Hit seed of a simulated station: a function of the campaign seed, the point
// and the attempt number there only, so the same seed gives the same hits
// whatever interrupted the campaign in between.
std::uint64_t hitSeed(std::uint64_t campaignSeed, int position, int attempt);

}  // namespace mozzi::devices::campaign
