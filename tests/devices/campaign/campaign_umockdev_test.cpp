// The campaign engine on the real MCC USB-1608FS-Plus driver, through
// libusb and umockdev's usbfs emulation (usb1608fsplus_device_model.h): the
// emulated DAQ sees a hammer hit every 4 s of its simulated clock (a
// half-sine on AI0 whose peak grows by 50 codes from one hit to the next, so
// each stored hit says which pulse it was) and two decaying modes on AI1..3.
// The cable is pulled in the middle of the third hit's record: that hit is
// discarded with a message, the engine waits for the device (reconnections
// fail while it is away), nothing committed is lost, and after the replug the
// campaign goes on with the next hit and finishes.
// Run under umockdev-wrapper (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "campaign_fixture.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_device_model.h"

namespace mozzi::devices::campaign {
namespace {

using namespace std::chrono_literals;

constexpr double kRate = 5000.0;
constexpr std::int64_t kPeriod = 20000;   // scans between hits (4 s)
constexpr std::int64_t kPulseAt = 10000;  // hit start within its period
constexpr std::int64_t kPulseWidth = 8;   // 1.6 ms half-sine
constexpr double kPi = 3.14159265358979323846;

int pulsePeak(std::int64_t hit) {
  return 2000 + 50 * static_cast<int>(hit);
}

// Codes of the emulated ADC: mid-scale 32768 is 0 V; +/-2 codes of
// deterministic noise on every channel.
std::uint16_t hammerCode(std::int64_t k, int c) {
  const std::int64_t hit = k / kPeriod, t = k % kPeriod - kPulseAt;
  const int noise = static_cast<int>(((k * 2654435761u) ^ (c * 40503u)) % 5) - 2;
  double v = 0.0;
  if (c == 0) {
    if (t >= 0 && t < kPulseWidth) v = pulsePeak(hit) * std::sin(kPi * (t + 0.5) / kPulseWidth);
  } else if (t >= 0) {
    const double s = static_cast<double>(t) / kRate;
    v = (1500.0 / c) * std::exp(-0.02 * 2 * kPi * 120 * s) * std::sin(2 * kPi * 120 * s) +
        (800.0 * c / 3) * std::exp(-0.03 * 2 * kPi * 310 * s) * std::sin(2 * kPi * 310 * s);
  }
  return static_cast<std::uint16_t>(32768 + static_cast<int>(std::lround(v)) + noise);
}

CampaignDefinition mccDefinition() {
  CampaignDefinition d;
  d.points = {core::Dof{1, core::Direction::Y, false}, core::Dof{2, core::Direction::Y, false}};
  d.constraint.kind = ConstraintKind::OnRig;
  ChannelAssignment h;
  h.input = 0;
  h.name = "hammer";
  h.transducer = {core::signal::TransducerKind::Force, "PCB 086C03", "H1", 2.25, "N", true};
  h.rangeCode = 0;  // +/-10 V
  h.roving = true;
  d.channels.push_back(h);
  for (int i = 1; i <= 3; ++i) {
    ChannelAssignment a;
    a.input = i;
    a.name = "acc " + std::to_string(i);
    a.transducer = {
        core::signal::TransducerKind::Acceleration, "PCB M352C65", "A" + std::to_string(i), 10.0, "m/s^2", true};
    a.rangeCode = 0;
    a.dof = core::Dof{10 + i, core::Direction::Y, false};
    d.channels.push_back(a);
  }
  d.acquisition = {kRate, 1.0, 0.1, 20.0};  // 1 s records, trigger at 20 N
  d.hitsPerPoint = 2;
  d.driver = "mcc-usb1608fsplus";
  return d;
}

class CampaignUmockdev : public ::testing::Test {
 protected:
  void SetUp() override {
    bed_.setUp();
    bed_.model_.code = hammerCode;
  }
  void TearDown() override { bed_.tearDown(); }
  mcc::emulation::Usb1608Testbed bed_;
};

// Peak force of a stored hit, in codes of the emulated ADC (2.25 mV/N on +/-10 V).
int peakCodes(const core::io::StoredHit& h) {
  const double peakN = h.samples.col(0).cwiseAbs().maxCoeff();
  return static_cast<int>(std::lround(peakN * 2.25e-3 / (20.0 / 65536.0)));
}

TEST_F(CampaignUmockdev, UnplugMidHitDiscardsItAndTheCampaignResumesAfterReplug) {
  const auto def = mccDefinition();
  auto p = testing::makeProject("mcc_unplug", def);
  // Mid-record of the third hit: 2000 scans after its trigger, 2500 before its end.
  bed_.model_.unplugAtScan = 2 * kPeriod + kPulseAt + 2000;
  EngineOptions o;
  o.autoDecide = true;
  o.autoArm = true;
  o.reconnectInterval = 50ms;
  auto e = CampaignEngine::open(p.store, p.campaignId, makeDriverStation(builtinDrivers(), def.driver), o).value();
  testing::Recorder rec;
  e->addObserver(&rec);
  e->start();
  ASSERT_TRUE(e->waitFor([](EngineState s) { return s == EngineState::WaitingForDevice; }, 60s))
      << "the unplug must be noticed";
  std::this_thread::sleep_for(400ms);  // several reconnections fail while it is away
  EXPECT_EQ(e->state(), EngineState::WaitingForDevice);
  auto before = p.store.hits(p.campaignId).value();
  ASSERT_EQ(before.size(), 2u) << "the two hits before the unplug are committed, the one in flight is not";
  std::vector<core::io::StoredHit> kept;
  for (const auto& h : before) kept.push_back(p.store.hit(h.id).value());
  {
    std::lock_guard<std::mutex> l(rec.mu);
    ASSERT_FALSE(rec.errors.empty());
    EXPECT_NE(rec.errors.front().message.find("hit in flight was discarded"), std::string::npos)
        << rec.errors.front().message;
  }
  bed_.model_.replug();
  ASSERT_TRUE(e->waitUntilFinished(60s));
  e->stop();

  auto hits = p.store.hits(p.campaignId).value();
  ASSERT_EQ(hits.size(), 4u);
  // Nothing committed was lost or changed.
  for (std::size_t k = 0; k < kept.size(); ++k) {
    EXPECT_EQ(hits[k].id, kept[k].id);
    EXPECT_TRUE(p.store.hit(hits[k].id)->samples == kept[k].samples);
  }
  // Pulses 0, 1, then 3 and 4: pulse 2 was in flight at the unplug. The
  // sampled half-sine peaks at sin(3.5 pi / 8) of its height; pulses differ by
  // 49 codes there, the tolerance (10) covers the noise (2) and the device
  // calibration of the model (slope 1.0001).
  const std::int64_t pulses[] = {0, 1, 3, 4};
  for (std::size_t k = 0; k < hits.size(); ++k) {
    EXPECT_TRUE(hits[k].accepted) << hits[k].qualityReasons;
    const double expected = pulsePeak(pulses[k]) * std::sin(kPi * 3.5 / kPulseWidth);
    EXPECT_NEAR(peakCodes(p.store.hit(hits[k].id).value()), expected, 10) << "hit " << k + 1;
    EXPECT_EQ(hits[k].point, def.points[k / 2]);
  }
  auto loaded = loadCampaign(p.store, p.campaignId).value();
  EXPECT_TRUE(loaded.finished());
  // The MCC's quantised rate is the stored one (40 MHz / 8000 = 5000 Hz exactly).
  EXPECT_DOUBLE_EQ(hits[0].sampleRateHz, 5000.0);
}

}  // namespace
}  // namespace mozzi::devices::campaign
