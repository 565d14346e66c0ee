#include "core/io/sample_codec.h"

#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <string>

namespace mozzi::core::io {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "sample blobs are little endian; a big-endian port must byte-swap here");
static_assert(sizeof(float) == 4, "sample blobs hold IEEE 754 binary32");

std::uint32_t sampleCrc32(const std::uint8_t* data, std::size_t size) {
  return sampleCrc32Update(0, data, size);
}

std::uint32_t sampleCrc32Update(std::uint32_t previous, const std::uint8_t* data, std::size_t size) {
  uLong crc = previous;
  if (data == nullptr) return previous;
  while (size > 0) {
    const uInt chunk = static_cast<uInt>(std::min<std::size_t>(size, UINT_MAX));
    crc = crc32(crc, data, chunk);
    data += chunk;
    size -= chunk;
  }
  return static_cast<std::uint32_t>(crc);
}

Result<std::vector<std::uint8_t>> encodeSamples(const float* values, std::size_t count, SampleEncoding encoding,
                                                int zlibLevel) {
  const std::size_t bytes = count * sizeof(float);
  const auto* raw = reinterpret_cast<const std::uint8_t*>(values);
  if (encoding == SampleEncoding::Raw) return std::vector<std::uint8_t>(raw, raw + bytes);
  if (encoding != SampleEncoding::ShuffledZlib) {
    return makeError(ErrorCode::InvalidArgument, "unknown sample encoding", "sample encoder");
  }

  // Byte planes: plane b holds byte b of every float.
  std::vector<std::uint8_t> shuffled(bytes);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t b = 0; b < 4; ++b) shuffled[b * count + i] = raw[i * 4 + b];
  }
  uLongf outSize = compressBound(static_cast<uLong>(bytes));
  std::vector<std::uint8_t> out(outSize);
  const int rc = compress2(out.data(), &outSize, shuffled.data(), static_cast<uLong>(bytes), zlibLevel);
  if (rc != Z_OK) {
    return makeError(ErrorCode::IoError, "zlib could not compress the samples (code " + std::to_string(rc) + ")",
                     "sample encoder");
  }
  out.resize(outSize);
  return out;
}

Result<std::vector<float>> decodeSamples(const std::uint8_t* blob, std::size_t blobSize, SampleEncoding encoding,
                                         std::uint64_t count, std::uint32_t expectedCrc, const std::string& where) {
  if (count == 0 || count > kMaxDecodedSampleBytes / sizeof(float)) {
    return makeError(ErrorCode::Corrupt, "implausible sample count " + std::to_string(count), where);
  }
  const std::size_t bytes = static_cast<std::size_t>(count) * sizeof(float);
  std::vector<float> values;
  if (encoding == SampleEncoding::Raw) {
    if (blobSize != bytes) {
      return makeError(
          ErrorCode::Corrupt,
          "sample blob holds " + std::to_string(blobSize) + " bytes, the header says " + std::to_string(bytes), where);
    }
    values.resize(static_cast<std::size_t>(count));
    std::memcpy(values.data(), blob, bytes);
  } else if (encoding == SampleEncoding::ShuffledZlib) {
    // Deflate cannot expand data by more than a factor of 1032; a blob that
    // claims more is corrupt, and checking first avoids a huge allocation.
    if (blobSize == 0 || bytes / 1032 > blobSize) {
      return makeError(ErrorCode::Corrupt,
                       "compressed sample blob of " + std::to_string(blobSize) + " bytes cannot hold " +
                           std::to_string(bytes) + " bytes",
                       where);
    }
    std::vector<std::uint8_t> shuffled(bytes);
    uLongf outSize = static_cast<uLongf>(bytes);
    const int rc = uncompress(shuffled.data(), &outSize, blob, static_cast<uLong>(blobSize));
    if (rc != Z_OK || outSize != bytes) {
      return makeError(ErrorCode::Corrupt, "compressed sample blob does not inflate to the stated size", where);
    }
    values.resize(static_cast<std::size_t>(count));
    auto* raw = reinterpret_cast<std::uint8_t*>(values.data());
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t b = 0; b < 4; ++b) raw[i * 4 + b] = shuffled[b * count + i];
    }
  } else {
    return makeError(ErrorCode::Unsupported, "unknown sample encoding " + std::to_string(static_cast<int>(encoding)),
                     where);
  }
  const std::uint32_t crc = sampleCrc32(reinterpret_cast<const std::uint8_t*>(values.data()), bytes);
  if (crc != expectedCrc) return makeError(ErrorCode::Corrupt, "sample data fail their CRC-32 check", where);
  return values;
}

}  // namespace mozzi::core::io
