// The calibration pipeline: code -> device calibration -> volts -> EU.
#include "devices/common/calibration.h"

#include <gtest/gtest.h>

namespace mozzi::devices {
namespace {

ChannelChain bipolar10(double sensitivity, double gain = 1.0) {
  ChannelChain c;
  c.range = InputRange{"+/-10 V", 0, -10.0, 10.0};
  c.conditionerGain = gain;
  c.transducer.sensitivityMvPerUnit = sensitivity;
  return c;
}

TEST(CalibrationPipeline, OffsetBinaryCodesToVolts) {
  auto c = bipolar10(1000.0);  // 1000 mV/EU: EU = volts
  // One LSB of +/-10 V over 16 bits is 20 V / 65536 = 305.17578125 uV (exact in binary).
  EXPECT_DOUBLE_EQ(c.voltsFromCode(32768), 0.0);
  EXPECT_DOUBLE_EQ(c.voltsFromCode(0), -10.0);
  EXPECT_DOUBLE_EQ(c.voltsFromCode(65535), 10.0 - 20.0 / 65536.0);
  EXPECT_DOUBLE_EQ(c.voltsFromCode(32769), 20.0 / 65536.0);
}

TEST(CalibrationPipeline, DeviceCalibrationRoundsAndClamps) {
  auto c = bipolar10(1000.0);
  c.calibration = DeviceCalibration{1.0002, -3.0};
  EXPECT_EQ(c.correctedCode(40000), 40005);  // 40000 * 1.0002 - 3 = 40005.0
  EXPECT_EQ(c.correctedCode(65535), 65535);  // 65545.1 clamps at the top code
  EXPECT_EQ(c.correctedCode(1), 0);          // -1.9998 clamps at 0
  EXPECT_TRUE(c.atFullScale(0));
  EXPECT_TRUE(c.atFullScale(65535));
  EXPECT_FALSE(c.atFullScale(65534));
}

TEST(CalibrationPipeline, SensitivityAndConditionerGain) {
  // PCB M352C65: 10 mV/(m/s^2) (thesis §1.4). 1 V at the DAQ with unit gain is
  // 100 m/s^2; behind a x10 conditioner it is 10 m/s^2.
  EXPECT_DOUBLE_EQ(bipolar10(10.0).engineeringFromVolts(1.0), 100.0);
  EXPECT_DOUBLE_EQ(bipolar10(10.0, 10.0).engineeringFromVolts(1.0), 10.0);
  // Hammer 2.25 mV/N on +/-10 V saturates at (10 V - 1 LSB) / 2.25 mV/N = 4444.3 N
  // (the top code 65535 reads 10 V - 20 V / 65536).
  EXPECT_NEAR(bipolar10(2.25).fullScaleEngineering(), (10.0 - 20.0 / 65536.0) * 1000.0 / 2.25, 1e-9);
}

TEST(CalibrationPipeline, InversePathReproducesValuesWithinOneLsb) {
  auto c = bipolar10(10.0);
  c.calibration = DeviceCalibration{1.0002, -3.0};
  const double lsbEu = c.engineeringFromVolts(20.0 / 65536.0);  // 0.0305 m/s^2
  for (double x : {-900.0, -12.345, 0.0, 0.5, 77.7, 999.0}) {
    const double back = c.engineeringFromRaw(c.rawFromEngineering(x));
    // Tolerance: half an LSB of quantisation plus at most one code where the
    // slope 1.0002 maps two raw codes onto neighbouring corrected codes.
    EXPECT_LE(std::abs(back - x), 1.5 * lsbEu) << x;
  }
  // Beyond full scale the code sticks at the end of the range.
  EXPECT_EQ(c.correctedCode(c.rawFromEngineering(5000.0)), 65535);
  EXPECT_EQ(c.correctedCode(c.rawFromEngineering(-5000.0)), 0);
}

TEST(CalibrationPipeline, ValidationNamesTheProblem) {
  auto c = bipolar10(0.0);
  auto r = validateChain(c, "channel 2 (hammer)");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "channel 2 (hammer)");
  EXPECT_NE(r.error().message.find("sensitivity"), std::string::npos);
  c = bipolar10(10.0, -1.0);
  EXPECT_FALSE(validateChain(c, "x").ok());
  c = bipolar10(10.0);
  c.calibration.slope = 0.0;
  EXPECT_FALSE(validateChain(c, "x").ok());
}

}  // namespace
}  // namespace mozzi::devices
