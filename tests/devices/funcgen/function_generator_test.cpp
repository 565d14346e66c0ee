// Function generator over SCPI, without USB: model profiles against the
// vendors' data-sheet figures, validation before anything is sent, the exact
// command sequence, and the read-back of what the instrument applied (the
// model keeps frequency to 1 uHz and amplitude to 0.1 mV).
#include "devices/funcgen/function_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../usbtmc/scpi_generator_model.h"

namespace mozzi::devices::funcgen {
namespace {

using devices::testing::ModelChannel;
using devices::testing::ScpiGeneratorModel;

const WaveformRange& rangeOf(const GeneratorCapabilities& c, Waveform w) {
  const WaveformRange* r = c.range(w);
  EXPECT_NE(r, nullptr);
  return *r;
}

TEST(FunctionGenerator, ProfilesFollowTheDataSheets) {
  // 33522B: two channels, 30 MHz sine, 200 kHz ramp, 20 Vpp / 10 V peak into high Z.
  auto k = capabilitiesFor({"Keysight Technologies", "33522B", "MY1", "1"});
  EXPECT_EQ(k.channels, 2);
  EXPECT_DOUBLE_EQ(rangeOf(k, Waveform::Sine).maxHz, 30e6);
  EXPECT_DOUBLE_EQ(rangeOf(k, Waveform::Ramp).maxHz, 200e3);
  EXPECT_DOUBLE_EQ(k.maxAmplitudeVpp, 20.0);
  EXPECT_DOUBLE_EQ(k.maxPeakV, 10.0);
  // 33511B: one channel, 20 MHz; Agilent-branded units use the same profile.
  auto a = capabilitiesFor({"Agilent Technologies", "33511B", "MY2", "1"});
  EXPECT_EQ(a.channels, 1);
  EXPECT_DOUBLE_EQ(rangeOf(a, Waveform::Sine).maxHz, 20e6);
  EXPECT_DOUBLE_EQ(rangeOf(capabilitiesFor({"Keysight Technologies", "33519B", "", ""}), Waveform::Sine).maxHz, 30e6);
  // DG1022Z: two channels, 25 MHz sine, 500 kHz ramp.
  auto r = capabilitiesFor({"Rigol Technologies", "DG1022Z", "DG1", "1"});
  EXPECT_EQ(r.channels, 2);
  EXPECT_DOUBLE_EQ(rangeOf(r, Waveform::Sine).maxHz, 25e6);
  EXPECT_DOUBLE_EQ(rangeOf(r, Waveform::Ramp).maxHz, 500e3);
  // Anything else: the conservative generic profile, still enough for the
  // actuator's 1 to 45 Hz sine.
  auto g = capabilitiesFor({"ACME", "FG-1", "0", "0"});
  EXPECT_EQ(g.channels, 1);
  EXPECT_NE(g.model.find("generic"), std::string::npos);
  EXPECT_LE(rangeOf(g, Waveform::Sine).minHz, 1.0);
  EXPECT_GE(rangeOf(g, Waveform::Sine).maxHz, 45.0);
}

TEST(FunctionGenerator, ValidationNamesFieldValueAndLimit) {
  const auto caps = capabilitiesFor({"Keysight Technologies", "33522B", "MY1", "1"});
  OutputSetting s;
  s.channel = 3;
  auto bad = validateSetting(caps, s);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().where, "channel");
  s.channel = 2;
  s.waveform = Waveform::Ramp;
  s.frequencyHz = 250e3;
  bad = validateSetting(caps, s);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message,
            "frequency 250000 Hz is outside 1e-06 .. 200000 Hz of the Keysight 33500B series (33522B)");
  s.frequencyHz = 10.0;
  s.amplitudeVpp = 10.0;
  s.offsetV = 6.0;  // 6 + 5 = 11 V peak
  bad = validateSetting(caps, s);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().where, "offset");
  EXPECT_NE(bad.error().message.find("reaches 11 V"), std::string::npos) << bad.error().message;
  s.offsetV = 5.0;  // exactly 10 V: allowed
  EXPECT_TRUE(validateSetting(caps, s).ok());
  s.frequencyHz = std::nan("");
  EXPECT_FALSE(validateSetting(caps, s).ok());
  OutputSetting dc;
  dc.waveform = Waveform::Dc;
  dc.offsetV = -3.0;
  auto okDc = validateSetting(caps, dc);
  ASSERT_TRUE(okDc.ok());
  EXPECT_EQ(okDc->amplitudeVpp, 0.0);
}

TEST(FunctionGenerator, CommandSequences) {
  OutputSetting sine;
  sine.channel = 1;
  sine.waveform = Waveform::Sine;
  sine.frequencyHz = 45.0;
  sine.amplitudeVpp = 4.0;
  EXPECT_EQ(settingCommands(sine),
            (std::vector<std::string>{"OUTP1:LOAD INF", "SOUR1:VOLT:OFFS 0", "SOUR1:FUNC SIN", "SOUR1:VOLT:UNIT VPP",
                                      "SOUR1:FREQ 45", "SOUR1:VOLT 4", "SOUR1:VOLT:OFFS 0"}));
  OutputSetting ramp;
  ramp.channel = 2;
  ramp.waveform = Waveform::Ramp;
  ramp.frequencyHz = 0.05;
  ramp.amplitudeVpp = 20.0;
  ramp.offsetV = 0.0;
  EXPECT_EQ(settingCommands(ramp), (std::vector<std::string>{"OUTP2:LOAD INF", "SOUR2:VOLT:OFFS 0", "SOUR2:FUNC RAMP",
                                                             "SOUR2:FUNC:RAMP:SYMM 50", "SOUR2:VOLT:UNIT VPP",
                                                             "SOUR2:FREQ 0.05", "SOUR2:VOLT 20", "SOUR2:VOLT:OFFS 0"}));
}

TEST(FunctionGenerator, ConfigureChecksEveryCommandAndReadsBack) {
  ScpiGeneratorModel model;
  ModelChannel channel(model);
  usbtmc::ScpiSession session(channel);
  FunctionGenerator gen(session, capabilitiesFor({"Keysight Technologies", "33522B", "MY1", "1"}));
  OutputSetting s;
  s.channel = 2;
  s.waveform = Waveform::Sine;
  s.frequencyHz = 12.3456789;   // the model keeps 1 uHz: 12.345679
  s.amplitudeVpp = 20.0 / 3.0;  // and 0.1 mV: 6.6667
  s.offsetV = 0.25;
  auto applied = gen.configure(s);
  ASSERT_TRUE(applied.ok()) << applied.error().describe();
  EXPECT_EQ(applied->waveform, Waveform::Sine);
  EXPECT_DOUBLE_EQ(applied->frequencyHz, 12.345679);
  EXPECT_DOUBLE_EQ(applied->amplitudeVpp, 6.6667);
  EXPECT_DOUBLE_EQ(applied->offsetV, 0.25);
  EXPECT_TRUE(model.channels[2].highZ);
  EXPECT_EQ(model.channels[1].function, "SIN");  // channel 1 untouched (default)
  EXPECT_DOUBLE_EQ(model.channels[1].frequency, 1000.0);
  // Each of the 7 commands is followed by one SYST:ERR? (no error), then the
  // four read-back queries.
  ASSERT_EQ(model.received.size(), 7u * 2u + 4u);
  for (std::size_t i = 1; i < 14; i += 2) EXPECT_EQ(model.received[i], "SYST:ERR?");
  EXPECT_EQ(model.received[8], "SOUR2:FREQ 12.3456789");
  EXPECT_EQ(model.received[10], "SOUR2:VOLT 6.666666667");
  EXPECT_EQ(model.received.back(), "SOUR2:VOLT?");
  ASSERT_TRUE(gen.setOutput(2, true).ok());
  EXPECT_TRUE(model.channels[2].output);
  EXPECT_FALSE(gen.setOutput(3, true).ok());
}

TEST(FunctionGenerator, InstrumentRejectionStopsTheSequence) {
  ScpiGeneratorModel model;
  ModelChannel channel(model);
  usbtmc::ScpiSession session(channel);
  // A profile wider than the instrument (as if the data sheet were misread):
  // 300 kHz passes validation, the instrument refuses it (200 kHz ramp).
  GeneratorCapabilities wide = capabilitiesFor({"Keysight Technologies", "33522B", "MY1", "1"});
  wide.waveforms[1].maxHz = 1e6;
  FunctionGenerator gen(session, wide);
  OutputSetting s;
  s.waveform = Waveform::Ramp;
  s.frequencyHz = 300e3;
  s.amplitudeVpp = 1.0;
  auto r = gen.configure(s);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "the instrument rejected \"SOUR1:FREQ 300000\": -222, Data out of range");
  // Nothing after the rejected command but its error-queue drain.
  EXPECT_EQ(std::count(model.received.begin(), model.received.end(), "SOUR1:VOLT 1"), 0);
  EXPECT_EQ(model.received[model.received.size() - 3], "SOUR1:FREQ 300000");
}

}  // namespace
}  // namespace mozzi::devices::funcgen
