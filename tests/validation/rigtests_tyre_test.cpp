// Validation of the tyre-tester sequences (devices/rigtests, issue 20) on the
// simulated Mototiremeter: the relaxation test (harmonic yaw, 1.5 deg, 5 km/h,
// the thesis's five frequencies, §5.1) gives back the virtual tyre's
// relaxation length within 2% at every frequency and in the band mean, and the
// steady-state test gives back its cornering stiffness within 1% and its
// camber stiffness within 1%. The virtual tyre's values come from the
// simulator's own set-up (sim::tyreTesterSetup: eq. 48 with Tables 16 and 17,
// C = 13 F_z, camber 0.9 F_z), not from the sequence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "devices/rigtests/tyre_tests.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::rigtests {
namespace {

std::unique_ptr<Device> tester() {
  return sim::makeTyreTesterDriver()->create(DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"}).value();
}

sim::TyreTesterSetup virtualTyre(const TyreRigSetup& setup) {
  return sim::tyreTesterSetup(setup.daqParameters).value();
}

// Three tyres of the six, three pressures: the radial motorcycle front, the
// high-wheel scooter rear, the small scooter front (sigma from 0.1 to 0.3 m).
struct Case {
  const char* tyre;
  double pressureBar;
};
const Case kCases[] = {{"tyre-120-70-r17", 2.0}, {"tyre-140-70-14", 1.0}, {"tyre-120-70-12", 3.0}};

TEST(RigTestsTyreValidation, RelaxationLengthWithinTwoPercentOfTheVirtualTyre) {
  for (const auto& c : kCases) {
    auto setup = simulatedTyreSetup(c.tyre, c.pressureBar, 9, false);
    ASSERT_TRUE(setup.ok()) << setup.error().describe();
    const double sigma = virtualTyre(*setup).relaxationLength;
    auto dev = tester();
    auto out = runRelaxationTest(*dev, *setup, RelaxationSettings{}, StoreTarget{});
    ASSERT_TRUE(out.ok()) << out.error().describe();
    ASSERT_EQ(out->status, TestStatus::Complete) << out->note;
    const Quantity* mean = findQuantity(out->results, "relaxation_length_m");
    ASSERT_NE(mean, nullptr);
    std::printf("%s at %.1f bar: virtual sigma %.4f m, band mean %.4f +/- %.4f m (%+.2f%%)\n", c.tyre, c.pressureBar,
                sigma, mean->value, mean->uncertainty, 100 * (mean->value / sigma - 1));
    // 2% (the issue): the fits see 2 N of load-cell noise on about 390 N of
    // force amplitude and a gyro quantised at 0.3 mrad/s; the first cycle of
    // each frequency (the lag's transient) is dropped.
    EXPECT_NEAR(mean->value / sigma, 1.0, 0.02) << c.tyre;
    ASSERT_EQ(out->steps.size(), 5u);
    for (const auto& s : out->steps) {
      const Quantity* q = findQuantity(s.results, "relaxation_length_m");
      ASSERT_NE(q, nullptr) << s.label << ": " << s.note;
      std::printf("  %s: sigma %.4f +/- %.4f m\n", s.label.c_str(), q->value, q->uncertainty);
      EXPECT_NEAR(q->value / sigma, 1.0, 0.02) << c.tyre << " " << s.label;
    }
  }
}

TEST(RigTestsTyreValidation, CorneringAndCamberStiffnessWithinOnePercent) {
  for (const auto& c : kCases) {
    auto setup = simulatedTyreSetup(c.tyre, c.pressureBar, 10, false);
    ASSERT_TRUE(setup.ok());
    const auto tyre = virtualTyre(*setup);
    auto dev = tester();
    SteadyStateSettings s;  // +/-6 deg slip in 1 deg, +/-45 deg camber in 5 deg steps
    auto out = runSteadyStateTest(*dev, *setup, s, StoreTarget{});
    ASSERT_TRUE(out.ok()) << out.error().describe();
    ASSERT_EQ(out->status, TestStatus::Complete) << out->note;
    const Quantity* ca = findQuantity(out->results, "cornering_stiffness");
    const Quantity* cg = findQuantity(out->results, "camber_stiffness");
    ASSERT_NE(ca, nullptr) << out->note;
    ASSERT_NE(cg, nullptr) << out->note;
    std::printf(
        "%s at %.1f bar: cornering %.0f +/- %.0f N/rad (virtual %.0f, %+.2f%%), camber %.1f +/- %.1f N/rad "
        "(virtual %.1f, %+.2f%%)\n",
        c.tyre, c.pressureBar, ca->value, ca->uncertainty, tyre.corneringStiffness,
        100 * (ca->value / tyre.corneringStiffness - 1), cg->value, cg->uncertainty, tyre.camberStiffness,
        100 * (cg->value / tyre.camberStiffness - 1));
    // 1% (the issue): a cubic over +/-3 deg (7 held points) leaves the Magic
    // Formula's fifth-order term below 0.5% of the slope; each point averages
    // 3 s of 2 N noise at 200 Hz (0.1 N).
    EXPECT_NEAR(ca->value / tyre.corneringStiffness, 1.0, 0.01) << c.tyre;
    EXPECT_NEAR(cg->value / tyre.camberStiffness, 1.0, 0.01) << c.tyre;
    // The Magic Formula fit: its cornering stiffness K = pKy1 F_z0 sin(2 atan(1 / pKy2))
    // (F_z = F_z0) against the virtual tyre's, 1%; its camber thrust pVy3 F_z likewise.
    ASSERT_TRUE(out->lateral.has_value()) << out->note;
    const auto& names = core::tire::mfLateralNames();
    auto mf = [&](const char* n) {
      return out->lateral->value[static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin())];
    };
    const double k = mf("pKy1") * setup->verticalLoadN * std::sin(2 * std::atan(1.0 / mf("pKy2")));
    std::printf("  Magic Formula: K %.0f N/rad, pVy3 F_z %.1f N/rad, rms %.2f N\n", k,
                mf("pVy3") * setup->verticalLoadN, out->lateral->rmsResidual);
    EXPECT_NEAR(k / tyre.corneringStiffness, 1.0, 0.01) << c.tyre;
    // The simulator's Magic Formula shape is the neutral set of
    // core/tire/magic_formula.h (pCy1 1.3, pDy1 1, pEy1 -0.5): the sweeps to
    // +/-6 deg (B alpha up to 1.05) give them back within 2% / 1% / 5%.
    const auto defaults = core::tire::mfLateralDefaults();
    auto def = [&](const char* n) {
      return defaults[static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin())];
    };
    EXPECT_NEAR(mf("pCy1") / def("pCy1"), 1.0, 0.02) << c.tyre;
    EXPECT_NEAR(mf("pDy1") / def("pDy1"), 1.0, 0.01) << c.tyre;
    EXPECT_NEAR(mf("pEy1") / def("pEy1"), 1.0, 0.05) << c.tyre;
    EXPECT_NEAR(mf("pVy3") * setup->verticalLoadN / tyre.camberStiffness, 1.0, 0.01) << c.tyre;
  }
}

}  // namespace
}  // namespace mozzi::devices::rigtests
