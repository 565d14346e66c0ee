// ProjectStore: rig tests and tyre tests, whole or committed step by step
// (devices/rigtests), their time records and results.

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::finite;
using data::insertRecord;
using data::readRecord;
using data::rigTestChecksum;
using data::setFinalStatus;
using data::setStatusNote;
using data::tyreTestChecksum;
using data::verifyChecksum;
using sql::sqliteError;

// --- rig tests ------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addRigTest(const StoredRigTest& test) {
  const std::string where = path_ + ", rig test '" + test.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (test.name.empty()) return makeError(ErrorCode::InvalidArgument, "a rig test needs a name", where);
    sql::Statement stmt(db_,
                        "INSERT INTO rig_test(specimen_id, rig_setup_id, kind, name, parameters_json, recorded_utc,"
                        " status, status_note, content_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
    stmt.bindAll(test.specimenId, test.rigSetupId,
                 std::string(test.kind == StoredRigTest::Kind::Static ? "static" : "dynamic"), test.name,
                 test.parametersJson, sql::nowUtc(), std::string(testStatusName(test.status)), test.statusNote,
                 rigTestChecksum(test));
    MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the rig test", where));
    MOZZI_TRY(insertRigResults(id, test.results, where));
    return id;
  });
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
    MOZZI_TRY(res.runWith("cannot store result '" + r.quantity + "'", where, rigTestId, r.quantity, r.value, r.unit,
                          r.uncertainty, r.step));
  }
  // Results arrive step by step: the checksum covers them all, so it is
  // computed again from what is now stored (inside the caller's transaction).
  MOZZI_TRY_ASSIGN(auto stored, readRigTest(rigTestId, false));
  sql::Statement crc(db_, "UPDATE rig_test SET content_crc32 = ?2 WHERE id = ?1");
  return crc.bindAll(rigTestId, rigTestChecksum(stored)).run("cannot update the rig test's checksum", where);
}

Result<StoredRigTest> ProjectStore::rigTest(std::int64_t rigTestId) const {
  return readRigTest(rigTestId, true);
}

Result<StoredRigTest> ProjectStore::readRigTest(std::int64_t rigTestId, bool verify) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId);
  sql::Statement head(db_,
                      "SELECT id, specimen_id, rig_setup_id, kind, name, parameters_json, status, status_note,"
                      " recorded_utc, " +
                          crcColumn("content_crc32") + " FROM rig_test WHERE id = ?1");
  MOZZI_TRY(head.lookup(rigTestId, "rig test", where));
  StoredRigTest t;
  std::string kind, status;
  sql::Row(head.get())
      .into(t.id, t.specimenId, t.rigSetupId, kind, t.name, t.parametersJson, status, t.statusNote, t.recordedUtc);
  t.kind = kind == "dynamic" ? StoredRigTest::Kind::Dynamic : StoredRigTest::Kind::Static;
  t.status = parseTestStatus(status);
  sql::Statement stmt(
      db_, "SELECT quantity, value, unit, uncertainty, step FROM rig_test_result WHERE rig_test_id = ?1 ORDER BY id");
  MOZZI_TRY(stmt.bindAll(rigTestId).forEachRow("cannot read rig test results", where, [&](const sql::Row& r) {
    t.results.push_back({r.text(0), r.real(1), r.text(2), r.real(3), r.optionalInt32(4)});
  }));
  if (kind != "static" && kind != "dynamic") {
    return makeError(ErrorCode::Corrupt, "unknown rig test kind '" + kind + "'", where);
  }
  if (verify) {
    MOZZI_TRY(verifyChecksum(head.get(), 9, rigTestChecksum(t), "rig test (parameters and results)", where));
  }
  return t;
}

Result<std::int64_t> ProjectStore::addRigTestRecord(std::int64_t rigTestId, int step, double sampleRateHz,
                                                    const Eigen::MatrixXf& samples) {
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    MOZZI_TRY(insertRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, samples, hitEncoding_, where));
    return static_cast<std::int64_t>(sqlite3_last_insert_rowid(db_));
  });
}

Result<Eigen::MatrixXf> ProjectStore::rigTestRecord(std::int64_t rigTestId, int step, double* sampleRateHz) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  return readRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, where);
}

// --- tyre tests -------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addTyreTest(const StoredTyreTest& test) {
  const std::string where = path_ + ", tyre test '" + test.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (test.name.empty()) return makeError(ErrorCode::InvalidArgument, "a tyre test needs a name", where);
    if (!finite(test.inflationPressurePa) || !finite(test.verticalLoadN) || !finite(test.speedMps)) {
      return makeError(ErrorCode::InvalidArgument, "operating condition is not finite", where);
    }
    sql::Statement stmt(
        db_,
        "INSERT INTO tyre_test(specimen_id, rig_setup_id, name, kind, inflation_pressure_pa, vertical_load_n,"
        " speed_m_s, recorded_utc, status, status_note, parameters_json, content_crc32)"
        " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)");
    stmt.bindAll(test.specimenId, test.rigSetupId, test.name, test.kind, test.inflationPressurePa, test.verticalLoadN,
                 test.speedMps, sql::nowUtc(), std::string(testStatusName(test.status)), test.statusNote,
                 test.parametersJson, tyreTestChecksum(test));
    MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the tyre test", where));
    MOZZI_TRY(insertTyreData(id, 0, test.points, test.parameters, where));
    return id;
  });
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
    MOZZI_TRY(pt.runWith("cannot store point " + std::to_string(index), where, tyreTestId, index, p.slipAngleRad,
                         p.camberRad, p.lateralForceN, p.aligningMomentNm, p.overturningMomentNm));
  }
  sql::Statement par(db_,
                     "INSERT INTO tyre_parameter(tyre_test_id, name, value, unit, uncertainty, step)"
                     " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (const auto& p : parameters) {
    if (!finite(p.value) || !finite(p.uncertainty) || p.uncertainty < 0) {
      return makeError(ErrorCode::InvalidArgument, "parameter '" + p.name + "' is not finite", where);
    }
    MOZZI_TRY(par.runWith("cannot store parameter '" + p.name + "'", where, tyreTestId, p.name, p.value, p.unit,
                          p.uncertainty, p.step));
  }
  // Points and parameters arrive step by step: the checksum is computed again
  // from what is now stored (inside the caller's transaction).
  MOZZI_TRY_ASSIGN(auto stored, readTyreTest(tyreTestId, false));
  sql::Statement crc(db_, "UPDATE tyre_test SET content_crc32 = ?2 WHERE id = ?1");
  return crc.bindAll(tyreTestId, tyreTestChecksum(stored)).run("cannot update the tyre test's checksum", where);
}

Result<StoredTyreTest> ProjectStore::tyreTest(std::int64_t tyreTestId) const {
  return readTyreTest(tyreTestId, true);
}

Result<StoredTyreTest> ProjectStore::readTyreTest(std::int64_t tyreTestId, bool verify) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId);
  sql::Statement head(db_,
                      "SELECT id, specimen_id, rig_setup_id, name, kind, inflation_pressure_pa, vertical_load_n,"
                      " speed_m_s, status, status_note, parameters_json, recorded_utc, " +
                          crcColumn("content_crc32") + " FROM tyre_test WHERE id = ?1");
  MOZZI_TRY(head.lookup(tyreTestId, "tyre test", where));
  StoredTyreTest t;
  std::string status;
  sql::Row(head.get())
      .into(t.id, t.specimenId, t.rigSetupId, t.name, t.kind, t.inflationPressurePa, t.verticalLoadN, t.speedMps,
            status, t.statusNote, t.parametersJson, t.recordedUtc);
  t.status = parseTestStatus(status);
  sql::Statement points(db_,
                        "SELECT slip_angle_rad, camber_rad, lateral_force_n, aligning_moment_nm, overturning_moment_nm"
                        " FROM tyre_test_point WHERE tyre_test_id = ?1 ORDER BY point_index");
  MOZZI_TRY(points.bindAll(tyreTestId).forEachRow("cannot read tyre test points", where, [&](const sql::Row& r) {
    t.points.push_back({r.real(0), r.real(1), r.real(2), r.real(3), r.real(4)});
  }));
  sql::Statement stmt(
      db_, "SELECT name, value, unit, uncertainty, step FROM tyre_parameter WHERE tyre_test_id = ?1 ORDER BY id");
  MOZZI_TRY(stmt.bindAll(tyreTestId).forEachRow("cannot read tyre parameters", where, [&](const sql::Row& r) {
    t.parameters.push_back({r.text(0), r.real(1), r.text(2), r.real(3), r.optionalInt32(4)});
  }));
  if (verify) {
    MOZZI_TRY(verifyChecksum(head.get(), 12, tyreTestChecksum(t), "tyre test (points and parameters)", where));
  }
  return t;
}

// --- tests run step by step (devices/rigtests) ---------------------------------------------

Result<void> ProjectStore::commitRigTestStep(std::int64_t rigTestId, int step, double sampleRateHz,
                                             const Eigen::MatrixXf& samples,
                                             const std::vector<StoredRigTest::Result>& results,
                                             const std::string& runningNote) {
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  return writeInTransaction(where, [&]() -> Result<void> {
    if (samples.size() > 0) {
      MOZZI_TRY(insertRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, samples, hitEncoding_, where));
    }
    MOZZI_TRY(insertRigResults(rigTestId, results, where));
    return setStatusNote(db_, "rig_test", rigTestId, runningNote, where);
  });
}

Result<void> ProjectStore::finishRigTest(std::int64_t rigTestId, TestStatus status, const std::string& note,
                                         const std::vector<StoredRigTest::Result>& results) {
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId);
  return writeInTransaction(where, [&]() -> Result<void> {
    MOZZI_TRY(setFinalStatus(db_, "rig_test", rigTestId, status, note, where));
    return insertRigResults(rigTestId, results, where);
  });
}

Result<void> ProjectStore::commitTyreTestStep(std::int64_t tyreTestId, int step, double sampleRateHz,
                                              const Eigen::MatrixXf& samples,
                                              const std::vector<StoredTyreTest::Point>& points,
                                              const std::vector<StoredTyreTest::Parameter>& parameters,
                                              const std::string& runningNote) {
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId) + ", step " + std::to_string(step);
  return writeInTransaction(where, [&]() -> Result<void> {
    if (samples.size() > 0) {
      MOZZI_TRY(insertRecord(db_, "tyre_test_record", tyreTestId, step, sampleRateHz, samples, hitEncoding_, where));
    }
    sql::Statement next(db_, "SELECT COALESCE(MAX(point_index) + 1, 0) FROM tyre_test_point WHERE tyre_test_id = ?1");
    if (next.bindAll(tyreTestId).step() != SQLITE_ROW) return sqliteError(db_, "cannot count the test's points", where);
    MOZZI_TRY(insertTyreData(tyreTestId, sqlite3_column_int64(next.get(), 0), points, parameters, where));
    return setStatusNote(db_, "tyre_test", tyreTestId, runningNote, where);
  });
}

Result<void> ProjectStore::finishTyreTest(std::int64_t tyreTestId, TestStatus status, const std::string& note,
                                          const std::vector<StoredTyreTest::Parameter>& parameters) {
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId);
  return writeInTransaction(where, [&]() -> Result<void> {
    MOZZI_TRY(setFinalStatus(db_, "tyre_test", tyreTestId, status, note, where));
    return insertTyreData(tyreTestId, 0, {}, parameters, where);
  });
}

Result<Eigen::MatrixXf> ProjectStore::tyreTestRecord(std::int64_t tyreTestId, int step, double* sampleRateHz) const {
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId) + ", step " + std::to_string(step);
  return readRecord(db_, "tyre_test_record", tyreTestId, step, sampleRateHz, where);
}

namespace {
Result<std::vector<TestInfo>> listTests(sqlite3* db, const char* text, const std::string& where) {
  sql::Statement stmt(db, text);
  std::vector<TestInfo> out;
  MOZZI_TRY(stmt.forEachRow("cannot list the tests", where, [&](const sql::Row& r) {
    out.push_back({r.int64(0), r.int64(1), r.text(2), r.text(3), r.text(4), parseTestStatus(r.text(5)), r.text(6),
                   r.text(7), r.int32(8), r.int32(9)});
  }));
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

}  // namespace mozzi::core::io
