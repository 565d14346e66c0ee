// The usbtmc-funcgen driver through the real libusb code path against the
// emulated 33522B of tests/devices/usbtmc/usbtmc_device_model.h: scan, open
// (profile from *IDN?, outputs off), the stiffness rig's sine and static ramp
// turned into the exact SCPI messages and Bulk-OUT bytes, the read-back that
// configure() returns, validation before anything is sent, start/stop as
// OUTP ON/OFF, and unplug while stopping.
#include "devices/funcgen/funcgen_driver.h"

#include <algorithm>

#include "../usbtmc/usbtmc_device_model.h"

namespace mozzi::devices::funcgen {
namespace {

using devices::testing::Bytes;
using devices::testing::UsbtmcDeviceModel;

struct ScpiGeneratorModelState {
  devices::testing::ScpiGeneratorModel::Channel ch1, ch2;
};

class FuncgenUmockdev : public devices::testing::UsbtmcTestbed {
 protected:
  void TearDown() override {
    device_.reset();  // closes (output off) while the emulated device is still attached
    UsbtmcTestbed::TearDown();
  }
  Device& openDevice() { return testing::openOnlyDevice(*makeFunctionGeneratorDriver(), device_); }
  static AcquisitionConfig sine(double hz, double newtons, double newtonsPerVolt) {
    AcquisitionConfig c;
    c.parameters = {{"mode", std::string("sine")},
                    {"sine.frequency", hz},
                    {"sine.amplitude", newtons},
                    {"actuator.newtons_per_volt", newtonsPerVolt}};
    return c;
  }
  // Messages the instrument received from index `from` on.
  std::vector<std::string> messagesFrom(std::size_t from) {
    const auto m = model_.log().messages;
    return std::vector<std::string>(m.begin() + static_cast<std::ptrdiff_t>(std::min(from, m.size())), m.end());
  }
  UsbtmcDeviceModel::Log log() { return model_.log(); }

  std::unique_ptr<Device> device_;
};

TEST_F(FuncgenUmockdev, ScanAndOpenIdentifyTheGeneratorAndSwitchItsOutputsOff) {
  auto found = makeFunctionGeneratorDriver()->scan();
  ASSERT_TRUE(found.ok()) << found.error().describe();
  ASSERT_EQ(found->size(), 1u);
  EXPECT_EQ((*found)[0].driver, "usbtmc-funcgen");
  EXPECT_EQ((*found)[0].model, "Keysight Technologies 33522B Waveform Generator");
  EXPECT_EQ((*found)[0].busPath, "usb:1.5");
  EXPECT_EQ((*found)[0].serial, "MY00000001");
  model_.with([](UsbtmcDeviceModel& m) { m.instrument.channels[2].output = true; });  // left on by someone else
  Device& dev = openDevice();
  EXPECT_EQ(dev.state(), DeviceState::Open);
  const Capabilities caps = dev.capabilities();
  EXPECT_EQ(caps.model, "Keysight 33500B series (33522B)");
  ASSERT_EQ(caps.outputs.size(), 3u);  // the force set-point and the two channels' voltages
  EXPECT_DOUBLE_EQ(caps.outputs[2].max, 10.0);
  EXPECT_TRUE(caps.inputs.empty());
  EXPECT_EQ(messagesFrom(0), (std::vector<std::string>{"*IDN?\n", "*CLS\n", "SOUR1:FUNC?\n", "SYST:ERR?\n",
                                                       "OUTP1 OFF\n", "SYST:ERR?\n", "OUTP2 OFF\n", "SYST:ERR?\n"}));
  bool out2 = true;
  model_.with([&](UsbtmcDeviceModel& m) { out2 = m.instrument.channels[2].output; });
  EXPECT_FALSE(out2);
}

TEST_F(FuncgenUmockdev, AnInstrumentThatIsNoGeneratorIsRefusedAndNothingStaysOpen) {
  model_.with([](UsbtmcDeviceModel& m) {
    m.instrument.generator = false;
    m.instrument.idn = "Keysight Technologies,34465A,MY00000002,A.03.01";  // a DMM
  });
  auto dev = makeFunctionGeneratorDriver()->create(makeFunctionGeneratorDriver()->scan()->front());
  ASSERT_TRUE(dev.ok());
  auto r = (*dev)->open();
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, core::ErrorCode::Unsupported);
  EXPECT_EQ(
      r.error().message,
      "Keysight Technologies 34465A does not know SOUR1:FUNC?: not a function generator (-113, Undefined header)");
  EXPECT_EQ((*dev)->state(), DeviceState::Closed);
  EXPECT_FALSE((*dev)->open().ok());  // tried again from scratch, not "already open"
  const auto log = model_.log();
  EXPECT_EQ(std::count(log.messages.begin(), log.messages.end(), "OUTP1 OFF\n"), 0);
}

TEST_F(FuncgenUmockdev, SineConfigureAndOutputOnWithExactBytes) {
  Device& dev = openDevice();
  const std::size_t before = log().messages.size();
  // 45 Hz, 2000 N at 500 N/V: 8 Vpp (2 x 2000 / 500), no offset.
  auto applied = dev.configure(sine(45.0, 2000.0, 500.0));
  ASSERT_TRUE(applied.ok()) << applied.error().describe();
  EXPECT_EQ(dev.state(), DeviceState::Configured);
  EXPECT_EQ(messagesFrom(before),
            (std::vector<std::string>{"OUTP1:LOAD INF\n", "SYST:ERR?\n", "SOUR1:VOLT:OFFS 0\n", "SYST:ERR?\n",
                                      "SOUR1:FUNC SIN\n", "SYST:ERR?\n", "SOUR1:VOLT:UNIT VPP\n", "SYST:ERR?\n",
                                      "SOUR1:FREQ 45\n", "SYST:ERR?\n", "SOUR1:VOLT 8\n", "SYST:ERR?\n",
                                      "SOUR1:VOLT:OFFS 0\n", "SYST:ERR?\n", "SOUR1:FUNC?\n", "SOUR1:VOLT:OFFS?\n",
                                      "SOUR1:FREQ?\n", "SOUR1:VOLT?\n"}));
  EXPECT_DOUBLE_EQ(std::get<double>(applied->parameters.at("sine.frequency")), 45.0);
  EXPECT_DOUBLE_EQ(std::get<double>(applied->parameters.at("sine.amplitude")), 2000.0);
  const std::size_t transfersBefore = log().bulkOut.size();
  StreamCollector col;
  ASSERT_TRUE(dev.start(col.sink()).ok());
  EXPECT_EQ(dev.state(), DeviceState::Running);
  ASSERT_TRUE(col.header().has_value());
  EXPECT_EQ(col.header()->device, "Keysight Technologies 33522B (serial MY00000001, usb:1.5)");
  // "OUTP1 ON\n": 12-byte header (MsgID 1, bTag, ~bTag, 0, TransferSize 9,
  // EOM), 9 bytes, 3 alignment bytes.
  const Bytes on = log().bulkOut.at(transfersBefore);
  ASSERT_EQ(on.size(), 24u);
  EXPECT_EQ(on[0], 0x01);
  EXPECT_EQ(static_cast<std::uint8_t>(on[1] ^ on[2]), 0xFF);
  EXPECT_EQ(Bytes(on.begin() + 3, on.end()), (Bytes{0x00, 0x09, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 'O', 'U',
                                                    'T',  'P',  '1',  ' ',  'O',  'N',  '\n', 0x00, 0x00, 0x00}));
  ScpiGeneratorModelState state;
  model_.with([&](UsbtmcDeviceModel& m) { state = {m.instrument.channels[1], m.instrument.channels[2]}; });
  EXPECT_TRUE(state.ch1.output);
  EXPECT_TRUE(state.ch1.highZ);
  EXPECT_EQ(state.ch1.function, "SIN");
  EXPECT_DOUBLE_EQ(state.ch1.frequency, 45.0);
  EXPECT_DOUBLE_EQ(state.ch1.amplitude, 8.0);
  EXPECT_FALSE(state.ch2.output);
  dev.stop();
  ASSERT_TRUE(col.end().has_value());
  EXPECT_EQ(col.end()->reason, EndReason::Stopped);
  EXPECT_EQ(messagesFrom(log().messages.size() - 2), (std::vector<std::string>{"OUTP1 OFF\n", "SYST:ERR?\n"}));
  model_.with([&](UsbtmcDeviceModel& m) { state.ch1 = m.instrument.channels[1]; });
  EXPECT_FALSE(state.ch1.output);
}

TEST_F(FuncgenUmockdev, StaticRampIsATriangleOverThePeriod) {
  Device& dev = openDevice();
  AcquisitionConfig c;
  // 5000 N peak (§1.1) at 500 N/V: 20 Vpp; 20 s period: 0.05 Hz; channel 2.
  c.parameters = {{"mode", std::string("static-ramp")},
                  {"static.max_force", 5000.0},
                  {"static.period_s", 20.0},
                  {"channel", std::int64_t{2}}};
  auto applied = dev.configure(c);
  ASSERT_TRUE(applied.ok()) << applied.error().describe();
  EXPECT_DOUBLE_EQ(std::get<double>(applied->parameters.at("static.period_s")), 20.0);
  EXPECT_DOUBLE_EQ(std::get<double>(applied->parameters.at("static.max_force")), 5000.0);
  devices::testing::ScpiGeneratorModel::Channel ch2;
  model_.with([&](UsbtmcDeviceModel& m) { ch2 = m.instrument.channels[2]; });
  EXPECT_EQ(ch2.function, "RAMP");
  EXPECT_DOUBLE_EQ(ch2.symmetry, 50.0);
  EXPECT_DOUBLE_EQ(ch2.frequency, 0.05);
  EXPECT_DOUBLE_EQ(ch2.amplitude, 20.0);
  EXPECT_DOUBLE_EQ(ch2.offset, 0.0);
  StreamCollector col;
  ASSERT_TRUE(dev.start(col.sink()).ok());
  model_.with([&](UsbtmcDeviceModel& m) { ch2 = m.instrument.channels[2]; });
  EXPECT_TRUE(ch2.output);
  dev.close();  // close while running: output off, stream ended
  model_.with([&](UsbtmcDeviceModel& m) { ch2 = m.instrument.channels[2]; });
  EXPECT_FALSE(ch2.output);
  ASSERT_TRUE(col.end().has_value());
  EXPECT_EQ(col.end()->reason, EndReason::Stopped);
}

TEST_F(FuncgenUmockdev, ConfigureReturnsWhatTheInstrumentApplied) {
  Device& dev = openDevice();
  // 1000 N at 300 N/V: 6.666666667 Vpp asked, the instrument keeps 0.1 mV:
  // 6.6667 Vpp, i.e. 6.6667 x 300 / 2 = 1000.005 N applied.
  auto applied = dev.configure(sine(12.5, 1000.0, 300.0));
  ASSERT_TRUE(applied.ok()) << applied.error().describe();
  EXPECT_DOUBLE_EQ(std::get<double>(applied->parameters.at("sine.amplitude")), 6.6667 * 300.0 / 2.0);
  EXPECT_DOUBLE_EQ(std::get<double>(applied->parameters.at("sine.frequency")), 12.5);
}

TEST_F(FuncgenUmockdev, OutOfRangeSetPointIsRefusedBeforeAnythingIsSent) {
  Device& dev = openDevice();
  const std::size_t before = log().bulkOut.size();
  // 5000 N at 200 N/V needs 50 Vpp; the 33522B gives 20 Vpp into high Z.
  AcquisitionConfig c;
  c.parameters = {{"static.max_force", 5000.0}, {"actuator.newtons_per_volt", 200.0}};
  auto r = dev.configure(c);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "parameter static.max_force");
  EXPECT_NE(r.error().message.find("amplitude 50 Vpp is outside 0.002 .. 20 Vpp"), std::string::npos)
      << r.error().message;
  auto freq = dev.configure(sine(50.0, 100.0, 500.0));  // the rig's sine stops at 45 Hz
  ASSERT_FALSE(freq.ok());
  EXPECT_EQ(freq.error().where, "parameter sine.frequency");
  AcquisitionConfig withChannel = sine(10.0, 100.0, 500.0);
  withChannel.channels.push_back(ChannelConfig{});
  EXPECT_FALSE(dev.configure(withChannel).ok());
  EXPECT_EQ(log().bulkOut.size(), before);
  EXPECT_FALSE(dev.start(StreamCollector().sink()).ok());  // not configured
}

TEST_F(FuncgenUmockdev, UnplugWhileStoppingEndsTheStreamAsDisconnected) {
  Device& dev = openDevice();
  ASSERT_TRUE(dev.configure(sine(10.0, 500.0, 500.0)).ok());
  StreamCollector col;
  ASSERT_TRUE(dev.start(col.sink()).ok());
  model_.with([](UsbtmcDeviceModel& m) { m.unplugOn = "SYST:ERR?"; });  // gone while OUTP1 OFF is checked
  const auto t0 = std::chrono::steady_clock::now();
  dev.stop();
  ASSERT_TRUE(col.end().has_value());
  EXPECT_EQ(col.end()->reason, EndReason::Disconnected);
  EXPECT_NE(col.end()->message.find("unplugged"), std::string::npos) << col.end()->message;
  dev.close();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(3));  // nothing hangs
  EXPECT_EQ(dev.state(), DeviceState::Closed);
}

TEST_F(FuncgenUmockdev, HotplugRemovalEndsARunningOutputAtOnce) {
  // No transfer is in flight while the output runs: only the kernel's
  // "remove" uevent, seen by libusb's hotplug monitor on the transport's
  // event thread, can tell; the stream must end without waiting for stop().
  Device& dev = openDevice();
  ASSERT_TRUE(dev.configure(sine(10.0, 500.0, 500.0)).ok());
  StreamCollector col;
  ASSERT_TRUE(dev.start(col.sink()).ok());
  umockdev_testbed_uevent(testbed_, sysPath_, "remove");
  umockdev_testbed_remove_device(testbed_, sysPath_);
  ASSERT_TRUE(col.waitForEnd(std::chrono::seconds(10))) << "the hotplug callback must end the stream";
  EXPECT_EQ(col.end()->reason, EndReason::Disconnected);
  EXPECT_EQ(col.end()->message,
            "the instrument was unplugged (Keysight Technologies 33522B (serial MY00000001, usb:1.5))");
  EXPECT_EQ(dev.state(), DeviceState::Open);
  const auto t0 = std::chrono::steady_clock::now();
  dev.stop();  // already ended: nothing more is sent or emitted
  dev.close();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
}

}  // namespace
}  // namespace mozzi::devices::funcgen
