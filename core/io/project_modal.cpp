// ProjectStore: modal results (modes and their complex shapes).

#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::ContentCrc;
using data::finite;
using data::verifyChecksum;
using sql::sqliteError;

// --- modal results ---------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addModalResult(const ModalResultInfo& info, const ModalTable& table) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
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
  MOZZI_TRY(tx.begun());
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
  MOZZI_TRY_ASSIGN(const std::int64_t id, res.insert("cannot store the modal result", where));
  sql::Statement mode(
      db_, "INSERT INTO mode(modal_result_id, mode_index, frequency_hz, damping_ratio) VALUES (?1, ?2, ?3, ?4)");
  sql::Statement shape(db_,
                       "INSERT INTO mode_shape(mode_id, dof_index, dof_node, dof_direction, re, im)"
                       " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    mode.reset();
    mode.bind(1, id).bind(2, static_cast<std::int64_t>(m)).bind(3, table.modes[m].frequencyHz);
    mode.bind(4, table.modes[m].dampingRatio);
    MOZZI_TRY_ASSIGN(const std::int64_t modeId, mode.insert("cannot store mode " + std::to_string(m + 1), where));
    for (Eigen::Index d = 0; d < table.modes[m].shape.size(); ++d) {
      shape.reset();
      shape.bind(1, modeId).bind(2, static_cast<std::int64_t>(d));
      shape.bindDof(3, table.dofs[static_cast<std::size_t>(d)]);
      shape.bind(5, table.modes[m].shape[d].real()).bind(6, table.modes[m].shape[d].imag());
      MOZZI_TRY(shape.run("cannot store a mode-shape entry", where));
    }
  }
  MOZZI_TRY(tx.commit());
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
  MOZZI_TRY(verifyChecksum(head.get(), 2, crc.value(), "modal result (modes and shapes)", where));
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
      MOZZI_TRY_ASSIGN(auto dof, sql::columnDof(shape.get(), 1, 2, where));
      dofs.push_back(dof);
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

}  // namespace mozzi::core::io
