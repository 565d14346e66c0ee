// Reading stored stiffness tests back (devices/rigtests/stiffness_results.h):
// a static and a dynamic test run on the simulated rig with frame A
// front-constrained; what is read must equal what the sequence returned in
// its outcome (the twist axis, k_lat, each frequency's axis) and the set-up
// it ran with (load point, lasers, bending and torsion axes, specimen key).
#include "devices/rigtests/stiffness_results.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/stiffness/dynamic_twist.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::rigtests {
namespace {

namespace fs = std::filesystem;

// The sine-fit loop of one frequency: lasers on a plate rotating about a known
// axis with a known phase lag, so the load point's phasor is known exactly
// (the plane through four exact points is exact): the loop must pass through
// (Re X, |F|) at theta = 0 and (-Im X, 0) at theta = pi/2, to 1e-12 relative.
TEST(StiffnessResults, FittedSineLoopFollowsTheLoadPointPhasor) {
  const std::vector<core::Vector2> lasers{{-0.1, -0.075}, {0.1, -0.075}, {0.1, 0.075}, {-0.1, 0.075}};
  const core::Vector2 load(0.02, -0.01);
  // w(u, v) = (w0 + gu u + gv v) e^{i phi}
  const double w0 = 2e-4, gu = 1e-3, gv = -4e-4, phi = -0.3;
  auto at = [&](const core::Vector2& p) { return std::polar(w0 + gu * p.x() + gv * p.y(), phi); };
  core::ComplexVector y(4);
  for (int i = 0; i < 4; ++i) y(i) = at(lasers[static_cast<std::size_t>(i)]);
  auto loop = fittedSineLoop(lasers, load, 250.0, y, 4);
  ASSERT_TRUE(loop.ok()) << loop.error().describe();
  ASSERT_EQ(loop->size(), 5u);
  const std::complex<double> x = at(load);
  EXPECT_NEAR((*loop)[0].x(), x.real(), 1e-12 * std::abs(x));
  EXPECT_NEAR((*loop)[0].y(), 250.0, 1e-9);
  EXPECT_NEAR((*loop)[1].x(), -x.imag(), 1e-12 * std::abs(x));
  EXPECT_NEAR((*loop)[1].y(), 0.0, 1e-9);
  EXPECT_NEAR((*loop)[4].x(), (*loop)[0].x(), 1e-15);  // closed
  // Phasors from a step's results, and the errors.
  std::vector<Quantity> results;
  for (int i = 0; i < 4; ++i) {
    const std::string k = "laser_" + std::to_string(i + 1);
    results.push_back(Quantity{k + "_amplitude", "", std::abs(y(i)), "m", 0.0});
    results.push_back(Quantity{k + "_phase", "", std::arg(y(i)), "rad", 0.0});
  }
  auto back = laserPhasorsOf(results, 4);
  ASSERT_TRUE(back.has_value());
  EXPECT_LT((*back - y).norm(), 1e-15);
  EXPECT_FALSE(laserPhasorsOf(results, 5).has_value());
  EXPECT_FALSE(fittedSineLoop(lasers, load, 0.0, y).ok());
  EXPECT_FALSE(fittedSineLoop({lasers[0], lasers[1], lasers[2]}, load, 1.0, y).ok());
  const std::vector<core::Vector2> collinear{{0, 0}, {0.1, 0}, {0.2, 0}, {0.3, 0}};
  EXPECT_FALSE(fittedSineLoop(collinear, load, 1.0, y).ok());
}

TEST(StiffnessResults, ReadsBackWhatTheSequencesStored) {
  const fs::path path = fs::temp_directory_path() / ("stiffness_results_" + std::to_string(::getpid()) + ".mozzi");
  fs::remove(path);
  {
    auto store = core::io::ProjectStore::create(path.string(), "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    auto specimen = store->addSpecimen("Frame A, front-constrained", "frame", "test");
    ASSERT_TRUE(specimen.ok());
    const std::string key = "frame-a-front-constrained";
    auto setup = simulatedStiffnessSetup(key, 3, false);
    ASSERT_TRUE(setup.ok()) << setup.error().describe();
    auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
    ASSERT_TRUE(dev.ok());
    StaticTestSettings st;
    st.periodS = 4.0;
    auto s = runStaticStiffnessTest(**dev, nullptr, *setup, st, StoreTarget{&*store, *specimen, "static"});
    ASSERT_TRUE(s.ok()) << s.error().describe();
    ASSERT_TRUE(s->twist.has_value());
    DynamicTestSettings dy;
    dy.frequenciesHz = {1, 5, 10};
    auto d = runDynamicStiffnessTest(**dev, nullptr, *setup, dy, StoreTarget{&*store, *specimen, "dynamic"});
    ASSERT_TRUE(d.ok()) << d.error().describe();
    ASSERT_TRUE(s->testId && d->testId);

    auto sv = readStiffnessTest(*store, *s->testId);
    ASSERT_TRUE(sv.ok()) << sv.error().describe();
    EXPECT_FALSE(sv->dynamic);
    EXPECT_EQ(sv->specimenKey, key);
    EXPECT_EQ(sv->laserPoints.size(), setup->laserPoints.size());
    for (std::size_t i = 0; i < setup->laserPoints.size(); ++i) EXPECT_EQ(sv->laserPoints[i], setup->laserPoints[i]);
    EXPECT_EQ(sv->loadPoint, setup->loadPoint);
    ASSERT_TRUE(sv->bendAxis && sv->torsAxis && setup->bendAxis);
    EXPECT_NEAR(sv->bendAxis->beta, setup->bendAxis->beta, 1e-12);
    ASSERT_TRUE(sv->axis.has_value());
    const auto& truth = s->twist->axis.axis;
    EXPECT_EQ(sv->axis->point, truth.point);
    EXPECT_EQ(sv->axis->beta, truth.beta);
    EXPECT_NEAR(sv->axis->direction(0), truth.direction(0), 1e-15);
    EXPECT_NEAR(sv->axis->direction(1), truth.direction(1), 1e-15);
    EXPECT_EQ(sv->axis->betaSigma, truth.betaSigma);
    ASSERT_NE(sv->result("k_lat"), nullptr);
    EXPECT_EQ(sv->result("k_lat")->value, s->twist->lateralStiffness);
    EXPECT_EQ(sv->result("k_lat")->unit, "N/m");
    EXPECT_TRUE(sv->steps.empty());

    auto dv = readStiffnessTest(*store, *d->testId);
    ASSERT_TRUE(dv.ok()) << dv.error().describe();
    EXPECT_TRUE(dv->dynamic);
    ASSERT_EQ(dv->steps.size(), 3u);
    ASSERT_EQ(d->sweep.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(dv->steps[k].frequencyHz, dy.frequenciesHz[k]);
      ASSERT_TRUE(d->sweep[k].axis && d->sweep[k].axis->axis.ok());
      const auto& a = d->sweep[k].axis->axis->axis.axis;
      ASSERT_TRUE(dv->steps[k].axis.has_value());
      EXPECT_EQ(dv->steps[k].axis->point, a.point);
      EXPECT_EQ(dv->steps[k].axis->beta, a.beta);
      // The stored phasors give the same axis again through core.
      ASSERT_EQ(dv->steps[k].laserPhasors.size(), 4);
      auto again = core::stiffness::phasorTwistAxis(dv->laserPoints, dv->steps[k].laserPhasors, dv->loadPoint);
      ASSERT_TRUE(again.ok()) << again.error().describe();
      EXPECT_NEAR(again->axis.axis.beta, a.beta, 1e-12);
      EXPECT_NEAR((again->axis.axis.point - a.point).norm(), 0.0, 1e-12);
    }
    EXPECT_EQ(dv->dynamicAxes().size(), 3u);
    EXPECT_FALSE(readStiffnessTest(*store, 99999).ok());
  }
  fs::remove(path);
  fs::remove(path.string() + "-wal");
  fs::remove(path.string() + "-shm");
}

}  // namespace
}  // namespace mozzi::devices::rigtests
