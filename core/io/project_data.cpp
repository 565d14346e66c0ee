// ProjectStore: the data tables (mesh, rig set-ups, campaigns, hits, FRFs,
// modal results, rig and tyre tests, models, analyses). Every write is one
// explicit transaction (sql::Transaction); readers validate what they read,
// because a project file may come from anywhere.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <utility>

#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

using sql::sqliteError;

// Largest record we accept from a file before allocating for it: 2^31 bytes of
// samples (kMaxDecodedSampleBytes) and 2^26 FRF lines.
constexpr std::int64_t kMaxFrfLines = std::int64_t{1} << 26;

bool finite(double v) {
  return std::isfinite(v);
}

std::string hitWhere(const std::string& path, std::int64_t id) {
  return path + ", hit " + std::to_string(id);
}

// Copies a blob of doubles out of a column, checking its size.
Result<std::vector<double>> columnDoubles(sqlite3_stmt* stmt, int column, std::int64_t count,
                                          const std::string& where) {
  const void* data = sqlite3_column_blob(stmt, column);
  const std::int64_t bytes = sqlite3_column_bytes(stmt, column);
  if (count < 0 || count > kMaxFrfLines * 2 || bytes != count * static_cast<std::int64_t>(sizeof(double))) {
    return makeError(
        ErrorCode::Corrupt,
        "blob of " + std::to_string(bytes) + " bytes where " + std::to_string(count) + " float64 values were expected",
        where);
  }
  std::vector<double> values(static_cast<std::size_t>(count));
  if (count > 0) std::memcpy(values.data(), data, static_cast<std::size_t>(bytes));
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
  auto values = decodeSamples(blob, blobSize, static_cast<SampleEncoding>(encoding),
                              static_cast<std::uint64_t>(channels * count), crc, where);
  if (!values) return values.error();
  return Eigen::MatrixXf(Eigen::Map<const Eigen::MatrixXf>(values->data(), count, channels));
}

// Inserts one time record into rig_test_record or tyre_test_record (same
// layout as hits) inside the caller's transaction.
Result<void> insertRecord(sqlite3* db, const char* table, std::int64_t testId, int step, double sampleRateHz,
                          const Eigen::MatrixXf& samples, SampleEncoding encoding, const std::string& where) {
  if (auto r = checkSamples(samples, sampleRateHz, where); !r) return r.error();
  const auto count = static_cast<std::size_t>(samples.size());
  auto blob = encodeSamples(samples.data(), count, encoding);
  if (!blob) return blob.error();
  const std::uint32_t crc = sampleCrc32(reinterpret_cast<const std::uint8_t*>(samples.data()), count * sizeof(float));
  const std::string owner = std::string(table) == "tyre_test_record" ? "tyre_test_id" : "rig_test_id";
  const std::string text = "INSERT INTO " + std::string(table) + "(" + owner +
                           ", step, sample_rate_hz, channel_count, sample_count,"
                           " encoding, samples, samples_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)";
  sql::Statement stmt(db, text.c_str());
  stmt.bind(1, testId).bind(2, step).bind(3, sampleRateHz).bind(4, static_cast<std::int64_t>(samples.cols()));
  stmt.bind(5, static_cast<std::int64_t>(samples.rows())).bind(6, static_cast<int>(encoding));
  stmt.bindBlob(7, blob->data(), blob->size()).bind(8, static_cast<std::int64_t>(crc));
  if (stmt.step() != SQLITE_DONE) return sqliteError(db, "cannot store the record", where);
  return {};
}

// Inside a transaction: the status note of a running test (nothing when empty).
Result<void> setStatusNote(sqlite3* db, const char* table, std::int64_t id, const std::string& note,
                           const std::string& where) {
  if (note.empty()) return {};
  const std::string text = "UPDATE " + std::string(table) + " SET status_note = ?2 WHERE id = ?1";
  sql::Statement stmt(db, text.c_str());
  stmt.bind(1, id).bind(2, note);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db, "cannot update the test's note", where);
  return {};
}

// Inside a transaction: the final status and note of a test; NotFound when
// there is no such test.
Result<void> setFinalStatus(sqlite3* db, const char* table, std::int64_t id, TestStatus status, const std::string& note,
                            const std::string& where) {
  const std::string text = "UPDATE " + std::string(table) + " SET status = ?2, status_note = ?3 WHERE id = ?1";
  sql::Statement stmt(db, text.c_str());
  stmt.bind(1, id).bind(2, std::string(testStatusName(status))).bind(3, note);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db, "cannot set the test's status", where);
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
  sql::Statement stmt(db, text.c_str());
  stmt.bind(1, testId).bind(2, step);
  const int rc = stmt.step();
  if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such record", where);
  if (rc != SQLITE_ROW) return sqliteError(db, "cannot read the record", where);
  if (sampleRateHz) *sampleRateHz = sqlite3_column_double(stmt.get(), 0);
  return columnSamples(stmt.get(), 1, where);
}

sql::Statement& bindStep(sql::Statement& stmt, int index, const std::optional<int>& step) {
  return step ? stmt.bind(index, *step) : stmt.bindNull(index);
}

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

}  // namespace

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
  return meshChecksum(StoredMesh{});
}
}  // namespace sql

// --- mesh -----------------------------------------------------------------------

Result<void> ProjectStore::setMesh(std::int64_t specimenId, const StoredMesh& mesh) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r;
  const std::string where = path_ + ", mesh of specimen " + std::to_string(specimenId);
  for (const auto& n : mesh.nodes) {
    if (!n.position.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(n.label) + " has a non-finite position",
                       where);
    }
  }
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun();
  {
    sql::Statement exists(db_, "SELECT 1 FROM specimen WHERE id = ?1");
    exists.bind(1, specimenId);
    if (exists.step() != SQLITE_ROW) return makeError(ErrorCode::NotFound, "no such specimen", where);
  }
  for (const char* table : {"mesh_face", "mesh_line", "mesh_node", "coordinate_system"}) {
    sql::Statement del(db_, (std::string("DELETE FROM ") + table + " WHERE specimen_id = ?1").c_str());
    del.bind(1, specimenId);
    if (del.step() != SQLITE_DONE) return sqliteError(db_, std::string("cannot clear ") + table, where);
  }
  sql::Statement cs(db_,
                    "INSERT INTO coordinate_system(specimen_id, label, name, kind, origin_x_m, origin_y_m, origin_z_m,"
                    " r11, r12, r13, r21, r22, r23, r31, r32, r33)"
                    " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16)");
  for (const auto& c : mesh.coordinateSystems) {
    cs.reset();
    cs.bind(1, specimenId).bind(2, c.label).bind(3, c.name).bind(4, static_cast<int>(c.kind));
    for (int i = 0; i < 3; ++i) cs.bind(5 + i, c.origin[i]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) cs.bind(8 + 3 * i + j, c.rotation(i, j));
    }
    if (cs.step() != SQLITE_DONE) {
      return sqliteError(db_, "cannot store coordinate system " + std::to_string(c.label), where);
    }
  }
  std::map<int, std::int64_t> nodeIds;
  sql::Statement node(db_,
                      "INSERT INTO mesh_node(specimen_id, label, definition_cs, displacement_cs, x_m, y_m, z_m)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  for (const auto& n : mesh.nodes) {
    node.reset();
    node.bind(1, specimenId).bind(2, n.label).bind(3, n.definitionCs).bind(4, n.displacementCs);
    for (int i = 0; i < 3; ++i) node.bind(5 + i, n.position[i]);
    if (node.step() != SQLITE_DONE) return sqliteError(db_, "cannot store node " + std::to_string(n.label), where);
    nodeIds[n.label] = sqlite3_last_insert_rowid(db_);
  }
  auto idOf = [&](int label, const char* what) -> Result<std::int64_t> {
    auto it = nodeIds.find(label);
    if (it == nodeIds.end()) {
      return makeError(ErrorCode::InvalidArgument,
                       std::string(what) + " names node " + std::to_string(label) + ", which is not in the mesh",
                       where);
    }
    return it->second;
  };
  sql::Statement line(db_, "INSERT INTO mesh_line(specimen_id, node_a, node_b) VALUES (?1, ?2, ?3)");
  for (const auto& l : mesh.lines) {
    auto a = idOf(l.nodeA, "a line");
    if (!a) return a.error();
    auto b = idOf(l.nodeB, "a line");
    if (!b) return b.error();
    line.reset();
    line.bind(1, specimenId).bind(2, *a).bind(3, *b);
    if (line.step() != SQLITE_DONE) return sqliteError(db_, "cannot store a trace line", where);
  }
  sql::Statement face(db_,
                      "INSERT INTO mesh_face(specimen_id, node_a, node_b, node_c, node_d) VALUES (?1, ?2, ?3, ?4, ?5)");
  for (const auto& f : mesh.faces) {
    auto a = idOf(f.nodeA, "a face");
    if (!a) return a.error();
    auto b = idOf(f.nodeB, "a face");
    if (!b) return b.error();
    auto c = idOf(f.nodeC, "a face");
    if (!c) return c.error();
    std::optional<std::int64_t> d;
    if (f.nodeD != 0) {
      auto dd = idOf(f.nodeD, "a face");
      if (!dd) return dd.error();
      d = *dd;
    }
    face.reset();
    face.bind(1, specimenId).bind(2, *a).bind(3, *b).bind(4, *c).bind(5, d);
    if (face.step() != SQLITE_DONE) return sqliteError(db_, "cannot store a face", where);
  }
  sql::Statement crc(db_, "UPDATE specimen SET mesh_crc32 = ?1 WHERE id = ?2");
  crc.bind(1, static_cast<std::int64_t>(meshChecksum(mesh))).bind(2, specimenId);
  if (crc.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the mesh checksum", where);
  return tx.commit();
}

Result<StoredMesh> ProjectStore::mesh(std::int64_t specimenId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", mesh of specimen " + std::to_string(specimenId);
  StoredMesh mesh;
  {
    sql::Statement stmt(
        db_,
        "SELECT id, label, name, kind, origin_x_m, origin_y_m, origin_z_m, r11, r12, r13, r21, r22, r23,"
        " r31, r32, r33 FROM coordinate_system WHERE specimen_id = ?1 ORDER BY label");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredCoordinateSystem c;
      c.id = sqlite3_column_int64(stmt.get(), 0);
      c.label = sqlite3_column_int(stmt.get(), 1);
      c.name = sql::columnText(stmt.get(), 2);
      const int kind = sqlite3_column_int(stmt.get(), 3);
      if (kind < 0 || kind > 2) return makeError(ErrorCode::Corrupt, "unknown coordinate-system kind", where);
      c.kind = static_cast<StoredCoordinateSystem::Kind>(kind);
      for (int i = 0; i < 3; ++i) c.origin[i] = sqlite3_column_double(stmt.get(), 4 + i);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) c.rotation(i, j) = sqlite3_column_double(stmt.get(), 7 + 3 * i + j);
      }
      mesh.coordinateSystems.push_back(c);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read coordinate systems", where);
  }
  {
    sql::Statement stmt(db_,
                        "SELECT id, label, definition_cs, displacement_cs, x_m, y_m, z_m FROM mesh_node"
                        " WHERE specimen_id = ?1 ORDER BY label");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredNode n;
      n.id = sqlite3_column_int64(stmt.get(), 0);
      n.label = sqlite3_column_int(stmt.get(), 1);
      n.definitionCs = sqlite3_column_int(stmt.get(), 2);
      n.displacementCs = sqlite3_column_int(stmt.get(), 3);
      for (int i = 0; i < 3; ++i) n.position[i] = sqlite3_column_double(stmt.get(), 4 + i);
      mesh.nodes.push_back(n);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read nodes", where);
  }
  {
    sql::Statement stmt(db_,
                        "SELECT a.label, b.label FROM mesh_line l JOIN mesh_node a ON a.id = l.node_a"
                        " JOIN mesh_node b ON b.id = l.node_b WHERE l.specimen_id = ?1 ORDER BY l.id");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      mesh.lines.push_back({sqlite3_column_int(stmt.get(), 0), sqlite3_column_int(stmt.get(), 1)});
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read trace lines", where);
  }
  {
    sql::Statement stmt(db_,
                        "SELECT a.label, b.label, c.label, d.label FROM mesh_face f"
                        " JOIN mesh_node a ON a.id = f.node_a JOIN mesh_node b ON b.id = f.node_b"
                        " JOIN mesh_node c ON c.id = f.node_c LEFT JOIN mesh_node d ON d.id = f.node_d"
                        " WHERE f.specimen_id = ?1 ORDER BY f.id");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredFace f;
      f.nodeA = sqlite3_column_int(stmt.get(), 0);
      f.nodeB = sqlite3_column_int(stmt.get(), 1);
      f.nodeC = sqlite3_column_int(stmt.get(), 2);
      f.nodeD = sqlite3_column_type(stmt.get(), 3) == SQLITE_NULL ? 0 : sqlite3_column_int(stmt.get(), 3);
      mesh.faces.push_back(f);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read faces", where);
  }
  sql::Statement crc(db_, ("SELECT " + crcColumn("mesh_crc32") + " FROM specimen WHERE id = ?1").c_str());
  crc.bind(1, specimenId);
  if (crc.step() == SQLITE_ROW) {
    if (auto r = verifyChecksum(crc.get(), 0, meshChecksum(mesh), "mesh", where); !r) return r.error();
  }
  return mesh;
}

// --- rig set-ups -------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addRigSetup(const StoredRigSetup& setup) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", rig set-up '" + setup.name + "'";
  if (setup.name.empty()) return makeError(ErrorCode::InvalidArgument, "a rig set-up needs a name", where);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO rig_setup(specimen_id, name, rig_kind, driver, axis_map_json, parameters_json,"
                      " created_utc) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  stmt.bind(1, setup.specimenId).bind(2, setup.name).bind(3, setup.rigKind).bind(4, setup.driver);
  stmt.bind(5, setup.axisMapJson).bind(6, setup.parametersJson).bind(7, sql::nowUtc());
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the rig set-up", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  sql::Statement tr(db_,
                    "INSERT INTO transducer(rig_setup_id, channel, quantity, unit, sensitivity, model, serial,"
                    " dof_node, dof_direction) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
  for (const auto& t : setup.transducers) {
    if (!(t.sensitivity > 0.0) || !finite(t.sensitivity)) {
      return makeError(ErrorCode::InvalidArgument,
                       "transducer on channel " + std::to_string(t.channel) + " needs a positive sensitivity", where);
    }
    tr.reset();
    tr.bind(1, id).bind(2, t.channel).bind(3, t.quantity).bind(4, t.unit).bind(5, t.sensitivity);
    tr.bind(6, t.model).bind(7, t.serial).bindDof(8, t.dof);
    if (tr.step() != SQLITE_DONE) {
      return sqliteError(db_, "cannot store the transducer on channel " + std::to_string(t.channel), where);
    }
  }
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<StoredRigSetup> ProjectStore::rigSetup(std::int64_t rigSetupId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig set-up " + std::to_string(rigSetupId);
  StoredRigSetup s;
  {
    sql::Statement stmt(db_,
                        "SELECT id, specimen_id, name, rig_kind, driver, axis_map_json, parameters_json FROM rig_setup"
                        " WHERE id = ?1");
    stmt.bind(1, rigSetupId);
    const int rc = stmt.step();
    if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such rig set-up", where);
    if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the rig set-up", where);
    s.id = sqlite3_column_int64(stmt.get(), 0);
    s.specimenId = sqlite3_column_int64(stmt.get(), 1);
    s.name = sql::columnText(stmt.get(), 2);
    s.rigKind = sql::columnText(stmt.get(), 3);
    s.driver = sql::columnText(stmt.get(), 4);
    s.axisMapJson = sql::columnText(stmt.get(), 5);
    s.parametersJson = sql::columnText(stmt.get(), 6);
  }
  sql::Statement stmt(db_,
                      "SELECT id, channel, quantity, unit, sensitivity, model, serial, dof_node, dof_direction"
                      " FROM transducer WHERE rig_setup_id = ?1 ORDER BY channel");
  stmt.bind(1, rigSetupId);
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    StoredTransducer t;
    t.id = sqlite3_column_int64(stmt.get(), 0);
    t.channel = sqlite3_column_int(stmt.get(), 1);
    t.quantity = sql::columnText(stmt.get(), 2);
    t.unit = sql::columnText(stmt.get(), 3);
    t.sensitivity = sqlite3_column_double(stmt.get(), 4);
    t.model = sql::columnText(stmt.get(), 5);
    t.serial = sql::columnText(stmt.get(), 6);
    t.dof = sql::columnOptionalDof(stmt.get(), 7, 8);
    s.transducers.push_back(std::move(t));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read transducers", where);
  return s;
}

// --- campaigns and hits --------------------------------------------------------------

Result<std::int64_t> ProjectStore::addCampaign(const StoredCampaign& campaign,
                                               const std::vector<StoredCampaignPoint>& points) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", campaign '" + campaign.name + "'";
  if (campaign.name.empty()) return makeError(ErrorCode::InvalidArgument, "a campaign needs a name", where);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO campaign(specimen_id, rig_setup_id, name, kind, started_utc, notes, settings_json)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  stmt.bind(1, campaign.specimenId).bind(2, campaign.rigSetupId).bind(3, campaign.name).bind(4, campaign.kind);
  stmt.bind(5, campaign.startedUtc.empty() ? sql::nowUtc() : campaign.startedUtc).bind(6, campaign.notes);
  stmt.bind(7, campaign.settingsJson.empty() ? std::string("{}") : campaign.settingsJson);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the campaign", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (auto r = sql::insertCampaignPoints(db_, id, points, where); !r) return r.error();
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<std::vector<StoredCampaign>> ProjectStore::campaigns(std::int64_t specimenId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(
      db_,
      (std::string("SELECT ") + sql::kCampaignColumns + " FROM campaign WHERE specimen_id = ?1 ORDER BY id").c_str());
  stmt.bind(1, specimenId);
  std::vector<StoredCampaign> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    out.push_back(sql::campaignFromRow(stmt.get()));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read campaigns", path_);
  return out;
}

Result<std::int64_t> ProjectStore::commitHit(const StoredHit& hit) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where =
      path_ + ", campaign " + std::to_string(hit.campaignId) + ", hit " + std::to_string(hit.sequence);
  if (hit.sequence <= 0) return makeError(ErrorCode::InvalidArgument, "hit sequence numbers start at 1", where);
  if (auto r = checkSamples(hit.samples, hit.sampleRateHz, where); !r) return r.error();
  if (!hit.channels.empty() && static_cast<Eigen::Index>(hit.channels.size()) != hit.channelCount()) {
    return makeError(ErrorCode::InvalidArgument,
                     std::to_string(hit.channels.size()) + " channel descriptions for " +
                         std::to_string(hit.channelCount()) + " channels of samples",
                     where);
  }
  // Encode before the transaction so the write lock is held only for the
  // insert and the fsync.
  const std::size_t count = static_cast<std::size_t>(hit.samples.size());
  auto blob = encodeSamples(hit.samples.data(), count, hitEncoding_);
  if (!blob) return blob.error();
  const std::uint32_t crc =
      sampleCrc32(reinterpret_cast<const std::uint8_t*>(hit.samples.data()), count * sizeof(float));

  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO hit(campaign_id, sequence, point_node, point_direction, recorded_utc,"
                      " sample_rate_hz, channel_count, sample_count, encoding, samples, samples_crc32, accepted,"
                      " quality_flags, quality_reasons)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)");
  stmt.bind(1, hit.campaignId).bind(2, hit.sequence).bind(3, hit.point.node).bind(4, hit.point.uffCode());
  stmt.bind(5, hit.recordedUtc.empty() ? sql::nowUtc() : hit.recordedUtc).bind(6, hit.sampleRateHz);
  stmt.bind(7, static_cast<std::int64_t>(hit.channelCount())).bind(8, static_cast<std::int64_t>(hit.sampleCount()));
  stmt.bind(9, static_cast<int>(hitEncoding_)).bindBlob(10, blob->data(), blob->size());
  stmt.bind(11, static_cast<std::int64_t>(crc)).bind(12, hit.accepted ? 1 : 0);
  stmt.bind(13, static_cast<std::int64_t>(hit.qualityFlags)).bind(14, hit.qualityReasons);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the hit", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (!hit.channels.empty()) {
    sql::Statement ch(db_,
                      "INSERT INTO hit_channel(hit_id, channel, quantity, unit, dof_node, dof_direction)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    for (std::size_t c = 0; c < hit.channels.size(); ++c) {
      ch.reset();
      ch.bind(1, id).bind(2, static_cast<std::int64_t>(c)).bind(3, hit.channels[c].quantity);
      ch.bind(4, hit.channels[c].unit).bindDof(5, hit.channels[c].dof);
      if (ch.step() != SQLITE_DONE) return sqliteError(db_, "cannot store channel " + std::to_string(c), where);
    }
  }
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<StoredHit> ProjectStore::hit(std::int64_t hitId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = hitWhere(path_, hitId);
  StoredHit h;
  {
    sql::Statement stmt(db_,
                        "SELECT id, campaign_id, sequence, point_node, point_direction, recorded_utc, sample_rate_hz,"
                        " channel_count, sample_count, encoding, samples, samples_crc32, accepted, quality_flags,"
                        " quality_reasons FROM hit WHERE id = ?1");
    if (!stmt.ok()) return sqliteError(db_, "cannot read the hit", where);
    stmt.bind(1, hitId);
    const int rc = stmt.step();
    if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such hit", where);
    if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the hit", where);
    h.id = sqlite3_column_int64(stmt.get(), 0);
    h.campaignId = sqlite3_column_int64(stmt.get(), 1);
    h.sequence = sqlite3_column_int(stmt.get(), 2);
    auto point = sql::columnDof(stmt.get(), 3, 4, where);
    if (!point) return point.error();
    h.point = *point;
    h.recordedUtc = sql::columnText(stmt.get(), 5);
    h.sampleRateHz = sqlite3_column_double(stmt.get(), 6);
    if (!(h.sampleRateHz > 0.0) || !finite(h.sampleRateHz)) {
      return makeError(ErrorCode::Corrupt, "stored sample rate is not a positive number", where);
    }
    auto samples = columnSamples(stmt.get(), 7, where);
    if (!samples) return samples.error();
    h.samples = std::move(*samples);
    h.accepted = sqlite3_column_int(stmt.get(), 12) != 0;
    h.qualityFlags = static_cast<std::uint32_t>(sqlite3_column_int64(stmt.get(), 13));
    h.qualityReasons = sql::columnText(stmt.get(), 14);
  }
  sql::Statement ch(db_,
                    "SELECT channel, quantity, unit, dof_node, dof_direction FROM hit_channel WHERE hit_id = ?1"
                    " ORDER BY channel");
  ch.bind(1, hitId);
  int rc;
  while ((rc = ch.step()) == SQLITE_ROW) {
    const std::int64_t index = sqlite3_column_int64(ch.get(), 0);
    if (index != static_cast<std::int64_t>(h.channels.size()) || index >= h.channelCount()) {
      return makeError(ErrorCode::Corrupt, "channel descriptions do not number 0..n-1", where);
    }
    StoredHitChannel c;
    c.quantity = sql::columnText(ch.get(), 1);
    c.unit = sql::columnText(ch.get(), 2);
    c.dof = sql::columnOptionalDof(ch.get(), 3, 4);
    h.channels.push_back(std::move(c));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read channel descriptions", where);
  return h;
}

Result<std::vector<HitInfo>> ProjectStore::hits(std::int64_t campaignId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", campaign " + std::to_string(campaignId);
  sql::Statement stmt(db_,
                      "SELECT id, sequence, point_node, point_direction, recorded_utc, sample_rate_hz, channel_count,"
                      " sample_count, accepted, quality_flags, quality_reasons, length(samples) FROM hit"
                      " WHERE campaign_id = ?1 ORDER BY sequence");
  stmt.bind(1, campaignId);
  std::vector<HitInfo> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    HitInfo h;
    h.id = sqlite3_column_int64(stmt.get(), 0);
    h.sequence = sqlite3_column_int(stmt.get(), 1);
    auto point = sql::columnDof(stmt.get(), 2, 3, hitWhere(path_, h.id));
    if (!point) return point.error();
    h.point = *point;
    h.recordedUtc = sql::columnText(stmt.get(), 4);
    h.sampleRateHz = sqlite3_column_double(stmt.get(), 5);
    h.channelCount = sqlite3_column_int(stmt.get(), 6);
    h.sampleCount = sqlite3_column_int64(stmt.get(), 7);
    h.accepted = sqlite3_column_int(stmt.get(), 8) != 0;
    h.qualityFlags = static_cast<std::uint32_t>(sqlite3_column_int64(stmt.get(), 9));
    h.qualityReasons = sql::columnText(stmt.get(), 10);
    h.storedBytes = sqlite3_column_int64(stmt.get(), 11);
    out.push_back(std::move(h));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot list hits", where);
  return out;
}

Result<void> ProjectStore::setHitAcceptance(std::int64_t hitId, bool accepted, std::uint32_t qualityFlags,
                                            const std::string& reasons) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r;
  const std::string where = hitWhere(path_, hitId);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun();
  sql::Statement stmt(db_, "UPDATE hit SET accepted = ?2, quality_flags = ?3, quality_reasons = ?4 WHERE id = ?1");
  stmt.bind(1, hitId).bind(2, accepted ? 1 : 0).bind(3, static_cast<std::int64_t>(qualityFlags)).bind(4, reasons);
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot update the hit", where);
  if (sqlite3_changes(db_) != 1) return makeError(ErrorCode::NotFound, "no such hit", where);
  return tx.commit();
}

// --- FRFs -------------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addFrfSet(const FrfSetInfo& info, const FrfMatrix& frf,
                                             const std::vector<std::int64_t>& hitIds) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", FRF set '" + info.name + "'";
  if (info.name.empty()) return makeError(ErrorCode::InvalidArgument, "an FRF set needs a name", where);
  if (auto r = frf.validate(); !r) return makeError(r.error().code, r.error().message, where + ": " + r.error().where);
  if (frf.lineCount() == 0 || frf.responseCount() == 0 || frf.referenceCount() == 0) {
    return makeError(ErrorCode::InvalidArgument, "an FRF set needs lines, responses and references", where);
  }
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement set(db_,
                     "INSERT INTO frf_set(specimen_id, campaign_id, name, source, estimator, frf_type, line_count,"
                     " frequency_hz, created_utc, content_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  const std::size_t frequencyBytes = static_cast<std::size_t>(frf.lineCount()) * sizeof(double);
  set.bind(1, info.specimenId).bind(2, info.campaignId).bind(3, info.name).bind(4, info.source);
  set.bind(5, info.estimator).bind(6, static_cast<int>(frf.type)).bind(7, static_cast<std::int64_t>(frf.lineCount()));
  set.bindBlob(8, frf.frequencyHz.data(), frequencyBytes);
  set.bind(9, sql::nowUtc());
  set.bind(10, static_cast<std::int64_t>(ContentCrc()
                                             .add(static_cast<int>(frf.type))
                                             .add(static_cast<std::int64_t>(frf.lineCount()))
                                             .bytes(frf.frequencyHz.data(), frequencyBytes)
                                             .value()));
  if (set.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the FRF set", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  sql::Statement row(db_,
                     "INSERT INTO frf(frf_set_id, response_node, response_direction, reference_node,"
                     " reference_direction, response_index, reference_index, h, coherence, content_crc32)"
                     " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  const auto nf = static_cast<std::size_t>(frf.lineCount());
  for (Eigen::Index i = 0; i < frf.referenceCount(); ++i) {
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      // Column o of h[i] is contiguous (column-major): nf complex<double> = 2 nf doubles.
      const ComplexVector column = frf.h[static_cast<std::size_t>(i)].col(o);
      Vector coherence;
      row.reset();
      row.bind(1, id).bind(2, frf.responses[static_cast<std::size_t>(o)].node);
      row.bind(3, frf.responses[static_cast<std::size_t>(o)].uffCode());
      row.bind(4, frf.references[static_cast<std::size_t>(i)].node);
      row.bind(5, frf.references[static_cast<std::size_t>(i)].uffCode());
      row.bind(6, static_cast<std::int64_t>(o)).bind(7, static_cast<std::int64_t>(i));
      row.bindBlob(8, column.data(), nf * sizeof(Complex));
      ContentCrc crc;
      crc.add(id).add(static_cast<std::int64_t>(o)).add(static_cast<std::int64_t>(i));
      crc.add(frf.responses[static_cast<std::size_t>(o)].node)
          .add(frf.responses[static_cast<std::size_t>(o)].uffCode());
      crc.add(frf.references[static_cast<std::size_t>(i)].node);
      crc.add(frf.references[static_cast<std::size_t>(i)].uffCode());
      crc.bytes(column.data(), nf * sizeof(Complex));
      if (!frf.coherence.empty()) {
        coherence = frf.coherence[static_cast<std::size_t>(i)].col(o);
        row.bindBlob(9, coherence.data(), nf * sizeof(double));
        crc.add(1).bytes(coherence.data(), nf * sizeof(double));
      } else {
        row.bindNull(9);
        crc.add(0);
      }
      row.bind(10, static_cast<std::int64_t>(crc.value()));
      if (row.step() != SQLITE_DONE) return sqliteError(db_, "cannot store an FRF", where);
    }
  }
  sql::Statement link(db_, "INSERT INTO frf_hit(frf_set_id, hit_id) VALUES (?1, ?2)");
  for (std::int64_t hitId : hitIds) {
    link.reset();
    link.bind(1, id).bind(2, hitId);
    if (link.step() != SQLITE_DONE) return sqliteError(db_, "cannot link hit " + std::to_string(hitId), where);
  }
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<std::vector<FrfSetInfo>> ProjectStore::frfSets() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(db_,
                      "SELECT s.id, s.specimen_id, s.campaign_id, s.name, s.source, s.estimator, s.frf_type,"
                      " s.line_count, (SELECT count(DISTINCT response_index) FROM frf WHERE frf_set_id = s.id),"
                      " (SELECT count(DISTINCT reference_index) FROM frf WHERE frf_set_id = s.id)"
                      " FROM frf_set s ORDER BY s.id");
  std::vector<FrfSetInfo> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    FrfSetInfo s;
    s.id = sqlite3_column_int64(stmt.get(), 0);
    s.specimenId = sqlite3_column_int64(stmt.get(), 1);
    if (sqlite3_column_type(stmt.get(), 2) != SQLITE_NULL) s.campaignId = sqlite3_column_int64(stmt.get(), 2);
    s.name = sql::columnText(stmt.get(), 3);
    s.source = sql::columnText(stmt.get(), 4);
    s.estimator = sql::columnText(stmt.get(), 5);
    const int type = sqlite3_column_int(stmt.get(), 6);
    s.type = static_cast<FrfType>(type >= 0 && type <= 2 ? type : 2);
    s.lineCount = sqlite3_column_int64(stmt.get(), 7);
    s.responseCount = sqlite3_column_int(stmt.get(), 8);
    s.referenceCount = sqlite3_column_int(stmt.get(), 9);
    out.push_back(std::move(s));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot list FRF sets", path_);
  return out;
}

Result<FrfMatrix> ProjectStore::frfSet(std::int64_t frfSetId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", FRF set " + std::to_string(frfSetId);
  FrfMatrix frf;
  std::int64_t lines = 0;
  {
    sql::Statement stmt(db_, ("SELECT frf_type, line_count, frequency_hz, " + crcColumn("content_crc32") +
                              " FROM frf_set WHERE id = ?1")
                                 .c_str());
    stmt.bind(1, frfSetId);
    const int rc = stmt.step();
    if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such FRF set", where);
    if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the FRF set", where);
    {
      ContentCrc crc;
      crc.add(sqlite3_column_int64(stmt.get(), 0)).add(sqlite3_column_int64(stmt.get(), 1));
      crc.bytes(sqlite3_column_blob(stmt.get(), 2), static_cast<std::size_t>(sqlite3_column_bytes(stmt.get(), 2)));
      if (auto r = verifyChecksum(stmt.get(), 3, crc.value(), "FRF set (type, lines, frequencies)", where); !r) {
        return r.error();
      }
    }
    const int type = sqlite3_column_int(stmt.get(), 0);
    if (type < 0 || type > 2) return makeError(ErrorCode::Corrupt, "unknown FRF type " + std::to_string(type), where);
    frf.type = static_cast<FrfType>(type);
    lines = sqlite3_column_int64(stmt.get(), 1);
    if (lines <= 0 || lines > kMaxFrfLines) {
      return makeError(ErrorCode::Corrupt, "implausible line count " + std::to_string(lines), where);
    }
    auto f = columnDoubles(stmt.get(), 2, lines, where + ", frequencies");
    if (!f) return f.error();
    frf.frequencyHz = Eigen::Map<const Vector>(f->data(), lines);
  }
  sql::Statement stmt(
      db_, ("SELECT response_index, reference_index, response_node, response_direction, reference_node,"
            " reference_direction, h, coherence, " +
            crcColumn("content_crc32") + " FROM frf WHERE frf_set_id = ?1 ORDER BY reference_index, response_index")
               .c_str());
  stmt.bind(1, frfSetId);
  struct Row {
    std::int64_t o, i;
    Dof response, reference;
    std::vector<double> h, coherence;
  };
  std::vector<Row> rows;
  std::int64_t no = 0, ni = 0;
  bool anyCoherence = false;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    Row r;
    {
      ContentCrc crc;
      crc.add(frfSetId);
      for (int c = 0; c < 6; ++c) crc.add(sqlite3_column_int64(stmt.get(), c));
      crc.bytes(sqlite3_column_blob(stmt.get(), 6), static_cast<std::size_t>(sqlite3_column_bytes(stmt.get(), 6)));
      if (sqlite3_column_type(stmt.get(), 7) == SQLITE_NULL) {
        crc.add(0);
      } else {
        crc.add(1).bytes(sqlite3_column_blob(stmt.get(), 7),
                         static_cast<std::size_t>(sqlite3_column_bytes(stmt.get(), 7)));
      }
      const std::string frfWhere = where + ", FRF row " + std::to_string(sqlite3_column_int64(stmt.get(), 0)) + "/" +
                                   std::to_string(sqlite3_column_int64(stmt.get(), 1)) + " (response " +
                                   std::to_string(sqlite3_column_int64(stmt.get(), 2)) + ", reference " +
                                   std::to_string(sqlite3_column_int64(stmt.get(), 4)) + ")";
      if (auto v = verifyChecksum(stmt.get(), 8, crc.value(), "FRF", frfWhere); !v) return v.error();
    }
    r.o = sqlite3_column_int64(stmt.get(), 0);
    r.i = sqlite3_column_int64(stmt.get(), 1);
    if (r.o < 0 || r.i < 0 || r.o >= 1 << 20 || r.i >= 1 << 20) {
      return makeError(ErrorCode::Corrupt, "FRF index out of range", where);
    }
    auto response = sql::columnDof(stmt.get(), 2, 3, where);
    if (!response) return response.error();
    auto reference = sql::columnDof(stmt.get(), 4, 5, where);
    if (!reference) return reference.error();
    r.response = *response;
    r.reference = *reference;
    auto h = columnDoubles(stmt.get(), 6, 2 * lines,
                           where + ", FRF " + formatDof(r.response) + "/" + formatDof(r.reference));
    if (!h) return h.error();
    r.h = std::move(*h);
    if (sqlite3_column_type(stmt.get(), 7) != SQLITE_NULL) {
      auto c = columnDoubles(stmt.get(), 7, lines, where + ", coherence");
      if (!c) return c.error();
      r.coherence = std::move(*c);
      anyCoherence = true;
    }
    no = std::max(no, r.o + 1);
    ni = std::max(ni, r.i + 1);
    rows.push_back(std::move(r));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read FRFs", where);
  if (rows.empty() || static_cast<std::int64_t>(rows.size()) != no * ni) {
    return makeError(ErrorCode::Corrupt, "the FRF set is not a full responses x references matrix", where);
  }
  frf.responses.resize(static_cast<std::size_t>(no));
  frf.references.resize(static_cast<std::size_t>(ni));
  frf.h.assign(static_cast<std::size_t>(ni), ComplexMatrix(lines, no));
  if (anyCoherence) frf.coherence.assign(static_cast<std::size_t>(ni), Matrix(lines, no));
  for (const Row& r : rows) {
    // Rows are sorted by (i, o) and their count is no * ni, so each (o, i)
    // appears exactly once and in order.
    frf.responses[static_cast<std::size_t>(r.o)] = r.response;
    frf.references[static_cast<std::size_t>(r.i)] = r.reference;
    auto column = frf.h[static_cast<std::size_t>(r.i)].col(r.o);
    for (std::int64_t k = 0; k < lines; ++k) column[k] = Complex(r.h[2 * k], r.h[2 * k + 1]);
    if (anyCoherence) {
      if (r.coherence.empty()) return makeError(ErrorCode::Corrupt, "coherence missing for some FRFs", where);
      std::memcpy(frf.coherence[static_cast<std::size_t>(r.i)].col(r.o).data(), r.coherence.data(),
                  r.coherence.size() * sizeof(double));
    }
  }
  if (auto v = frf.validate(); !v) return makeError(ErrorCode::Corrupt, v.error().message, where);
  return frf;
}

// --- modal results ---------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addModalResult(const ModalResultInfo& info, const ModalTable& table) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", modal result '" + info.name + "'";
  if (info.name.empty()) return makeError(ErrorCode::InvalidArgument, "a modal result needs a name", where);
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    if (!finite(mode.frequencyHz) || mode.frequencyHz < 0 || !finite(mode.dampingRatio)) {
      return makeError(ErrorCode::InvalidArgument,
                       "mode " + std::to_string(m + 1) + " has an invalid frequency or damping", where);
    }
    if (mode.shape.size() != 0 && mode.shape.size() != static_cast<Eigen::Index>(table.dofs.size())) {
      return makeError(ErrorCode::InvalidArgument,
                       "mode " + std::to_string(m + 1) + " shape has " + std::to_string(mode.shape.size()) +
                           " entries for " + std::to_string(table.dofs.size()) + " DOFs",
                       where);
    }
    if (!mode.shape.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "mode " + std::to_string(m + 1) + " shape is not finite", where);
    }
  }
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  ContentCrc crc;
  crc.add(info.bandLowHz).add(info.bandHighHz).add(static_cast<std::int64_t>(table.modes.size()));
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    crc.add(static_cast<std::int64_t>(m)).add(mode.frequencyHz).add(mode.dampingRatio);
    crc.add(static_cast<std::int64_t>(mode.shape.size()));
    for (Eigen::Index d = 0; d < mode.shape.size(); ++d) {
      const Dof& dof = table.dofs[static_cast<std::size_t>(d)];
      crc.add(static_cast<std::int64_t>(d)).add(dof.node).add(dof.uffCode());
      crc.add(mode.shape[d].real()).add(mode.shape[d].imag());
    }
  }
  sql::Statement res(db_,
                     "INSERT INTO modal_result(specimen_id, frf_set_id, name, method, band_low_hz, band_high_hz,"
                     " created_utc, content_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
  res.bind(1, info.specimenId).bind(2, info.frfSetId).bind(3, info.name).bind(4, info.method);
  res.bind(5, info.bandLowHz).bind(6, info.bandHighHz).bind(7, sql::nowUtc());
  res.bind(8, static_cast<std::int64_t>(crc.value()));
  if (res.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the modal result", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  sql::Statement mode(
      db_, "INSERT INTO mode(modal_result_id, mode_index, frequency_hz, damping_ratio) VALUES (?1, ?2, ?3, ?4)");
  sql::Statement shape(db_,
                       "INSERT INTO mode_shape(mode_id, dof_index, dof_node, dof_direction, re, im)"
                       " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    mode.reset();
    mode.bind(1, id).bind(2, static_cast<std::int64_t>(m)).bind(3, table.modes[m].frequencyHz);
    mode.bind(4, table.modes[m].dampingRatio);
    if (mode.step() != SQLITE_DONE) return sqliteError(db_, "cannot store mode " + std::to_string(m + 1), where);
    const std::int64_t modeId = sqlite3_last_insert_rowid(db_);
    for (Eigen::Index d = 0; d < table.modes[m].shape.size(); ++d) {
      shape.reset();
      shape.bind(1, modeId).bind(2, static_cast<std::int64_t>(d));
      shape.bindDof(3, table.dofs[static_cast<std::size_t>(d)]);
      shape.bind(5, table.modes[m].shape[d].real()).bind(6, table.modes[m].shape[d].imag());
      if (shape.step() != SQLITE_DONE) return sqliteError(db_, "cannot store a mode-shape entry", where);
    }
  }
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<std::vector<ModalResultInfo>> ProjectStore::modalResults() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(db_,
                      "SELECT r.id, r.specimen_id, r.frf_set_id, r.name, r.method, r.band_low_hz, r.band_high_hz,"
                      " (SELECT count(*) FROM mode WHERE modal_result_id = r.id) FROM modal_result r ORDER BY r.id");
  std::vector<ModalResultInfo> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    ModalResultInfo m;
    m.id = sqlite3_column_int64(stmt.get(), 0);
    m.specimenId = sqlite3_column_int64(stmt.get(), 1);
    if (sqlite3_column_type(stmt.get(), 2) != SQLITE_NULL) m.frfSetId = sqlite3_column_int64(stmt.get(), 2);
    m.name = sql::columnText(stmt.get(), 3);
    m.method = sql::columnText(stmt.get(), 4);
    m.bandLowHz = sqlite3_column_double(stmt.get(), 5);
    m.bandHighHz = sqlite3_column_double(stmt.get(), 6);
    m.modeCount = sqlite3_column_int(stmt.get(), 7);
    out.push_back(std::move(m));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot list modal results", path_);
  return out;
}

Result<ModalTable> ProjectStore::modalResult(std::int64_t modalResultId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", modal result " + std::to_string(modalResultId);
  sql::Statement head(
      db_,
      ("SELECT band_low_hz, band_high_hz, " + crcColumn("content_crc32") + " FROM modal_result WHERE id = ?1").c_str());
  head.bind(1, modalResultId);
  if (head.step() != SQLITE_ROW) return makeError(ErrorCode::NotFound, "no such modal result", where);
  ContentCrc crc;
  crc.add(sqlite3_column_double(head.get(), 0)).add(sqlite3_column_double(head.get(), 1));
  ModalTable table;
  std::vector<std::int64_t> modeIds;
  std::vector<std::int64_t> modeIndices;
  {
    sql::Statement stmt(db_,
                        "SELECT id, frequency_hz, damping_ratio, mode_index FROM mode WHERE modal_result_id = ?1"
                        " ORDER BY mode_index");
    stmt.bind(1, modalResultId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      modeIds.push_back(sqlite3_column_int64(stmt.get(), 0));
      modeIndices.push_back(sqlite3_column_int64(stmt.get(), 3));
      StoredMode m;
      m.frequencyHz = sqlite3_column_double(stmt.get(), 1);
      m.dampingRatio = sqlite3_column_double(stmt.get(), 2);
      table.modes.push_back(m);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read modes", where);
  }
  crc.add(static_cast<std::int64_t>(modeIds.size()));
  sql::Statement shape(db_,
                       "SELECT dof_index, dof_node, dof_direction, re, im FROM mode_shape WHERE mode_id = ?1"
                       " ORDER BY dof_index");
  for (std::size_t m = 0; m < modeIds.size(); ++m) {
    shape.reset();
    shape.bind(1, modeIds[m]);
    struct Entry {
      std::int64_t index, node, direction;
      double re, im;
    };
    std::vector<Entry> raw;
    int rc;
    while ((rc = shape.step()) == SQLITE_ROW) {
      raw.push_back({sqlite3_column_int64(shape.get(), 0), sqlite3_column_int64(shape.get(), 1),
                     sqlite3_column_int64(shape.get(), 2), sqlite3_column_double(shape.get(), 3),
                     sqlite3_column_double(shape.get(), 4)});
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read a mode shape", where);
    crc.add(modeIndices[m]).add(table.modes[m].frequencyHz).add(table.modes[m].dampingRatio);
    crc.add(static_cast<std::int64_t>(raw.size()));
    for (const auto& e : raw) crc.add(e.index).add(e.node).add(e.direction).add(e.re).add(e.im);
  }
  if (auto r = verifyChecksum(head.get(), 2, crc.value(), "modal result (modes and shapes)", where); !r) {
    return r.error();
  }
  for (std::size_t m = 0; m < modeIds.size(); ++m) {
    shape.reset();
    shape.bind(1, modeIds[m]);
    std::vector<Complex> values;
    std::vector<Dof> dofs;
    int rc;
    while ((rc = shape.step()) == SQLITE_ROW) {
      if (sqlite3_column_int64(shape.get(), 0) != static_cast<std::int64_t>(values.size())) {
        return makeError(ErrorCode::Corrupt, "mode-shape DOFs do not number 0..n-1", where);
      }
      auto dof = sql::columnDof(shape.get(), 1, 2, where);
      if (!dof) return dof.error();
      dofs.push_back(*dof);
      values.emplace_back(sqlite3_column_double(shape.get(), 3), sqlite3_column_double(shape.get(), 4));
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read a mode shape", where);
    if (m == 0) table.dofs = dofs;
    if (!values.empty() && dofs != table.dofs) {
      return makeError(ErrorCode::Corrupt, "mode " + std::to_string(m + 1) + " uses other DOFs than mode 1", where);
    }
    table.modes[m].shape = Eigen::Map<const ComplexVector>(values.data(), static_cast<Eigen::Index>(values.size()));
  }
  return table;
}

// --- rig tests ------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addRigTest(const StoredRigTest& test) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", rig test '" + test.name + "'";
  if (test.name.empty()) return makeError(ErrorCode::InvalidArgument, "a rig test needs a name", where);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO rig_test(specimen_id, rig_setup_id, kind, name, parameters_json, recorded_utc,"
                      " status, status_note, content_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
  stmt.bind(1, test.specimenId).bind(2, test.rigSetupId);
  stmt.bind(3, std::string(test.kind == StoredRigTest::Kind::Static ? "static" : "dynamic"));
  stmt.bind(4, test.name).bind(5, test.parametersJson).bind(6, sql::nowUtc());
  stmt.bind(7, std::string(testStatusName(test.status))).bind(8, test.statusNote);
  stmt.bind(9, static_cast<std::int64_t>(rigTestChecksum(test)));
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the rig test", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (auto r = insertRigResults(id, test.results, where); !r) return r.error();
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<void> ProjectStore::insertRigResults(std::int64_t rigTestId, const std::vector<StoredRigTest::Result>& results,
                                            const std::string& where) {
  sql::Statement res(db_,
                     "INSERT INTO rig_test_result(rig_test_id, quantity, value, unit, uncertainty, step)"
                     " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (const auto& r : results) {
    if (!finite(r.value) || !finite(r.uncertainty) || r.uncertainty < 0) {
      return makeError(ErrorCode::InvalidArgument, "result '" + r.quantity + "' is not finite", where);
    }
    res.reset();
    res.bind(1, rigTestId).bind(2, r.quantity).bind(3, r.value).bind(4, r.unit).bind(5, r.uncertainty);
    bindStep(res, 6, r.step);
    if (res.step() != SQLITE_DONE) return sqliteError(db_, "cannot store result '" + r.quantity + "'", where);
  }
  // Results arrive step by step: the checksum covers them all, so it is
  // computed again from what is now stored (inside the caller's transaction).
  auto stored = readRigTest(rigTestId, false);
  if (!stored) return stored.error();
  sql::Statement crc(db_, "UPDATE rig_test SET content_crc32 = ?2 WHERE id = ?1");
  crc.bind(1, rigTestId).bind(2, static_cast<std::int64_t>(rigTestChecksum(*stored)));
  if (crc.step() != SQLITE_DONE) return sqliteError(db_, "cannot update the rig test's checksum", where);
  return {};
}

Result<StoredRigTest> ProjectStore::rigTest(std::int64_t rigTestId) const {
  return readRigTest(rigTestId, true);
}

Result<StoredRigTest> ProjectStore::readRigTest(std::int64_t rigTestId, bool verify) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId);
  StoredRigTest t;
  sql::Statement head(db_, ("SELECT id, specimen_id, rig_setup_id, kind, name, parameters_json, status, status_note,"
                            " recorded_utc, " +
                            crcColumn("content_crc32") + " FROM rig_test WHERE id = ?1")
                               .c_str());
  head.bind(1, rigTestId);
  {
    sql::Statement& stmt = head;
    const int rc = stmt.step();
    if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such rig test", where);
    if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the rig test", where);
    t.id = sqlite3_column_int64(stmt.get(), 0);
    t.specimenId = sqlite3_column_int64(stmt.get(), 1);
    if (sqlite3_column_type(stmt.get(), 2) != SQLITE_NULL) t.rigSetupId = sqlite3_column_int64(stmt.get(), 2);
    t.kind = sql::columnText(stmt.get(), 3) == "dynamic" ? StoredRigTest::Kind::Dynamic : StoredRigTest::Kind::Static;
    t.name = sql::columnText(stmt.get(), 4);
    t.parametersJson = sql::columnText(stmt.get(), 5);
    t.status = parseTestStatus(sql::columnText(stmt.get(), 6));
    t.statusNote = sql::columnText(stmt.get(), 7);
    t.recordedUtc = sql::columnText(stmt.get(), 8);
  }
  sql::Statement stmt(
      db_, "SELECT quantity, value, unit, uncertainty, step FROM rig_test_result WHERE rig_test_id = ?1 ORDER BY id");
  stmt.bind(1, rigTestId);
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    StoredRigTest::Result r{sql::columnText(stmt.get(), 0), sqlite3_column_double(stmt.get(), 1),
                            sql::columnText(stmt.get(), 2), sqlite3_column_double(stmt.get(), 3), std::nullopt};
    if (sqlite3_column_type(stmt.get(), 4) != SQLITE_NULL) r.step = sqlite3_column_int(stmt.get(), 4);
    t.results.push_back(r);
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read rig test results", where);
  if (sql::columnText(head.get(), 3) != "static" && sql::columnText(head.get(), 3) != "dynamic") {
    return makeError(ErrorCode::Corrupt, "unknown rig test kind '" + sql::columnText(head.get(), 3) + "'", where);
  }
  if (auto r = verify ? verifyChecksum(head.get(), 9, rigTestChecksum(t), "rig test (parameters and results)", where)
                      : Result<void>{};
      !r) {
    return r.error();
  }
  return t;
}

Result<std::int64_t> ProjectStore::addRigTestRecord(std::int64_t rigTestId, int step, double sampleRateHz,
                                                    const Eigen::MatrixXf& samples) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  if (auto r = insertRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, samples, hitEncoding_, where); !r)
    return r.error();
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<Eigen::MatrixXf> ProjectStore::rigTestRecord(std::int64_t rigTestId, int step, double* sampleRateHz) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  return readRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, where);
}

// --- tyre tests -------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addTyreTest(const StoredTyreTest& test) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", tyre test '" + test.name + "'";
  if (test.name.empty()) return makeError(ErrorCode::InvalidArgument, "a tyre test needs a name", where);
  if (!finite(test.inflationPressurePa) || !finite(test.verticalLoadN) || !finite(test.speedMps)) {
    return makeError(ErrorCode::InvalidArgument, "operating condition is not finite", where);
  }
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO tyre_test(specimen_id, rig_setup_id, name, kind, inflation_pressure_pa,"
                      " vertical_load_n, speed_m_s, recorded_utc, status, status_note, parameters_json, content_crc32)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)");
  stmt.bind(1, test.specimenId).bind(2, test.rigSetupId).bind(3, test.name).bind(4, test.kind);
  stmt.bind(5, test.inflationPressurePa).bind(6, test.verticalLoadN).bind(7, test.speedMps).bind(8, sql::nowUtc());
  stmt.bind(9, std::string(testStatusName(test.status))).bind(10, test.statusNote).bind(11, test.parametersJson);
  stmt.bind(12, static_cast<std::int64_t>(tyreTestChecksum(test)));
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the tyre test", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (auto r = insertTyreData(id, 0, test.points, test.parameters, where); !r) return r.error();
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<void> ProjectStore::insertTyreData(std::int64_t tyreTestId, std::int64_t firstPoint,
                                          const std::vector<StoredTyreTest::Point>& points,
                                          const std::vector<StoredTyreTest::Parameter>& parameters,
                                          const std::string& where) {
  sql::Statement pt(
      db_,
      "INSERT INTO tyre_test_point(tyre_test_id, point_index, slip_angle_rad, camber_rad, lateral_force_n,"
      " aligning_moment_nm, overturning_moment_nm) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& p = points[k];
    const std::int64_t index = firstPoint + static_cast<std::int64_t>(k);
    if (!finite(p.slipAngleRad) || !finite(p.camberRad) || !finite(p.lateralForceN) || !finite(p.aligningMomentNm) ||
        !finite(p.overturningMomentNm)) {
      return makeError(ErrorCode::InvalidArgument, "point " + std::to_string(index) + " is not finite", where);
    }
    pt.reset();
    pt.bind(1, tyreTestId).bind(2, index).bind(3, p.slipAngleRad).bind(4, p.camberRad);
    pt.bind(5, p.lateralForceN).bind(6, p.aligningMomentNm).bind(7, p.overturningMomentNm);
    if (pt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store point " + std::to_string(index), where);
  }
  sql::Statement par(db_,
                     "INSERT INTO tyre_parameter(tyre_test_id, name, value, unit, uncertainty, step)"
                     " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (const auto& p : parameters) {
    if (!finite(p.value) || !finite(p.uncertainty) || p.uncertainty < 0) {
      return makeError(ErrorCode::InvalidArgument, "parameter '" + p.name + "' is not finite", where);
    }
    par.reset();
    par.bind(1, tyreTestId).bind(2, p.name).bind(3, p.value).bind(4, p.unit).bind(5, p.uncertainty);
    bindStep(par, 6, p.step);
    if (par.step() != SQLITE_DONE) return sqliteError(db_, "cannot store parameter '" + p.name + "'", where);
  }
  // Points and parameters arrive step by step: the checksum is computed again
  // from what is now stored (inside the caller's transaction).
  auto stored = readTyreTest(tyreTestId, false);
  if (!stored) return stored.error();
  sql::Statement crc(db_, "UPDATE tyre_test SET content_crc32 = ?2 WHERE id = ?1");
  crc.bind(1, tyreTestId).bind(2, static_cast<std::int64_t>(tyreTestChecksum(*stored)));
  if (crc.step() != SQLITE_DONE) return sqliteError(db_, "cannot update the tyre test's checksum", where);
  return {};
}

Result<StoredTyreTest> ProjectStore::tyreTest(std::int64_t tyreTestId) const {
  return readTyreTest(tyreTestId, true);
}

Result<StoredTyreTest> ProjectStore::readTyreTest(std::int64_t tyreTestId, bool verify) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId);
  StoredTyreTest t;
  sql::Statement head(db_, ("SELECT id, specimen_id, rig_setup_id, name, kind, inflation_pressure_pa, vertical_load_n,"
                            " speed_m_s, status, status_note, parameters_json, recorded_utc, " +
                            crcColumn("content_crc32") + " FROM tyre_test WHERE id = ?1")
                               .c_str());
  {
    sql::Statement& stmt = head;
    stmt.bind(1, tyreTestId);
    const int rc = stmt.step();
    if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such tyre test", where);
    if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the tyre test", where);
    t.id = sqlite3_column_int64(stmt.get(), 0);
    t.specimenId = sqlite3_column_int64(stmt.get(), 1);
    if (sqlite3_column_type(stmt.get(), 2) != SQLITE_NULL) t.rigSetupId = sqlite3_column_int64(stmt.get(), 2);
    t.name = sql::columnText(stmt.get(), 3);
    t.kind = sql::columnText(stmt.get(), 4);
    t.inflationPressurePa = sqlite3_column_double(stmt.get(), 5);
    t.verticalLoadN = sqlite3_column_double(stmt.get(), 6);
    t.speedMps = sqlite3_column_double(stmt.get(), 7);
    t.status = parseTestStatus(sql::columnText(stmt.get(), 8));
    t.statusNote = sql::columnText(stmt.get(), 9);
    t.parametersJson = sql::columnText(stmt.get(), 10);
    t.recordedUtc = sql::columnText(stmt.get(), 11);
  }
  {
    sql::Statement stmt(db_,
                        "SELECT slip_angle_rad, camber_rad, lateral_force_n, aligning_moment_nm, overturning_moment_nm"
                        " FROM tyre_test_point WHERE tyre_test_id = ?1 ORDER BY point_index");
    stmt.bind(1, tyreTestId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredTyreTest::Point p;
      p.slipAngleRad = sqlite3_column_double(stmt.get(), 0);
      p.camberRad = sqlite3_column_double(stmt.get(), 1);
      p.lateralForceN = sqlite3_column_double(stmt.get(), 2);
      p.aligningMomentNm = sqlite3_column_double(stmt.get(), 3);
      p.overturningMomentNm = sqlite3_column_double(stmt.get(), 4);
      t.points.push_back(p);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read tyre test points", where);
  }
  sql::Statement stmt(
      db_, "SELECT name, value, unit, uncertainty, step FROM tyre_parameter WHERE tyre_test_id = ?1 ORDER BY id");
  stmt.bind(1, tyreTestId);
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    StoredTyreTest::Parameter p{sql::columnText(stmt.get(), 0), sqlite3_column_double(stmt.get(), 1),
                                sql::columnText(stmt.get(), 2), sqlite3_column_double(stmt.get(), 3), std::nullopt};
    if (sqlite3_column_type(stmt.get(), 4) != SQLITE_NULL) p.step = sqlite3_column_int(stmt.get(), 4);
    t.parameters.push_back(p);
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read tyre parameters", where);
  if (auto r = verify ? verifyChecksum(head.get(), 12, tyreTestChecksum(t), "tyre test (points and parameters)", where)
                      : Result<void>{};
      !r) {
    return r.error();
  }
  return t;
}

// --- tests run step by step (devices/rigtests) ---------------------------------------------

Result<void> ProjectStore::commitRigTestStep(std::int64_t rigTestId, int step, double sampleRateHz,
                                             const Eigen::MatrixXf& samples,
                                             const std::vector<StoredRigTest::Result>& results,
                                             const std::string& runningNote) {
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  if (samples.size() > 0) {
    if (auto r = insertRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, samples, hitEncoding_, where); !r)
      return r.error();
  }
  if (auto r = insertRigResults(rigTestId, results, where); !r) return r.error();
  if (auto r = setStatusNote(db_, "rig_test", rigTestId, runningNote, where); !r) return r.error();
  return tx.commit();
}

Result<void> ProjectStore::finishRigTest(std::int64_t rigTestId, TestStatus status, const std::string& note,
                                         const std::vector<StoredRigTest::Result>& results) {
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  if (auto r = setFinalStatus(db_, "rig_test", rigTestId, status, note, where); !r) return r.error();
  if (auto r = insertRigResults(rigTestId, results, where); !r) return r.error();
  return tx.commit();
}

Result<void> ProjectStore::commitTyreTestStep(std::int64_t tyreTestId, int step, double sampleRateHz,
                                              const Eigen::MatrixXf& samples,
                                              const std::vector<StoredTyreTest::Point>& points,
                                              const std::vector<StoredTyreTest::Parameter>& parameters,
                                              const std::string& runningNote) {
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId) + ", step " + std::to_string(step);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  if (samples.size() > 0) {
    if (auto r = insertRecord(db_, "tyre_test_record", tyreTestId, step, sampleRateHz, samples, hitEncoding_, where);
        !r)
      return r.error();
  }
  sql::Statement next(db_, "SELECT COALESCE(MAX(point_index) + 1, 0) FROM tyre_test_point WHERE tyre_test_id = ?1");
  next.bind(1, tyreTestId);
  if (next.step() != SQLITE_ROW) return sqliteError(db_, "cannot count the test's points", where);
  const std::int64_t first = sqlite3_column_int64(next.get(), 0);
  if (auto r = insertTyreData(tyreTestId, first, points, parameters, where); !r) return r.error();
  if (auto r = setStatusNote(db_, "tyre_test", tyreTestId, runningNote, where); !r) return r.error();
  return tx.commit();
}

Result<void> ProjectStore::finishTyreTest(std::int64_t tyreTestId, TestStatus status, const std::string& note,
                                          const std::vector<StoredTyreTest::Parameter>& parameters) {
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  if (auto r = setFinalStatus(db_, "tyre_test", tyreTestId, status, note, where); !r) return r.error();
  if (auto r = insertTyreData(tyreTestId, 0, {}, parameters, where); !r) return r.error();
  return tx.commit();
}

Result<Eigen::MatrixXf> ProjectStore::tyreTestRecord(std::int64_t tyreTestId, int step, double* sampleRateHz) const {
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId) + ", step " + std::to_string(step);
  return readRecord(db_, "tyre_test_record", tyreTestId, step, sampleRateHz, where);
}

namespace {
Result<std::vector<TestInfo>> listTests(sqlite3* db, const char* text, const std::string& where) {
  sql::Statement stmt(db, text);
  std::vector<TestInfo> out;
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    TestInfo t;
    t.id = sqlite3_column_int64(stmt.get(), 0);
    t.specimenId = sqlite3_column_int64(stmt.get(), 1);
    t.specimenName = sql::columnText(stmt.get(), 2);
    t.kind = sql::columnText(stmt.get(), 3);
    t.name = sql::columnText(stmt.get(), 4);
    t.status = parseTestStatus(sql::columnText(stmt.get(), 5));
    t.statusNote = sql::columnText(stmt.get(), 6);
    t.recordedUtc = sql::columnText(stmt.get(), 7);
    t.recordCount = sqlite3_column_int(stmt.get(), 8);
    t.resultCount = sqlite3_column_int(stmt.get(), 9);
    out.push_back(t);
  }
  if (rc != SQLITE_DONE) return sqliteError(db, "cannot list the tests", where);
  return out;
}
}  // namespace

Result<std::vector<TestInfo>> ProjectStore::rigTests() const {
  return listTests(db_,
                   "SELECT t.id, t.specimen_id, s.name, t.kind, t.name, t.status, t.status_note, t.recorded_utc,"
                   " (SELECT COUNT(*) FROM rig_test_record r WHERE r.rig_test_id = t.id),"
                   " (SELECT COUNT(*) FROM rig_test_result r WHERE r.rig_test_id = t.id)"
                   " FROM rig_test t JOIN specimen s ON s.id = t.specimen_id ORDER BY t.id",
                   path_ + ", rig tests");
}

Result<std::vector<TestInfo>> ProjectStore::tyreTests() const {
  return listTests(db_,
                   "SELECT t.id, t.specimen_id, s.name, t.kind, t.name, t.status, t.status_note, t.recorded_utc,"
                   " (SELECT COUNT(*) FROM tyre_test_record r WHERE r.tyre_test_id = t.id),"
                   " (SELECT COUNT(*) FROM tyre_parameter r WHERE r.tyre_test_id = t.id)"
                   " FROM tyre_test t JOIN specimen s ON s.id = t.specimen_id ORDER BY t.id",
                   path_ + ", tyre tests");
}

// --- models and analyses ------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addModel(const StoredModel& model) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", model '" + model.name + "'";
  if (model.name.empty()) return makeError(ErrorCode::InvalidArgument, "a model needs a name", where);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO model(specimen_id, name, kind, source, parameters_json, created_utc)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  stmt.bind(1, model.specimenId).bind(2, model.name).bind(3, model.kind).bind(4, model.source);
  stmt.bind(5, model.parametersJson).bind(6, sql::nowUtc());
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the model", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<std::int64_t> ProjectStore::addAnalysis(const StoredAnalysis& analysis) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  if (auto r = requireWritable(); !r) return r.error();
  const std::string where = path_ + ", analysis '" + analysis.name + "'";
  if (analysis.name.empty()) return makeError(ErrorCode::InvalidArgument, "an analysis needs a name", where);
  sql::Transaction tx(db_, where);
  if (!tx.begun()) return tx.begun().error();
  sql::Statement stmt(db_,
                      "INSERT INTO analysis(specimen_id, model_id, frf_set_id, modal_result_id, rig_test_id,"
                      " tyre_test_id, kind, name, result_json, created_utc)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  stmt.bind(1, analysis.specimenId).bind(2, analysis.modelId).bind(3, analysis.frfSetId);
  stmt.bind(4, analysis.modalResultId).bind(5, analysis.rigTestId).bind(6, analysis.tyreTestId);
  stmt.bind(7, analysis.kind).bind(8, analysis.name).bind(9, analysis.resultJson).bind(10, sql::nowUtc());
  if (stmt.step() != SQLITE_DONE) return sqliteError(db_, "cannot store the analysis", where);
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  sql::Statement f(
      db_,
      "INSERT INTO gap_finding(analysis_id, band_low_hz, band_high_hz, mode_index, dof_node, dof_direction,"
      " condition, effect, size, unit, uncertainty, remaining_gap)"
      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)");
  for (std::size_t k = 0; k < analysis.findings.size(); ++k) {
    const auto& g = analysis.findings[k];
    if (!finite(g.bandLowHz) || !finite(g.bandHighHz) || !finite(g.size) || !finite(g.uncertainty) ||
        !finite(g.remainingGap)) {
      return makeError(ErrorCode::InvalidArgument, "finding " + std::to_string(k + 1) + " is not finite", where);
    }
    f.reset();
    f.bind(1, id).bind(2, g.bandLowHz).bind(3, g.bandHighHz);
    if (g.modeIndex) {
      f.bind(4, *g.modeIndex);
    } else {
      f.bindNull(4);
    }
    f.bindDof(5, g.dof).bind(7, g.condition).bind(8, g.effect).bind(9, g.size).bind(10, g.unit);
    f.bind(11, g.uncertainty).bind(12, g.remainingGap);
    if (f.step() != SQLITE_DONE) return sqliteError(db_, "cannot store finding " + std::to_string(k + 1), where);
  }
  if (auto r = tx.commit(); !r) return r.error();
  return id;
}

Result<StoredAnalysis> ProjectStore::analysis(std::int64_t analysisId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", analysis " + std::to_string(analysisId);
  StoredAnalysis a;
  auto optId = [](sqlite3_stmt* s, int c) -> std::optional<std::int64_t> {
    if (sqlite3_column_type(s, c) == SQLITE_NULL) return std::nullopt;
    return sqlite3_column_int64(s, c);
  };
  {
    sql::Statement stmt(
        db_,
        "SELECT id, specimen_id, model_id, frf_set_id, modal_result_id, rig_test_id, tyre_test_id, kind,"
        " name, result_json FROM analysis WHERE id = ?1");
    stmt.bind(1, analysisId);
    const int rc = stmt.step();
    if (rc == SQLITE_DONE) return makeError(ErrorCode::NotFound, "no such analysis", where);
    if (rc != SQLITE_ROW) return sqliteError(db_, "cannot read the analysis", where);
    a.id = sqlite3_column_int64(stmt.get(), 0);
    a.specimenId = sqlite3_column_int64(stmt.get(), 1);
    a.modelId = optId(stmt.get(), 2);
    a.frfSetId = optId(stmt.get(), 3);
    a.modalResultId = optId(stmt.get(), 4);
    a.rigTestId = optId(stmt.get(), 5);
    a.tyreTestId = optId(stmt.get(), 6);
    a.kind = sql::columnText(stmt.get(), 7);
    a.name = sql::columnText(stmt.get(), 8);
    a.resultJson = sql::columnText(stmt.get(), 9);
  }
  sql::Statement stmt(db_,
                      "SELECT band_low_hz, band_high_hz, mode_index, dof_node, dof_direction, condition, effect, size,"
                      " unit, uncertainty, remaining_gap FROM gap_finding WHERE analysis_id = ?1 ORDER BY id");
  stmt.bind(1, analysisId);
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    StoredAnalysis::Finding g;
    g.bandLowHz = sqlite3_column_double(stmt.get(), 0);
    g.bandHighHz = sqlite3_column_double(stmt.get(), 1);
    if (sqlite3_column_type(stmt.get(), 2) != SQLITE_NULL) g.modeIndex = sqlite3_column_int(stmt.get(), 2);
    g.dof = sql::columnOptionalDof(stmt.get(), 3, 4);
    g.condition = sql::columnText(stmt.get(), 5);
    g.effect = sql::columnText(stmt.get(), 6);
    g.size = sqlite3_column_double(stmt.get(), 7);
    g.unit = sql::columnText(stmt.get(), 8);
    g.uncertainty = sqlite3_column_double(stmt.get(), 9);
    g.remainingGap = sqlite3_column_double(stmt.get(), 10);
    a.findings.push_back(std::move(g));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read findings", where);
  return a;
}

// Every stored analysis with its findings, in id order.
Result<std::vector<StoredAnalysis>> ProjectStore::analyses() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  std::vector<std::int64_t> ids;
  {
    sql::Statement stmt(db_, "SELECT id FROM analysis ORDER BY id");
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) ids.push_back(sqlite3_column_int64(stmt.get(), 0));
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot list the analyses", path_);
  }
  std::vector<StoredAnalysis> out;
  for (const auto id : ids) {
    auto a = analysis(id);
    if (!a) return a.error();
    out.push_back(std::move(*a));
  }
  return out;
}

}  // namespace mozzi::core::io
