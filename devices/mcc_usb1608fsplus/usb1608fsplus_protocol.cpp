#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"

#include <cmath>
#include <cstring>

namespace mozzi::devices::mcc {

namespace {

void putU32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::uint32_t getU32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
}
float getF32(const std::uint8_t* p) {
  const std::uint32_t bits = getU32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}
void putF32(std::uint8_t* p, float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  putU32(p, bits);
}

}  // namespace

const std::vector<InputRange>& ranges() {
  static const std::vector<InputRange> kRanges = {
      {"+/-10 V", 0, -10.0, 10.0},      {"+/-5 V", 1, -5.0, 5.0},
      {"+/-2.5 V", 2, -2.5, 2.5},       {"+/-2 V", 3, -2.0, 2.0},
      {"+/-1.25 V", 4, -1.25, 1.25},    {"+/-1 V", 5, -1.0, 1.0},
      {"+/-0.625 V", 6, -0.625, 0.625}, {"+/-0.3125 V", 7, -0.3125, 0.3125},
  };
  return kRanges;
}

core::Result<InputRange> rangeForCode(std::uint8_t code) {
  if (code >= kRangeCount)
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "range code " + std::to_string(code) + " does not exist (0 to 7)", "USB-1608FS-Plus range");
  return ranges()[code];
}

core::Result<std::uint32_t> pacerPeriodFor(double rateHz, int channels) {
  if (!std::isfinite(rateHz) || rateHz <= 0.0 || rateHz > kMaxRatePerChannelHz * (1.0 + 1e-12))
    return core::makeError(core::ErrorCode::InvalidArgument, "the rate per channel must be in (0, 100000] Hz",
                           "USB-1608FS-Plus pacer");
  if (channels < 1 || channels > kChannelCount)
    return core::makeError(core::ErrorCode::InvalidArgument, "1 to 8 channels", "USB-1608FS-Plus pacer");
  if (rateHz * channels > kMaxAggregateHz * (1.0 + 1e-12))
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "aggregate rate " + std::to_string(rateHz * channels) + " S/s exceeds 400000 S/s",
                           "USB-1608FS-Plus pacer");
  const double period = std::round(kTimebaseHz / rateHz) - 1.0;  // pacer_period = 40 MHz / f - 1
  if (period < 1.0 || period > 4294967295.0)
    return core::makeError(core::ErrorCode::InvalidArgument, "the rate is outside the pacer's range",
                           "USB-1608FS-Plus pacer");
  return static_cast<std::uint32_t>(period);
}

double rateForPacerPeriod(std::uint32_t pacerPeriod) {
  return kTimebaseHz / (static_cast<double>(pacerPeriod) + 1.0);
}

std::array<std::uint8_t, 10> encodeScanStart(const ScanRequest& r) {
  std::array<std::uint8_t, 10> b{};
  putU32(&b[0], r.scanCount);
  putU32(&b[4], r.pacerPeriod);
  b[8] = r.channelMask;
  b[9] = r.options;
  return b;
}

core::Result<ScanRequest> decodeScanStart(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() != 10)
    return core::makeError(core::ErrorCode::ParseError,
                           "AIN_SCAN_START carries 10 bytes, got " + std::to_string(bytes.size()), "request 0x11");
  ScanRequest r;
  r.scanCount = getU32(&bytes[0]);
  r.pacerPeriod = getU32(&bytes[4]);
  r.channelMask = bytes[8];
  r.options = bytes[9];
  return r;
}

std::array<std::uint8_t, 8> encodeRangeConfig(const std::array<std::uint8_t, 8>& rangeCodes) {
  return rangeCodes;
}

std::uint16_t calibrationAddress(int rangeCode, int channel) {
  return static_cast<std::uint16_t>((rangeCode * kChannelCount + channel) * 8);
}

core::Result<CalibrationTable> parseCalibrationTable(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() < kCalTableBytes)
    return core::makeError(core::ErrorCode::ParseError,
                           "the calibration table has 512 bytes, got " + std::to_string(bytes.size()),
                           "calibration memory");
  CalibrationTable table{};
  for (int r = 0; r < kRangeCount; ++r)
    for (int c = 0; c < kChannelCount; ++c) {
      const std::uint16_t a = calibrationAddress(r, c);
      const double slope = getF32(&bytes[a]);
      const double intercept = getF32(&bytes[a + 4u]);
      if (!std::isfinite(slope) || slope == 0.0 || !std::isfinite(intercept))
        return core::makeError(core::ErrorCode::Corrupt,
                               "the calibration memory holds no valid slope/intercept (unprogrammed or damaged); "
                               "return the device for calibration",
                               "range " + std::to_string(r) + ", channel " + std::to_string(c));
      table[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = DeviceCalibration{slope, intercept};
    }
  return table;
}

std::vector<std::uint8_t> encodeCalibrationTable(const CalibrationTable& table) {
  std::vector<std::uint8_t> bytes(kCalTableBytes);
  for (int r = 0; r < kRangeCount; ++r)
    for (int c = 0; c < kChannelCount; ++c) {
      const auto& e = table[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
      const std::uint16_t a = calibrationAddress(r, c);
      putF32(&bytes[a], static_cast<float>(e.slope));
      putF32(&bytes[a + 4u], static_cast<float>(e.intercept));
    }
  return bytes;
}

core::Result<std::uint16_t> parseStatus(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() != 2)
    return core::makeError(core::ErrorCode::ParseError, "STATUS carries 2 bytes, got " + std::to_string(bytes.size()),
                           "request 0x44");
  return static_cast<std::uint16_t>(bytes[0] | bytes[1] << 8);
}

std::int64_t ScanAssembler::append(const std::uint8_t* data, int length, std::vector<std::int32_t>& codes) {
  const std::size_t scanBytes = static_cast<std::size_t>(channels_) * 2;
  std::int64_t scans = 0;
  int i = 0;
  // Complete a scan begun in an earlier packet.
  while (!carry_.empty() && i < length) {
    carry_.push_back(data[i++]);
    if (carry_.size() == scanBytes) {
      for (std::size_t k = 0; k < scanBytes; k += 2) codes.push_back(carry_[k] | carry_[k + 1] << 8);
      carry_.clear();
      ++scans;
    }
  }
  const std::size_t remaining = static_cast<std::size_t>(length - i);
  const std::size_t whole = remaining / scanBytes;
  const std::uint8_t* p = data + i;
  codes.reserve(codes.size() + whole * static_cast<std::size_t>(channels_));
  for (std::size_t k = 0; k < whole * scanBytes; k += 2) codes.push_back(p[k] | p[k + 1] << 8);
  scans += static_cast<std::int64_t>(whole);
  carry_.insert(carry_.end(), p + whole * scanBytes, data + length);
  return scans;
}

std::vector<std::uint8_t> encodeSamples(const std::vector<std::uint16_t>& codes) {
  std::vector<std::uint8_t> b(codes.size() * 2);
  for (std::size_t i = 0; i < codes.size(); ++i) {
    b[2 * i] = static_cast<std::uint8_t>(codes[i] & 0xFF);
    b[2 * i + 1] = static_cast<std::uint8_t>(codes[i] >> 8);
  }
  return b;
}

}  // namespace mozzi::devices::mcc
