// The sequences' settings as ParameterSpec lists (the workbench's forms): the
// defaults of every list give back the settings' defaults, a form's values
// reach the settings, and a malformed list is refused naming its key.
#include "devices/rigtests/sequence_parameters.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mozzi::devices::rigtests
