// The campaign definition: JSON round trip (what is stored with the
// campaign), validation errors that name the field, the acquisition
// configuration and time record of a hit at a point, and the roving schedule's
// bookkeeping (order, skips, redo, progress, replay of stored hits).
#include <gtest/gtest.h>

#include "devices/campaign/campaign_definition.h"
#include "devices/campaign/campaign_store.h"
#include "devices/campaign/roving_schedule.h"
#include "devices/campaign/virtual_campaign.h"

namespace mozzi::devices::campaign {
namespace {

using core::Direction;
using core::Dof;

CampaignDefinition sample() {
  CampaignDefinition d;
  d.specimenKey = "fork-a-with-wheel";
  d.meshTemplate = "fork-with-wheel-10+8";
  d.points = {Dof{1, Direction::Y, false}, Dof{2, Direction::Y, false}, Dof{3, Direction::X, true}};
  d.constraint = {ConstraintKind::Clamped, {7, 8}, "steering tube clamped"};
  d.excitation = ExcitationKind::RovingHammer;
  ChannelAssignment h;
  h.input = 0;
  h.name = "hammer";
  h.transducer = {core::signal::TransducerKind::Force, "PCB 086C03", "H123", 2.25, "N", true};
  h.calibrationDate = "2026-01-15";
  h.rangeCode = 4;
  h.roving = true;
  ChannelAssignment a;
  a.input = 3;
  a.name = "acc";
  a.transducer = {core::signal::TransducerKind::Acceleration, "PCB M352C65", "A7", 10.0, "m/s^2", true};
  a.rangeCode = 2;
  a.conditionerGain = 10.0;
  a.dof = Dof{2, Direction::Y, false};
  d.channels = {h, a};
  d.acquisition = {2048.0, 1.5, 0.125, 12.5};
  d.hitsPerPoint = 4;
  d.windows = {0.01, 0.002, 0.5};
  d.estimator = core::signal::FrfEstimator::Hv;
  d.frfMaxHz = 400.0;
  d.rules = {true, false, 40.0, 25.0, 0.85, 10.0, 300.0};
  d.driver = "mcc-usb1608fsplus";
  d.deviceSerial = "01ABCDEF";
  d.deviceParameters = {{"overrun.policy", std::string("stop")}, {"usb.transfer_ms", std::int64_t{50}}};
  d.seed = 18446744073709551615ull;  // the largest seed survives the JSON text
  return d;
}

TEST(CampaignDefinition, JsonRoundTripKeepsEveryField) {
  const auto d = sample();
  ASSERT_TRUE(d.validate().ok()) << d.validate().error().describe();
  const std::string text = definitionToJson(d).dump();
  auto back = parseDefinition(text);
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(definitionToJson(*back).dump(), text);
  EXPECT_EQ(back->seed, d.seed);
  EXPECT_EQ(back->points, d.points);
  EXPECT_EQ(back->channels[1].dof, d.channels[1].dof);
  EXPECT_EQ(back->channels[0].calibrationDate, "2026-01-15");
  EXPECT_EQ(back->estimator, core::signal::FrfEstimator::Hv);
  EXPECT_EQ(std::get<std::int64_t>(back->deviceParameters.at("usb.transfer_ms")), 50);
}

TEST(CampaignDefinition, ErrorsNameTheField) {
  auto j = definitionToJson(sample());
  auto expectError = [](nlohmann::json bad, const std::string& field) {
    auto r = definitionFromJson(bad);
    ASSERT_FALSE(r.ok()) << field;
    EXPECT_NE(r.error().where.find(field), std::string::npos) << r.error().describe();
  };
  auto bad = j;
  bad["channels"][1]["sensitivity_mv_per_unit"] = -1.0;
  expectError(bad, "channels[1].sensitivity_mv_per_unit");
  bad = j;
  bad["points"][2] = "3:+Q";
  expectError(bad, "points[2]");
  bad = j;
  bad["points"][2] = "1:+Y";
  expectError(bad, "points");
  bad = j;
  bad["acquisition"].erase("sample_rate_hz");
  expectError(bad, "acquisition.sample_rate_hz");
  bad = j;
  bad["channels"][1]["roving"] = true;  // roving hammer must rove the hammer only
  expectError(bad, "roving");
  bad = j;
  bad["station"]["seed"] = "-3";
  expectError(bad, "station.seed");
  bad = j;
  bad["format"] = "something else";
  expectError(bad, "format");
  bad = j;
  bad["constraint"]["clamped_nodes"] = nlohmann::json::array();
  expectError(bad, "constraint.clamped_nodes");
  EXPECT_FALSE(parseDefinition("{not json").ok());
}

TEST(CampaignDefinition, ConfigurationAndRecordOfAHitAtAPoint) {
  const auto d = sample();
  const Dof point{3, Direction::X, true};
  ParameterMap overrides{{"overrun.policy", std::string("restart")}};
  const auto cfg = acquisitionConfigFor(d, point, overrides);
  ASSERT_EQ(cfg.channels.size(), 2u);
  EXPECT_EQ(cfg.channels[0].dof, point);  // the roving hammer measures at the point
  EXPECT_EQ(cfg.channels[1].dof, d.channels[1].dof);
  EXPECT_EQ(cfg.channels[1].input, 3);
  EXPECT_DOUBLE_EQ(cfg.channels[1].conditionerGain, 10.0);
  EXPECT_EQ(std::get<std::string>(cfg.parameters.at("overrun.policy")), "restart");
  EXPECT_EQ(d.recordScans(), 3072);
  EXPECT_EQ(d.preTriggerScans(), 384);
  const auto tr = timeRecordFor(d, point, 2047.5, {555.0, 25.0}, core::Matrix::Zero(3072, 2));
  EXPECT_DOUBLE_EQ(tr.sampleRateHz, 2047.5);
  EXPECT_EQ(tr.preTriggerSamples, 384);
  EXPECT_EQ(tr.channels[0].dof, point);
  EXPECT_DOUBLE_EQ(tr.channels[1].fullScale, 25.0);
  // Windows: force x exponential on the hammer, exponential on the response.
  const auto o = d.frfOptions();
  EXPECT_EQ(o.referenceWindow.kind, core::signal::WindowKind::Force);
  EXPECT_DOUBLE_EQ(o.referenceWindow.exponentialTauS, 0.5);
  EXPECT_EQ(o.responseWindow.kind, core::signal::WindowKind::Exponential);
}

TEST(RovingSchedule, OrderSkipsRedoAndProgress) {
  std::vector<core::io::StoredCampaignPoint> pts;
  for (int i = 0; i < 4; ++i) pts.push_back({i, Dof{i + 1, Direction::Z, false}, false, {}});
  pts[2].skipped = true;
  pts[2].skipReason = "no access";
  RovingSchedule s(pts, 2);
  std::vector<core::io::HitInfo> hits;
  auto hit = [&](int node, bool accepted) {
    core::io::HitInfo h;
    h.point = Dof{node, Direction::Z, false};
    h.accepted = accepted;
    hits.push_back(h);
  };
  hit(1, true), hit(1, false), hit(1, true), hit(2, true), hit(9, true);  // node 9 is not in the schedule
  s.replay(hits);
  EXPECT_EQ(s.ignoredHits(), 1);
  EXPECT_TRUE(s.point(0).done);
  EXPECT_EQ(s.point(0).attempts, 3);
  EXPECT_EQ(s.next(), std::optional<int>(1));
  auto p = s.progress();
  EXPECT_EQ(p.pointsDone, 1);
  EXPECT_EQ(p.pointsSkipped, 1);
  EXPECT_EQ(p.acceptedHits, 3);
  EXPECT_EQ(p.rejectedHits, 1);
  EXPECT_DOUBLE_EQ(p.fraction(), 0.5);
  s.recordHit(1, true);
  EXPECT_EQ(s.next(), std::optional<int>(3));  // 2 is skipped
  s.redo(0);
  EXPECT_EQ(s.next(), std::optional<int>(0));  // a redone point comes first again
  EXPECT_EQ(s.progress().rejectedHits, 3);     // its two accepted hits were set aside
  s.setSkipped(2, false, "");
  s.recordHit(0, true), s.recordHit(0, true), s.recordHit(2, true), s.recordHit(2, true);
  s.recordHit(3, true), s.recordHit(3, true);
  EXPECT_TRUE(s.progress().complete());
}

TEST(CampaignDefinition, HitSeedsDependOnSeedPointAndAttemptOnly) {
  EXPECT_EQ(hitSeed(1, 2, 3), hitSeed(1, 2, 3));
  EXPECT_NE(hitSeed(1, 2, 3), hitSeed(1, 2, 4));
  EXPECT_NE(hitSeed(1, 2, 3), hitSeed(1, 3, 3));
  EXPECT_NE(hitSeed(1, 2, 3), hitSeed(2, 2, 3));
  EXPECT_LE(hitSeed(99, 7, 1), 0xFFFFFFFFull);  // sim.seed's range
}

TEST(VirtualCampaign, RangesHoldTheExpectedPeaksAndAnUnknownKeyIsNamed) {
  auto d = virtualSpecimenCampaign("fork-a-with-wheel");
  ASSERT_TRUE(d.ok()) << d.error().describe();
  EXPECT_EQ(d->channels[0].transducer.kind, core::signal::TransducerKind::Force);
  EXPECT_EQ(d->channels[0].rangeCode, 5);  // 220 N x 2.25 mV/N = 0.495 V: twice that (0.99 V) within +/-1 V
  auto bad = virtualSpecimenCampaign("fork-z");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("rig list"), std::string::npos);
  // The bound is an upper bound of a synthesised hit's peak: one mode, unit
  // mass, a 1 ms half-sine of 1 N: the peak acceleration lies between the
  // force itself (the pulse drives the mass) and twice it.
  core::Matrix phi(1, 1);
  phi(0, 0) = 1.0;
  const double a = peakAccelerationBound(phi, {50.0}, {0.02}, 0, 0, 1.0, 1e-3);
  EXPECT_GT(a, 0.9);
  EXPECT_LT(a, 2.0);
}

}  // namespace
}  // namespace mozzi::devices::campaign
