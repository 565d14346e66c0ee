// USBTMC/USB488 codec against the byte layouts of the USBTMC 1.0 and USB488
// 1.0 specifications (expected bytes written out by hand from the tables of
// the header comment in devices/usbtmc/usbtmc_protocol.h, not produced by the
// code under test).
#include "devices/usbtmc/usbtmc_protocol.h"

#include <gtest/gtest.h>

namespace mozzi::devices::usbtmc {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes bytesOf(const std::string& s) {
  return Bytes(s.begin(), s.end());
}

Bytes concat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// A Bulk-IN DEV_DEP_MSG_IN transfer as an instrument sends it.
Bytes bulkIn(std::uint8_t tag, const std::string& data, bool eom, std::size_t padding) {
  Bytes b = {2,
             tag,
             static_cast<std::uint8_t>(~tag),
             0,
             static_cast<std::uint8_t>(data.size()),
             0,
             0,
             0,
             static_cast<std::uint8_t>(eom ? 1 : 0),
             0,
             0,
             0};
  b = concat(b, bytesOf(data));
  b.resize(b.size() + padding, 0);
  return b;
}

TEST(UsbtmcProtocol, DevDepMsgOutHeaderPaddingAndEom) {
  // "*IDN?\n", bTag 1: 12-byte header, 6 data bytes, 2 alignment bytes (20 = 5 x 4).
  const std::string idn = "*IDN?\n";
  const Bytes expected = {0x01, 0x01, 0xFE, 0x00, 0x06, 0x00, 0x00, 0x00, 0x01, 0x00,
                          0x00, 0x00, '*',  'I',  'D',  'N',  '?',  '\n', 0x00, 0x00};
  EXPECT_EQ(encodeDevDepMsgOut(1, reinterpret_cast<const std::uint8_t*>(idn.data()), idn.size(), true), expected);
  // Four data bytes need no padding; EOM clear; a large TransferSize little-endian.
  const std::string four = "ABCD";
  const Bytes noPad = encodeDevDepMsgOut(0x80, reinterpret_cast<const std::uint8_t*>(four.data()), 4, false);
  EXPECT_EQ(noPad.size(), 16u);
  EXPECT_EQ(noPad[1], 0x80);
  EXPECT_EQ(noPad[2], 0x7F);
  EXPECT_EQ(noPad[8], 0x00);
  const std::string big(0x10203, 'x');
  const Bytes large = encodeDevDepMsgOut(5, reinterpret_cast<const std::uint8_t*>(big.data()), big.size(), true);
  EXPECT_EQ((Bytes{large[4], large[5], large[6], large[7]}), (Bytes{0x03, 0x02, 0x01, 0x00}));
  EXPECT_EQ(large.size(), 12u + 0x10203u + 1u);  // 0x1020F rounded up to 0x10210
}

TEST(UsbtmcProtocol, TagsSkipZeroAndStatusTagsStayIn2To127) {
  EXPECT_EQ(nextTag(1), 2);
  EXPECT_EQ(nextTag(254), 255);
  EXPECT_EQ(nextTag(255), 1);  // bTag 0 is not allowed
  EXPECT_EQ(nextTag(0), 1);
  EXPECT_EQ(nextStatusTag(126), 127);
  EXPECT_EQ(nextStatusTag(127), 2);
  EXPECT_EQ(nextStatusTag(0), 2);
}

TEST(UsbtmcProtocol, LongMessagesAreSplitWithEomOnTheLast) {
  std::uint8_t tag = 254;
  const auto transfers = encodeMessage(tag, "0123456789", 4);
  ASSERT_EQ(transfers.size(), 3u);
  EXPECT_EQ(transfers[0][1], 255);
  EXPECT_EQ(transfers[1][1], 1);  // wraps past 0
  EXPECT_EQ(transfers[2][1], 2);
  EXPECT_EQ(tag, 2);
  EXPECT_EQ(transfers[0][8], 0);
  EXPECT_EQ(transfers[1][8], 0);
  EXPECT_EQ(transfers[2][8], 1);
  EXPECT_EQ(transfers[2][4], 2);  // "89"
  EXPECT_EQ(transfers[2].size(), 16u);
  std::uint8_t t = 0;
  const auto empty = encodeMessage(t, "", 100);
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_EQ(empty[0], (Bytes{1, 1, 0xFE, 0, 0, 0, 0, 0, 1, 0, 0, 0}));
}

TEST(UsbtmcProtocol, RequestDevDepMsgIn) {
  EXPECT_EQ(encodeRequestDevDepMsgIn(2, 4084),
            (Bytes{0x02, 0x02, 0xFD, 0x00, 0xF4, 0x0F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(encodeRequestDevDepMsgIn(7, 64, std::uint8_t{'\n'}),
            (Bytes{0x02, 0x07, 0xF8, 0x00, 0x40, 0x00, 0x00, 0x00, 0x02, 0x0A, 0x00, 0x00}));
}

TEST(UsbtmcProtocol, BulkInHeaderChecks) {
  const Bytes good = bulkIn(9, "1\n", true, 2);
  auto h = parseBulkInHeader(good.data(), good.size(), 9, 100);
  ASSERT_TRUE(h.ok()) << h.error().describe();
  EXPECT_EQ(h->transferSize, 2u);
  EXPECT_TRUE(h->eom);
  EXPECT_FALSE(h->termChar);

  auto wrongTag = parseBulkInHeader(good.data(), good.size(), 10, 100);
  ASSERT_FALSE(wrongTag.ok());
  EXPECT_NE(wrongTag.error().message.find("bTag 0x09 does not match the request's bTag 0x0A"), std::string::npos)
      << wrongTag.error().message;
  Bytes badInverse = good;
  badInverse[2] = 0x00;
  EXPECT_FALSE(parseBulkInHeader(badInverse.data(), badInverse.size(), 9, 100).ok());
  Bytes badId = good;
  badId[0] = 1;
  EXPECT_NE(parseBulkInHeader(badId.data(), badId.size(), 9, 100).error().message.find("MsgID"), std::string::npos);
  EXPECT_FALSE(parseBulkInHeader(good.data(), 11, 9, 100).ok());
  auto tooBig = parseBulkInHeader(good.data(), good.size(), 9, 1);
  ASSERT_FALSE(tooBig.ok());
  EXPECT_NE(tooBig.error().message.find("exceeds the 1 bytes requested"), std::string::npos);
}

TEST(UsbtmcProtocol, AssemblerJoinsTransfersAndContinuedReads) {
  ResponseAssembler a;
  // Transfer 1: 5 bytes, no EOM, split over two reads (header + 3, then 2 + 3 padding).
  a.expect(3, 5);
  const Bytes t1 = bulkIn(3, "ABCDE", false, 3);
  auto s = a.feed(t1.data(), 15);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(*s, ResponseAssembler::Step::NeedMoreData);
  s = a.feed(t1.data() + 15, t1.size() - 15);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_EQ(*s, ResponseAssembler::Step::TransferDone);
  // Transfer 2, new tag: "FG\n" with EOM.
  a.expect(4, 5);
  const Bytes t2 = bulkIn(4, "FG\n", true, 1);
  s = a.feed(t2.data(), t2.size());
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_EQ(*s, ResponseAssembler::Step::MessageDone);
  EXPECT_EQ(a.text(), "ABCDEFG\n");
  EXPECT_EQ(a.transfers(), 2);
}

TEST(UsbtmcProtocol, AssemblerRejectsWhatWouldConfuseTheHost) {
  ResponseAssembler a(8);
  const Bytes t = bulkIn(1, "x", true, 3);
  EXPECT_FALSE(a.feed(t.data(), t.size()).ok());  // no request outstanding
  a.expect(2, 100);
  EXPECT_FALSE(a.feed(t.data(), t.size()).ok());  // answer to another request
  a.expect(1, 100);
  Bytes extra = t;
  extra.resize(extra.size() + 4, 0);  // more than the alignment bytes
  EXPECT_FALSE(a.feed(extra.data(), extra.size()).ok());
  ResponseAssembler small(8);
  small.expect(1, 100);
  const Bytes big = bulkIn(1, "123456789", true, 3);
  auto s = small.feed(big.data(), big.size());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("longer than 8 bytes"), std::string::npos);
  ResponseAssembler empty;
  empty.expect(1, 100);
  const Bytes nothing = bulkIn(1, "", false, 0);
  EXPECT_FALSE(empty.feed(nothing.data(), nothing.size()).ok());  // would loop forever
  ResponseAssembler cut;
  cut.expect(1, 100);
  const Bytes part = bulkIn(1, "ABCDEFGH", true, 0);
  ASSERT_TRUE(cut.feed(part.data(), 14).ok());
  EXPECT_FALSE(cut.feed(part.data(), 0).ok());  // zero-length read inside the transfer
}

TEST(UsbtmcProtocol, ClassRequestSetups) {
  // bmRequestType 0xA2: device-to-host, class, endpoint; 0xA1: ... interface.
  auto s = initiateAbortBulkOut(0x11, 0x02);
  EXPECT_EQ((Bytes{s.requestType, s.request}), (Bytes{0xA2, 1}));
  EXPECT_EQ(s.value, 0x11);
  EXPECT_EQ(s.index, 0x02);
  EXPECT_EQ(s.length, 2);
  s = checkAbortBulkOutStatus(0x02);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.length)}), (Bytes{0xA2, 2, 8}));
  s = initiateAbortBulkIn(0x12, 0x81);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.value), static_cast<std::uint8_t>(s.index)}),
            (Bytes{0xA2, 3, 0x12, 0x81}));
  s = checkAbortBulkInStatus(0x81);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.length)}), (Bytes{0xA2, 4, 8}));
  s = initiateClear(0);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.length)}), (Bytes{0xA1, 5, 1}));
  s = checkClearStatus(0);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.length)}), (Bytes{0xA1, 6, 2}));
  s = getCapabilities(1);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.index), static_cast<std::uint8_t>(s.length)}),
            (Bytes{0xA1, 7, 1, 0x18}));
  s = readStatusByte(0x42, 0);
  EXPECT_EQ((Bytes{s.requestType, s.request, static_cast<std::uint8_t>(s.value), static_cast<std::uint8_t>(s.length)}),
            (Bytes{0xA1, 128, 0x42, 3}));
  EXPECT_EQ(classRequestName(kCheckClearStatus), "CHECK_CLEAR_STATUS");
}

TEST(UsbtmcProtocol, ClassRequestAnswers) {
  auto abort = parseAbortAnswer({0x01, 0x11});
  ASSERT_TRUE(abort.ok());
  EXPECT_EQ(abort->status, 0x01);
  EXPECT_EQ(abort->tag, 0x11);
  EXPECT_FALSE(parseAbortAnswer({0x01}).ok());
  // CHECK_ABORT_BULK_IN_STATUS: pending, bmAbortBulkIn.D0 = 1, NBYTES_TXD = 0x00012345.
  auto check = parseCheckAbortAnswer({0x02, 0x01, 0, 0, 0x45, 0x23, 0x01, 0x00});
  ASSERT_TRUE(check.ok());
  EXPECT_EQ(statusName(check->status), "pending");
  EXPECT_TRUE(check->bulkInFifoHasData);
  EXPECT_EQ(check->bytes, 0x12345u);
  auto clear = parseCheckClearAnswer({0x01, 0x00});
  ASSERT_TRUE(clear.ok());
  EXPECT_FALSE(clear->bulkInFifoHasData);
  EXPECT_FALSE(parseCheckClearAnswer({0x01}).ok());
  EXPECT_EQ(statusName(0x80), "failed");
  EXPECT_EQ(statusName(0x81), "transfer not in progress");
  EXPECT_EQ(statusName(0x55), "unknown status 0x55");
  // GET_CAPABILITIES of a USB488 instrument: bcdUSBTMC 1.00, indicator pulse,
  // TermChar; bcdUSB488 1.00, 488.2 interface + REN + trigger; SCPI, SR1, RL1, DT1.
  Bytes caps(0x18, 0);
  caps[0] = 0x01;
  caps[2] = 0x00;
  caps[3] = 0x01;
  caps[4] = 0x04;
  caps[5] = 0x01;
  caps[12] = 0x00;
  caps[13] = 0x01;
  caps[14] = 0x07;
  caps[15] = 0x0F;
  auto c = parseCapabilities(caps);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->bcdUsbtmc, 0x0100);
  EXPECT_TRUE(c->indicatorPulse && c->termChar && !c->talkOnly && !c->listenOnly);
  EXPECT_EQ(c->bcdUsb488, 0x0100);
  EXPECT_TRUE(c->usb4882 && c->remoteLocal && c->trigger && c->scpi && c->sr1 && c->rl1 && c->dt1);
  caps.pop_back();
  EXPECT_FALSE(parseCapabilities(caps).ok());
  // READ_STATUS_BYTE: control answer and Interrupt-IN notification (0x80 | bTag).
  auto stb = parseStatusByteAnswer({0x01, 0x05, 0x10}, 0x05);
  ASSERT_TRUE(stb.ok());
  EXPECT_EQ(stb->statusByte, 0x10);
  EXPECT_FALSE(parseStatusByteAnswer({0x01, 0x06, 0x10}, 0x05).ok());
  auto note = parseInterruptNotification({0x85, 0x40}, 0x05);
  ASSERT_TRUE(note.ok());
  EXPECT_EQ(note->statusByte, 0x40);
  EXPECT_FALSE(parseInterruptNotification({0x05, 0x40}, 0x05).ok());  // D7 must be set
  EXPECT_FALSE(parseInterruptNotification({0x86, 0x40}, 0x05).ok());
}

}  // namespace
}  // namespace mozzi::devices::usbtmc
