// ProjectStore: models and analyses with their gap findings.

#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::finite;
using sql::sqliteError;

// --- models and analyses ------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addModel(const StoredModel& model) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", model '" + model.name + "'";
  if (model.name.empty()) return makeError(ErrorCode::InvalidArgument, "a model needs a name", where);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO model(specimen_id, name, kind, source, parameters_json, created_utc)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  stmt.bind(1, model.specimenId).bind(2, model.name).bind(3, model.kind).bind(4, model.source);
  stmt.bind(5, model.parametersJson).bind(6, sql::nowUtc());
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the model", where));
  MOZZI_TRY(tx.commit());
  return id;
}

Result<std::int64_t> ProjectStore::addAnalysis(const StoredAnalysis& analysis) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", analysis '" + analysis.name + "'";
  if (analysis.name.empty()) return makeError(ErrorCode::InvalidArgument, "an analysis needs a name", where);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO analysis(specimen_id, model_id, frf_set_id, modal_result_id, rig_test_id,"
                      " tyre_test_id, kind, name, result_json, created_utc)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  stmt.bind(1, analysis.specimenId).bind(2, analysis.modelId).bind(3, analysis.frfSetId);
  stmt.bind(4, analysis.modalResultId).bind(5, analysis.rigTestId).bind(6, analysis.tyreTestId);
  stmt.bind(7, analysis.kind).bind(8, analysis.name).bind(9, analysis.resultJson).bind(10, sql::nowUtc());
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the analysis", where));
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
    MOZZI_TRY(f.run("cannot store finding " + std::to_string(k + 1), where));
  }
  MOZZI_TRY(tx.commit());
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
    MOZZI_TRY(stmt.single("cannot read the analysis", "no such analysis", where));
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
    MOZZI_TRY_ASSIGN(auto a, analysis(id));
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace mozzi::core::io
