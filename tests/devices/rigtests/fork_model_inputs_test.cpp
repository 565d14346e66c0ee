// The Lumped Fork page's inputs as parameter specs (fork_model_inputs.h):
// their defaults are the thesis's inputs as core's validation uses them
// (tests/validation/stiffness_forks_test.cpp: Table 12; Table 21 with
// d = 0.060 m and the carbon fork's modes of Tables 19 and 20); the CLI
// arguments carry every number exactly; the JSON has `mozzi-cli fork lumped
// --json`'s keys and values.
#include "devices/rigtests/fork_model_inputs.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace mozzi::devices::rigtests {
namespace {

ParameterMap defaults(const std::vector<ParameterSpec>& specs) {
  auto applied = applyParameters(specs, {});
  EXPECT_TRUE(applied.ok());
  return applied.ok() ? *applied : ParameterMap{};
}

TEST(ForkModelInputs, DefaultsAreTheThesisInputs) {
  const auto in = lumpedForkInput(defaults(lumpedForkParameterSpecs()));
  EXPECT_EQ(in.staticBendStiffness, 28e3);
  EXPECT_EQ(in.staticAxisArm, 0.670);
  EXPECT_EQ(in.dynamicAxisArm, 0.846);
  EXPECT_NEAR(in.wheelCentreHeight, 0.670 - 0.405, 1e-15);
  EXPECT_EQ(in.vibratingMass, 11.0);
  EXPECT_EQ(in.wheelInertia, 0.278);
  EXPECT_EQ(in.measuredFrequencyHz, 22.3);
  EXPECT_EQ(in.zeta, 0.024);
  const auto b = bicycleForkInput(defaults(bicycleForkParameterSpecs()));
  EXPECT_EQ(b.parameters.forkMass, 0.393);
  EXPECT_EQ(b.parameters.wheelMass, 1.334);
  EXPECT_EQ(b.parameters.wheelRadius, 0.350);
  EXPECT_EQ(b.parameters.hubMass, 0.094);
  EXPECT_EQ(b.parameters.hubRadius, 0.004);
  EXPECT_EQ(b.parameters.hubLength, 0.225);
  EXPECT_EQ(b.parameters.tipDistance, 0.060);
  EXPECT_EQ(b.parameters.maxBendArm, 0.460);
  EXPECT_EQ(b.torsionWithWheelHz, 19.3);
  EXPECT_EQ(b.torsionWithWheelEta, 0.1004);
  EXPECT_EQ(b.torsionAloneHz, 191.2);
  EXPECT_EQ(b.torsionAlone2Hz, 0.0);
  EXPECT_EQ(b.bendingWithWheelHz, 21.3);
  EXPECT_EQ(b.bendingWithWheelEta, 0.0424);
  EXPECT_EQ(b.bendingAloneHz, 64.0);
}

TEST(ForkModelInputs, CliArgumentsCarryEveryNumberExactly) {
  core::stiffness::ForkLumpedInput in{28123.456789012345, 0.1 + 0.2,         -0.846, 1.0 / 3.0, 11.0, 0.278,
                                      22.2985768297988,   0.0239836809103995};
  const auto args = lumpedForkCliArguments(in);
  ASSERT_EQ(args.size(), 16u);
  const double expected[] = {in.staticBendStiffness, in.staticAxisArm, in.dynamicAxisArm,      in.wheelCentreHeight,
                             in.vibratingMass,       in.wheelInertia,  in.measuredFrequencyHz, in.zeta};
  const char* names[] = {"--k", "--l1", "--l2", "--wheel-centre", "--mass", "--wheel-inertia", "--freq", "--zeta"};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(args[2 * i], names[i]);
    EXPECT_EQ(std::strtod(args[2 * i + 1].c_str(), nullptr), expected[i]) << names[i];
  }
  auto b = bicycleForkInput(defaults(bicycleForkParameterSpecs()));
  EXPECT_EQ(bicycleForkCliArguments(b).size(), 28u);  // no second torsion mode
  b.torsionAlone2Hz = 230.1;
  const auto withSecond = bicycleForkCliArguments(b);
  ASSERT_EQ(withSecond.size(), 30u);
  EXPECT_EQ(withSecond[28], "--f-tors-alone2");
  EXPECT_EQ(std::strtod(withSecond[29].c_str(), nullptr), 230.1);
}

TEST(ForkModelInputs, JsonHoldsTheModels) {
  const auto models = core::stiffness::forkLumpedModels(lumpedForkInput(defaults(lumpedForkParameterSpecs())));
  ASSERT_TRUE(models.ok());
  const auto j = lumpedModelsJson(*models);
  const core::stiffness::LumpedModel* ms[] = {&models->model1, &models->model2, &models->model3};
  for (int i = 0; i < 3; ++i) {
    const auto& m = j.at("model" + std::to_string(i + 1));
    EXPECT_EQ(m.at("stiffness_Nm_per_rad").get<double>(), ms[i]->stiffness);
    EXPECT_EQ(m.at("arm_m").get<double>(), ms[i]->arm);
    EXPECT_EQ(m.at("inertia_kgm2").get<double>(), ms[i]->inertia);
    EXPECT_EQ(m.at("pure_moment_kgm2").get<double>(), ms[i]->pureMoment);
    EXPECT_EQ(m.at("frequency_Hz").get<double>(), ms[i]->frequencyHz);
    EXPECT_EQ(m.at("damping_Nms_per_rad").get<double>(), ms[i]->damping);
    EXPECT_EQ(m.at("zeta").get<double>(), ms[i]->zeta);
  }
}

}  // namespace
}  // namespace mozzi::devices::rigtests
