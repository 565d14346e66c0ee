// ProjectStore: FRF sets (frequency lines, one row per response/reference
// pair, optional coherence) and the hits they came from.

#include <algorithm>
#include <cstring>
#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::columnDoubles;
using data::ContentCrc;
using data::kMaxFrfLines;
using data::verifyChecksum;

// --- FRFs -------------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addFrfSet(const FrfSetInfo& info, const FrfMatrix& frf,
                                             const std::vector<std::int64_t>& hitIds) {
  const std::string where = path_ + ", FRF set '" + info.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (info.name.empty()) return makeError(ErrorCode::InvalidArgument, "an FRF set needs a name", where);
    // The error keeps the FRF's own place after the set's.
    if (auto r = frf.validate(); !r)
      return makeError(r.error().code, r.error().message, where + ": " + r.error().where);
    if (frf.lineCount() == 0 || frf.responseCount() == 0 || frf.referenceCount() == 0) {
      return makeError(ErrorCode::InvalidArgument, "an FRF set needs lines, responses and references", where);
    }
    return insertFrfSet(info, frf, hitIds, where);
  });
}

Result<std::int64_t> ProjectStore::insertFrfSet(const FrfSetInfo& info, const FrfMatrix& frf,
                                                const std::vector<std::int64_t>& hitIds, const std::string& where) {
  sql::Statement set(db_,
                     "INSERT INTO frf_set(specimen_id, campaign_id, name, source, estimator, frf_type, line_count,"
                     " frequency_hz, created_utc, content_crc32) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  const std::size_t frequencyBytes = static_cast<std::size_t>(frf.lineCount()) * sizeof(double);
  const std::uint32_t setCrc = ContentCrc()
                                   .add(static_cast<int>(frf.type))
                                   .add(static_cast<std::int64_t>(frf.lineCount()))
                                   .bytes(frf.frequencyHz.data(), frequencyBytes)
                                   .value();
  set.bindAll(info.specimenId, info.campaignId, info.name, info.source, info.estimator, frf.type, frf.lineCount(),
              sql::Blob{frf.frequencyHz.data(), frequencyBytes}, sql::nowUtc(), setCrc);
  MOZZI_TRY_ASSIGN(const std::int64_t id, set.insert("cannot store the FRF set", where));
  sql::Statement row(db_,
                     "INSERT INTO frf(frf_set_id, response_node, response_direction, reference_node,"
                     " reference_direction, response_index, reference_index, h, coherence, content_crc32)"
                     " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  const auto nf = static_cast<std::size_t>(frf.lineCount());
  for (Eigen::Index i = 0; i < frf.referenceCount(); ++i) {
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      // Column o of h[i] is contiguous (column-major): nf complex<double> = 2 nf doubles.
      const ComplexVector column = frf.h[static_cast<std::size_t>(i)].col(o);
      const Dof& response = frf.responses[static_cast<std::size_t>(o)];
      const Dof& reference = frf.references[static_cast<std::size_t>(i)];
      Vector coherence;
      ContentCrc crc;
      crc.add(id).add(static_cast<std::int64_t>(o)).add(static_cast<std::int64_t>(i));
      crc.add(response.node).add(response.uffCode()).add(reference.node).add(reference.uffCode());
      crc.bytes(column.data(), nf * sizeof(Complex));
      if (!frf.coherence.empty()) {
        coherence = frf.coherence[static_cast<std::size_t>(i)].col(o);
        crc.add(1).bytes(coherence.data(), nf * sizeof(double));
      } else {
        crc.add(0);
      }
      row.reset();
      row.bindAll(id, response, reference, o, i, sql::Blob{column.data(), nf * sizeof(Complex)});
      if (frf.coherence.empty()) {
        row.bindNull(9);
      } else {
        row.bindBlob(9, coherence.data(), nf * sizeof(double));
      }
      MOZZI_TRY(row.bind(10, static_cast<std::int64_t>(crc.value())).run("cannot store an FRF", where));
    }
  }
  sql::Statement link(db_, "INSERT INTO frf_hit(frf_set_id, hit_id) VALUES (?1, ?2)");
  for (std::int64_t hitId : hitIds)
    MOZZI_TRY(link.runWith("cannot link hit " + std::to_string(hitId), where, id, hitId));
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
  MOZZI_TRY(stmt.forEachRow("cannot list FRF sets", path_, [&](const sql::Row& r) {
    const int type = r.int32(6);  // an unknown type lists as accelerance; frfSet() refuses it
    out.push_back({r.int64(0), r.int64(1), r.optionalInt64(2), r.text(3), r.text(4), r.text(5),
                   static_cast<FrfType>(type >= 0 && type <= 2 ? type : 2), r.int64(7), r.int32(8), r.int32(9)});
  }));
  return out;
}

Result<FrfMatrix> ProjectStore::frfSet(std::int64_t frfSetId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", FRF set " + std::to_string(frfSetId);
  FrfMatrix frf;
  std::int64_t lines = 0;
  {
    sql::Statement stmt(db_, "SELECT frf_type, line_count, frequency_hz, " + crcColumn("content_crc32") +
                                 " FROM frf_set WHERE id = ?1");
    MOZZI_TRY(stmt.lookup(frfSetId, "FRF set", where));
    {
      ContentCrc crc;
      crc.add(sqlite3_column_int64(stmt.get(), 0)).add(sqlite3_column_int64(stmt.get(), 1));
      crc.bytes(sqlite3_column_blob(stmt.get(), 2), static_cast<std::size_t>(sqlite3_column_bytes(stmt.get(), 2)));
      MOZZI_TRY(verifyChecksum(stmt.get(), 3, crc.value(), "FRF set (type, lines, frequencies)", where));
    }
    const int type = sqlite3_column_int(stmt.get(), 0);
    if (type < 0 || type > 2) return makeError(ErrorCode::Corrupt, "unknown FRF type " + std::to_string(type), where);
    frf.type = static_cast<FrfType>(type);
    lines = sqlite3_column_int64(stmt.get(), 1);
    if (lines <= 0 || lines > kMaxFrfLines) {
      return makeError(ErrorCode::Corrupt, "implausible line count " + std::to_string(lines), where);
    }
    MOZZI_TRY_ASSIGN(auto f, columnDoubles(stmt.get(), 2, lines, where + ", frequencies"));
    frf.frequencyHz = Eigen::Map<const Vector>(f.data(), lines);
  }
  // In the order of the UNIQUE (frf_set_id, response_index, reference_index)
  // index: SQLite walks it rather than sorting the FRF blobs in a temporary
  // b-tree (on the demo's 180 FRFs x 3201 lines that sort spilled to disk).
  sql::Statement stmt(db_,
                      "SELECT response_index, reference_index, response_node, response_direction, reference_node,"
                      " reference_direction, h, coherence, " +
                          crcColumn("content_crc32") +
                          " FROM frf WHERE frf_set_id = ?1 ORDER BY response_index, reference_index");
  // A row's checksum over its indices, DOFs and blobs: a damaged value is
  // named by its row, whatever else it breaks.
  auto verifyRow = [&](const sql::Row& row) -> Result<void> {
    sqlite3_stmt* const s = row.get();
    ContentCrc crc;
    crc.add(frfSetId);
    for (int c = 0; c < 6; ++c) crc.add(row.int64(c));
    crc.bytes(sqlite3_column_blob(s, 6), static_cast<std::size_t>(sqlite3_column_bytes(s, 6)));
    if (row.isNull(7)) {
      crc.add(0);
    } else {
      crc.add(1).bytes(sqlite3_column_blob(s, 7), static_cast<std::size_t>(sqlite3_column_bytes(s, 7)));
    }
    const std::string frfWhere = where + ", FRF row " + std::to_string(row.int64(0)) + "/" +
                                 std::to_string(row.int64(1)) + " (response " + std::to_string(row.int64(2)) +
                                 ", reference " + std::to_string(row.int64(4)) + ")";
    return verifyChecksum(s, 8, crc.value(), "FRF", frfWhere);
  };
  // A set whose shape is wrong: a damaged row's checksum names it, else the
  // shape is the error.
  auto shapeError = [&](const std::string& message) -> Error {
    stmt.reset();
    auto checked = stmt.bindAll(frfSetId).forEachRow("cannot read FRFs", where, verifyRow);
    return checked ? Error{ErrorCode::Corrupt, message, where} : checked.error();
  };
  // The matrix's shape first, from the covering UNIQUE index, so that each
  // row's blobs are decoded straight into their column (no copy per row).
  std::int64_t no = 0, ni = 0;
  {
    sql::Statement shape(db_,
                         "SELECT count(*), max(response_index), max(reference_index) FROM frf WHERE frf_set_id = ?1");
    MOZZI_TRY(shape.bindAll(frfSetId).single("cannot read FRFs", "no FRF", where));
    const std::int64_t rowCount = sqlite3_column_int64(shape.get(), 0);
    const std::int64_t lastResponse = sqlite3_column_int64(shape.get(), 1);
    const std::int64_t lastReference = sqlite3_column_int64(shape.get(), 2);
    if (rowCount > 0 &&
        (lastResponse < 0 || lastReference < 0 || lastResponse >= 1 << 20 || lastReference >= 1 << 20)) {
      return shapeError("FRF index out of range");
    }
    no = lastResponse + 1;
    ni = lastReference + 1;
    if (rowCount == 0 || rowCount != no * ni) {
      return shapeError("the FRF set is not a full responses x references matrix");
    }
  }
  frf.responses.resize(static_cast<std::size_t>(no));
  frf.references.resize(static_cast<std::size_t>(ni));
  // no * ni rows with every (o, i) below (no, ni): each appears once unless one
  // repeats, which the schema's UNIQUE forbids but a damaged file may not.
  std::vector<bool> seen(static_cast<std::size_t>(no * ni), false);
  std::int64_t withCoherence = 0;
  auto readRow = [&](const sql::Row& row) -> Result<void> {
    sqlite3_stmt* const s = row.get();
    const std::int64_t o = row.int64(0), i = row.int64(1);
    MOZZI_TRY(verifyRow(row));
    if (o < 0 || i < 0 || o >= no || i >= ni) return makeError(ErrorCode::Corrupt, "FRF index out of range", where);
    const auto cell = static_cast<std::size_t>(o * ni + i);
    if (seen[cell]) {
      return makeError(ErrorCode::Corrupt,
                       "FRF " + std::to_string(o) + "/" + std::to_string(i) + " appears twice in the set", where);
    }
    seen[cell] = true;
    MOZZI_TRY_ASSIGN(const Dof response, row.dof(2, 3, where));
    MOZZI_TRY_ASSIGN(const Dof reference, row.dof(4, 5, where));
    frf.responses[static_cast<std::size_t>(o)] = response;
    frf.references[static_cast<std::size_t>(i)] = reference;
    const std::string blobWhere = where + ", FRF " + formatDof(response) + "/" + formatDof(reference);
    // Blobs are checked against line_count before the matrices are made, so a
    // damaged line count cannot ask for more memory than the file holds.
    MOZZI_TRY(data::checkDoublesBlob(s, 6, 2 * lines, blobWhere));
    if (frf.h.empty()) {
      frf.h.resize(static_cast<std::size_t>(ni));
      for (ComplexMatrix& h : frf.h) h.resize(lines, no);
    }
    // std::complex<double> is an array of (re, im) doubles, the blob's layout.
    std::memcpy(frf.h[static_cast<std::size_t>(i)].col(o).data(), sqlite3_column_blob(s, 6),
                static_cast<std::size_t>(2 * lines) * sizeof(double));
    if (!row.isNull(7)) {
      MOZZI_TRY(data::checkDoublesBlob(s, 7, lines, blobWhere + ", coherence"));
      if (frf.coherence.empty()) {
        frf.coherence.resize(static_cast<std::size_t>(ni));
        for (Matrix& c : frf.coherence) c.resize(lines, no);
      }
      std::memcpy(frf.coherence[static_cast<std::size_t>(i)].col(o).data(), sqlite3_column_blob(s, 7),
                  static_cast<std::size_t>(lines) * sizeof(double));
      ++withCoherence;
    }
    return {};
  };
  MOZZI_TRY(stmt.bindAll(frfSetId).forEachRow("cannot read FRFs", where, readRow));
  if (std::find(seen.begin(), seen.end(), false) != seen.end()) {
    return makeError(ErrorCode::Corrupt, "the FRF set is not a full responses x references matrix", where);
  }
  if (withCoherence != 0 && withCoherence != no * ni) {
    return makeError(ErrorCode::Corrupt, "coherence missing for some FRFs", where);
  }
  if (auto v = frf.validate(); !v) return makeError(ErrorCode::Corrupt, v.error().message, where);
  return frf;
}

}  // namespace mozzi::core::io
