// ProjectStore: rig tests and tyre tests, whole or committed step by step
// (devices/rigtests), their time records and results.

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::bindStep;
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
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", rig test '" + test.name + "'";
  if (test.name.empty()) return makeError(ErrorCode::InvalidArgument, "a rig test needs a name", where);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO rig_test(specimen_id, rig_setup_id, kind, name, parameters_json, recorded_utc,"
                      " status, status_note, content_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
  stmt.bind(1, test.specimenId).bind(2, test.rigSetupId);
  stmt.bind(3, std::string(test.kind == StoredRigTest::Kind::Static ? "static" : "dynamic"));
  stmt.bind(4, test.name).bind(5, test.parametersJson).bind(6, sql::nowUtc());
  stmt.bind(7, std::string(testStatusName(test.status))).bind(8, test.statusNote);
  stmt.bind(9, static_cast<std::int64_t>(rigTestChecksum(test)));
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the rig test", where));
  MOZZI_TRY(insertRigResults(id, test.results, where));
  MOZZI_TRY(tx.commit());
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
    MOZZI_TRY(res.run("cannot store result '" + r.quantity + "'", where));
  }
  // Results arrive step by step: the checksum covers them all, so it is
  // computed again from what is now stored (inside the caller's transaction).
  MOZZI_TRY_ASSIGN(auto stored, readRigTest(rigTestId, false));
  sql::Statement crc(db_, "UPDATE rig_test SET content_crc32 = ?2 WHERE id = ?1");
  crc.bind(1, rigTestId).bind(2, static_cast<std::int64_t>(rigTestChecksum(stored)));
  MOZZI_TRY(crc.run("cannot update the rig test's checksum", where));
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
    MOZZI_TRY(stmt.single("cannot read the rig test", "no such rig test", where));
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
  if (verify) {
    MOZZI_TRY(verifyChecksum(head.get(), 9, rigTestChecksum(t), "rig test (parameters and results)", where));
  }
  return t;
}

Result<std::int64_t> ProjectStore::addRigTestRecord(std::int64_t rigTestId, int step, double sampleRateHz,
                                                    const Eigen::MatrixXf& samples) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  MOZZI_TRY(insertRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, samples, hitEncoding_, where));
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  MOZZI_TRY(tx.commit());
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
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", tyre test '" + test.name + "'";
  if (test.name.empty()) return makeError(ErrorCode::InvalidArgument, "a tyre test needs a name", where);
  if (!finite(test.inflationPressurePa) || !finite(test.verticalLoadN) || !finite(test.speedMps)) {
    return makeError(ErrorCode::InvalidArgument, "operating condition is not finite", where);
  }
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO tyre_test(specimen_id, rig_setup_id, name, kind, inflation_pressure_pa,"
                      " vertical_load_n, speed_m_s, recorded_utc, status, status_note, parameters_json, content_crc32)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)");
  stmt.bind(1, test.specimenId).bind(2, test.rigSetupId).bind(3, test.name).bind(4, test.kind);
  stmt.bind(5, test.inflationPressurePa).bind(6, test.verticalLoadN).bind(7, test.speedMps).bind(8, sql::nowUtc());
  stmt.bind(9, std::string(testStatusName(test.status))).bind(10, test.statusNote).bind(11, test.parametersJson);
  stmt.bind(12, static_cast<std::int64_t>(tyreTestChecksum(test)));
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the tyre test", where));
  MOZZI_TRY(insertTyreData(id, 0, test.points, test.parameters, where));
  MOZZI_TRY(tx.commit());
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
    MOZZI_TRY(pt.run("cannot store point " + std::to_string(index), where));
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
    MOZZI_TRY(par.run("cannot store parameter '" + p.name + "'", where));
  }
  // Points and parameters arrive step by step: the checksum is computed again
  // from what is now stored (inside the caller's transaction).
  MOZZI_TRY_ASSIGN(auto stored, readTyreTest(tyreTestId, false));
  sql::Statement crc(db_, "UPDATE tyre_test SET content_crc32 = ?2 WHERE id = ?1");
  crc.bind(1, tyreTestId).bind(2, static_cast<std::int64_t>(tyreTestChecksum(stored)));
  MOZZI_TRY(crc.run("cannot update the tyre test's checksum", where));
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
    MOZZI_TRY(stmt.single("cannot read the tyre test", "no such tyre test", where));
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
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId) + ", step " + std::to_string(step);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  if (samples.size() > 0) {
    MOZZI_TRY(insertRecord(db_, "rig_test_record", rigTestId, step, sampleRateHz, samples, hitEncoding_, where));
  }
  MOZZI_TRY(insertRigResults(rigTestId, results, where));
  MOZZI_TRY(setStatusNote(db_, "rig_test", rigTestId, runningNote, where));
  return tx.commit();
}

Result<void> ProjectStore::finishRigTest(std::int64_t rigTestId, TestStatus status, const std::string& note,
                                         const std::vector<StoredRigTest::Result>& results) {
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", rig test " + std::to_string(rigTestId);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  MOZZI_TRY(setFinalStatus(db_, "rig_test", rigTestId, status, note, where));
  MOZZI_TRY(insertRigResults(rigTestId, results, where));
  return tx.commit();
}

Result<void> ProjectStore::commitTyreTestStep(std::int64_t tyreTestId, int step, double sampleRateHz,
                                              const Eigen::MatrixXf& samples,
                                              const std::vector<StoredTyreTest::Point>& points,
                                              const std::vector<StoredTyreTest::Parameter>& parameters,
                                              const std::string& runningNote) {
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId) + ", step " + std::to_string(step);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  if (samples.size() > 0) {
    MOZZI_TRY(insertRecord(db_, "tyre_test_record", tyreTestId, step, sampleRateHz, samples, hitEncoding_, where));
  }
  sql::Statement next(db_, "SELECT COALESCE(MAX(point_index) + 1, 0) FROM tyre_test_point WHERE tyre_test_id = ?1");
  next.bind(1, tyreTestId);
  if (next.step() != SQLITE_ROW) return sqliteError(db_, "cannot count the test's points", where);
  const std::int64_t first = sqlite3_column_int64(next.get(), 0);
  MOZZI_TRY(insertTyreData(tyreTestId, first, points, parameters, where));
  MOZZI_TRY(setStatusNote(db_, "tyre_test", tyreTestId, runningNote, where));
  return tx.commit();
}

Result<void> ProjectStore::finishTyreTest(std::int64_t tyreTestId, TestStatus status, const std::string& note,
                                          const std::vector<StoredTyreTest::Parameter>& parameters) {
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", tyre test " + std::to_string(tyreTestId);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  MOZZI_TRY(setFinalStatus(db_, "tyre_test", tyreTestId, status, note, where));
  MOZZI_TRY(insertTyreData(tyreTestId, 0, {}, parameters, where));
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

}  // namespace mozzi::core::io
