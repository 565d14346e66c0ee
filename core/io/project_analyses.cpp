// ProjectStore: models and analyses with their gap findings.

#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::finite;

// --- models and analyses ------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addModel(const StoredModel& model) {
  const std::string where = path_ + ", model '" + model.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (model.name.empty()) return makeError(ErrorCode::InvalidArgument, "a model needs a name", where);
    sql::Statement stmt(db_,
                        "INSERT INTO model(specimen_id, name, kind, source, parameters_json, created_utc)"
                        " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    return stmt.bindAll(model.specimenId, model.name, model.kind, model.source, model.parametersJson, sql::nowUtc())
        .insert("cannot store the model", where);
  });
}

Result<std::int64_t> ProjectStore::addAnalysis(const StoredAnalysis& analysis) {
  const std::string where = path_ + ", analysis '" + analysis.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (analysis.name.empty()) return makeError(ErrorCode::InvalidArgument, "an analysis needs a name", where);
    sql::Statement stmt(db_,
                        "INSERT INTO analysis(specimen_id, model_id, frf_set_id, modal_result_id, rig_test_id,"
                        " tyre_test_id, kind, name, result_json, created_utc)"
                        " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
    stmt.bindAll(analysis.specimenId, analysis.modelId, analysis.frfSetId, analysis.modalResultId, analysis.rigTestId,
                 analysis.tyreTestId, analysis.kind, analysis.name, analysis.resultJson, sql::nowUtc());
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
      MOZZI_TRY(f.runWith("cannot store finding " + std::to_string(k + 1), where, id, g.bandLowHz, g.bandHighHz,
                          g.modeIndex, g.dof, g.condition, g.effect, g.size, g.unit, g.uncertainty, g.remainingGap));
    }
    return id;
  });
}

Result<StoredAnalysis> ProjectStore::analysis(std::int64_t analysisId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", analysis " + std::to_string(analysisId);
  sql::Statement head(db_,
                      "SELECT id, specimen_id, model_id, frf_set_id, modal_result_id, rig_test_id, tyre_test_id, kind,"
                      " name, result_json FROM analysis WHERE id = ?1");
  MOZZI_TRY(head.lookup(analysisId, "analysis", where));
  StoredAnalysis a;
  sql::Row(head.get())
      .into(a.id, a.specimenId, a.modelId, a.frfSetId, a.modalResultId, a.rigTestId, a.tyreTestId, a.kind, a.name,
            a.resultJson);
  sql::Statement stmt(db_,
                      "SELECT band_low_hz, band_high_hz, mode_index, dof_node, dof_direction, condition, effect, size,"
                      " unit, uncertainty, remaining_gap FROM gap_finding WHERE analysis_id = ?1 ORDER BY id");
  MOZZI_TRY(stmt.bindAll(analysisId).forEachRow("cannot read findings", where, [&](const sql::Row& r) {
    a.findings.push_back({r.real(0), r.real(1), r.optionalInt32(2), r.optionalDof(3, 4), r.text(5), r.text(6),
                          r.real(7), r.text(8), r.real(9), r.real(10)});
  }));
  return a;
}

// Every stored analysis with its findings, in id order.
Result<std::vector<StoredAnalysis>> ProjectStore::analyses() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  std::vector<std::int64_t> ids;
  sql::Statement stmt(db_, "SELECT id FROM analysis ORDER BY id");
  MOZZI_TRY(stmt.forEachRow("cannot list the analyses", path_, [&](const sql::Row& r) { ids.push_back(r.int64(0)); }));
  std::vector<StoredAnalysis> out;
  for (const auto id : ids) {
    MOZZI_TRY_ASSIGN(auto a, analysis(id));
    out.push_back(std::move(a));
  }
  return out;
}

// One query over the analysis table's header columns: a listing never reads
// result_json (a diagnosis keeps its overlay curves there) nor the findings.
Result<std::vector<AnalysisInfo>> ProjectStore::analysisInfos() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(db_, "SELECT id, specimen_id, kind, name FROM analysis ORDER BY id");
  std::vector<AnalysisInfo> out;
  MOZZI_TRY(stmt.forEachRow("cannot list the analyses", path_, [&](const sql::Row& r) {
    AnalysisInfo info;
    r.into(info.id, info.specimenId, info.kind, info.name);
    out.push_back(std::move(info));
  }));
  return out;
}

}  // namespace mozzi::core::io
