// CSV exchange of FRF matrices (docs/formats/csv.md, "FRFs").

#include "core/io/csv/csv_exchange.h"

#include <algorithm>
#include <ostream>
#include <sstream>

#include "core/io/csv/csv_internal.h"

namespace mozzi::core::io::csv {

using namespace detail;  // NOLINT(google-build-using-namespace): the exchange's private helpers

// --- FRFs ---------------------------------------------------------------------------------

Result<void> writeFrfCsv(const FrfMatrix& frf, std::ostream& out) {
  if (auto v = frf.validate(); !v)
    return makeError(v.error().code, v.error().message, "CSV export: " + v.error().where);
  if (frf.lineCount() == 0 || frf.responseCount() == 0 || frf.referenceCount() == 0) {
    return makeError(ErrorCode::InvalidArgument, "empty FRF matrix", "CSV export");
  }
  const char* unit = frfUnitText(frf.type);
  out << kMagic << ", frf\n# frf_type = " << frfTypeName(frf.type) << "\nfrequency [Hz]";
  const bool coherence = !frf.coherence.empty();
  for (std::size_t i = 0; i < frf.references.size(); ++i) {
    for (std::size_t o = 0; o < frf.responses.size(); ++o) {
      const std::string pair = formatDof(frf.responses[o]) + "/" + formatDof(frf.references[i]);
      out << ",H " << pair << " re [" << unit << "],H " << pair << " im [" << unit << ']';
      if (coherence) out << ",coherence " << pair << " [1]";
    }
  }
  out << '\n';
  for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
    out << num(frf.frequencyHz[k]);
    for (std::size_t i = 0; i < frf.references.size(); ++i) {
      for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
        const Complex h = frf.h[i](k, o);
        out << ',' << num(h.real()) << ',' << num(h.imag());
        if (coherence) out << ',' << num(frf.coherence[i](k, o));
      }
    }
    out << '\n';
  }
  return written(out);
}

Result<FrfMatrix> readFrfCsv(std::string_view text, const std::string& source) {
  MOZZI_TRY_ASSIGN(const Table t, parseTableOf(text, source, "frf", "FRFs"));
  const Title f = splitTitle(t.titles[0]);
  auto fUnit = siUnit(f.unit.value_or(""));
  if (lower(f.name) != "frequency" || !fUnit || fUnit->quantity != "frequency") {
    return parseError("first column must be 'frequency [Hz]'", source, t.headerLine, 1);
  }
  // Each FRF: "H <resp>/<ref> re [unit]", "H <resp>/<ref> im [unit]", optional
  // "coherence <resp>/<ref> [1]". Collect them by pair.
  struct Columns {
    int re = -1, im = -1, coh = -1;
    Dof response, reference;
    double factor = 1.0;
  };
  std::vector<std::pair<std::string, Columns>> pairs;
  std::optional<FrfType> type;
  auto find = [&](const std::string& key) -> Columns& {
    for (auto& p : pairs) {
      if (p.first == key) return p.second;
    }
    pairs.emplace_back(key, Columns{});
    return pairs.back().second;
  };
  for (std::size_t c = 1; c < t.titles.size(); ++c) {
    const int col = static_cast<int>(c + 1);
    const Title title = splitTitle(t.titles[c]);
    std::istringstream words(title.name);
    std::string what, pair, part;
    words >> what >> pair >> part;
    what = lower(what);
    part = lower(part);
    const std::size_t slash = pair.find('/');
    if ((what != "h" && what != "coherence") || slash == std::string::npos) {
      return parseError("column title '" + t.titles[c] +
                            "' is not 'H <response>/<reference> re|im [unit]' or "
                            "'coherence <response>/<reference> [1]'",
                        source, t.headerLine, col);
    }
    auto response = parseDof(pair.substr(0, slash));
    auto reference = parseDof(pair.substr(slash + 1));
    if (!response || !reference) {
      return parseError("'" + pair + "' is not a response/reference DOF pair like 21:+Z/1:+Z", source, t.headerLine,
                        col);
    }
    Columns& cols = find(formatDof(*response) + "/" + formatDof(*reference));
    cols.response = *response;
    cols.reference = *reference;
    if (!title.unit) return parseError("column has no unit in brackets", source, t.headerLine, col);
    if (what == "coherence") {
      if (cols.coh >= 0) return parseError("coherence of " + pair + " appears twice", source, t.headerLine, col);
      cols.coh = static_cast<int>(c);
      continue;
    }
    auto u = frfUnit(*title.unit);
    if (!u) return parseError(u.error().message, source, t.headerLine, col);
    if (type && *type != u->type) {
      return parseError("FRF columns mix receptance, mobility and accelerance", source, t.headerLine, col);
    }
    type = u->type;
    int& slot = part == "re" ? cols.re : part == "im" ? cols.im : cols.coh;
    if (part != "re" && part != "im") {
      return parseError("FRF column must end in 're' or 'im' before the unit", source, t.headerLine, col);
    }
    if (slot >= 0) return parseError(part + " part of " + pair + " appears twice", source, t.headerLine, col);
    slot = static_cast<int>(c);
    cols.factor = u->factor;
  }
  if (pairs.empty() || !type) return parseError("no FRF columns", source, t.headerLine);
  // Responses and references in order of first appearance; the set must be
  // the full matrix.
  FrfMatrix frf;
  frf.type = *type;
  for (const auto& [key, cols] : pairs) {
    if (cols.re < 0 || cols.im < 0) {
      return parseError("FRF " + key + " lacks its re or im column", source, t.headerLine);
    }
    if (std::find(frf.responses.begin(), frf.responses.end(), cols.response) == frf.responses.end()) {
      frf.responses.push_back(cols.response);
    }
    if (std::find(frf.references.begin(), frf.references.end(), cols.reference) == frf.references.end()) {
      frf.references.push_back(cols.reference);
    }
  }
  if (pairs.size() != frf.responses.size() * frf.references.size()) {
    return parseError("FRF columns do not form a full responses x references matrix (" + std::to_string(pairs.size()) +
                          " pairs for " + std::to_string(frf.responses.size()) + " x " +
                          std::to_string(frf.references.size()) + ")",
                      source, t.headerLine);
  }
  const bool anyCoh = std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return p.second.coh >= 0; });
  const bool allCoh = std::all_of(pairs.begin(), pairs.end(), [](const auto& p) { return p.second.coh >= 0; });
  if (anyCoh && !allCoh) return parseError("coherence given for some FRFs only", source, t.headerLine);
  const auto nf = static_cast<Eigen::Index>(t.rows.size());
  const auto no = static_cast<Eigen::Index>(frf.responses.size());
  frf.frequencyHz.resize(nf);
  frf.h.assign(frf.references.size(), ComplexMatrix(nf, no));
  if (allCoh) frf.coherence.assign(frf.references.size(), Matrix(nf, no));
  for (const auto& [key, cols] : pairs) {
    const auto o = std::find(frf.responses.begin(), frf.responses.end(), cols.response) - frf.responses.begin();
    const auto i = static_cast<std::size_t>(std::find(frf.references.begin(), frf.references.end(), cols.reference) -
                                            frf.references.begin());
    for (Eigen::Index k = 0; k < nf; ++k) {
      const auto& row = t.rows[static_cast<std::size_t>(k)];
      frf.h[i](k, o) =
          cols.factor * Complex(row[static_cast<std::size_t>(cols.re)], row[static_cast<std::size_t>(cols.im)]);
      if (allCoh) frf.coherence[i](k, o) = row[static_cast<std::size_t>(cols.coh)];
    }
  }
  for (Eigen::Index k = 0; k < nf; ++k) frf.frequencyHz[k] = fUnit->factor * t.rows[static_cast<std::size_t>(k)][0];
  for (Eigen::Index k = 1; k < nf; ++k) {
    if (!(frf.frequencyHz[k] > frf.frequencyHz[k - 1])) {
      return parseError("frequencies must increase strictly", source, t.rowLines[static_cast<std::size_t>(k)], 1);
    }
  }
  if (auto v = frf.validate(); !v)
    return parseError(v.error().message + " (" + v.error().where + ")", source, t.headerLine);
  return frf;
}

}  // namespace mozzi::core::io::csv
