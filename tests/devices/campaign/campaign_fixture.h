#pragma once
// What the campaign engine tests share: a fresh project in the build folder,
// a small campaign on a virtual specimen of the simulated hammer station, and
// an observer that records every callback (with the engine thread's view of
// the project at the moment the station is armed).

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "core/io/project_store.h"
#include "devices/campaign/campaign_engine.h"
#include "devices/campaign/virtual_campaign.h"

namespace mozzi::devices::campaign::testing {

inline std::string freshProject(const std::string& tag) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(MOZZI_BINARY_DIR) / "campaign_tests";
  fs::create_directories(dir);
  const fs::path p = dir / (tag + "_" + std::to_string(::getpid()) + ".mozzi");
  for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(p.string() + suffix);
  return p.string();
}

// fork-a-without-wheel (thesis Table 11, left), three points, `hits` per
// point, no simulated faults unless asked.
inline CampaignDefinition smallDefinition(int hits = 2, std::uint64_t seed = 7, double doubleHits = 0.0,
                                          double overloads = 0.0) {
  VirtualCampaignOptions o;
  o.hitsPerPoint = hits;
  o.seed = seed;
  o.doubleHitProbability = doubleHits;
  o.overloadProbability = overloads;
  auto d = virtualSpecimenCampaign("fork-a-without-wheel", o);
  EXPECT_TRUE(d.ok()) << d.error().describe();
  // Three points: the accelerometers' own DOFs (driving points, where every
  // mode shows; the mesh template's first points sit at the clamp). The
  // whole mesh would make each case a long campaign.
  std::vector<core::Dof> points;
  for (std::size_t c = 1; c < d->channels.size() && points.size() < 3; ++c) points.push_back(d->channels[c].dof);
  d->points = points;
  EXPECT_TRUE(d->validate().ok());
  return *d;
}

struct ProjectWithCampaign {
  core::io::ProjectStore store;
  std::int64_t specimenId = 0;
  std::int64_t campaignId = 0;
};

inline ProjectWithCampaign makeProject(const std::string& tag, const CampaignDefinition& def) {
  auto store = core::io::ProjectStore::create(freshProject(tag), "test");
  EXPECT_TRUE(store.ok()) << store.error().describe();
  auto sp = store->addSpecimen("Fork A (enduro) without wheel", "fork", "virtual");
  EXPECT_TRUE(sp.ok());
  auto id = createCampaign(*store, *sp, "test campaign", def);
  EXPECT_TRUE(id.ok()) << id.error().describe();
  return {std::move(*store), *sp, *id};
}

inline EngineOptions fastOptions(bool autoDecide = true, bool autoArm = true) {
  EngineOptions o;
  o.autoDecide = autoDecide;
  o.autoArm = autoArm;
  o.deviceOverrides["sim.realtime"] = false;
  o.reconnectInterval = std::chrono::milliseconds(20);
  return o;
}

class Recorder : public CampaignObserver {
 public:
  explicit Recorder(const core::io::ProjectStore* store = nullptr, std::int64_t campaignId = 0)
      : store_(store), campaignId_(campaignId) {}
  void onState(EngineState s, const std::string& message) override {
    std::lock_guard<std::mutex> l(mu);
    states.push_back(s);
    messages.push_back(message);
    if (s == EngineState::Armed && store_) {
      // Hits in the project at each arm (read on the engine thread, as the
      // arm happens): must equal every verdict so far.
      auto hits = store_->hits(campaignId_);
      hitsAtArm.push_back(hits ? static_cast<int>(hits->size()) : -1);
      verdictsAtArm.push_back(static_cast<int>(verdicts.size()));
    }
  }
  void onLiveBlock(const LiveBlock&) override { ++liveBlocks; }
  void onVerdict(const HitVerdictEvent& v) override {
    std::lock_guard<std::mutex> l(mu);
    verdicts.push_back(v);
  }
  void onHitCommitted(const CommittedHitEvent& h) override {
    std::lock_guard<std::mutex> l(mu);
    committed.push_back(h);
    ++commits;
  }
  void onRunningFrf(const RunningFrfEvent& f) override {
    std::lock_guard<std::mutex> l(mu);
    frfs.push_back(f);
  }
  void onProgress(const EngineProgress& p) override {
    std::lock_guard<std::mutex> l(mu);
    progress.push_back(p);
  }
  void onError(const core::Error& e) override {
    std::lock_guard<std::mutex> l(mu);
    errors.push_back(e);
  }
  void onFinished(const FinishedEvent& f) override {
    std::lock_guard<std::mutex> l(mu);
    finished.push_back(f);
  }

  std::mutex mu;
  std::vector<EngineState> states;
  std::vector<std::string> messages;
  std::vector<int> hitsAtArm, verdictsAtArm;
  std::atomic<int> liveBlocks{0}, commits{0};
  std::vector<HitVerdictEvent> verdicts;
  std::vector<CommittedHitEvent> committed;
  std::vector<RunningFrfEvent> frfs;
  std::vector<EngineProgress> progress;
  std::vector<core::Error> errors;
  std::vector<FinishedEvent> finished;

 private:
  const core::io::ProjectStore* store_;
  std::int64_t campaignId_;
};

}  // namespace mozzi::devices::campaign::testing
