// UsbtmcTransport and ScpiSession through the real libusb code path against
// the USBTMC instrument emulated in usbtmc_device_model.h: discovery by
// interface class, the exact Bulk-OUT bytes of a query, class requests, the
// status byte on Interrupt-IN, Bulk-IN and Bulk-OUT timeouts with their abort
// sequences and the session usable afterwards, and unplug as a clean error.
#include "devices/usbtmc/usbtmc_transport.h"

#include <chrono>

#include "usbtmc_device_model.h"

namespace mozzi::devices::usbtmc {
namespace {

using namespace std::chrono_literals;
using devices::testing::Bytes;
using devices::testing::UsbtmcDeviceModel;

class UsbtmcUmockdev : public devices::testing::UsbtmcTestbed {
 protected:
  std::unique_ptr<UsbtmcTransport> open() {
    auto t = UsbtmcTransport::open("");
    EXPECT_TRUE(t.ok()) << t.error().describe();
    return t.ok() ? std::move(*t) : nullptr;
  }
};

TEST_F(UsbtmcUmockdev, EnumerateFindsOnlyTheUsbtmcInterface) {
  auto found = UsbtmcTransport::enumerate();
  ASSERT_TRUE(found.ok()) << found.error().describe();
  ASSERT_EQ(found->size(), 1u);  // the vendor-class device at usb:1.2 is not an instrument
  const auto& i = (*found)[0];
  EXPECT_EQ(i.usb.busPath(), "usb:1.5");
  EXPECT_EQ(i.usb.vendorId, 0x0957);
  EXPECT_EQ(i.usb.productId, 0x2C07);
  EXPECT_EQ(i.usb.serial, "MY00000001");
  EXPECT_EQ(i.manufacturer, "Keysight Technologies");
  EXPECT_EQ(i.product, "33522B Waveform Generator");
  EXPECT_EQ(i.interfaceNumber, 0);
  EXPECT_EQ(i.protocol, kProtocolUsb488);
  EXPECT_EQ(i.bulkOut, 0x02);
  EXPECT_EQ(i.bulkIn, 0x81);
  EXPECT_EQ(i.interruptIn, 0x83);
}

TEST_F(UsbtmcUmockdev, OpenReadsCapabilitiesAndClearsTheDevice) {
  auto t = open();
  ASSERT_TRUE(t);
  EXPECT_EQ(t->capabilities().bcdUsbtmc, 0x0100);
  EXPECT_TRUE(t->capabilities().scpi);
  const auto log = model_.log();
  // GET_CAPABILITIES, INITIATE_CLEAR, CHECK_CLEAR_STATUS, then the Bulk-OUT halt cleared.
  ASSERT_EQ(log.classRequests.size(), 3u);
  EXPECT_EQ(log.classRequests[0].first, kGetCapabilities);
  EXPECT_EQ(log.classRequests[1].first, kInitiateClear);
  EXPECT_EQ(log.classRequests[2].first, kCheckClearStatus);
  EXPECT_EQ(log.clearHalts, (std::vector<unsigned>{0x02}));
  EXPECT_FALSE(UsbtmcTransport::open("usb:1.2").ok());  // no USBTMC interface there
}

TEST_F(UsbtmcUmockdev, IdnRoundTripWithExactBytes) {
  auto t = open();
  ASSERT_TRUE(t);
  ScpiSession s(*t);
  auto id = s.identify();
  ASSERT_TRUE(id.ok()) << id.error().describe();
  EXPECT_EQ(id->manufacturer, "Keysight Technologies");
  EXPECT_EQ(id->model, "33522B");
  const auto log = model_.log();
  ASSERT_EQ(log.bulkOut.size(), 2u);
  // DEV_DEP_MSG_OUT bTag 1 "*IDN?\n" + 2 alignment bytes; then
  // REQUEST_DEV_DEP_MSG_IN bTag 2 for 4084 bytes (0x0FF4).
  EXPECT_EQ(log.bulkOut[0], (Bytes{0x01, 0x01, 0xFE, 0x00, 0x06, 0x00, 0x00, 0x00, 0x01, 0x00,
                                   0x00, 0x00, '*',  'I',  'D',  'N',  '?',  '\n', 0x00, 0x00}));
  EXPECT_EQ(log.bulkOut[1], (Bytes{0x02, 0x02, 0xFD, 0x00, 0xF4, 0x0F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(log.protocolErrors, 0);
}

TEST_F(UsbtmcUmockdev, LongAnswerComesInSeveralTransfers) {
  UsbtmcOptions o;
  o.maxTransferData = 16;  // force the answer (61 bytes + newline) into four transfers
  auto t = UsbtmcTransport::open("", o);
  ASSERT_TRUE(t.ok()) << t.error().describe();
  ScpiSession s(**t);
  auto idn = s.query("*IDN?");
  ASSERT_TRUE(idn.ok()) << idn.error().describe();
  EXPECT_EQ(*idn, "Keysight Technologies,33522B,MY00000001,4.00-1.19-2.00-58-00");
  const auto log = model_.log();
  ASSERT_EQ(log.bulkOut.size(), 1u + 4u);  // the query, then one REQUEST_DEV_DEP_MSG_IN per transfer
  for (std::size_t i = 1; i < 5; ++i) EXPECT_EQ(log.bulkOut[i][0], kRequestDevDepMsgIn);
}

TEST_F(UsbtmcUmockdev, CommonCommandsAndErrorQueue) {
  auto t = open();
  ASSERT_TRUE(t);
  ScpiSession s(*t);
  ASSERT_TRUE(s.reset().ok());
  ASSERT_TRUE(s.waitComplete().ok());
  auto r = s.command("SOUR1:VOLT 30");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "the instrument rejected \"SOUR1:VOLT 30\": -222, Data out of range");
  EXPECT_EQ(r.error().where, "usbtmc usb:1.5");
  const auto log = model_.log();
  EXPECT_EQ(log.messages, (std::vector<std::string>{"*RST\n", "*OPC?\n", "*OPC?\n", "SOUR1:VOLT 30\n", "SYST:ERR?\n",
                                                    "SYST:ERR?\n"}));
}

TEST_F(UsbtmcUmockdev, StatusByteComesOnInterruptIn) {
  auto t = open();
  ASSERT_TRUE(t);
  auto clean = t->readStatusByte();
  ASSERT_TRUE(clean.ok()) << clean.error().describe();
  EXPECT_EQ(*clean, 0x00);
  ScpiSession s(*t);
  ASSERT_TRUE(s.write("BOGUS").ok());  // an error in the queue: EAV, bit 2
  ASSERT_TRUE(s.write("*IDN?").ok());  // an answer waiting: MAV bit 4
  auto stb = t->readStatusByte();
  ASSERT_TRUE(stb.ok()) << stb.error().describe();
  EXPECT_EQ(*stb, 0x14);
  const auto log = model_.log();
  EXPECT_EQ(log.classRequests.back().first, kReadStatusByte);
  EXPECT_EQ(log.classRequests.back().second, 3);  // second READ_STATUS_BYTE: bTag 3 (2..127)
}

TEST_F(UsbtmcUmockdev, ReadTimeoutAbortsTheRequestAndTheSessionGoesOn) {
  auto t = open();
  ASSERT_TRUE(t);
  ScpiSession s(*t, 300);
  const auto t0 = std::chrono::steady_clock::now();
  auto r = s.query("SILENT?");
  const auto elapsed = std::chrono::steady_clock::now() - t0;
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "\"SILENT?\": no answer within 300 ms (transfer aborted)");
  EXPECT_GE(elapsed, 290ms);  // libusb's timer, not an early give-up
  EXPECT_LT(elapsed, 5s);
  auto log = model_.log();
  EXPECT_GE(log.discards, 1);  // libusb cancelled the Bulk-IN URB
  // INITIATE_ABORT_BULK_IN with the request's bTag (the query had 1, the
  // request 2), the short packet read, CHECK_ABORT_BULK_IN_STATUS success.
  const auto n = log.classRequests.size();
  ASSERT_GE(n, 2u);
  EXPECT_EQ(log.classRequests[n - 2], (std::pair<int, int>{kInitiateAbortBulkIn, 2}));
  EXPECT_EQ(log.classRequests[n - 1].first, kCheckAbortBulkInStatus);
  auto id = s.identify();
  ASSERT_TRUE(id.ok()) << id.error().describe();
  EXPECT_EQ(id->model, "33522B");
}

TEST_F(UsbtmcUmockdev, WriteTimeoutAbortsTheTransferAndClearsTheHalt) {
  auto t = open();
  ASSERT_TRUE(t);
  ScpiSession s(*t, 200);
  const std::size_t halts = model_.log().clearHalts.size();  // one from the clear on open
  model_.with([](UsbtmcDeviceModel& m) { m.holdBulkOut = true; });
  auto r = s.write("SOUR1:FREQ 10");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            "\"SOUR1:FREQ 10\": the instrument did not accept the message within 200 ms (transfer aborted)");
  auto log = model_.log();
  const auto n = log.classRequests.size();
  ASSERT_GE(n, 2u);
  EXPECT_EQ(log.classRequests[n - 2], (std::pair<int, int>{kInitiateAbortBulkOut, 1}));
  EXPECT_EQ(log.classRequests[n - 1].first, kCheckAbortBulkOutStatus);
  // CLEAR_FEATURE(ENDPOINT_HALT) on Bulk-OUT after the abort.
  EXPECT_EQ(std::vector<unsigned>(log.clearHalts.begin() + static_cast<std::ptrdiff_t>(halts), log.clearHalts.end()),
            (std::vector<unsigned>{0x02}));
  ASSERT_TRUE(s.command("SOUR1:FREQ 10").ok());
  double f = 0.0;
  model_.with([&](UsbtmcDeviceModel& m) { f = m.instrument.channels[1].frequency; });
  EXPECT_DOUBLE_EQ(f, 10.0);
}

TEST_F(UsbtmcUmockdev, UnplugMidQueryIsACleanErrorAndNothingHangs) {
  auto t = open();
  ASSERT_TRUE(t);
  ScpiSession s(*t, 5000);
  model_.with([](UsbtmcDeviceModel& m) { m.unplugOn = "SILENT?"; });
  const auto t0 = std::chrono::steady_clock::now();
  auto r = s.query("SILENT?");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, core::ErrorCode::NotFound);
  EXPECT_EQ(r.error().message, "\"SILENT?\": the instrument was unplugged (Bulk-IN transfer failed)");
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 3s);  // ended by the unplug, not the 5 s timeout
  EXPECT_TRUE(t->disconnected());
  auto again = s.identify();
  ASSERT_FALSE(again.ok());
  EXPECT_EQ(again.error().message, "\"*IDN?\": the instrument was unplugged");
  const auto t1 = std::chrono::steady_clock::now();
  t.reset();
  EXPECT_LT(std::chrono::steady_clock::now() - t1, 2s);
}

}  // namespace
}  // namespace mozzi::devices::usbtmc
