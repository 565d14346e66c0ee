#include "devices/campaign/demo_campaigns.h"

#include <chrono>
#include <mutex>
#include <optional>

#include "devices/campaign/campaign_engine.h"
#include "devices/campaign/virtual_campaign.h"

namespace mozzi::devices::campaign {

const std::vector<DemoCampaign>& demoCampaigns() {
  static const std::vector<DemoCampaign> kCampaigns = {
      {"fork-a-with-wheel", "Fork A (enduro) with wheel", 41, 2, 2048.0},
      {"frame-a-front-constrained", "Frame A", 26, 2, 2048.0},
  };
  return kCampaigns;
}

namespace {

// Collects the first error the engine reports.
class ErrorCatcher final : public CampaignObserver {
 public:
  void onError(const core::Error& e) override {
    std::lock_guard<std::mutex> l(mu_);
    if (!first_) first_ = e;
  }
  std::optional<core::Error> first() const {
    std::lock_guard<std::mutex> l(mu_);
    return first_;
  }

 private:
  mutable std::mutex mu_;
  std::optional<core::Error> first_;
};

}  // namespace

core::Result<void> addDemoCampaigns(core::io::ProjectStore& store) {
  auto summary = store.summary();
  if (!summary) return summary.error();
  // Reproducible content: no fsync per hit while it is written (a crash
  // leaves an incomplete demo, made again), then durable as every project.
  if (auto r = store.setDurable(false); !r) return r;
  struct Durable {
    core::io::ProjectStore& s;
    ~Durable() { (void)s.setDurable(true); }
  } durable{store};
  for (const auto& demo : demoCampaigns()) {
    const std::string where = "demo campaign on " + demo.specimenKey;
    std::optional<std::int64_t> specimen;
    for (const auto& s : summary->specimens)
      if (s.name == demo.specimenName) specimen = s.id;
    if (!specimen)
      return core::makeError(core::ErrorCode::NotFound, "the demo project has no specimen '" + demo.specimenName + "'",
                             where);
    VirtualCampaignOptions o;
    o.hitsPerPoint = demo.hitsPerPoint;
    o.seed = demo.seed;
    o.sampleRateHz = demo.sampleRateHz;
    auto def = virtualSpecimenCampaign(demo.specimenKey, o);
    if (!def) return def.error();
    auto id = createCampaign(store, *specimen, demo.specimenKey + " hammer 1", *def,
                             "demo: simulated hammer station, seed " + std::to_string(demo.seed));
    if (!id) return id.error();
    EngineOptions eo;
    eo.autoDecide = true;
    eo.autoArm = true;
    eo.deviceOverrides["sim.realtime"] = false;
    eo.checkpointBetweenHits = false;
    auto engine = CampaignEngine::open(store, *id, makeDriverStation(builtinDrivers(), def->driver), eo);
    if (!engine) return engine.error();
    ErrorCatcher errors;
    (*engine)->addObserver(&errors);
    (*engine)->start();
    // A simulated station at full speed: minutes would mean something is wrong.
    const bool finished = (*engine)->waitUntilFinished(std::chrono::minutes(10));
    (*engine)->stop();
    if (!finished) {
      auto e = errors.first();
      return core::makeError(e ? e->code : core::ErrorCode::Cancelled,
                             e ? e->message : std::string("did not finish within 10 minutes"), where);
    }
  }
  return {};
}

}  // namespace mozzi::devices::campaign
