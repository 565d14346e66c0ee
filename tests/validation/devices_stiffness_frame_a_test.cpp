// Validation of the simulated Motostiffmeter (thesis §1.1): a static ramp on
// the virtual frame A front-constrained, acquired through the driver (load
// cell with noise, four lasers quantised to 4 um, 16-bit DAQ), processed by
// the static twist test of core/stiffness gives back Table 3: lateral
// stiffness 167 kN/m and twist arm 0.551 m within 1% (the tolerance).
#include <gtest/gtest.h>

#include <cmath>

#include "core/stiffness/plate_motion.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices {
namespace {

using namespace std::chrono_literals;

TEST(DevicesStiffnessFrameA, StaticRampGivesBackTable3) {
  AcquisitionConfig cfg;
  cfg.sampleRateHz = 100.0;
  cfg.scanCount = 2000;  // one 20 s ramp period: 0 -> +1000 N -> -1000 N -> 0
  ChannelConfig lc;
  lc.input = 0;
  lc.name = "load cell";
  lc.transducer = core::signal::Transducer{core::signal::TransducerKind::Force, "load cell +/-200 kg", "", 10000.0 / (200 * 9.80665), "N", false};
  cfg.channels.push_back(lc);
  for (int i = 1; i <= 4; ++i) {
    ChannelConfig l;
    l.input = i;
    l.name = "laser " + std::to_string(i);
    l.transducer = core::signal::Transducer{core::signal::TransducerKind::Displacement, "laser 20 mm", "", 1e6, "m", false};  // 1 V/mm
    cfg.channels.push_back(l);
  }
  cfg.parameters["sim.realtime"] = false;
  cfg.parameters["static.max_force"] = 1000.0;

  auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"}).value();
  ASSERT_TRUE(dev->open().ok());
  ASSERT_TRUE(dev->configure(cfg).ok());
  StreamCollector col;
  ASSERT_TRUE(dev->start(col.sink()).ok());
  ASSERT_TRUE(col.waitForEnd(60s));
  dev->stop();
  ASSERT_EQ(col.end()->reason, EndReason::Completed);
  const core::Matrix v = col.values();

  const auto spec = sim::staticSpecimen("frame-a-front-constrained").value();
  const core::Vector force = v.col(0);
  const core::Matrix disp = v.rightCols(4);
  auto res = core::stiffness::staticTwistTest(spec.laserPoints, force, disp, spec.loadPoint);
  ASSERT_TRUE(res.ok()) << res.error().describe();
  std::printf("k_lat = %.1f N/m (Table 3: 167000), a_tw = %.4f m (Table 3: 0.551), k_tw = %.0f Nm/rad (50.8e3)\n",
              res->lateralStiffness, res->twistArm, res->twistStiffness);
  EXPECT_NEAR(res->lateralStiffness / 167e3, 1.0, 0.01);
  EXPECT_NEAR(res->twistArm / 0.551, 1.0, 0.01);
  // Eq. 30: k_tw = k_lat a_tw^2 = 50.7 kNm/rad (Table 3 prints 50.8 from rounded inputs).
  EXPECT_NEAR(res->twistStiffness / (167e3 * 0.551 * 0.551), 1.0, 0.03);
}

}  // namespace
}  // namespace mozzi::devices
