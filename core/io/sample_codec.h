#pragma once
// Lossless encoding of float32 time data for the project file's sample blobs.
// Layout of the raw bytes: float32 little endian, column-major (channel 0's
// samples, then channel 1's, ...). Encoding 1 ("shuffled zlib") splits those
// bytes into four planes (all first bytes, all second bytes, ...) and deflates
// the result: the sign/exponent plane of ADC data is highly redundant, the
// low-mantissa plane is noise, so shuffling lets deflate find the redundancy
// (the HDF5 "shuffle" filter idea). Decoding inverts both steps exactly.

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::io {

enum class SampleEncoding : int { Raw = 0, ShuffledZlib = 1 };

// Upper bound on the decoded size of one record (2 GiB): a header that claims
// more is rejected before anything is allocated.
inline constexpr std::uint64_t kMaxDecodedSampleBytes = std::uint64_t{1} << 31;

// CRC-32 (zlib polynomial) of a byte range.
std::uint32_t sampleCrc32(const std::uint8_t* data, std::size_t size);
// Continues a CRC-32: sampleCrc32Update(sampleCrc32(a), b) == CRC-32 of a then b
// (start from 0 for an empty prefix).
std::uint32_t sampleCrc32Update(std::uint32_t previous, const std::uint8_t* data, std::size_t size);

// Encodes `count` floats. zlibLevel 1 (fast) .. 9; ignored for Raw.
Result<std::vector<std::uint8_t>> encodeSamples(const float* values, std::size_t count, SampleEncoding encoding,
                                                int zlibLevel = 1);

// Decodes a blob into exactly `count` floats, checking size and CRC. `where`
// names the record for the error message.
Result<std::vector<float>> decodeSamples(const std::uint8_t* blob, std::size_t blobSize, SampleEncoding encoding,
                                         std::uint64_t count, std::uint32_t expectedCrc, const std::string& where);

}  // namespace mozzi::core::io
