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
using sql::sqliteError;

// --- FRFs -------------------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addFrfSet(const FrfSetInfo& info, const FrfMatrix& frf,
                                             const std::vector<std::int64_t>& hitIds) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", FRF set '" + info.name + "'";
  if (info.name.empty()) return makeError(ErrorCode::InvalidArgument, "an FRF set needs a name", where);
  if (auto r = frf.validate(); !r) return makeError(r.error().code, r.error().message, where + ": " + r.error().where);
  if (frf.lineCount() == 0 || frf.responseCount() == 0 || frf.referenceCount() == 0) {
    return makeError(ErrorCode::InvalidArgument, "an FRF set needs lines, responses and references", where);
  }
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
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
      MOZZI_TRY(row.run("cannot store an FRF", where));
    }
  }
  sql::Statement link(db_, "INSERT INTO frf_hit(frf_set_id, hit_id) VALUES (?1, ?2)");
  for (std::int64_t hitId : hitIds) {
    link.reset();
    link.bind(1, id).bind(2, hitId);
    MOZZI_TRY(link.run("cannot link hit " + std::to_string(hitId), where));
  }
  MOZZI_TRY(tx.commit());
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
    MOZZI_TRY(stmt.single("cannot read the FRF set", "no such FRF set", where));
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
      MOZZI_TRY(verifyChecksum(stmt.get(), 8, crc.value(), "FRF", frfWhere));
    }
    r.o = sqlite3_column_int64(stmt.get(), 0);
    r.i = sqlite3_column_int64(stmt.get(), 1);
    if (r.o < 0 || r.i < 0 || r.o >= 1 << 20 || r.i >= 1 << 20) {
      return makeError(ErrorCode::Corrupt, "FRF index out of range", where);
    }
    MOZZI_TRY_ASSIGN(auto response, sql::columnDof(stmt.get(), 2, 3, where));
    MOZZI_TRY_ASSIGN(auto reference, sql::columnDof(stmt.get(), 4, 5, where));
    r.response = response;
    r.reference = reference;
    auto h = columnDoubles(stmt.get(), 6, 2 * lines,
                           where + ", FRF " + formatDof(r.response) + "/" + formatDof(r.reference));
    if (!h) return h.error();
    r.h = std::move(*h);
    if (sqlite3_column_type(stmt.get(), 7) != SQLITE_NULL) {
      MOZZI_TRY_ASSIGN(auto c, columnDoubles(stmt.get(), 7, lines, where + ", coherence"));
      r.coherence = std::move(c);
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

}  // namespace mozzi::core::io
