#pragma once
// MCC USB-1608FS-Plus wire protocol, without I/O (STYLE 1: libsigrok's
// protocol.c). Sources: Measurement Computing's USB-1608FS-Plus documentation
// as reproduced in the open MCC Linux drivers (W. Jasper, mcc-libusb,
// usb-1608FS-Plus.{h,c}); layouts checked in tests/devices/mcc_usb1608fsplus.
//
//  - Vendor requests, bmRequestType 0x40 (out) / 0xC0 (in), wIndex 0:
//      0x11 AIN_SCAN_START  out, 10 bytes: count u32 LE (0 = continuous),
//           pacer_period u32 LE = round(40 MHz / rate) - 1, channel bit mask u8,
//           options u8 (bit 0 immediate transfer, bits 2-4 trigger mode,
//           bit 5 debug counter data, bit 7 inhibit stall on overrun)
//      0x12 AIN_SCAN_STOP   out, no data
//      0x14 AIN_CONFIG      out/in, 8 bytes: range code of channels 0..7
//      0x15 AIN_CLR_FIFO    out, no data
//      0x30 CAL_MEMORY      in, wValue = address (0..0x2FF): IEEE-754 float32 LE
//           slope then intercept for range r, channel c at (r * 8 + c) * 8
//      0x44 STATUS          in, 2 bytes u16 LE: bit 1 scan running, bit 2 overrun
//  - Bulk IN endpoint 0x81, 64-byte packets: u16 LE codes, scan-interleaved,
//    enabled channels in ascending order; 16-bit offset binary.
//  - Overrun (the 32768-sample FIFO full): the device stalls endpoint 0x81.
//  - Calibrated code = code * slope + intercept.

#include <array>
#include <cstdint>
#include <vector>

#include "core/common/result.h"
#include "devices/common/calibration.h"
#include "devices/common/capabilities.h"

namespace mozzi::devices::mcc {

constexpr std::uint16_t kVendorId = 0x09DB;
constexpr std::uint16_t kProductId = 0x00EA;
constexpr std::uint8_t kBulkInEndpoint = 0x81;
constexpr int kPacketBytes = 64;
constexpr int kChannelCount = 8;
constexpr int kRangeCount = 8;
constexpr double kTimebaseHz = 40e6;  // pacer timer clock
constexpr double kMaxRatePerChannelHz = 100e3;
constexpr double kMaxAggregateHz = 400e3;  // issue 9 / data sheet: 400 kS/s over all channels
constexpr std::int64_t kFifoSamples = 32768;
constexpr std::uint16_t kCalMemoryBytes = 0x300;
constexpr std::uint16_t kCalTableBytes = kRangeCount * kChannelCount * 8;  // 512

enum Request : std::uint8_t {
  kAInScanStart = 0x11,
  kAInScanStop = 0x12,
  kAInConfig = 0x14,
  kAInClearFifo = 0x15,
  kCalMemory = 0x30,
  kStatus = 0x44,
};

enum StatusBits : std::uint16_t {
  kStatusScanRunning = 1u << 1,
  kStatusScanOverrun = 1u << 2,
};

// The eight bipolar ranges, codes 0..7: +/-10, 5, 2.5, 2, 1.25, 1, 0.625, 0.3125 V.
const std::vector<InputRange>& ranges();
core::Result<InputRange> rangeForCode(std::uint8_t code);

struct ScanRequest {
  std::uint32_t scanCount = 0;    // 0 = continuous
  std::uint32_t pacerPeriod = 0;  // 40 MHz / rate - 1
  std::uint8_t channelMask = 0;   // bit c = channel c
  std::uint8_t options = 0;
};

// pacer_period for a per-channel rate; errors outside (0, 100 kHz] or when the
// aggregate over `channels` exceeds 400 kS/s.
core::Result<std::uint32_t> pacerPeriodFor(double rateHz, int channels);
double rateForPacerPeriod(std::uint32_t pacerPeriod);  // 40 MHz / (period + 1)

std::array<std::uint8_t, 10> encodeScanStart(const ScanRequest& request);
core::Result<ScanRequest> decodeScanStart(const std::vector<std::uint8_t>& bytes);

std::array<std::uint8_t, 8> encodeRangeConfig(const std::array<std::uint8_t, 8>& rangeCodes);

std::uint16_t calibrationAddress(int rangeCode, int channel);  // slope; intercept at +4

// Calibration table: [range][channel] slope, intercept from the 512-byte block
// at address 0. Errors: short block, non-finite or zero slope (unprogrammed
// memory reads 0xFF.. = NaN), naming range and channel.
using CalibrationTable = std::array<std::array<DeviceCalibration, kChannelCount>, kRangeCount>;
core::Result<CalibrationTable> parseCalibrationTable(const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> encodeCalibrationTable(const CalibrationTable& table);  // for device models

core::Result<std::uint16_t> parseStatus(const std::vector<std::uint8_t>& bytes);

// Splits a byte stream into scans. Bytes that do not complete a scan stay in
// `carry` for the next packet (a scan may straddle packets and transfers).
class ScanAssembler {
 public:
  explicit ScanAssembler(int channels) : channels_(channels) {}
  // Appends the codes of the complete scans in `data` (plus carried bytes) to
  // `codes`, scan-interleaved; returns the number of complete scans added.
  std::int64_t append(const std::uint8_t* data, int length, std::vector<std::int32_t>& codes);
  void reset() { carry_.clear(); }
  std::size_t carriedBytes() const { return carry_.size(); }

 private:
  int channels_;
  std::vector<std::uint8_t> carry_;
};

// Byte stream of `codes` (scan-interleaved) as the device sends it, for
// device models and tests.
std::vector<std::uint8_t> encodeSamples(const std::vector<std::uint16_t>& codes);

}  // namespace mozzi::devices::mcc
