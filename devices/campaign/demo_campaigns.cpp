#include "devices/campaign/demo_campaigns.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>

#include "core/modal/identification.h"
#include "core/modal/pole_selection.h"
#include "devices/campaign/campaign_engine.h"
#include "devices/campaign/frf_set_window.h"
#include "devices/campaign/virtual_campaign.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::campaign {

const std::vector<DemoCampaign>& demoCampaigns() {
  static const std::vector<DemoCampaign> kCampaigns = {
      {"fork-a-with-wheel", "Fork A (enduro) with wheel", 41, 2, 2048.0, 4.0},
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
  if (auto r = store.setPowerLossDurable(false); !r) return r;
  struct Durable {
    core::io::ProjectStore& s;
    ~Durable() { (void)s.setPowerLossDurable(true); }
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
    o.recordSeconds = demo.recordSeconds;
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
    // A simulated station at full speed: minutes would mean something is
    // wrong, and an engine back at Idle with an error (auto-arm stopped after
    // too many rejections in a row) will not go on by itself.
    bool finished = false;
    int idlePolls = 0;
    for (int second = 0; second < 600 && !finished; ++second) {
      finished = (*engine)->waitUntilFinished(std::chrono::seconds(1));
      idlePolls = !finished && (*engine)->state() == EngineState::Idle && errors.first() ? idlePolls + 1 : 0;
      if (idlePolls >= 2) break;
    }
    (*engine)->stop();
    if (!finished) {
      auto e = errors.first();
      return core::makeError(e ? e->code : core::ErrorCode::Cancelled,
                             e ? e->message : std::string("did not finish within 10 minutes"), where);
    }
  }
  return {};
}

core::Result<void> identifyDemoCampaigns(core::io::ProjectStore& store) {
  namespace md = core::modal;
  auto summary = store.summary();
  if (!summary) return summary.error();
  auto sets = store.frfSets();
  if (!sets) return sets.error();
  for (const DemoCampaign& demo : demoCampaigns()) {
    const std::string where = "demo identification on " + demo.specimenKey;
    std::optional<std::int64_t> specimen;
    for (const auto& s : summary->specimens)
      if (s.name == demo.specimenName) specimen = s.id;
    const sim::SpecimenEntry* entry = nullptr;
    for (const auto& e : sim::specimenCatalogue())
      if (e.key == demo.specimenKey) entry = &e;
    if (!specimen || !entry || entry->modes.empty()) {
      return core::makeError(core::ErrorCode::NotFound, "no specimen with catalogued modes", where);
    }
    double lo = 1e300, hi = 0.0;
    for (const auto& m : entry->modes) lo = std::min(lo, m.frequencyHz), hi = std::max(hi, m.frequencyHz);
    lo *= 0.8;
    hi *= 1.15;
    for (const auto& set : *sets) {
      if (set.specimenId != *specimen || !set.campaignId) continue;
      auto frf = store.frfSet(set.id);
      if (!frf) return frf.error();
      auto tauS = frfSetExponentialTauS(store, set.id);
      if (!tauS) return tauS.error();
      // As `mozzi-cli identify` by default: pLSCF to order 60, capped at what
      // the band's lines support.
      md::IdentificationOptions opt;
      opt.estimator.bandLowHz = lo;
      opt.estimator.bandHighHz = hi;
      opt.estimator.maxOrder = std::min(60, std::max(8, md::plscfOrderLimit(*frf, lo, hi)));
      auto identified = md::identifyModes(*frf, opt);
      if (!identified) return identified.error();
      core::io::ModalResultInfo info;
      info.specimenId = set.specimenId;
      info.frfSetId = set.id;
      info.bandLowHz = lo;
      info.bandHighHz = hi;
      const std::vector<double> none;
      const auto& refined = identified->refined;
      auto stored = md::storeModalResult(store, identified->model(), info, "plscf", *tauS,
                                         refined ? refined->frequencyStdHz : none, refined ? refined->zetaStd : none);
      if (!stored) return stored.error();
    }
  }
  return {};
}

}  // namespace mozzi::devices::campaign
