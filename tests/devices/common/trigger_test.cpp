// Software trigger with pre-trigger ring buffer: exact sample indices for
// level, slope, pre-trigger fraction, hold-off and overload counting.
#include "devices/common/trigger.h"

#include <gtest/gtest.h>

namespace mozzi::devices {
namespace {

// Feeds `x` (one channel) in blocks of `blockSize` and gathers the records.
std::vector<TriggeredRecord> feedAll(SoftwareTrigger& t, const std::vector<double>& x, Eigen::Index blockSize) {
  std::vector<TriggeredRecord> out;
  for (std::size_t start = 0; start < x.size(); start += static_cast<std::size_t>(blockSize)) {
    const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(blockSize), x.size() - start);
    core::Matrix b(static_cast<Eigen::Index>(n), 1);
    for (std::size_t i = 0; i < n; ++i) b(static_cast<Eigen::Index>(i), 0) = x[start + i];
    auto r = t.feed(static_cast<std::int64_t>(start), b);
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

std::vector<double> ramp(int n) {
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = 0.001 * i;  // distinct values identify samples
  return x;
}

TEST(SoftwareTrigger, RisingEdgeCutsRecordWithTenPercentPreTrigger) {
  auto x = ramp(100);
  for (int k = 20; k < 23; ++k) x[static_cast<std::size_t>(k)] = 1.0;
  SoftwareTriggerConfig cfg;
  cfg.level = 0.5;
  cfg.recordScans = 20;  // pre = round(0.1 * 20) = 2
  auto t = SoftwareTrigger::create(cfg, 1);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->preTriggerScans(), 2);
  auto recs = feedAll(*t, x, 7);  // blocks of 7: the record straddles three blocks
  ASSERT_EQ(recs.size(), 1u);
  EXPECT_EQ(recs[0].triggerSample, 20);
  EXPECT_EQ(recs[0].firstSample, 18);
  ASSERT_EQ(recs[0].samples.rows(), 20);
  EXPECT_DOUBLE_EQ(recs[0].samples(0, 0), 0.018);  // sample 18
  EXPECT_DOUBLE_EQ(recs[0].samples(1, 0), 0.019);
  EXPECT_DOUBLE_EQ(recs[0].samples(2, 0), 1.0);     // the trigger sample at index pre
  EXPECT_DOUBLE_EQ(recs[0].samples(19, 0), 0.037);  // sample 37
}

TEST(SoftwareTrigger, HoldOffIgnoresRingingAndAcceptsLaterHit) {
  std::vector<double> x(200, 0.0);
  for (int k : {30, 45, 62, 90}) x[static_cast<std::size_t>(k)] = 1.0;  // hits (single-sample pulses)
  SoftwareTriggerConfig cfg;
  cfg.level = 0.5;
  cfg.recordScans = 10;   // pre = 1
  cfg.holdOffScans = 25;  // record of hit 30 spans 29..38; blocked until 29 + 10 + 25 = 64
  auto t = SoftwareTrigger::create(cfg, 1);
  ASSERT_TRUE(t.ok());
  auto recs = feedAll(*t, x, 16);
  ASSERT_EQ(recs.size(), 2u);
  EXPECT_EQ(recs[0].triggerSample, 30);
  EXPECT_EQ(recs[1].triggerSample, 90);  // 45 and 62 fall inside the hold-off
  EXPECT_EQ(recs[1].firstSample, 89);
  EXPECT_EQ(t->crossingsIgnored(), 2);
  EXPECT_EQ(t->triggersAccepted(), 2);
}

TEST(SoftwareTrigger, FallingAndEitherSlopes) {
  std::vector<double> x(60, 0.0);
  for (int k = 10; k < 30; ++k) x[static_cast<std::size_t>(k)] = -1.0;  // falls at 10, rises at 30
  SoftwareTriggerConfig cfg;
  cfg.level = -0.5;
  cfg.recordScans = 5;
  cfg.preTriggerFraction = 0.2;  // pre = 1
  cfg.slope = TriggerSlope::Falling;
  auto falling = SoftwareTrigger::create(cfg, 1);
  ASSERT_TRUE(falling.ok());
  auto r1 = feedAll(*falling, x, 8);
  ASSERT_EQ(r1.size(), 1u);
  EXPECT_EQ(r1[0].triggerSample, 10);
  cfg.slope = TriggerSlope::Either;
  auto either = SoftwareTrigger::create(cfg, 1);
  auto r2 = feedAll(*either, x, 8);
  ASSERT_EQ(r2.size(), 2u);
  EXPECT_EQ(r2[0].triggerSample, 10);
  EXPECT_EQ(r2[1].triggerSample, 30);
  cfg.slope = TriggerSlope::Rising;  // -1 -> 0 crosses -0.5 upwards at 30
  auto rising = SoftwareTrigger::create(cfg, 1);
  auto r3 = feedAll(*rising, x, 8);
  ASSERT_EQ(r3.size(), 1u);
  EXPECT_EQ(r3[0].triggerSample, 30);
}

TEST(SoftwareTrigger, CrossingBeforePreTriggerIsFullIsIgnored) {
  std::vector<double> x(40, 0.0);
  x[1] = 1.0;  // only one sample in the ring, pre needs 3
  x[20] = 1.0;
  SoftwareTriggerConfig cfg;
  cfg.level = 0.5;
  cfg.recordScans = 10;
  cfg.preTriggerFraction = 0.3;  // pre = 3
  auto t = SoftwareTrigger::create(cfg, 1);
  auto recs = feedAll(*t, x, 5);
  ASSERT_EQ(recs.size(), 1u);
  EXPECT_EQ(recs[0].triggerSample, 20);
  EXPECT_EQ(recs[0].firstSample, 17);
  EXPECT_EQ(t->crossingsIgnored(), 1);
}

TEST(SoftwareTrigger, OverloadNeedsThreeSamplesAtFullScale) {
  // Two channels; channel 1 hits full scale (2.0) twice in the first record
  // and three times in the second: only the second is overloaded.
  const int n = 80;
  core::Matrix m = core::Matrix::Zero(n, 2);
  m(10, 0) = 1.0;
  m(11, 1) = 2.0;
  m(12, 1) = -2.0;
  m(50, 0) = 1.0;
  m(51, 1) = 2.0;
  m(52, 1) = 2.5;
  m(53, 1) = -2.0;
  SoftwareTriggerConfig cfg;
  cfg.level = 0.5;
  cfg.recordScans = 20;
  cfg.fullScale = {5.0, 2.0};
  auto t = SoftwareTrigger::create(cfg, 2);
  ASSERT_TRUE(t.ok());
  auto recs = t->feed(0, m);
  ASSERT_EQ(recs.size(), 2u);
  EXPECT_EQ(recs[0].fullScaleCounts[1], 2);
  EXPECT_FALSE(recs[0].overloaded);
  EXPECT_EQ(recs[1].fullScaleCounts[1], 3);
  EXPECT_TRUE(recs[1].overloaded);
  EXPECT_EQ(recs[1].fullScaleCounts[0], 0);
}

TEST(SoftwareTrigger, GapResetsRingAndPendingRecord) {
  std::vector<double> x(10, 0.0);
  x[8] = 1.0;  // triggers, record pending (needs 10 scans)
  SoftwareTriggerConfig cfg;
  cfg.level = 0.5;
  cfg.recordScans = 10;
  auto t = SoftwareTrigger::create(cfg, 1);
  core::Matrix b1 = Eigen::Map<core::Matrix>(x.data(), 10, 1);
  EXPECT_TRUE(t->feed(0, b1).empty());
  core::Matrix b2 = core::Matrix::Zero(20, 1);
  b2(5, 0) = 1.0;  // sample 105 after a gap of 90 scans
  auto recs = t->feed(100, b2);
  ASSERT_EQ(recs.size(), 1u);  // the pending record of sample 8 was dropped, not completed with foreign data
  EXPECT_EQ(recs[0].triggerSample, 105);
  EXPECT_EQ(recs[0].firstSample, 104);
}

TEST(SoftwareTrigger, InvalidSettingsAreErrors) {
  SoftwareTriggerConfig cfg;
  cfg.recordScans = 0;
  EXPECT_FALSE(SoftwareTrigger::create(cfg, 1).ok());
  cfg.recordScans = 10;
  cfg.channel = 3;
  EXPECT_FALSE(SoftwareTrigger::create(cfg, 2).ok());
  cfg.channel = 0;
  cfg.preTriggerFraction = 1.0;
  EXPECT_FALSE(SoftwareTrigger::create(cfg, 2).ok());
  cfg.preTriggerFraction = 0.1;
  cfg.fullScale = {1.0};
  auto e = SoftwareTrigger::create(cfg, 2);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("full-scale"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::devices
