// Driver model: registry, descriptors, capabilities as data, parameter specs
// and configure() returning the applied configuration.
#include "devices/common/driver.h"

#include <gtest/gtest.h>

#include "devices/mcc_usb1608fsplus/usb1608fsplus_driver.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices {
namespace {

TEST(DriverRegistry, BuiltinDriversAndDuplicates) {
  auto& reg = builtinDrivers();
  ASSERT_NE(reg.find("mcc-usb1608fsplus"), nullptr);
  ASSERT_NE(reg.find("sim-hammer"), nullptr);
  ASSERT_NE(reg.find("sim-stiffness"), nullptr);
  EXPECT_EQ(reg.find("no-such-driver"), nullptr);
  EXPECT_FALSE(reg.find("mcc-usb1608fsplus")->simulated());
  EXPECT_TRUE(reg.find("sim-hammer")->simulated());
  DriverRegistry local;
  ASSERT_TRUE(local.add(sim::makeHammerStationDriver()).ok());
  auto dup = local.add(sim::makeHammerStationDriver());
  ASSERT_FALSE(dup.ok());
  EXPECT_EQ(dup.error().where, "driver sim-hammer");
  auto missing = local.create(DeviceDescriptor{"mcc-usb1608fsplus", "", 0, 0, "", ""});
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, core::ErrorCode::NotFound);
}

TEST(DriverRegistry, SimulatedRigsAreFoundByScan) {
  DriverRegistry local;
  ASSERT_TRUE(local.add(sim::makeHammerStationDriver()).ok());
  ASSERT_TRUE(local.add(sim::makeStiffnessRigDriver()).ok());
  auto found = local.scanAll();
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].driver, "sim-hammer");
  EXPECT_EQ(found[0].busPath, "sim:0");
  EXPECT_EQ(found[0].label(), "Simulated impact hammer station (serial SIM-0001, sim:0)");
}

TEST(Capabilities, Usb1608FsPlusDeclaresItsHardware) {
  auto drv = mcc::makeUsb1608FsPlusDriver();
  auto dev = drv->create(DeviceDescriptor{"mcc-usb1608fsplus", "MCC USB-1608FS-Plus", 0x09DB, 0x00EA, "", ""});
  ASSERT_TRUE(dev.ok());
  const Capabilities caps = (*dev)->capabilities();
  ASSERT_EQ(caps.inputs.size(), 8u);
  EXPECT_EQ(caps.inputs[7].name, "AI7");
  ASSERT_EQ(caps.inputs[0].ranges.size(), 8u);
  EXPECT_DOUBLE_EQ(caps.inputs[0].ranges[7].maxVolts, 0.3125);
  EXPECT_FALSE(caps.inputs[0].iepeSupply);  // IEPE through external conditioners
  EXPECT_DOUBLE_EQ(caps.rates.maxHz, 100e3);
  EXPECT_DOUBLE_EQ(caps.rates.maxAggregateHz, 400e3);
  EXPECT_DOUBLE_EQ(caps.rates.timebaseHz, 40e6);
  EXPECT_EQ(caps.fifoSamples, 32768);
  // Configuring before open is refused with a clear message.
  auto cfg = (*dev)->configure(AcquisitionConfig{});
  ASSERT_FALSE(cfg.ok());
  EXPECT_NE(cfg.error().message.find("open"), std::string::npos);
}

AcquisitionConfig hammerConfig(double rate) {
  AcquisitionConfig c;
  c.sampleRateHz = rate;
  ChannelConfig f;
  f.input = 0;
  f.name = "hammer";
  f.transducer.kind = core::signal::TransducerKind::Force;
  f.transducer.sensitivityMvPerUnit = 2.25;
  f.transducer.unit = "N";
  c.channels.push_back(f);
  return c;
}

TEST(Configure, ValidatesAndReturnsAppliedConfiguration) {
  auto dev = sim::makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"});
  ASSERT_TRUE(dev.ok());
  ASSERT_TRUE((*dev)->open().ok());
  auto applied = (*dev)->configure(hammerConfig(2048.0));
  ASSERT_TRUE(applied.ok()) << applied.error().describe();
  EXPECT_DOUBLE_EQ(applied->sampleRateHz, 2048.0);
  EXPECT_EQ(applied->blockScans, 103);  // ceil(0.05 s x 2048 Hz)
  // Every declared parameter comes back with its default.
  EXPECT_EQ(std::get<std::string>(applied->parameters.at("hammer.tip")), "plastic");
  EXPECT_EQ(std::get<std::int64_t>(applied->parameters.at("sim.seed")), 1);

  auto tooFast = hammerConfig(1e6);
  auto e1 = (*dev)->configure(tooFast);
  ASSERT_FALSE(e1.ok());
  EXPECT_EQ(e1.error().where, "sample rate");

  auto badInput = hammerConfig(1000.0);
  badInput.channels[0].input = 9;
  auto e2 = (*dev)->configure(badInput);
  ASSERT_FALSE(e2.ok());
  EXPECT_NE(e2.error().message.find("does not exist"), std::string::npos);

  auto badParam = hammerConfig(1000.0);
  badParam.parameters["hammer.tip"] = std::string("wood");
  auto e3 = (*dev)->configure(badParam);
  ASSERT_FALSE(e3.ok());
  EXPECT_EQ(e3.error().where, "parameter hammer.tip");

  auto unknown = hammerConfig(1000.0);
  unknown.parameters["no.such"] = 1.0;
  EXPECT_FALSE((*dev)->configure(unknown).ok());

  auto outOfRange = hammerConfig(1000.0);
  outOfRange.parameters["fault.double_hit_probability"] = 1.5;
  EXPECT_FALSE((*dev)->configure(outOfRange).ok());
}

TEST(Configure, RateQuantisationOfA40MHzTimebase) {
  RateSpec spec{0.01, 100e3, 400e3, 40e6, true};
  // 40 MHz / 3000 Hz = 13333.33 -> divisor 13333 -> 3000.075 Hz.
  auto r = quantiseRate(spec, 3000.0);
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(*r, 40e6 / 13333.0);
  EXPECT_FALSE(quantiseRate(spec, 0.0).ok());
  EXPECT_FALSE(quantiseRate(spec, 200e3).ok());
}

TEST(Parameters, SpecsCarryTypeUnitRangeAndChoices) {
  auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
  const auto caps = (*dev)->capabilities();
  const ParameterSpec* freq = nullptr;
  for (const auto& p : caps.parameters)
    if (p.key == "sine.frequency") freq = &p;
  ASSERT_NE(freq, nullptr);
  EXPECT_EQ(freq->unit, "Hz");
  EXPECT_DOUBLE_EQ(*freq->min, 1.0);  // §1.1: sine 1 to 45 Hz
  EXPECT_DOUBLE_EQ(*freq->max, 45.0);
  ASSERT_EQ(caps.outputs.size(), 1u);
  EXPECT_DOUBLE_EQ(caps.outputs[0].max, 5000.0);  // §1.1: static load up to 5000 N
  EXPECT_EQ(caps.inputs.size(), 5u);              // load cell + four lasers
}

}  // namespace
}  // namespace mozzi::devices
