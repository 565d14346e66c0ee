// Simulated rigs: seeded fault injection with counters, the calibration
// pipeline on simulated data, and the end reasons of a session.
#include "devices/sim/sim_drivers.h"

#include <gtest/gtest.h>

#include <cmath>

#include "devices/common/trigger.h"

namespace mozzi::devices::sim {
namespace {

using namespace std::chrono_literals;

AcquisitionConfig hammerConfig(double rate, double seconds) {
  AcquisitionConfig c;
  c.sampleRateHz = rate;
  c.scanCount = static_cast<std::int64_t>(rate * seconds);
  ChannelConfig f;
  f.input = 0;
  f.name = "hammer";
  f.rangeCode = 0;  // +/-10 V
  f.transducer.kind = core::signal::TransducerKind::Force;
  f.transducer.sensitivityMvPerUnit = 2.25;  // PCB 086C03
  f.transducer.unit = "N";
  c.channels.push_back(f);
  for (int i = 1; i <= 3; ++i) {
    ChannelConfig a;
    a.input = i;
    a.name = "acc " + std::to_string(i);
    a.rangeCode = 0;
    a.transducer.kind = core::signal::TransducerKind::Acceleration;
    a.transducer.sensitivityMvPerUnit = 10.0;  // PCB M352C65, thesis §1.4
    a.transducer.unit = "m/s^2";
    c.channels.push_back(a);
  }
  c.parameters["sim.realtime"] = false;
  c.parameters["hammer.interval_s"] = 1.0;
  return c;
}

struct Session {
  std::unique_ptr<Device> device;
  StreamCollector collector;
};

std::unique_ptr<Session> run(std::unique_ptr<Driver> driver, const AcquisitionConfig& config) {
  auto s = std::make_unique<Session>();
  auto dev = driver->create(driver->scan()->front());
  EXPECT_TRUE(dev.ok());
  s->device = std::move(*dev);
  EXPECT_TRUE(s->device->open().ok());
  auto applied = s->device->configure(config);
  EXPECT_TRUE(applied.ok()) << applied.error().describe();
  EXPECT_TRUE(s->device->start(s->collector.sink()).ok());
  EXPECT_TRUE(s->collector.waitForEnd(60s));
  s->device->stop();
  return s;
}

FaultCounters countersOf(const Session& s) {
  return dynamic_cast<const SimulatedRig&>(*s.device).counters();
}

TEST(HammerStation, CleanSessionCompletesWithOneHitPerInterval) {
  auto s = run(makeHammerStationDriver(), hammerConfig(2048.0, 5.0));
  ASSERT_TRUE(s->collector.end().has_value());
  EXPECT_EQ(s->collector.end()->reason, EndReason::Completed);
  EXPECT_EQ(s->collector.scans(), 10240);
  EXPECT_EQ(s->collector.end()->samplesDelivered, 10240);
  EXPECT_TRUE(s->collector.orderedAndContiguous());
  EXPECT_EQ(countersOf(*s).hits, 5);
  EXPECT_EQ(countersOf(*s).doubleHits, 0);
  EXPECT_TRUE(s->collector.overloads().empty());
  // The hammer peaks are about 200 N (+/-10%) at 0.25 s into each second.
  const core::Matrix v = s->collector.values();
  for (int hit = 0; hit < 5; ++hit) {
    const double peak = v.col(0).segment(hit * 2048, 2048).maxCoeff();
    EXPECT_GT(peak, 170.0);
    EXPECT_LT(peak, 230.0);
  }
  // Values are what the calibration pipeline makes of the raw codes: force
  // channel LSB = 20 V / 65536 / 2.25 mV/N = 0.1356 N.
  const auto raw = s->collector.raw();
  ChannelChain chain;
  chain.range = InputRange{"+/-10 V", 0, -10.0, 10.0};
  chain.calibration = DeviceCalibration{1.0002, -3.0};
  chain.transducer.sensitivityMvPerUnit = 2.25;
  for (int k = 0; k < 2000; k += 97)
    EXPECT_DOUBLE_EQ(v(k, 0), chain.engineeringFromRaw(raw[static_cast<std::size_t>(k) * 4]));
}

TEST(HammerStation, SameSeedSameData) {
  auto a = run(makeHammerStationDriver(), hammerConfig(1024.0, 2.0));
  auto b = run(makeHammerStationDriver(), hammerConfig(1024.0, 2.0));
  EXPECT_EQ(a->collector.raw(), b->collector.raw());
  auto c = hammerConfig(1024.0, 2.0);
  c.parameters["sim.seed"] = std::int64_t{2};
  auto d = run(makeHammerStationDriver(), c);
  EXPECT_NE(a->collector.raw(), d->collector.raw());
}

TEST(HammerStation, DoubleHitsAndOverloadsOnRequest) {
  auto cfg = hammerConfig(4096.0, 6.0);
  cfg.channels[0].rangeCode = 1;  // +/-5 V: 2222 N full scale at 2.25 mV/N
  cfg.parameters["fault.double_hit_probability"] = 0.5;
  cfg.parameters["fault.overload_probability"] = 0.5;
  auto s = run(makeHammerStationDriver(), cfg);
  const auto n = countersOf(*s);
  EXPECT_EQ(n.hits, 6);
  EXPECT_GT(n.doubleHits, 0);
  EXPECT_LT(n.doubleHits, 6);
  EXPECT_GT(n.overloadHits, 0);
  // Overloaded hits (30 x 200 N = 5400..6600 N > 2222 N full scale) put the
  // middle 3 of the 4 samples of their 1 ms pulse at full scale; the trigger
  // flags exactly those records.
  EXPECT_FALSE(s->collector.overloads().empty());
  SoftwareTriggerConfig tc;
  tc.channel = 0;
  tc.level = 20.0;  // N
  tc.recordScans = 2048;
  tc.fullScale = {s->collector.header()->channels[0].fullScale, s->collector.header()->channels[1].fullScale,
                  s->collector.header()->channels[2].fullScale, s->collector.header()->channels[3].fullScale};
  auto trig = SoftwareTrigger::create(tc, 4);
  ASSERT_TRUE(trig.ok());
  auto records = trig->feed(0, s->collector.values());
  ASSERT_EQ(static_cast<std::int64_t>(records.size()), n.hits);
  std::int64_t overloaded = 0;
  for (const auto& r : records) overloaded += r.overloaded ? 1 : 0;
  EXPECT_EQ(overloaded, n.overloadHits);
  // Pre-trigger is 10% of the record and the hits sit 0.25 s into each second.
  EXPECT_EQ(records[0].preTriggerScans, 205);
  EXPECT_NEAR(static_cast<double>(records[0].triggerSample), 0.25 * 4096,
              8.0);  // level reached within 2 ms of the pulse start
}

TEST(SimulatedFaults, OverrunsAreReportedAndCounted) {
  auto cfg = hammerConfig(1000.0, 10.0);
  cfg.parameters["fault.overrun_probability"] = 0.2;
  auto s = run(makeHammerStationDriver(), cfg);
  const auto n = countersOf(*s);
  EXPECT_GT(n.overruns, 0);
  EXPECT_EQ(static_cast<std::int64_t>(s->collector.overruns().size()), n.overruns);
  std::int64_t lost = 0;
  for (const auto& o : s->collector.overruns()) lost += o.lostScans;
  EXPECT_EQ(lost, n.lostScans);
  EXPECT_EQ(s->collector.scans() + n.lostScans, 10000);  // every scan is delivered or reported lost
  EXPECT_EQ(s->collector.end()->reason, EndReason::Completed);
}

TEST(SimulatedFaults, DisconnectEndsCleanlyWithDataSoFar) {
  auto cfg = hammerConfig(1000.0, 10.0);
  cfg.blockScans = 100;
  cfg.parameters["fault.disconnect_after_s"] = 2.5;
  auto s = run(makeHammerStationDriver(), cfg);
  ASSERT_TRUE(s->collector.end().has_value());
  EXPECT_EQ(s->collector.end()->reason, EndReason::Disconnected);
  EXPECT_EQ(s->collector.end()->samplesDelivered, 2500);
  EXPECT_EQ(s->collector.scans(), 2500);
  EXPECT_EQ(countersOf(*s).disconnects, 1);
}

TEST(SimulatedFaults, TimeoutEndsTheSession) {
  auto cfg = hammerConfig(1000.0, 10.0);
  cfg.blockScans = 100;
  cfg.parameters["fault.timeout_after_s"] = 1.0;
  auto s = run(makeHammerStationDriver(), cfg);
  EXPECT_EQ(s->collector.end()->reason, EndReason::Timeout);
  EXPECT_EQ(s->collector.scans(), 1000);
  EXPECT_EQ(countersOf(*s).timeouts, 1);
}

TEST(SimulatedFaults, StopEndsAContinuousRealTimeSession) {
  auto cfg = hammerConfig(1000.0, 0.0);  // continuous
  cfg.parameters["sim.realtime"] = true;
  auto dev = makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"}).value();
  StreamCollector col;
  ASSERT_TRUE(dev->open().ok());
  ASSERT_TRUE(dev->configure(cfg).ok());
  ASSERT_TRUE(dev->start(col.sink()).ok());
  ASSERT_TRUE(col.waitForScans(100, 5s));
  dev->stop();
  ASSERT_TRUE(col.end().has_value());
  EXPECT_EQ(col.end()->reason, EndReason::Stopped);
  EXPECT_EQ(col.end()->samplesDelivered, col.scans());
  EXPECT_EQ(dev->state(), DeviceState::Configured);
}

TEST(SimulatedFaults, ASessionThatEndedByItselfCanBeFollowedByAnother) {
  auto cfg = hammerConfig(1000.0, 0.5);
  auto dev = makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"}).value();
  ASSERT_TRUE(dev->open().ok());
  ASSERT_TRUE(dev->configure(cfg).ok());
  for (int run = 0; run < 2; ++run) {
    StreamCollector col;
    ASSERT_TRUE(dev->start(col.sink()).ok()) << "run " << run;
    ASSERT_TRUE(col.waitForEnd(10s));
    EXPECT_EQ(col.end()->reason, EndReason::Completed);
    EXPECT_EQ(col.scans(), 500);
  }
  // A start while a session runs is refused.
  cfg.scanCount = 0;
  cfg.parameters["sim.realtime"] = true;
  ASSERT_TRUE(dev->configure(cfg).ok());
  StreamCollector col;
  ASSERT_TRUE(dev->start(col.sink()).ok());
  EXPECT_FALSE(dev->start(col.sink()).ok());
  dev->stop();
  EXPECT_EQ(col.end()->reason, EndReason::Stopped);
}

TEST(StiffnessRig, SineAmplitudeFallsLogarithmically) {
  EXPECT_DOUBLE_EQ(actuatorSineAmplitude(1000.0, 1.0), 1000.0);
  EXPECT_NEAR(actuatorSineAmplitude(1000.0, 45.0), 200.0, 1e-9);
  EXPECT_NEAR(hammerPulseWidthS(0.16, 1.6e6), 3.14159265358979 * 1e-3 / 3.16227766016838 * std::sqrt(1.0), 1e-12);
}

TEST(StiffnessRig, LasersQuantiseToFourMicrometres) {
  AcquisitionConfig c;
  c.sampleRateHz = 100.0;
  c.scanCount = 2000;
  ChannelConfig lc;
  lc.input = 0;
  lc.transducer.kind = core::signal::TransducerKind::Force;
  lc.transducer.sensitivityMvPerUnit = 10000.0 / (200 * 9.80665);  // +/-200 kg on +/-10 V
  c.channels.push_back(lc);
  ChannelConfig laser;
  laser.input = 1;
  laser.transducer.kind = core::signal::TransducerKind::Displacement;
  laser.transducer.sensitivityMvPerUnit = 1e6;  // 20 mm on +/-10 V: 1 V/mm
  c.channels.push_back(laser);
  c.parameters["sim.realtime"] = false;
  c.parameters["static.max_force"] = 1000.0;  // the default follows the specimen (frame A: the thesis's 300 N)
  auto s = run(makeStiffnessRigDriver(), c);
  const core::Matrix v = s->collector.values();
  // DAQ LSB on the laser channel is 20 mm / 65536 = 0.305 um, far below the
  // laser's 4 um steps: every value sits within one DAQ LSB of a 4 um step.
  const double daqLsb = 0.020 / 65536.0;
  for (Eigen::Index k = 0; k < v.rows(); ++k) {
    const double steps = v(k, 1) / 4e-6;
    EXPECT_LE(std::abs(steps - std::round(steps)) * 4e-6, 1.5 * daqLsb) << k;
  }
  EXPECT_GT(v.col(0).maxCoeff(), 990.0);  // the ramp reaches its 1000 N peak at 5 s
}

}  // namespace
}  // namespace mozzi::devices::sim
