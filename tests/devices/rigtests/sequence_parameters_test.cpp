// The sequences' settings as ParameterSpec lists (the workbench's forms): the
// defaults of every list give back the settings' defaults, a form's values
// reach the settings, and a malformed list is refused naming its key.
#include "devices/rigtests/sequence_parameters.h"

#include <gtest/gtest.h>

#include <cmath>

#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::rigtests {
namespace {

ParameterMap defaults(const std::vector<ParameterSpec>& specs) {
  ParameterMap m;
  for (const auto& s : specs) m[s.key] = s.defaultValue;
  return m;
}

TEST(SequenceParameters, DefaultsAreTheSettingsDefaults) {
  auto st = staticSettingsFrom(defaults(staticTestParameters()));
  ASSERT_TRUE(st.ok()) << st.error().describe();
  EXPECT_EQ(st->peakForceN, StaticTestSettings{}.peakForceN);
  EXPECT_EQ(st->periodS, StaticTestSettings{}.periodS);
  auto dy = dynamicSettingsFrom(defaults(dynamicTestParameters()));
  ASSERT_TRUE(dy.ok()) << dy.error().describe();
  EXPECT_EQ(dy->frequenciesHz, DynamicTestSettings{}.frequenciesHz);
  auto re = relaxationSettingsFrom(defaults(relaxationTestParameters()));
  ASSERT_TRUE(re.ok()) << re.error().describe();
  EXPECT_EQ(re->frequenciesHz, RelaxationSettings{}.frequenciesHz);
  EXPECT_EQ(re->cycles, RelaxationSettings{}.cycles);
  auto ss = steadyStateSettingsFrom(defaults(steadyStateTestParameters()));
  ASSERT_TRUE(ss.ok()) << ss.error().describe();
  EXPECT_EQ(ss->slipDeg, SteadyStateSettings{}.slipDeg);
  EXPECT_EQ(ss->camberDeg, SteadyStateSettings{}.camberDeg);
  EXPECT_EQ(ss->holdS, SteadyStateSettings{}.holdS);
}

TEST(SequenceParameters, FormValuesReachTheSettings) {
  auto st = staticSettingsFrom({{"static.peak_force", 500.0}, {"static.period", 4.0}});
  ASSERT_TRUE(st.ok());
  EXPECT_EQ(st->peakForceN, 500.0);  // fork B's ramp
  EXPECT_EQ(st->periodS, 4.0);
  auto re = relaxationSettingsFrom(
      {{"relaxation.frequencies", std::string(" 0.84, 1.26 ,1.68")}, {"relaxation.cycles", std::int64_t{6}}});
  ASSERT_TRUE(re.ok()) << re.error().describe();
  EXPECT_EQ(re->frequenciesHz, (std::vector<double>{0.84, 1.26, 1.68}));
  EXPECT_EQ(re->cycles, 6);
  auto ss = steadyStateSettingsFrom({{"steady.camber", std::string("-10,0,10")}, {"steady.magic_formula", false}});
  ASSERT_TRUE(ss.ok());
  EXPECT_EQ(ss->camberDeg, (std::vector<double>{-10, 0, 10}));
  EXPECT_FALSE(ss->fitMagicFormula);
}

TEST(SequenceParameters, MalformedValuesAreRefusedNamingTheKey) {
  auto dy = dynamicSettingsFrom({{"dynamic.frequencies", std::string("1, two, 5")}});
  ASSERT_FALSE(dy.ok());
  EXPECT_NE(dy.error().describe().find("dynamic.frequencies"), std::string::npos) << dy.error().describe();
  auto empty = steadyStateSettingsFrom({{"steady.slip", std::string(" ")}});
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.error().describe().find("steady.slip"), std::string::npos) << empty.error().describe();
  auto range = staticSettingsFrom({{"static.peak_force", 6000.0}});  // the actuator's 5000 N (§1.1)
  ASSERT_FALSE(range.ok());
  EXPECT_NE(range.error().describe().find("static.peak_force"), std::string::npos) << range.error().describe();
}

TEST(SequenceParameters, SimulatedRigSettingsAreTheDevicesOwn) {
  auto stiff = simulatedRigParameters(false);
  ASSERT_EQ(stiff.size(), 2u);
  EXPECT_EQ(stiff[0].key, "sim.seed");
  EXPECT_EQ(stiff[1].key, "sim.realtime");
  auto tyre = simulatedRigParameters(true);
  ASSERT_EQ(tyre.size(), 3u);
  EXPECT_EQ(tyre[2].key, "tyre.pressure_bar");
}

// The stiffness rig's set-up form: its defaults give back the simulated
// rig's layout (lasers, load point; a 220 x 170 mm plate around the load
// point, the lasers' 200 x 150 mm spread with 10 mm to spare),
// edited points reach the set-up and the simulated device's parameters, and
// the geometry check names the field to correct: collinear lasers, two lasers
// on one spot, a laser off the plate, the constrained end on the plate.
TEST(SequenceParameters, StiffnessSetupFormAndGeometryCheck) {
  auto base = simulatedStiffnessSetup("fork-a-with-wheel", 1, false);
  ASSERT_TRUE(base.ok()) << base.error().describe();
  const core::Vector2 locked(-0.05, 1.1);
  const auto specs = stiffnessSetupParameters(*base, locked);
  ASSERT_EQ(specs.size(), 2u + 8u + 2u + 2u);
  auto s = stiffnessSetupFrom(*base, defaults(specs));
  ASSERT_TRUE(s.ok()) << s.error().describe();
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT((s->laserPoints[i] - base->laserPoints[i]).norm(), 1e-12) << i;
  EXPECT_LT((s->loadPoint - base->loadPoint).norm(), 1e-12);
  ASSERT_TRUE(s->constrainedEnd.has_value());
  EXPECT_LT((*s->constrainedEnd - locked).norm(), 1e-12);
  ASSERT_EQ(s->plateOutline.size(), 4u);
  EXPECT_NEAR(s->plateOutline[2].x() - s->plateOutline[0].x(), 0.220, 1e-12);
  EXPECT_NEAR(s->plateOutline[2].y() - s->plateOutline[0].y(), 0.170, 1e-12);
  EXPECT_TRUE(checkPlateGeometry(*s).ok());

  auto with = [&](ParameterMap changes) {
    ParameterMap v = defaults(specs);
    for (const auto& [k, x] : changes) v[k] = x;
    auto r = stiffnessSetupFrom(*base, v);
    EXPECT_TRUE(r.ok()) << r.error().describe();
    return *r;
  };
  // An edited laser and load point reach the simulated rig.
  auto moved = with({{"setup.laser2_u", 80.0}, {"setup.load_v", -5.0}});
  EXPECT_NEAR(moved.laserPoints[1].x(), 0.080, 1e-12);
  EXPECT_NEAR(moved.loadPoint.y(), -0.005, 1e-12);
  EXPECT_EQ(parameterText(moved.daqParameters, "load.point", ""), "0:-0.005");
  EXPECT_NE(parameterText(moved.daqParameters, "lasers.points", "").find("0.08:-0.075"), std::string::npos)
      << parameterText(moved.daqParameters, "lasers.points", "");
  EXPECT_TRUE(checkPlateGeometry(moved).ok());

  // All four lasers on the line v = -75 mm... laser 3 and 4 moved onto it.
  auto line =
      with({{"setup.laser3_v", -75.0}, {"setup.laser4_v", -75.0}, {"setup.laser4_u", 30.0}, {"setup.laser3_u", -30.0}});
  auto r = checkPlateGeometry(line);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("one line"), std::string::npos) << r.error().describe();
  EXPECT_EQ(r.error().where.rfind("setup.laser", 0), 0u) << r.error().where;
  // Two lasers on one spot: the later one is named.
  r = checkPlateGeometry(with({{"setup.laser3_u", -100.0}, {"setup.laser3_v", -73.0}}));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "setup.laser3_u") << r.error().describe();
  // Off the plate.
  r = checkPlateGeometry(with({{"setup.plate_width", 100.0}, {"setup.plate_height", 150.0}}));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "setup.laser1_u") << r.error().describe();
  EXPECT_NE(r.error().message.find("off the 100 x 150 mm plate"), std::string::npos) << r.error().message;
  // The constrained end on the plate.
  r = checkPlateGeometry(with({{"setup.constrained_u", 10.0}, {"setup.constrained_v", 10.0}}));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "setup.constrained_u") << r.error().describe();
  // The sequences refuse it before anything moves.
  auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
  ASSERT_TRUE(dev.ok());
  auto run = runStaticStiffnessTest(**dev, nullptr, line, StaticTestSettings{}, StoreTarget{});
  ASSERT_FALSE(run.ok());
  EXPECT_NE(run.error().message.find("one line"), std::string::npos) << run.error().describe();
  EXPECT_EQ((*dev)->state(), DeviceState::Closed);
}

// The simulated rig measures where the set-up puts the lasers and loads where
// it puts the load point: a static ramp with laser 2 moved and the load point
// 40 mm off still gives the specimen's static field there (reciprocal
// single-axis model, w(p) = F arm(q) arm(p) / k_tw): k_lat at the new load
// point is k_lat a_tw^2 / arm(q)^2, within 1%.
TEST(SequenceParameters, SimulatedRigFollowsTheSetupGeometry) {
  auto base = simulatedStiffnessSetup("frame-a-front-constrained", 2, false);
  ASSERT_TRUE(base.ok());
  auto specs = stiffnessSetupParameters(*base, core::Vector2(0.0, 0.8));
  ParameterMap v = defaults(specs);
  v["setup.laser2_u"] = 70.0;
  v["setup.load_u"] = 40.0;
  v["setup.plate_width"] = 300.0;  // the plate follows the load point
  auto s = stiffnessSetupFrom(*base, v);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
  ASSERT_TRUE(dev.ok());
  StaticTestSettings st;
  st.periodS = 4.0;
  auto out = runStaticStiffnessTest(**dev, nullptr, *s, st, StoreTarget{});
  ASSERT_TRUE(out.ok()) << out.error().describe();
  ASSERT_TRUE(out->twist.has_value()) << out->note;
  const auto spec = sim::staticSpecimen("frame-a-front-constrained").value();
  // displacement at q per newton at q
  const double expected = 1.0 / spec.displacementAt(s->loadPoint, s->loadPoint, 1.0);
  std::printf("k_lat at the moved load point %.1f N/m (model %.1f, at the specimen's load point %.1f)\n",
              out->twist->lateralStiffness, expected, spec.lateralStiffness);
  EXPECT_NEAR(out->twist->lateralStiffness / expected, 1.0, 0.01);
  EXPECT_GT(std::abs(expected / spec.lateralStiffness - 1.0), 0.02);  // the move matters
}

}  // namespace
}  // namespace mozzi::devices::rigtests
