// USB-1608FS-Plus codec against the documented byte layouts (MCC's
// USB-1608FS-Plus command reference as reproduced in the open mcc-libusb
// driver: AInScan 10 bytes = count u32, pacer_period u32, channels u8,
// options u8; calibration floats at (range * 8 + channel) * 8).
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mozzi::devices::mcc {
namespace {

TEST(Usb1608Protocol, ScanStartLayout) {
  ScanRequest r;
  r.scanCount = 1000;   // 0x000003E8
  r.pacerPeriod = 799;  // 40 MHz / 50 kHz - 1 = 0x0000031F
  r.channelMask = 0xFF;
  r.options = 0x00;
  const auto b = encodeScanStart(r);
  const std::array<std::uint8_t, 10> expected = {0xE8, 0x03, 0x00, 0x00, 0x1F, 0x03, 0x00, 0x00, 0xFF, 0x00};
  EXPECT_EQ(b, expected);
  auto back = decodeScanStart(std::vector<std::uint8_t>(b.begin(), b.end()));
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->scanCount, 1000u);
  EXPECT_EQ(back->pacerPeriod, 799u);
  EXPECT_FALSE(decodeScanStart(std::vector<std::uint8_t>(9, 0)).ok());
}

TEST(Usb1608Protocol, PacerPeriodAndLimits) {
  EXPECT_EQ(*pacerPeriodFor(50e3, 8), 799u);
  EXPECT_EQ(*pacerPeriodFor(100e3, 4), 399u);
  EXPECT_EQ(*pacerPeriodFor(1000.0, 1), 39999u);
  EXPECT_DOUBLE_EQ(rateForPacerPeriod(799), 50e3);
  EXPECT_FALSE(pacerPeriodFor(100e3, 8).ok());  // 800 kS/s aggregate > 400 kS/s
  EXPECT_FALSE(pacerPeriodFor(150e3, 1).ok());  // > 100 kS/s per channel
  EXPECT_FALSE(pacerPeriodFor(std::nan(""), 1).ok());
}

TEST(Usb1608Protocol, RangeConfigAndRanges) {
  const auto b = encodeRangeConfig({0, 1, 2, 3, 4, 5, 6, 7});
  for (int i = 0; i < 8; ++i) EXPECT_EQ(b[static_cast<std::size_t>(i)], i);
  EXPECT_DOUBLE_EQ(rangeForCode(3)->maxVolts, 2.0);
  EXPECT_DOUBLE_EQ(rangeForCode(6)->minVolts, -0.625);
  EXPECT_FALSE(rangeForCode(8).ok());
}

TEST(Usb1608Protocol, CalibrationTableAddressesAndFloats) {
  EXPECT_EQ(calibrationAddress(0, 0), 0);
  EXPECT_EQ(calibrationAddress(0, 1), 8);
  EXPECT_EQ(calibrationAddress(1, 0), 64);
  EXPECT_EQ(calibrationAddress(7, 7), 504);
  CalibrationTable t{};
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c)
      t[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = DeviceCalibration{1.0 + 0.001 * r, -2.0 * c};
  auto bytes = encodeCalibrationTable(t);
  ASSERT_EQ(bytes.size(), 512u);
  // Slope 1.0 of range 0 channel 0 as IEEE-754 little endian: 00 00 80 3F.
  EXPECT_EQ(bytes[0], 0x00);
  EXPECT_EQ(bytes[1], 0x00);
  EXPECT_EQ(bytes[2], 0x80);
  EXPECT_EQ(bytes[3], 0x3F);
  // Intercept -2.0 of range 0 channel 1 (address 12): 00 00 00 C0.
  EXPECT_EQ(bytes[12 + 3], 0xC0);
  auto parsed = parseCalibrationTable(bytes);
  ASSERT_TRUE(parsed.ok());
  // float32 storage: the slopes round to 24-bit mantissas (relative 6e-8).
  EXPECT_NEAR((*parsed)[7][5].slope, 1.007, 1e-7);
  EXPECT_DOUBLE_EQ((*parsed)[7][5].intercept, -10.0);
}

TEST(Usb1608Protocol, UnprogrammedCalibrationIsCorrupt) {
  std::vector<std::uint8_t> erased(512, 0xFF);  // erased flash reads as NaN floats
  auto r = parseCalibrationTable(erased);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, core::ErrorCode::Corrupt);
  EXPECT_EQ(r.error().where, "range 0, channel 0");
  EXPECT_FALSE(parseCalibrationTable(std::vector<std::uint8_t>(100, 0)).ok());
}

TEST(Usb1608Protocol, StatusBits) {
  auto s = parseStatus({0x06, 0x00});
  ASSERT_TRUE(s.ok());
  EXPECT_TRUE(*s & kStatusScanRunning);
  EXPECT_TRUE(*s & kStatusScanOverrun);
  EXPECT_FALSE(parseStatus({0x06}).ok());
}

TEST(Usb1608Protocol, ScansStraddlePacketsAndTransfers) {
  // Three channels = 6 bytes per scan; 64-byte packets hold 10 scans and 4
  // bytes of the eleventh.
  std::vector<std::uint16_t> codes;
  for (int i = 0; i < 3 * 40; ++i) codes.push_back(static_cast<std::uint16_t>(1000 + 7 * i));
  const auto bytes = encodeSamples(codes);
  EXPECT_EQ(bytes[0], 0xE8);  // 1000 = 0x03E8, little endian
  EXPECT_EQ(bytes[1], 0x03);
  ScanAssembler a(3);
  std::vector<std::int32_t> out;
  EXPECT_EQ(a.append(bytes.data(), 64, out), 10);
  EXPECT_EQ(a.carriedBytes(), 4u);
  EXPECT_EQ(a.append(bytes.data() + 64, 64, out), 11);  // completes scan 10, 10 more, 2 bytes carried
  EXPECT_EQ(a.carriedBytes(), 2u);
  EXPECT_EQ(a.append(bytes.data() + 128, static_cast<int>(bytes.size()) - 128, out), 19);
  ASSERT_EQ(out.size(), codes.size());
  for (std::size_t i = 0; i < codes.size(); ++i) ASSERT_EQ(out[i], codes[i]) << i;
}

}  // namespace
}  // namespace mozzi::devices::mcc
