#pragma once
// Private helpers shared by the data tables of the project store
// (core/io/project_data.cpp defines them; project_mesh.cpp, project_hits.cpp,
// project_frf.cpp, project_modal.cpp, project_tests.cpp and
// project_analyses.cpp use them). Not part of core's public face.

#include <sqlite3.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/io/project_sql.h"
#include "core/io/sample_codec.h"

namespace mozzi::core::io::data {

// Largest record we accept from a file before allocating for it: 2^31 bytes of
// samples (kMaxDecodedSampleBytes) and 2^26 FRF lines.
inline constexpr std::int64_t kMaxFrfLines = std::int64_t{1} << 26;

inline bool finite(double v) {
  return std::isfinite(v);
}

inline std::string hitWhere(const std::string& path, std::int64_t id) {
  return path + ", hit " + std::to_string(id);
}

// Corrupt unless the blob in `column` holds `count` float64 values.
Result<void> checkDoublesBlob(sqlite3_stmt* stmt, int column, std::int64_t count, const std::string& where);
// Copies a blob of doubles out of a column, checking its size.
Result<std::vector<double>> columnDoubles(sqlite3_stmt* stmt, int column, std::int64_t count, const std::string& where);

// A record's samples: positive finite rate, at least one channel and one
// sample, at most 2 GiB, every sample finite.
Result<void> checkSamples(const Eigen::MatrixXf& samples, double sampleRateHz, const std::string& where);

// Reads encoding, counts, blob, crc from columns [first, first + 4] =
// (channel_count, sample_count, encoding, samples, samples_crc32).
Result<Eigen::MatrixXf> columnSamples(sqlite3_stmt* stmt, int first, const std::string& where);

// Inserts one time record into rig_test_record or tyre_test_record (same
// layout as hits) inside the caller's transaction.
Result<void> insertRecord(sqlite3* db, const char* table, std::int64_t testId, int step, double sampleRateHz,
                          const Eigen::MatrixXf& samples, SampleEncoding encoding, const std::string& where);

// Inside a transaction: the status note of a running test (nothing when empty).
Result<void> setStatusNote(sqlite3* db, const char* table, std::int64_t id, const std::string& note,
                           const std::string& where);

// Inside a transaction: the final status and note of a test; NotFound when
// there is no such test.
Result<void> setFinalStatus(sqlite3* db, const char* table, std::int64_t id, TestStatus status, const std::string& note,
                            const std::string& where);

// One time record of a rig or tyre test (NotFound when absent).
Result<Eigen::MatrixXf> readRecord(sqlite3* db, const char* table, std::int64_t testId, int step, double* sampleRateHz,
                                   const std::string& where);

// CRC-32 (zlib) over a record's content as typed values: integers as int64
// and doubles as their IEEE-754 bits, both little endian; text as its length
// (int64) then its bytes. -0.0 is hashed as +0.0, because SQLite stores a
// REAL with an integral value as an integer and reads it back as +0.0.
// docs/formats/project.md, "Checksums", lists what each record hashes.
class ContentCrc {
 public:
  ContentCrc& add(std::int64_t v) {
    std::uint8_t b[8];
    for (int k = 0; k < 8; ++k) b[k] = static_cast<std::uint8_t>(static_cast<std::uint64_t>(v) >> (8 * k));
    return bytes(b, 8);
  }
  ContentCrc& add(int v) { return add(static_cast<std::int64_t>(v)); }
  ContentCrc& add(long long v) { return add(static_cast<std::int64_t>(v)); }  // sqlite3_int64
  ContentCrc& add(double v) {
    if (v == 0.0) v = 0.0;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return add(static_cast<std::int64_t>(bits));
  }
  ContentCrc& add(const std::string& s) {
    add(static_cast<std::int64_t>(s.size()));
    return bytes(s.data(), s.size());
  }
  // Raw blob bytes (the float64 arrays of FRF sets are stored as bytes).
  ContentCrc& bytes(const void* data, std::size_t size) {
    crc_ = sampleCrc32Update(crc_, static_cast<const std::uint8_t*>(data), size);
    return *this;
  }
  std::uint32_t value() const { return crc_; }

 private:
  std::uint32_t crc_ = 0;
};

// Checks the stored checksum in `column` against `computed`. NULL: the record
// was written before schema 4 and carries none.
Result<void> verifyChecksum(sqlite3_stmt* stmt, int column, std::uint32_t computed, const std::string& what,
                            const std::string& where);

// Content checksums of the records docs/formats/project.md, "Checksums", lists.
std::uint32_t meshChecksum(const StoredMesh& mesh);
std::uint32_t rigTestChecksum(const StoredRigTest& t);
std::uint32_t tyreTestChecksum(const StoredTyreTest& t);

}  // namespace mozzi::core::io::data
