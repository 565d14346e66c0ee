// The campaign engine on the simulated hammer station (sim-hammer, faster
// than real time): a whole campaign with automatic decisions, planted double
// hits and overloads rejected by the rules with their reasons, every hit
// committed before the next arm, manual decisions, skip and redo, resume
// after a stop, and an unplug in the middle of a hit. The numbers checked are
// the project's: hits, their flags and reasons, and the FRF set computed
// independently from the stored hits.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "campaign_fixture.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::campaign {
namespace {

using namespace std::chrono_literals;
using testing::fastOptions;
using testing::makeProject;
using testing::Recorder;
using testing::smallDefinition;

std::unique_ptr<Station> simStation() {
  return makeDriverStation(builtinDrivers(), "sim-hammer");
}

// Bitwise equality of two FRF matrices (lines, DOFs, values, coherence).
void expectSameFrf(const core::FrfMatrix& a, const core::FrfMatrix& b) {
  ASSERT_EQ(a.lineCount(), b.lineCount());
  ASSERT_EQ(a.references, b.references);
  ASSERT_EQ(a.responses, b.responses);
  EXPECT_TRUE((a.frequencyHz.array() == b.frequencyHz.array()).all());
  ASSERT_EQ(a.h.size(), b.h.size());
  for (std::size_t i = 0; i < a.h.size(); ++i) {
    EXPECT_TRUE((a.h[i].array() == b.h[i].array()).all()) << "reference " << i;
    EXPECT_TRUE((a.coherence[i].array() == b.coherence[i].array()).all()) << "reference " << i;
  }
}

TEST(CampaignEngine, RunsAWholeCampaignAndStoresTheFrfSetTiedToItsHits) {
  auto def = smallDefinition(3, 11);
  auto p = makeProject("whole", def);
  auto engine = CampaignEngine::open(p.store, p.campaignId, simStation(), fastOptions());
  ASSERT_TRUE(engine.ok()) << engine.error().describe();
  Recorder rec(&p.store, p.campaignId);
  (*engine)->addObserver(&rec);
  (*engine)->start();
  ASSERT_TRUE((*engine)->waitUntilFinished(120s));
  const auto progress = (*engine)->progress();
  (*engine)->stop();
  ASSERT_TRUE(rec.errors.empty()) << rec.errors.front().describe();
  ASSERT_EQ(rec.finished.size(), 1u);
  ASSERT_TRUE(progress.frfSetId.has_value());
  EXPECT_EQ(progress.schedule.pointsDone, 3);
  EXPECT_EQ(progress.schedule.acceptedHits, 9);

  auto hits = p.store.hits(p.campaignId).value();
  ASSERT_EQ(hits.size(), 9u);  // no fault planted: every hit clean
  for (std::size_t k = 0; k < hits.size(); ++k) {
    EXPECT_TRUE(hits[k].accepted);
    EXPECT_EQ(hits[k].sequence, static_cast<int>(k) + 1);
    EXPECT_EQ(hits[k].point, def.points[k / 3]);  // three hits per point, in roving order
    EXPECT_EQ(hits[k].sampleCount, def.recordScans());
  }
  // The FRF set: roving hammer, references = the points, responses = the
  // fixed accelerometers; tied to exactly the accepted hits; equal to the
  // FRFs computed again from the stored hits.
  auto set = p.store.frfSet(*progress.frfSetId).value();
  EXPECT_EQ(set.references, def.points);
  EXPECT_EQ(set.responseCount(), 3);
  EXPECT_EQ(set.type, core::FrfType::Accelerance);
  EXPECT_NEAR(set.frequencyHz[set.lineCount() - 1], def.storedBandHz(), 0.5);  // lines up to fs / 2.56
  auto tied = p.store.frfSetHits(*progress.frfSetId).value();
  EXPECT_EQ(tied.size(), 9u);
  auto loaded = loadCampaign(p.store, p.campaignId).value();
  EXPECT_TRUE(loaded.finished());
  auto again = computeCampaignFrf(p.store, loaded).value();
  expectSameFrf(set, again.frf);
  // Live traces: every device block (~50 ms) of every armed session.
  EXPECT_GT(rec.liveBlocks.load(), 9 * 40);
  // A running FRF after each accepted hit, with as many hits as accepted so far at the point.
  ASSERT_EQ(rec.frfs.size(), 9u);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_EQ(rec.frfs[k].hits, static_cast<int>(k % 3) + 1);
}

TEST(CampaignEngine, EveryHitIsCommittedBeforeTheNextArm) {
  // Double hits and overloads planted often: rejected hits are committed too.
  auto def = smallDefinition(2, 3, 0.3, 0.2);  // seed 3: rejections among the first hits
  auto p = makeProject("commit_before_arm", def);
  auto engine = CampaignEngine::open(p.store, p.campaignId, simStation(), fastOptions());
  ASSERT_TRUE(engine.ok());
  Recorder rec(&p.store, p.campaignId);
  (*engine)->addObserver(&rec);
  (*engine)->start();
  ASSERT_TRUE((*engine)->waitUntilFinished(120s));
  (*engine)->stop();
  ASSERT_GT(rec.hitsAtArm.size(), 6u);
  for (std::size_t k = 0; k < rec.hitsAtArm.size(); ++k)
    EXPECT_EQ(rec.hitsAtArm[k], rec.verdictsAtArm[k]) << "arm " << k << ": a decided hit was not in the project yet";
  EXPECT_EQ(static_cast<int>(p.store.hits(p.campaignId)->size()), static_cast<int>(rec.verdicts.size()));
}

TEST(CampaignEngine, RulesRejectPlantedDoubleHitsAndOverloadsWithReasons) {
  auto def = smallDefinition(2, 3, 0.3, 0.2);
  auto p = makeProject("rules", def);
  auto engine = CampaignEngine::open(p.store, p.campaignId, simStation(), fastOptions());
  ASSERT_TRUE(engine.ok());
  Recorder rec;
  (*engine)->addObserver(&rec);
  (*engine)->start();
  ASSERT_TRUE((*engine)->waitUntilFinished(120s));
  (*engine)->stop();
  auto hits = p.store.hits(p.campaignId).value();
  int doubles = 0, overloads = 0, accepted = 0;
  for (const auto& h : hits) {
    if (h.accepted) {
      ++accepted;
      EXPECT_EQ(h.qualityFlags, 0u) << h.qualityReasons;
      continue;
    }
    EXPECT_NE(h.qualityFlags & (core::io::kHitDoubleHit | core::io::kHitOverload), 0u) << h.qualityReasons;
    if (h.qualityFlags & core::io::kHitDoubleHit) {
      ++doubles;
      EXPECT_NE(h.qualityReasons.find("double hit"), std::string::npos) << h.qualityReasons;
    }
    if (h.qualityFlags & core::io::kHitOverload) {
      ++overloads;
      EXPECT_NE(h.qualityReasons.find("overload"), std::string::npos) << h.qualityReasons;
    }
  }
  EXPECT_EQ(accepted, 6);  // rejected hits repeated until each point has its two
  EXPECT_GT(doubles, 0);
  EXPECT_GT(overloads, 0);
  // The station planted exactly what the rules found: the verdicts say which
  // hits the simulation made double or overloaded (its fault draws are per
  // hit seed), and the rejected count equals the hits that failed.
  int failed = 0;
  for (const auto& v : rec.verdicts) failed += v.verdict.passed ? 0 : 1;
  EXPECT_EQ(failed, static_cast<int>(hits.size()) - accepted);
}

TEST(CampaignEngine, ManualDecisionsSkipAndRedo) {
  auto def = smallDefinition(1, 9, 1.0, 0.0);  // every hit a double hit
  auto p = makeProject("manual", def);
  auto engine = CampaignEngine::open(p.store, p.campaignId, simStation(), fastOptions(false, false));
  ASSERT_TRUE(engine.ok());
  Recorder rec;
  auto& e = **engine;
  e.addObserver(&rec);
  e.start();
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::Idle; }, 10s));
  e.accept();  // nothing pending: refused with a message, state unchanged
  e.arm();
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::VerdictPending; }, 30s));
  auto pending = e.pendingVerdict();
  ASSERT_TRUE(pending.has_value());
  EXPECT_FALSE(pending->verdict.passed);
  EXPECT_NE(pending->verdict.flags & core::io::kHitDoubleHit, 0u);
  EXPECT_TRUE(pending->awaitingDecision);
  e.reject("tip slipped");
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::Idle; }, 10s));
  e.arm();
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::VerdictPending; }, 30s));
  e.accept();  // the technician overrules the rule
  // Point 0 done (one hit per point); skip point 1 with a reason.
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::Idle; }, 10s));
  e.skip("accelerometer cable loose");
  ASSERT_TRUE(e.waitFor([&](EngineState) { return e.progress().current == std::optional<int>(2); }, 10s));
  e.arm();
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::VerdictPending; }, 30s));
  e.accept();
  ASSERT_TRUE(e.waitUntilFinished(30s));
  auto first = e.progress();
  ASSERT_TRUE(first.frfSetId.has_value());
  // Redo point 0 after the end: its accepted hit is set aside, the campaign
  // is unfinished until the point is measured again and a new FRF set stored.
  e.redo(0, "hit on the wrong face");
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::Idle; }, 10s));
  EXPECT_EQ(e.progress().current, std::optional<int>(0));
  e.arm();
  ASSERT_TRUE(e.waitFor([](EngineState s) { return s == EngineState::VerdictPending; }, 30s));
  e.accept();
  ASSERT_TRUE(e.waitUntilFinished(30s));
  auto second = e.progress();
  e.stop();
  ASSERT_TRUE(second.frfSetId.has_value());
  EXPECT_NE(*second.frfSetId, *first.frfSetId);

  auto hits = p.store.hits(p.campaignId).value();
  ASSERT_EQ(hits.size(), 4u);
  EXPECT_FALSE(hits[0].accepted);  // rejected by the technician: rule reason and theirs
  EXPECT_NE(hits[0].qualityReasons.find("double hit"), std::string::npos);
  EXPECT_NE(hits[0].qualityReasons.find("tip slipped"), std::string::npos);
  EXPECT_FALSE(hits[1].accepted);  // accepted despite the rule, then set aside by the redo
  EXPECT_NE(hits[1].qualityReasons.find("accepted by the technician despite"), std::string::npos);
  EXPECT_NE(hits[1].qualityReasons.find("redone: hit on the wrong face"), std::string::npos);
  EXPECT_NE(hits[1].qualityFlags & core::io::kHitManualReject, 0u);
  EXPECT_TRUE(hits[2].accepted);
  EXPECT_EQ(hits[2].point, def.points[2]);
  EXPECT_TRUE(hits[3].accepted);
  EXPECT_EQ(hits[3].point, def.points[0]);
  auto points = p.store.campaignPoints(p.campaignId).value();
  EXPECT_TRUE(points[1].skipped);
  EXPECT_EQ(points[1].skipReason, "accelerometer cable loose");
  auto set = p.store.frfSet(*second.frfSetId).value();
  EXPECT_EQ(set.references, (std::vector<core::Dof>{def.points[0], def.points[2]}));  // the skipped point left out
  EXPECT_EQ(p.store.frfSetHits(*second.frfSetId).value(), (std::vector<std::int64_t>{hits[2].id, hits[3].id}));
  bool refused = false;
  for (const auto& err : rec.errors) refused = refused || err.message.find("no hit is waiting") != std::string::npos;
  EXPECT_TRUE(refused);
}

TEST(CampaignEngine, ResumesAtTheFirstIncompletePointWithTheSameHitsAndFrfs) {
  const auto def = smallDefinition(4, 21, 0.2, 0.1);
  // Straight through.
  auto straight = makeProject("resume_straight", def);
  {
    auto e = CampaignEngine::open(straight.store, straight.campaignId, simStation(), fastOptions()).value();
    e->start();
    ASSERT_TRUE(e->waitUntilFinished(120s));
  }
  // Interrupted three times, each time after a few more commits.
  auto broken = makeProject("resume_broken", def);
  for (int stopAfter : {3, 2, 5}) {
    auto e = CampaignEngine::open(broken.store, broken.campaignId, simStation(), fastOptions()).value();
    Recorder rec;
    e->addObserver(&rec);
    auto before = loadCampaign(broken.store, broken.campaignId).value();
    e->start();
    ASSERT_TRUE(e->waitFor([&](EngineState) { return rec.commits.load() >= stopAfter; }, 60s));
    e->stop();
    // It started where the project said: the first point neither done nor skipped.
    ASSERT_FALSE(rec.progress.empty());
    EXPECT_EQ(rec.progress.front().current, before.schedule.next());
  }
  {
    auto e = CampaignEngine::open(broken.store, broken.campaignId, simStation(), fastOptions()).value();
    e->start();
    ASSERT_TRUE(e->waitUntilFinished(120s));
  }
  auto a = straight.store.hits(straight.campaignId).value();
  auto b = broken.store.hits(broken.campaignId).value();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].point, b[k].point);
    EXPECT_EQ(a[k].accepted, b[k].accepted);
    EXPECT_EQ(a[k].qualityFlags, b[k].qualityFlags);
    const auto ha = straight.store.hit(a[k].id).value(), hb = broken.store.hit(b[k].id).value();
    ASSERT_EQ(ha.samples.size(), hb.samples.size());
    EXPECT_EQ(0, std::memcmp(ha.samples.data(), hb.samples.data(), sizeof(float) * ha.samples.size()))
        << "hit " << k + 1 << " differs";
  }
  auto la = loadCampaign(straight.store, straight.campaignId).value();
  auto lb = loadCampaign(broken.store, broken.campaignId).value();
  ASSERT_TRUE(la.frfSetId && lb.frfSetId);
  expectSameFrf(straight.store.frfSet(*la.frfSetId).value(), broken.store.frfSet(*lb.frfSetId).value());
}

// A station whose device is unplugged in the middle of the first armed hit
// and comes back after a few failed reconnections.
class UnpluggingStation final : public Station {
 public:
  std::string label() const override { return "unplugging sim-hammer"; }
  core::Result<Device*> connect() override {
    if (device_) return device_.get();
    if (unplugged_ && failuresLeft_-- > 0)
      return core::makeError(core::ErrorCode::NotFound, "no device found", label());
    ++connects;
    auto d = sim::makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"});
    if (!d) return d.error();
    device_ = std::make_unique<Flaky>(std::move(*d), !unplugged_);
    if (auto o = device_->open(); !o) return o.error();
    return device_.get();
  }
  void disconnect() override {
    if (device_) unplugged_ = true;
    device_.reset();
  }
  int connects = 0;

 private:
  // The sim device, with the cable pulled 0.8 s into its first session:
  // after the 0.45 s of quiet before the hit, mid-record.
  class Flaky final : public Device {
   public:
    Flaky(std::unique_ptr<Device> inner, bool pull) : inner_(std::move(inner)), pull_(pull) {}
    const DeviceDescriptor& descriptor() const override { return inner_->descriptor(); }
    core::Result<void> open() override { return inner_->open(); }
    void close() override { inner_->close(); }
    Capabilities capabilities() const override { return inner_->capabilities(); }
    core::Result<AcquisitionConfig> configure(const AcquisitionConfig& requested) override {
      AcquisitionConfig c = requested;
      if (pull_) c.parameters["fault.disconnect_after_s"] = 0.8;
      pull_ = false;
      return inner_->configure(c);
    }
    core::Result<void> start(StreamSink sink) override { return inner_->start(std::move(sink)); }
    void stop() override { inner_->stop(); }
    DeviceState state() const override { return inner_->state(); }

   private:
    std::unique_ptr<Device> inner_;
    bool pull_;
  };
  std::unique_ptr<Device> device_;
  bool unplugged_ = false;
  int failuresLeft_ = 3;
};

TEST(CampaignEngine, UnplugMidHitDiscardsItWaitsForTheDeviceAndGoesOn) {
  auto def = smallDefinition(2, 13);
  auto p = makeProject("unplug", def);
  auto station = std::make_unique<UnpluggingStation>();
  auto* raw = station.get();
  auto e = CampaignEngine::open(p.store, p.campaignId, std::move(station), fastOptions()).value();
  Recorder rec;
  e->addObserver(&rec);
  e->start();
  ASSERT_TRUE(e->waitUntilFinished(120s));
  e->stop();
  EXPECT_EQ(raw->connects, 2);  // the first device, then the one plugged back in
  // The hit in flight was discarded with a message; nothing was committed from it.
  ASSERT_FALSE(rec.errors.empty());
  EXPECT_NE(rec.errors.front().message.find("hit in flight was discarded"), std::string::npos)
      << rec.errors.front().message;
  bool waited = false;
  for (auto s : rec.states) waited = waited || s == EngineState::WaitingForDevice;
  EXPECT_TRUE(waited);
  auto hits = p.store.hits(p.campaignId).value();
  ASSERT_EQ(hits.size(), 6u);
  for (const auto& h : hits) EXPECT_TRUE(h.accepted);
  // The discarded attempt is not counted: the first hit has attempt 0's seed,
  // i.e. the same data as a run without the unplug.
  auto plain = makeProject("unplug_reference", def);
  auto r = CampaignEngine::open(plain.store, plain.campaignId, simStation(), fastOptions()).value();
  r->start();
  ASSERT_TRUE(r->waitUntilFinished(120s));
  r->stop();
  const auto h1 = p.store.hit(hits[0].id).value();
  const auto h2 = plain.store.hit(plain.store.hits(plain.campaignId)->front().id).value();
  EXPECT_TRUE(h1.samples == h2.samples);
}

TEST(CampaignEngine, RefusesAReadOnlyProjectAndAnUnknownCampaign) {
  auto def = smallDefinition();
  auto p = makeProject("refuse", def);
  auto none = CampaignEngine::open(p.store, p.campaignId + 100, simStation());
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().code, core::ErrorCode::NotFound);
  auto ro = core::io::ProjectStore::open(p.store.path(), core::io::ProjectStore::OpenMode::ReadOnly).value();
  auto refused = CampaignEngine::open(ro, p.campaignId, simStation());
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, core::ErrorCode::Locked);
}

}  // namespace
}  // namespace mozzi::devices::campaign
