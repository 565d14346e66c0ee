// ProjectStore: what the data tables share (core/io/project_data_internal.h):
// sample and blob columns, time records of rig and tyre tests, test status,
// content checksums. The tables themselves live one record kind per file:
// project_mesh.cpp (mesh, rig set-ups), project_hits.cpp (campaigns, hits),
// project_frf.cpp, project_modal.cpp, project_tests.cpp (rig and tyre tests),
// project_analyses.cpp (models, analyses). Every write is one explicit
// transaction (sql::Transaction); readers validate what they read, because a
// project file may come from anywhere.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace data {

using sql::sqliteError;

// Copies a blob of doubles out of a column, checking its size.
Result<void> checkDoublesBlob(sqlite3_stmt* stmt, int column, std::int64_t count, const std::string& where) {
  const std::int64_t bytes = sqlite3_column_bytes(stmt, column);
  if (count < 0 || count > kMaxFrfLines * 2 || bytes != count * static_cast<std::int64_t>(sizeof(double))) {
    return makeError(
        ErrorCode::Corrupt,
        "blob of " + std::to_string(bytes) + " bytes where " + std::to_string(count) + " float64 values were expected",
        where);
  }
  return {};
}

Result<std::vector<double>> columnDoubles(sqlite3_stmt* stmt, int column, std::int64_t count,
                                          const std::string& where) {
  MOZZI_TRY(checkDoublesBlob(stmt, column, count, where));
  std::vector<double> values(static_cast<std::size_t>(count));
  if (count > 0) std::memcpy(values.data(), sqlite3_column_blob(stmt, column), values.size() * sizeof(double));
  return values;
}

Result<void> checkSamples(const Eigen::MatrixXf& samples, double sampleRateHz, const std::string& where) {
  if (!(sampleRateHz > 0.0) || !finite(sampleRateHz)) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be a positive number of Hz", where);
  }
  if (samples.rows() == 0 || samples.cols() == 0) {
    return makeError(ErrorCode::InvalidArgument, "a record needs at least one channel and one sample", where);
  }
  if (static_cast<std::uint64_t>(samples.size()) * sizeof(float) > kMaxDecodedSampleBytes) {
    return makeError(ErrorCode::InvalidArgument, "record larger than 2 GiB", where);
  }
  for (Eigen::Index c = 0; c < samples.cols(); ++c) {
    for (Eigen::Index r = 0; r < samples.rows(); ++r) {
      if (!std::isfinite(samples(r, c))) {
        return makeError(ErrorCode::InvalidArgument,
                         "sample " + std::to_string(r) + " of channel " + std::to_string(c) + " is not finite", where);
      }
    }
  }
  return {};
}

// Reads encoding, counts, blob, crc from columns [first, first + 4] =
// (channel_count, sample_count, encoding, samples, samples_crc32).
Result<Eigen::MatrixXf> columnSamples(sqlite3_stmt* stmt, int first, const std::string& where) {
  const std::int64_t channels = sqlite3_column_int64(stmt, first);
  const std::int64_t count = sqlite3_column_int64(stmt, first + 1);
  const std::int64_t encoding = sqlite3_column_int64(stmt, first + 2);
  if (channels <= 0 || count <= 0 || channels > 65536 ||
      static_cast<std::uint64_t>(count) >
          kMaxDecodedSampleBytes / sizeof(float) / static_cast<std::uint64_t>(channels)) {
    return makeError(
        ErrorCode::Corrupt,
        "implausible record size: " + std::to_string(channels) + " channels x " + std::to_string(count) + " samples",
        where);
  }
  if (encoding != 0 && encoding != 1) {
    return makeError(ErrorCode::Corrupt, "unknown sample encoding " + std::to_string(encoding), where);
  }
  const auto* blob = static_cast<const std::uint8_t*>(sqlite3_column_blob(stmt, first + 3));
  const auto blobSize = static_cast<std::size_t>(sqlite3_column_bytes(stmt, first + 3));
  const auto crc = static_cast<std::uint32_t>(sqlite3_column_int64(stmt, first + 4));
  MOZZI_TRY_ASSIGN(const auto values, decodeSamples(blob, blobSize, static_cast<SampleEncoding>(encoding),
                                                    static_cast<std::uint64_t>(channels * count), crc, where));
  return Eigen::MatrixXf(Eigen::Map<const Eigen::MatrixXf>(values.data(), count, channels));
}

// Inserts one time record into rig_test_record or tyre_test_record (same
// layout as hits) inside the caller's transaction.
Result<void> insertRecord(sqlite3* db, const char* table, std::int64_t testId, int step, double sampleRateHz,
                          const Eigen::MatrixXf& samples, SampleEncoding encoding, const std::string& where) {
  MOZZI_TRY(checkSamples(samples, sampleRateHz, where));
  const auto count = static_cast<std::size_t>(samples.size());
  MOZZI_TRY_ASSIGN(auto blob, encodeSamples(samples.data(), count, encoding));
  const std::uint32_t crc = sampleCrc32(reinterpret_cast<const std::uint8_t*>(samples.data()), count * sizeof(float));
  const std::string owner = std::string(table) == "tyre_test_record" ? "tyre_test_id" : "rig_test_id";
  const std::string text = "INSERT INTO " + std::string(table) + "(" + owner +
                           ", step, sample_rate_hz, channel_count, sample_count,"
                           " encoding, samples, samples_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)";
  sql::Statement stmt(db, text);
  return stmt
      .bindAll(testId, step, sampleRateHz, samples.cols(), samples.rows(), encoding,
               sql::Blob{blob.data(), blob.size()}, crc)
      .run("cannot store the record", where);
}

// Inside a transaction: the status note of a running test (nothing when empty).
Result<void> setStatusNote(sqlite3* db, const char* table, std::int64_t id, const std::string& note,
                           const std::string& where) {
  if (note.empty()) return {};
  const std::string text = "UPDATE " + std::string(table) + " SET status_note = ?2 WHERE id = ?1";
  sql::Statement stmt(db, text);
  return stmt.bindAll(id, note).run("cannot update the test's note", where);
}

// Inside a transaction: the final status and note of a test; NotFound when
// there is no such test.
Result<void> setFinalStatus(sqlite3* db, const char* table, std::int64_t id, TestStatus status, const std::string& note,
                            const std::string& where) {
  const std::string text = "UPDATE " + std::string(table) + " SET status = ?2, status_note = ?3 WHERE id = ?1";
  sql::Statement stmt(db, text);
  MOZZI_TRY(stmt.bindAll(id, std::string(testStatusName(status)), note).run("cannot set the test's status", where));
  if (sqlite3_changes(db) != 1) return makeError(ErrorCode::NotFound, "no such test", where);
  return {};
}

// One time record of a rig or tyre test (NotFound when absent).
Result<Eigen::MatrixXf> readRecord(sqlite3* db, const char* table, std::int64_t testId, int step, double* sampleRateHz,
                                   const std::string& where) {
  const std::string owner = std::string(table) == "tyre_test_record" ? "tyre_test_id" : "rig_test_id";
  const std::string text =
      "SELECT sample_rate_hz, channel_count, sample_count, encoding, samples, samples_crc32 FROM " +
      std::string(table) + " WHERE " + owner + " = ?1 AND step = ?2";
  sql::Statement stmt(db, text);
  MOZZI_TRY(stmt.bindAll(testId, step).single("cannot read the record", "no such record", where));
  if (sampleRateHz) *sampleRateHz = sqlite3_column_double(stmt.get(), 0);
  return columnSamples(stmt.get(), 1, where);
}

// Checks the stored checksum in `column` against `computed`. NULL: the record
// was written before schema 4 and carries none.
Result<void> verifyChecksum(sqlite3_stmt* stmt, int column, std::uint32_t computed, const std::string& what,
                            const std::string& where) {
  if (sqlite3_column_type(stmt, column) == SQLITE_NULL) return {};
  const auto stored = static_cast<std::uint64_t>(sqlite3_column_int64(stmt, column));
  if (stored == computed) return {};
  char text[96];
  std::snprintf(text, sizeof text, " (stored CRC-32 %08llx, content gives %08x)",
                static_cast<unsigned long long>(stored), computed);
  return makeError(ErrorCode::Corrupt, "checksum mismatch: the " + what + " was damaged after it was written" + text,
                   where);
}

std::uint32_t meshChecksum(const StoredMesh& mesh) {
  // Canonical order: coordinate systems and nodes by label (as mesh() reads
  // them), lines and faces in stored order.
  std::vector<const StoredCoordinateSystem*> systems;
  for (const auto& c : mesh.coordinateSystems) systems.push_back(&c);
  std::sort(systems.begin(), systems.end(), [](auto* a, auto* b) { return a->label < b->label; });
  std::vector<const StoredNode*> nodes;
  for (const auto& n : mesh.nodes) nodes.push_back(&n);
  std::sort(nodes.begin(), nodes.end(), [](auto* a, auto* b) { return a->label < b->label; });
  ContentCrc crc;
  crc.add(static_cast<std::int64_t>(systems.size()));
  for (const auto* c : systems) {
    crc.add(c->label).add(c->name).add(static_cast<int>(c->kind));
    for (int i = 0; i < 3; ++i) crc.add(c->origin[i]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) crc.add(c->rotation(i, j));
    }
  }
  crc.add(static_cast<std::int64_t>(nodes.size()));
  for (const auto* n : nodes) {
    crc.add(n->label).add(n->definitionCs).add(n->displacementCs);
    for (int i = 0; i < 3; ++i) crc.add(n->position[i]);
  }
  crc.add(static_cast<std::int64_t>(mesh.lines.size()));
  for (const auto& l : mesh.lines) crc.add(l.nodeA).add(l.nodeB);
  crc.add(static_cast<std::int64_t>(mesh.faces.size()));
  for (const auto& f : mesh.faces) crc.add(f.nodeA).add(f.nodeB).add(f.nodeC).add(f.nodeD);
  return crc.value();
}

std::uint32_t rigTestChecksum(const StoredRigTest& t) {
  ContentCrc crc;
  crc.add(std::string(t.kind == StoredRigTest::Kind::Static ? "static" : "dynamic")).add(t.parametersJson);
  crc.add(static_cast<std::int64_t>(t.results.size()));
  for (const auto& r : t.results) crc.add(r.quantity).add(r.value).add(r.unit).add(r.uncertainty);
  return crc.value();
}

std::uint32_t tyreTestChecksum(const StoredTyreTest& t) {
  ContentCrc crc;
  crc.add(t.kind).add(t.inflationPressurePa).add(t.verticalLoadN).add(t.speedMps);
  crc.add(static_cast<std::int64_t>(t.points.size()));
  for (const auto& p : t.points) {
    crc.add(p.slipAngleRad).add(p.camberRad).add(p.lateralForceN).add(p.aligningMomentNm).add(p.overturningMomentNm);
  }
  crc.add(static_cast<std::int64_t>(t.parameters.size()));
  for (const auto& p : t.parameters) crc.add(p.name).add(p.value).add(p.unit).add(p.uncertainty);
  return crc.value();
}

}  // namespace data

const char* testStatusName(TestStatus status) {
  switch (status) {
    case TestStatus::Running: return "running";
    case TestStatus::Complete: return "complete";
    case TestStatus::Interrupted: return "interrupted";
    case TestStatus::Failed: return "failed";
  }
  return "failed";
}

TestStatus parseTestStatus(const std::string& name) {
  for (auto s : {TestStatus::Running, TestStatus::Complete, TestStatus::Interrupted})
    if (name == testStatusName(s)) return s;
  return TestStatus::Failed;
}

namespace sql {
std::uint32_t emptyMeshChecksum() {
  return data::meshChecksum(StoredMesh{});
}
}  // namespace sql

}  // namespace mozzi::core::io
