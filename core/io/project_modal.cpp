// ProjectStore: modal results (modes and their complex shapes).

#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::ContentCrc;
using data::finite;
using data::verifyChecksum;

// --- modal results ---------------------------------------------------------------------

namespace {

// Checks every mode of a table before anything is written.
Result<void> checkModes(const ModalResultInfo& info, const ModalTable& table, const std::string& where) {
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
    for (const auto& std : {mode.frequencyStdHz, mode.dampingRatioStd}) {
      if (std && (!finite(*std) || *std < 0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "mode " + std::to_string(m + 1) + " has an invalid standard error (negative or not finite)",
                         where);
      }
    }
  }
  return {};
}

// The standard errors in the content checksum: nothing when a mode has none,
// so that results kept before schema 5 keep their checksums; else which are
// present (1: frequency, 2: damping ratio) and their values.
void addUncertainty(ContentCrc& crc, const std::optional<double>& frequencyStdHz,
                    const std::optional<double>& dampingRatioStd) {
  if (!frequencyStdHz && !dampingRatioStd) return;
  crc.add(static_cast<std::int64_t>((frequencyStdHz ? 1 : 0) | (dampingRatioStd ? 2 : 0)));
  if (frequencyStdHz) crc.add(*frequencyStdHz);
  if (dampingRatioStd) crc.add(*dampingRatioStd);
}

}  // namespace

Result<std::int64_t> ProjectStore::addModalResult(const ModalResultInfo& info, const ModalTable& table) {
  const std::string where = path_ + ", modal result '" + info.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    MOZZI_TRY(checkModes(info, table, where));
    return insertModalResult(info, table, where);
  });
}

Result<std::int64_t> ProjectStore::insertModalResult(const ModalResultInfo& info, const ModalTable& table,
                                                     const std::string& where) {
  ContentCrc crc;
  crc.add(info.bandLowHz).add(info.bandHighHz).add(static_cast<std::int64_t>(table.modes.size()));
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    crc.add(static_cast<std::int64_t>(m)).add(mode.frequencyHz).add(mode.dampingRatio);
    addUncertainty(crc, mode.frequencyStdHz, mode.dampingRatioStd);
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
  res.bindAll(info.specimenId, info.frfSetId, info.name, info.method, info.bandLowHz, info.bandHighHz, sql::nowUtc(),
              crc.value());
  MOZZI_TRY_ASSIGN(const std::int64_t id, res.insert("cannot store the modal result", where));
  sql::Statement mode(db_,
                      "INSERT INTO mode(modal_result_id, mode_index, frequency_hz, damping_ratio, frequency_std_hz,"
                      " damping_ratio_std) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  sql::Statement shape(db_,
                       "INSERT INTO mode_shape(mode_id, dof_index, dof_node, dof_direction, re, im)"
                       " VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const StoredMode& stored = table.modes[m];
    MOZZI_TRY_ASSIGN(const std::int64_t modeId,
                     mode.insertWith("cannot store mode " + std::to_string(m + 1), where, id, m, stored.frequencyHz,
                                     stored.dampingRatio, stored.frequencyStdHz, stored.dampingRatioStd));
    for (Eigen::Index d = 0; d < stored.shape.size(); ++d) {
      MOZZI_TRY(shape.runWith("cannot store a mode-shape entry", where, modeId, d,
                              table.dofs[static_cast<std::size_t>(d)], stored.shape[d].real(), stored.shape[d].imag()));
    }
  }
  return id;
}

Result<std::vector<ModalResultInfo>> ProjectStore::modalResults() const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  sql::Statement stmt(db_,
                      "SELECT r.id, r.specimen_id, r.frf_set_id, r.name, r.method, r.band_low_hz, r.band_high_hz,"
                      " (SELECT count(*) FROM mode WHERE modal_result_id = r.id) FROM modal_result r ORDER BY r.id");
  std::vector<ModalResultInfo> out;
  MOZZI_TRY(stmt.forEachRow("cannot list modal results", path_, [&](const sql::Row& r) {
    out.push_back({r.int64(0), r.int64(1), r.optionalInt64(2), r.text(3), r.text(4), r.real(5), r.real(6), r.int32(7)});
  }));
  return out;
}

Result<ModalTable> ProjectStore::modalResult(std::int64_t modalResultId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", modal result " + std::to_string(modalResultId);
  sql::Statement head(
      db_, "SELECT band_low_hz, band_high_hz, " + crcColumn("content_crc32") + " FROM modal_result WHERE id = ?1");
  if (head.bindAll(modalResultId).step() != SQLITE_ROW)
    return makeError(ErrorCode::NotFound, "no such modal result", where);
  ContentCrc crc;
  crc.add(sqlite3_column_double(head.get(), 0)).add(sqlite3_column_double(head.get(), 1));
  ModalTable table;
  std::vector<std::int64_t> modeIds;
  std::vector<std::int64_t> modeIndices;
  const std::string uncertainty = modeUncertainty_ ? "frequency_std_hz, damping_ratio_std" : "NULL, NULL";
  sql::Statement modes(db_, "SELECT id, frequency_hz, damping_ratio, mode_index, " + uncertainty +
                                " FROM mode WHERE modal_result_id = ?1 ORDER BY mode_index");
  MOZZI_TRY(modes.bindAll(modalResultId).forEachRow("cannot read modes", where, [&](const sql::Row& r) {
    modeIds.push_back(r.int64(0));
    modeIndices.push_back(r.int64(3));
    StoredMode mode;
    mode.frequencyHz = r.real(1);
    mode.dampingRatio = r.real(2);
    mode.frequencyStdHz = r.optionalReal(4);
    mode.dampingRatioStd = r.optionalReal(5);
    table.modes.push_back(std::move(mode));
  }));
  crc.add(static_cast<std::int64_t>(modeIds.size()));
  sql::Statement shape(db_,
                       "SELECT dof_index, dof_node, dof_direction, re, im FROM mode_shape WHERE mode_id = ?1"
                       " ORDER BY dof_index");
  for (std::size_t m = 0; m < modeIds.size(); ++m) {
    struct Entry {
      std::int64_t index, node, direction;
      double re, im;
    };
    std::vector<Entry> raw;
    shape.reset();
    MOZZI_TRY(shape.bindAll(modeIds[m]).forEachRow("cannot read a mode shape", where, [&](const sql::Row& r) {
      raw.push_back({r.int64(0), r.int64(1), r.int64(2), r.real(3), r.real(4)});
    }));
    crc.add(modeIndices[m]).add(table.modes[m].frequencyHz).add(table.modes[m].dampingRatio);
    addUncertainty(crc, table.modes[m].frequencyStdHz, table.modes[m].dampingRatioStd);
    crc.add(static_cast<std::int64_t>(raw.size()));
    for (const auto& e : raw) crc.add(e.index).add(e.node).add(e.direction).add(e.re).add(e.im);
  }
  MOZZI_TRY(verifyChecksum(head.get(), 2, crc.value(), "modal result (modes and shapes)", where));
  for (std::size_t m = 0; m < modeIds.size(); ++m) {
    std::vector<Complex> values;
    std::vector<Dof> dofs;
    auto readEntry = [&](const sql::Row& r) -> Result<void> {
      if (r.int64(0) != static_cast<std::int64_t>(values.size())) {
        return makeError(ErrorCode::Corrupt, "mode-shape DOFs do not number 0..n-1", where);
      }
      MOZZI_TRY_ASSIGN(const Dof dof, r.dof(1, 2, where));
      dofs.push_back(dof);
      values.emplace_back(r.real(3), r.real(4));
      return {};
    };
    shape.reset();
    MOZZI_TRY(shape.bindAll(modeIds[m]).forEachRow("cannot read a mode shape", where, readEntry));
    if (m == 0) table.dofs = dofs;
    if (!values.empty() && dofs != table.dofs) {
      return makeError(ErrorCode::Corrupt, "mode " + std::to_string(m + 1) + " uses other DOFs than mode 1", where);
    }
    table.modes[m].shape = Eigen::Map<const ComplexVector>(values.data(), static_cast<Eigen::Index>(values.size()));
  }
  return table;
}

}  // namespace mozzi::core::io
