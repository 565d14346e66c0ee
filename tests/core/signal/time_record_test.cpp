// Time-record data model: validation and unit conversion.
#include "core/signal/time_record.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::signal {
namespace {

TimeRecord record() {
  TimeRecord r;
  r.sampleRateHz = 2048.0;
  r.preTriggerSamples = 16;
  r.channels.resize(2);
  // thesis §1.4: PCB 086C03 hammer, PCB M352C65 accelerometer 10 mV/(m/s^2)
  r.channels[0] = Channel{"hammer", Transducer{TransducerKind::Force, "PCB 086C03", "H1234", 2.25, "N", true},
                          Dof{21, Direction::Z, true}, 2200.0};
  r.channels[1] = Channel{"acc", Transducer{TransducerKind::Acceleration, "PCB M352C65", "A77", 10.0, "m/s^2", true},
                          Dof{21, Direction::Y, false}, 490.0};
  r.samples = Matrix::Zero(256, 2);
  return r;
}

TEST(TimeRecord, ValidRecordAndAccessors) {
  const TimeRecord r = record();
  EXPECT_TRUE(r.validate().ok());
  EXPECT_EQ(r.sampleCount(), 256);
  EXPECT_EQ(r.channelCount(), 2);
  EXPECT_DOUBLE_EQ(r.durationS(), 0.125);
  auto f = findForceChannel(r);
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(*f, 0);
  EXPECT_STREQ(transducerKindName(TransducerKind::Acceleration), "acceleration");
}

TEST(TimeRecord, VoltsToEngineeringUnits) {
  // 10 mV/(m/s^2): 0.5 V is 50 m/s^2
  Vector v(2);
  v << 0.5, -0.01;
  auto eu = engineeringFromVolts(v, record().channels[1].transducer);
  ASSERT_TRUE(eu.ok());
  EXPECT_DOUBLE_EQ((*eu)[0], 50.0);
  EXPECT_DOUBLE_EQ((*eu)[1], -1.0);
  Transducer bad;
  bad.sensitivityMvPerUnit = 0.0;
  EXPECT_FALSE(engineeringFromVolts(v, bad).ok());
}

TEST(TimeRecord, InvalidRecordsNameTheProblem) {
  TimeRecord r = record();
  r.sampleRateHz = 0.0;
  EXPECT_NE(r.validate().error().message.find("sample rate"), std::string::npos);
  r = record();
  r.samples.resize(0, 2);
  EXPECT_NE(r.validate().error().message.find("empty"), std::string::npos);
  r = record();
  r.samples.resize(256, 3);
  EXPECT_NE(r.validate().error().message.find("mismatched"), std::string::npos);
  r = record();
  r.preTriggerSamples = 300;
  EXPECT_FALSE(r.validate().ok());
  r = record();
  r.samples(9, 1) = std::nan("");
  const auto e = r.validate();
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().where.find("sample 9"), std::string::npos) << e.error().describe();
  EXPECT_NE(e.error().where.find("'acc'"), std::string::npos) << e.error().describe();
  r = record();
  r.channels[1].transducer.sensitivityMvPerUnit = -1.0;
  EXPECT_FALSE(r.validate().ok());
  r = record();
  r.channels.clear();
  EXPECT_FALSE(r.validate().ok());
  r = record();
  r.channels[1].transducer.kind = TransducerKind::Force;
  EXPECT_FALSE(findForceChannel(r).ok());
  r.channels[0].transducer.kind = TransducerKind::Other;
  r.channels[1].transducer.kind = TransducerKind::Other;
  EXPECT_EQ(findForceChannel(r).error().code, ErrorCode::NotFound);
}

}  // namespace
}  // namespace mozzi::core::signal
