#include "core/io/csv/csv_exchange.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

#include "core/io/output_file.h"

namespace mozzi::core::io::csv {
namespace {

constexpr const char* kMagic = "# mozzi-csv 1";
constexpr std::uintmax_t kMaxCsvBytes = std::uintmax_t{1} << 31;  // 2 GiB

std::string trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  std::string out(s.substr(b, e - b));
  if (out.size() >= 2 && out.front() == '"' && out.back() == '"') out = out.substr(1, out.size() - 2);
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// 17 significant digits: enough to read back the same double (IEEE 754).
std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// One parsed file: comment keys, header titles and numeric rows, each row
// remembering its 1-based line number for messages.
struct Table {
  std::string kind;  // from "# mozzi-csv 1, <kind>", may be empty for foreign files
  std::map<std::string, std::string> keys;
  std::vector<std::string> titles;
  int headerLine = 0;
  std::vector<std::vector<double>> rows;
  std::vector<int> rowLines;
};

Error parseError(const std::string& message, const std::string& source, int line, int column = 0) {
  std::string where = source + ":" + std::to_string(line);
  if (column > 0) where += ", column " + std::to_string(column);
  return makeError(ErrorCode::ParseError, message, where);
}

std::vector<std::string_view> splitFields(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i < line.size() && line[i] == '"') quoted = !quoted;
    if (i == line.size() || (line[i] == sep && !quoted)) {
      out.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

Result<Table> parseTable(std::string_view text, const std::string& source, int lineOffset = 0) {
  Table t;
  std::size_t pos = 0;
  int lineNo = lineOffset;
  char sep = ',';
  bool first = true;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (first && line.size() >= 3 && static_cast<unsigned char>(line[0]) == 0xEF &&
        static_cast<unsigned char>(line[1]) == 0xBB && static_cast<unsigned char>(line[2]) == 0xBF) {
      line.remove_prefix(3);  // UTF-8 byte-order mark written by spreadsheet programs
    }
    first = false;
    const std::string trimmed = trim(line);
    if (trimmed.empty()) continue;
    if (trimmed[0] == '#') {
      if (trimmed.rfind(kMagic, 0) == 0) {
        const std::size_t comma = trimmed.find(',');
        if (comma != std::string::npos) t.kind = lower(trim(std::string_view(trimmed).substr(comma + 1)));
        continue;
      }
      const std::size_t eq = trimmed.find('=');
      if (eq != std::string::npos) {
        t.keys[lower(trim(std::string_view(trimmed).substr(1, eq - 1)))] =
            trim(std::string_view(trimmed).substr(eq + 1));
      }
      continue;
    }
    if (t.titles.empty()) {
      // The header decides the separator: ',' unless it has none and ';' or tab.
      if (line.find(',') == std::string_view::npos) {
        if (line.find(';') != std::string_view::npos)
          sep = ';';
        else if (line.find('\t') != std::string_view::npos)
          sep = '\t';
      }
      for (auto f : splitFields(line, sep)) t.titles.push_back(trim(f));
      t.headerLine = lineNo;
      continue;
    }
    const auto fields = splitFields(line, sep);
    if (fields.size() != t.titles.size()) {
      return parseError("expected " + std::to_string(t.titles.size()) + " fields as in the header, found " +
                            std::to_string(fields.size()),
                        source, lineNo);
    }
    std::vector<double> row(fields.size());
    for (std::size_t c = 0; c < fields.size(); ++c) {
      std::string f = trim(fields[c]);
      if (!f.empty() && f[0] == '+') f.erase(0, 1);
      const char* b = f.data();
      const char* e = f.data() + f.size();
      auto [ptr, ec] = std::from_chars(b, e, row[c]);
      if (f.empty() || ec != std::errc() || ptr != e) {
        return parseError("'" + f.substr(0, 40) + "' is not a number (decimal point, no thousands separator)", source,
                          lineNo, static_cast<int>(c + 1));
      }
      if (!std::isfinite(row[c])) {
        return parseError("value is not finite", source, lineNo, static_cast<int>(c + 1));
      }
    }
    t.rows.push_back(std::move(row));
    t.rowLines.push_back(lineNo);
  }
  if (t.titles.empty()) return parseError("no header line with column titles", source, std::max(lineNo, 1));
  if (t.rows.empty()) return parseError("no data rows after the header", source, t.headerLine);
  return t;
}

// "accel 21:+Z [m/s^2]" -> name "accel 21:+Z", unit "m/s^2". A title without
// brackets has no unit (error for the caller to word).
struct Title {
  std::string name;
  std::optional<std::string> unit;
};

Title splitTitle(const std::string& title) {
  const std::size_t open = title.rfind('[');
  const std::size_t close = title.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return {trim(title), std::nullopt};
  return {trim(std::string_view(title).substr(0, open)),
          trim(std::string_view(title).substr(open + 1, close - open - 1))};
}

// Last whitespace-separated word of a name that parses as a DOF.
std::optional<Dof> dofInName(const std::string& name) {
  const std::size_t space = name.find_last_of(" \t");
  const std::string word = space == std::string::npos ? name : name.substr(space + 1);
  if (word.empty() || !std::isdigit(static_cast<unsigned char>(word[0]))) return std::nullopt;
  auto dof = parseDof(word);
  if (!dof) return std::nullopt;
  return *dof;
}

struct FrfUnit {
  FrfType type;
  double factor;
};

// FRF units: <response unit>/<force unit>, e.g. "m/s^2/N", "g/N", "mm/N".
Result<FrfUnit> frfUnit(const std::string& unit) {
  const std::size_t slash = unit.rfind('/');
  if (slash == std::string::npos) return makeError(ErrorCode::ParseError, "FRF unit '" + unit + "' has no '/N'");
  auto force = siUnit(std::string_view(unit).substr(slash + 1));
  auto response = siUnit(std::string_view(unit).substr(0, slash));
  if (!force || force->quantity != "force" || !response) {
    return makeError(ErrorCode::ParseError, "FRF unit '" + unit + "' is not a translational response per force");
  }
  FrfType type;
  if (response->quantity == "displacement")
    type = FrfType::Receptance;
  else if (response->quantity == "velocity")
    type = FrfType::Mobility;
  else if (response->quantity == "acceleration")
    type = FrfType::Accelerance;
  else
    return makeError(ErrorCode::ParseError,
                     "FRF unit '" + unit + "' is not displacement, velocity or acceleration per force");
  return FrfUnit{type, response->factor / force->factor};
}

const char* frfUnitText(FrfType type) {
  switch (type) {
    case FrfType::Receptance: return "m/N";
    case FrfType::Mobility: return "m/s/N";
    case FrfType::Accelerance: return "m/s^2/N";
  }
  return "m/s^2/N";
}

Result<std::string> readWholeFile(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return makeError(ErrorCode::NotFound, "cannot read the file: " + ec.message(), path);
  if (size > kMaxCsvBytes) return makeError(ErrorCode::Unsupported, "CSV files above 2 GiB are not read", path);
  std::ifstream in(path, std::ios::binary);
  if (!in) return makeError(ErrorCode::IoError, "cannot open the file", path);
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size)) return makeError(ErrorCode::IoError, "short read", path);
  return text;
}

Result<void> writeFile(const std::string& path, const std::string& text) {
  return writeOutputFile(path, text);  // temporary file renamed into place (core/io/output_file.h)
}

}  // namespace

Result<SiUnit> siUnit(std::string_view text) {
  static const std::map<std::string, SiUnit> kUnits = {
      {"n", {1.0, "N", "force"}},
      {"kn", {1e3, "N", "force"}},
      {"lbf", {4.4482216152605, "N", "force"}},
      {"m/s^2", {1.0, "m/s^2", "acceleration"}},
      {"m/s2", {1.0, "m/s^2", "acceleration"}},
      {"mm/s^2", {1e-3, "m/s^2", "acceleration"}},
      {"g", {9.80665, "m/s^2", "acceleration"}},  // standard gravity, ISO 80000-3
      {"m/s", {1.0, "m/s", "velocity"}},
      {"mm/s", {1e-3, "m/s", "velocity"}},
      {"m", {1.0, "m", "displacement"}},
      {"mm", {1e-3, "m", "displacement"}},
      {"um", {1e-6, "m", "displacement"}},
      {"s", {1.0, "s", "time"}},
      {"ms", {1e-3, "s", "time"}},
      {"hz", {1.0, "Hz", "frequency"}},
      {"khz", {1e3, "Hz", "frequency"}},
      {"v", {1.0, "V", "voltage"}},
      {"mv", {1e-3, "V", "voltage"}},
      {"pa", {1.0, "Pa", "pressure"}},
      {"kpa", {1e3, "Pa", "pressure"}},
      {"bar", {1e5, "Pa", "pressure"}},
      {"rad", {1.0, "rad", "angle"}},
      {"deg", {M_PI / 180.0, "rad", "angle"}},
      {"n m", {1.0, "N m", "moment"}},
      {"nm", {1.0, "N m", "moment"}},
      {"1", {1.0, "1", ""}},
      {"", {1.0, "1", ""}},
      {"%", {0.01, "1", ""}},
  };
  std::string key = lower(trim(text));
  if (key.size() >= 2 && key.front() == '(' && key.back() == ')') key = key.substr(1, key.size() - 2);
  auto it = kUnits.find(key);
  if (it == kUnits.end()) return makeError(ErrorCode::ParseError, "unknown unit '" + std::string(text) + "'");
  return it->second;
}

// --- time records ----------------------------------------------------------------------

Result<void> writeTimeCsv(const TimeTable& table, std::ostream& out) {
  if (!(table.sampleRateHz > 0.0) || !std::isfinite(table.sampleRateHz)) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be positive", "CSV export");
  }
  if (table.samples.rows() == 0 || table.samples.cols() == 0 ||
      table.samples.cols() != static_cast<Eigen::Index>(table.channels.size())) {
    return makeError(ErrorCode::InvalidArgument, "time table needs samples and one description per channel",
                     "CSV export");
  }
  if (!table.samples.allFinite()) return makeError(ErrorCode::InvalidArgument, "samples are not finite", "CSV export");
  out << kMagic << ", time-record\n# sample_rate_hz = " << num(table.sampleRateHz) << "\ntime [s]";
  for (const auto& ch : table.channels) {
    std::string name = ch.name.empty() ? ch.quantity : ch.name;
    if (ch.dof && !dofInName(name)) name += (name.empty() ? "" : " ") + formatDof(*ch.dof);
    if (name.empty()) name = "channel";
    out << ',' << name << " [" << (ch.unit.empty() ? "1" : ch.unit) << ']';
  }
  out << '\n';
  for (Eigen::Index r = 0; r < table.samples.rows(); ++r) {
    out << num(table.startTimeS + static_cast<double>(r) / table.sampleRateHz);
    for (Eigen::Index c = 0; c < table.samples.cols(); ++c) out << ',' << num(table.samples(r, c));
    out << '\n';
  }
  if (!out) return makeError(ErrorCode::IoError, "cannot write the CSV text", "CSV export");
  return {};
}

Result<TimeTable> readTimeCsv(std::string_view text, const std::string& source) {
  auto parsed = parseTable(text, source);
  if (!parsed) return parsed.error();
  const Table& t = *parsed;
  if (!t.kind.empty() && t.kind != "time-record") {
    return parseError("this is a '" + t.kind + "' file, not a time record", source, 1);
  }
  TimeTable out;
  // Columns: optional leading time column, then channels.
  const Title firstTitle = splitTitle(t.titles[0]);
  std::size_t firstChannel = 0;
  double timeFactor = 1.0;
  if (lower(firstTitle.name) == "time" || lower(firstTitle.name) == "t") {
    firstChannel = 1;
    auto u = siUnit(firstTitle.unit.value_or("s"));
    if (!u || u->quantity != "time") return parseError("time column unit must be s or ms", source, t.headerLine, 1);
    timeFactor = u->factor;
  }
  if (firstChannel >= t.titles.size()) return parseError("no channel columns", source, t.headerLine);
  for (std::size_t c = firstChannel; c < t.titles.size(); ++c) {
    const Title title = splitTitle(t.titles[c]);
    if (!title.unit) {
      return parseError("column title '" + t.titles[c] + "' has no unit in brackets, e.g. 'force 1:+Z [N]'", source,
                        t.headerLine, static_cast<int>(c + 1));
    }
    auto unit = siUnit(*title.unit);
    if (!unit) return parseError(unit.error().message, source, t.headerLine, static_cast<int>(c + 1));
    out.channels.push_back({title.name, dofInName(title.name), unit->quantity, unit->unit});
  }
  const auto n = static_cast<Eigen::Index>(t.rows.size());
  out.samples.resize(n, static_cast<Eigen::Index>(out.channels.size()));
  for (Eigen::Index r = 0; r < n; ++r) {
    for (std::size_t c = firstChannel; c < t.titles.size(); ++c) {
      const auto unit = siUnit(*splitTitle(t.titles[c]).unit);
      out.samples(r, static_cast<Eigen::Index>(c - firstChannel)) =
          unit->factor * t.rows[static_cast<std::size_t>(r)][c];
    }
  }
  // Sample rate: the comment key wins; otherwise the time column, which must
  // be evenly spaced to 0.1 % of a sample period (printing with 6 digits, as
  // many programs do, stays well inside that for records below 10^5 samples).
  std::optional<double> rate;
  if (auto it = t.keys.find("sample_rate_hz"); it != t.keys.end()) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(it->second.data(), it->second.data() + it->second.size(), v);
    if (ec != std::errc() || ptr != it->second.data() + it->second.size() || !(v > 0) || !std::isfinite(v)) {
      return parseError("sample_rate_hz '" + it->second + "' is not a positive number", source, 1);
    }
    rate = v;
  }
  if (firstChannel == 1) {
    const double t0 = t.rows.front()[0] * timeFactor;
    out.startTimeS = t0;
    if (n >= 2) {
      const double dt = (t.rows.back()[0] - t.rows.front()[0]) * timeFactor / static_cast<double>(n - 1);
      if (!(dt > 0)) return parseError("time column does not increase", source, t.rowLines.back(), 1);
      for (Eigen::Index r = 0; r < n; ++r) {
        const double expected = t0 + static_cast<double>(r) * dt;
        if (std::abs(t.rows[static_cast<std::size_t>(r)][0] * timeFactor - expected) > 1e-3 * dt) {
          return parseError("time column is not evenly spaced (expected " + num(expected) + " s)", source,
                            t.rowLines[static_cast<std::size_t>(r)], 1);
        }
      }
      if (rate && std::abs(*rate * dt - 1.0) > 1e-3) {
        return parseError("sample_rate_hz disagrees with the time column", source, t.headerLine, 1);
      }
      if (!rate) rate = 1.0 / dt;
    }
  }
  if (!rate) return parseError("no time column and no '# sample_rate_hz = ...' line", source, t.headerLine);
  out.sampleRateHz = *rate;
  return out;
}

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
  if (!out) return makeError(ErrorCode::IoError, "cannot write the CSV text", "CSV export");
  return {};
}

Result<FrfMatrix> readFrfCsv(std::string_view text, const std::string& source) {
  auto parsed = parseTable(text, source);
  if (!parsed) return parsed.error();
  const Table& t = *parsed;
  if (!t.kind.empty() && t.kind != "frf") return parseError("this is a '" + t.kind + "' file, not FRFs", source, 1);
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

// --- modal tables --------------------------------------------------------------------------

Result<void> writeModalCsv(const ModalTable& table, std::ostream& out) {
  if (table.modes.empty()) return makeError(ErrorCode::InvalidArgument, "no modes to write", "CSV export");
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    if (!std::isfinite(mode.frequencyHz) || !std::isfinite(mode.dampingRatio) || !mode.shape.allFinite() ||
        (mode.shape.size() != 0 && mode.shape.size() != static_cast<Eigen::Index>(table.dofs.size()))) {
      return makeError(ErrorCode::InvalidArgument,
                       "mode " + std::to_string(m + 1) +
                           " is not finite or its shape "
                           "does not match the DOFs",
                       "CSV export");
    }
  }
  out << kMagic << ", modal\nmode [1],frequency [Hz],damping ratio [1]";
  const bool shapes =
      std::any_of(table.modes.begin(), table.modes.end(), [](const auto& m) { return m.shape.size() > 0; });
  if (shapes) {
    for (const Dof& d : table.dofs) out << ',' << formatDof(d) << " re [1]," << formatDof(d) << " im [1]";
  }
  out << '\n';
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    out << (m + 1) << ',' << num(mode.frequencyHz) << ',' << num(mode.dampingRatio);
    if (shapes) {
      for (std::size_t d = 0; d < table.dofs.size(); ++d) {
        const Complex v = mode.shape.size() ? mode.shape[static_cast<Eigen::Index>(d)] : Complex(0.0, 0.0);
        out << ',' << num(v.real()) << ',' << num(v.imag());
      }
    }
    out << '\n';
  }
  if (!out) return makeError(ErrorCode::IoError, "cannot write the CSV text", "CSV export");
  return {};
}

Result<ModalTable> readModalCsv(std::string_view text, const std::string& source) {
  auto parsed = parseTable(text, source);
  if (!parsed) return parsed.error();
  const Table& t = *parsed;
  if (!t.kind.empty() && t.kind != "modal") return parseError("this is a '" + t.kind + "' file, not modes", source, 1);
  int freqCol = -1, dampCol = -1;
  double dampFactor = 1.0;  // to viscous ratio zeta
  double freqFactor = 1.0;
  struct ShapeCols {
    Dof dof;
    int re = -1, im = -1;
  };
  std::vector<ShapeCols> shape;
  for (std::size_t c = 0; c < t.titles.size(); ++c) {
    const int col = static_cast<int>(c + 1);
    const Title title = splitTitle(t.titles[c]);
    const std::string name = lower(title.name);
    if (name == "mode") continue;
    if (name == "frequency") {
      auto u = siUnit(title.unit.value_or(""));
      if (!u || u->quantity != "frequency") return parseError("frequency unit must be Hz", source, t.headerLine, col);
      freqFactor = u->factor;
      freqCol = static_cast<int>(c);
      continue;
    }
    if (name == "damping ratio" || name == "loss factor") {
      auto u = siUnit(title.unit.value_or("1"));
      if (!u || !u->quantity.empty())
        return parseError("damping must be dimensionless ([1] or [%])", source, t.headerLine, col);
      // Loss factor eta = 2 zeta (DESIGN.md conventions); stored as zeta.
      dampFactor = u->factor * (name == "loss factor" ? 0.5 : 1.0);
      dampCol = static_cast<int>(c);
      continue;
    }
    std::istringstream words(title.name);
    std::string dofText, part;
    words >> dofText >> part;
    auto dof = parseDof(dofText);
    part = lower(part);
    if (!dof || (part != "re" && part != "im")) {
      return parseError("column title '" + t.titles[c] +
                            "' is not mode, frequency, damping ratio, loss factor or "
                            "'<DOF> re|im'",
                        source, t.headerLine, col);
    }
    auto it = std::find_if(shape.begin(), shape.end(), [&](const ShapeCols& s) { return s.dof == *dof; });
    if (it == shape.end()) {
      shape.push_back({*dof});
      it = shape.end() - 1;
    }
    int& slot = part == "re" ? it->re : it->im;
    if (slot >= 0) return parseError(part + " part of " + dofText + " appears twice", source, t.headerLine, col);
    slot = static_cast<int>(c);
  }
  if (freqCol < 0) return parseError("no 'frequency [Hz]' column", source, t.headerLine);
  if (dampCol < 0) return parseError("no 'damping ratio [1]' or 'loss factor [1]' column", source, t.headerLine);
  ModalTable out;
  for (const auto& s : shape) {
    if (s.re < 0 || s.im < 0) return parseError("shape " + formatDof(s.dof) + " lacks re or im", source, t.headerLine);
    out.dofs.push_back(s.dof);
  }
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    StoredMode m;
    m.frequencyHz = freqFactor * t.rows[r][static_cast<std::size_t>(freqCol)];
    m.dampingRatio = dampFactor * t.rows[r][static_cast<std::size_t>(dampCol)];
    if (m.frequencyHz < 0) return parseError("negative natural frequency", source, t.rowLines[r], freqCol + 1);
    m.shape.resize(static_cast<Eigen::Index>(shape.size()));
    for (std::size_t d = 0; d < shape.size(); ++d) {
      m.shape[static_cast<Eigen::Index>(d)] =
          Complex(t.rows[r][static_cast<std::size_t>(shape[d].re)], t.rows[r][static_cast<std::size_t>(shape[d].im)]);
    }
    out.modes.push_back(std::move(m));
  }
  return out;
}

// --- measurement meshes ----------------------------------------------------------------------
namespace {

constexpr std::array<const char*, 6> kMeshSections = {
    "coordinate-systems", "nodes", "lines", "faces", "dofs", "slaves"};

// One section of a mesh file: its name, its text and the line before it.
struct MeshSection {
  std::string name;
  std::string_view text;
  int lineOffset = 0;
  int line = 0;  // line of the "# section = " comment (0: implicit nodes section)
};

Result<int> integerField(double v, const std::string& what, const std::string& source, int line, int column) {
  if (v != std::floor(v) || std::abs(v) > 2147483647.0) {
    return parseError(what + " must be a whole number", source, line, column);
  }
  return static_cast<int>(v);
}

// Column index per expected name (lower case, units checked by the caller).
struct MeshColumns {
  std::map<std::string, std::size_t> index;
  std::map<std::string, std::optional<std::string>> unit;
};

Result<MeshColumns> meshColumns(const Table& t, const std::vector<std::string>& required,
                                const std::vector<std::string>& optional, const std::string& section,
                                const std::string& source) {
  MeshColumns cols;
  for (std::size_t c = 0; c < t.titles.size(); ++c) {
    const Title title = splitTitle(t.titles[c]);
    std::string name = lower(title.name);
    if (section == "nodes" && (name == "label" || name == "id" || name == "node id")) name = "node";
    const bool known = std::find(required.begin(), required.end(), name) != required.end() ||
                       std::find(optional.begin(), optional.end(), name) != optional.end();
    if (!known) {
      return parseError("column title '" + t.titles[c] + "' is not a column of the " + section + " section", source,
                        t.headerLine, static_cast<int>(c + 1));
    }
    if (!cols.index.emplace(name, c).second) {
      return parseError("column '" + name + "' appears twice", source, t.headerLine, static_cast<int>(c + 1));
    }
    cols.unit[name] = title.unit;
  }
  for (const auto& r : required) {
    if (!cols.index.count(r))
      return parseError("no '" + r + "' column in the " + section + " section", source, t.headerLine);
  }
  return cols;
}

// Length factor to metres of a coordinate column: a length unit is required.
Result<double> lengthFactor(const MeshColumns& cols, const std::string& name, const Table& t,
                            const std::string& source) {
  const auto& unit = cols.unit.at(name);
  const int col = static_cast<int>(cols.index.at(name) + 1);
  if (!unit) return parseError("column '" + name + "' needs a length unit ([m] or [mm])", source, t.headerLine, col);
  auto u = siUnit(*unit);
  if (!u || u->quantity != "displacement") {
    return parseError("column '" + name + "' needs a length unit ([m] or [mm])", source, t.headerLine, col);
  }
  return u->factor;
}

Result<void> checkDimensionless(const MeshColumns& cols, const std::string& name, const Table& t,
                                const std::string& source) {
  const auto& unit = cols.unit.at(name);
  if (unit && !unit->empty() && *unit != "1") {
    return parseError("column '" + name + "' is a count or a code: its unit is [1]", source, t.headerLine,
                      static_cast<int>(cols.index.at(name) + 1));
  }
  return {};
}

}  // namespace

Result<void> writeMeshCsv(const MeshDocument& document, std::ostream& out) {
  const auto& mesh = document.mesh;
  if (mesh.nodes.empty()) return makeError(ErrorCode::InvalidArgument, "the mesh has no nodes", "CSV export");
  for (const auto& cs : mesh.coordinateSystems) {
    if (!cs.origin.allFinite() || !cs.rotation.allFinite()) {
      return makeError(ErrorCode::InvalidArgument,
                       "coordinate system " + std::to_string(cs.label) + " has a non-finite value", "CSV export");
    }
    if (cs.name.find_first_of("\r\n") != std::string::npos) {
      return makeError(ErrorCode::InvalidArgument,
                       "the name of coordinate system " + std::to_string(cs.label) + " has a line break", "CSV export");
    }
  }
  for (const auto& n : mesh.nodes) {
    if (!n.position.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(n.label) + " has a non-finite coordinate",
                       "CSV export");
    }
  }
  out << kMagic << ", mesh\n";
  if (!mesh.coordinateSystems.empty()) {
    out << "# section = coordinate-systems\n";
    for (const auto& cs : mesh.coordinateSystems)
      if (!cs.name.empty()) out << "# name " << cs.label << " = " << cs.name << '\n';
    out << "cs [1],type [1],origin x [m],origin y [m],origin z [m],x axis x [1],x axis y [1],x axis z [1],"
           "y axis x [1],y axis y [1],y axis z [1],z axis x [1],z axis y [1],z axis z [1]\n";
    for (const auto& cs : mesh.coordinateSystems) {
      out << cs.label << ',' << static_cast<int>(cs.kind) << ',' << num(cs.origin.x()) << ',' << num(cs.origin.y())
          << ',' << num(cs.origin.z());
      for (int axis = 0; axis < 3; ++axis)
        for (int k = 0; k < 3; ++k) out << ',' << num(cs.rotation(k, axis));  // column = axis
      out << '\n';
    }
  }
  out << "# section = nodes\n# coordinates in the node's definition system; angles of cylindrical and spherical "
         "systems in degrees\nnode [1],cs [1],displacement cs [1],x [m],y [m],z [m]\n";
  for (const auto& n : mesh.nodes) {
    out << n.label << ',' << n.definitionCs << ',' << n.displacementCs << ',' << num(n.position.x()) << ','
        << num(n.position.y()) << ',' << num(n.position.z()) << '\n';
  }
  if (!mesh.lines.empty()) {
    out << "# section = lines\nnode a [1],node b [1]\n";
    for (const auto& l : mesh.lines) out << l.nodeA << ',' << l.nodeB << '\n';
  }
  if (!mesh.faces.empty()) {
    out << "# section = faces\n# node d = 0 for a triangle\nnode a [1],node b [1],node c [1],node d [1]\n";
    for (const auto& f : mesh.faces) out << f.nodeA << ',' << f.nodeB << ',' << f.nodeC << ',' << f.nodeD << '\n';
  }
  if (!document.measurementDofs.empty()) {
    out << "# section = dofs\n# direction: UFF code +/-1..6 = X, Y, Z, RX, RY, RZ\nnode [1],direction [1]\n";
    for (const auto& d : document.measurementDofs) out << d.node << ',' << d.uffCode() << '\n';
  }
  if (!document.slaves.empty()) {
    out << "# section = slaves\n# u(slave) = sum of weight x u(master), one row per master\n"
           "slave node [1],slave direction [1],master node [1],master direction [1],weight [1]\n";
    for (const auto& s : document.slaves) {
      for (const auto& [master, weight] : s.masters) {
        if (!std::isfinite(weight)) {
          return makeError(ErrorCode::InvalidArgument, "a weight of slave " + formatDof(s.slave) + " is not finite",
                           "CSV export");
        }
        out << s.slave.node << ',' << s.slave.uffCode() << ',' << master.node << ',' << master.uffCode() << ','
            << num(weight) << '\n';
      }
    }
  }
  if (!out) return makeError(ErrorCode::IoError, "cannot write the CSV text", "CSV export");
  return {};
}

Result<MeshDocument> readMeshCsv(std::string_view text, const std::string& source) {
  // Split into sections at "# section = <name>" lines; text before the first
  // one (other than comments) is a nodes table (the common "node, x, y, z"
  // file of other programs).
  std::vector<MeshSection> sections;
  std::string kind;
  {
    MeshSection current{"nodes", {}, 0, 0};
    std::size_t sectionStart = 0;
    std::size_t pos = 0;
    int lineNo = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::string trimmed = lower(trim(text.substr(pos, end - pos)));
      ++lineNo;
      if (trimmed.rfind(kMagic, 0) == 0) {
        const std::size_t comma = trimmed.find(',');
        if (comma != std::string::npos) kind = trim(std::string_view(trimmed).substr(comma + 1));
      }
      if (trimmed.rfind("# section", 0) == 0 && trimmed.find('=') != std::string::npos) {
        current.text = text.substr(sectionStart, pos - sectionStart);
        sections.push_back(current);
        const std::string name = trim(std::string_view(trimmed).substr(trimmed.find('=') + 1));
        if (std::find(kMeshSections.begin(), kMeshSections.end(), name) == kMeshSections.end()) {
          return parseError("unknown section '" + name + "' (coordinate-systems, nodes, lines, faces, dofs or slaves)",
                            source, lineNo);
        }
        current = MeshSection{name, {}, lineNo, lineNo};
        sectionStart = std::min(end + 1, text.size());
      }
      pos = end + 1;
    }
    current.text = text.substr(std::min(sectionStart, text.size()));
    sections.push_back(current);
  }
  if (!kind.empty() && kind != "mesh") return parseError("this is a '" + kind + "' file, not a mesh", source, 1);

  MeshDocument doc;
  auto& mesh = doc.mesh;
  std::map<std::string, int> seen;
  std::map<int, StoredCoordinateSystem::Kind> systemKinds;
  for (const auto& section : sections) {
    // The implicit leading section may hold only comments.
    const bool implicit = section.line == 0;
    if (implicit) {
      bool content = false;
      std::size_t pos = 0;
      while (pos < section.text.size() && !content) {
        std::size_t end = section.text.find('\n', pos);
        if (end == std::string_view::npos) end = section.text.size();
        const std::string t = trim(section.text.substr(pos, end - pos));
        // A UTF-8 byte-order mark alone is not content.
        content = !t.empty() && t[0] != '#' && t != "\xEF\xBB\xBF";
        pos = end + 1;
      }
      if (!content) continue;
    }
    if (seen.count(section.name)) {
      return parseError("section '" + section.name + "' appears twice", source, std::max(section.line, 1));
    }
    seen[section.name] = section.line;
    auto parsed = parseTable(section.text, source, section.lineOffset);
    if (!parsed) return parsed.error();
    const Table& t = *parsed;
    auto intAt = [&](std::size_t r, const MeshColumns& cols, const std::string& name) -> Result<int> {
      const std::size_t c = cols.index.at(name);
      return integerField(t.rows[r][c], name, source, t.rowLines[r], static_cast<int>(c + 1));
    };
    if (section.name == "coordinate-systems") {
      if (seen.count("nodes")) {
        return parseError("the coordinate-systems section must come before the nodes", source, section.line);
      }
      std::vector<std::string> required = {"cs", "type", "origin x", "origin y", "origin z"};
      for (const char* axis : {"x", "y", "z"})
        for (const char* k : {"x", "y", "z"}) required.push_back(std::string(axis) + " axis " + k);
      auto cols = meshColumns(t, required, {}, section.name, source);
      if (!cols) return cols.error();
      double factor[3];
      for (int k = 0; k < 3; ++k) {
        auto f = lengthFactor(*cols, std::string("origin ") + "xyz"[k], t, source);
        if (!f) return f.error();
        factor[k] = *f;
      }
      for (const auto& name : {"cs", "type"})
        if (auto r = checkDimensionless(*cols, name, t, source); !r) return r.error();
      for (std::size_t r = 0; r < t.rows.size(); ++r) {
        StoredCoordinateSystem cs;
        auto label = intAt(r, *cols, "cs");
        if (!label) return label.error();
        auto type = intAt(r, *cols, "type");
        if (!type) return type.error();
        if (*label <= 0) return parseError("coordinate system labels are positive", source, t.rowLines[r]);
        if (*type < 0 || *type > 2) {
          return parseError("type must be 0 (cartesian), 1 (cylindrical) or 2 (spherical)", source, t.rowLines[r],
                            static_cast<int>(cols->index.at("type") + 1));
        }
        cs.label = *label;
        cs.kind = static_cast<StoredCoordinateSystem::Kind>(*type);
        for (int k = 0; k < 3; ++k)
          cs.origin[k] = factor[k] * t.rows[r][cols->index.at(std::string("origin ") + "xyz"[k])];
        for (int axis = 0; axis < 3; ++axis)
          for (int k = 0; k < 3; ++k)
            cs.rotation(k, axis) = t.rows[r][cols->index.at(std::string(1, "xyz"[axis]) + " axis " + "xyz"[k])];
        if (auto it = t.keys.find("name " + std::to_string(cs.label)); it != t.keys.end()) cs.name = it->second;
        if (!systemKinds.emplace(cs.label, cs.kind).second) {
          return parseError("coordinate system " + std::to_string(cs.label) + " is defined twice", source,
                            t.rowLines[r]);
        }
        mesh.coordinateSystems.push_back(std::move(cs));
      }
    } else if (section.name == "nodes") {
      auto cols = meshColumns(t, {"node", "x", "y", "z"}, {"cs", "displacement cs"}, section.name, source);
      if (!cols) return cols.error();
      double factor[3];
      for (int k = 0; k < 3; ++k) {
        auto f = lengthFactor(*cols, std::string(1, "xyz"[k]), t, source);
        if (!f) return f.error();
        factor[k] = *f;
      }
      for (const auto& name : {"node", "cs", "displacement cs"})
        if (cols->index.count(name))
          if (auto r = checkDimensionless(*cols, name, t, source); !r) return r.error();
      for (std::size_t r = 0; r < t.rows.size(); ++r) {
        StoredNode n;
        auto label = intAt(r, *cols, "node");
        if (!label) return label.error();
        n.label = *label;
        if (n.label <= 0) return parseError("node labels are positive", source, t.rowLines[r]);
        for (const auto& [name, field] : {std::pair<const char*, int*>{"cs", &n.definitionCs},
                                          std::pair<const char*, int*>{"displacement cs", &n.displacementCs}}) {
          if (!cols->index.count(name)) continue;
          auto v = intAt(r, *cols, name);
          if (!v) return v.error();
          if (*v < 0) return parseError(std::string(name) + " must not be negative", source, t.rowLines[r]);
          *field = *v;
        }
        for (int k = 0; k < 3; ++k) n.position[k] = t.rows[r][cols->index.at(std::string(1, "xyz"[k]))];
        // Lengths scale with the column unit; angles (degrees) of cylindrical
        // (theta) and spherical (theta, phi) systems do not.
        const auto kindIt = systemKinds.find(n.definitionCs);
        const auto kindOf = kindIt == systemKinds.end() ? StoredCoordinateSystem::Kind::Cartesian : kindIt->second;
        n.position[0] *= factor[0];
        if (kindOf == StoredCoordinateSystem::Kind::Cartesian) n.position[1] *= factor[1];
        if (kindOf != StoredCoordinateSystem::Kind::Spherical) n.position[2] *= factor[2];
        mesh.nodes.push_back(n);
      }
    } else if (section.name == "lines" || section.name == "faces") {
      const bool lines = section.name == "lines";
      std::vector<std::string> required = {"node a", "node b"};
      if (!lines) required.push_back("node c");
      auto cols = meshColumns(t, required, lines ? std::vector<std::string>{} : std::vector<std::string>{"node d"},
                              section.name, source);
      if (!cols) return cols.error();
      for (const auto& [name, index] : cols->index)
        if (auto r = checkDimensionless(*cols, name, t, source); !r) return r.error();
      for (std::size_t r = 0; r < t.rows.size(); ++r) {
        int v[4] = {0, 0, 0, 0};
        for (int k = 0; k < 4; ++k) {
          const std::string name = std::string("node ") + "abcd"[k];
          if (!cols->index.count(name)) continue;
          auto x = intAt(r, *cols, name);
          if (!x) return x.error();
          if (*x < 0 || (*x == 0 && k < 3)) {
            return parseError(name + " must be a node label (positive)", source, t.rowLines[r],
                              static_cast<int>(cols->index.at(name) + 1));
          }
          v[k] = *x;
        }
        if (lines) {
          mesh.lines.push_back({v[0], v[1]});
        } else {
          mesh.faces.push_back({v[0], v[1], v[2], v[3]});
        }
      }
    } else if (section.name == "dofs") {
      auto cols = meshColumns(t, {"node", "direction"}, {}, section.name, source);
      if (!cols) return cols.error();
      for (std::size_t r = 0; r < t.rows.size(); ++r) {
        auto node = intAt(r, *cols, "node");
        if (!node) return node.error();
        auto code = intAt(r, *cols, "direction");
        if (!code) return code.error();
        auto dof = dofFromUff(*node, *code);
        if (!dof) {
          return parseError("direction must be a UFF code +/-1..6", source, t.rowLines[r],
                            static_cast<int>(cols->index.at("direction") + 1));
        }
        doc.measurementDofs.push_back(*dof);
      }
    } else if (section.name == "slaves") {
      auto cols = meshColumns(t, {"slave node", "slave direction", "master node", "master direction", "weight"}, {},
                              section.name, source);
      if (!cols) return cols.error();
      for (std::size_t r = 0; r < t.rows.size(); ++r) {
        Dof dofs[2];
        for (int k = 0; k < 2; ++k) {
          const std::string who = k == 0 ? "slave" : "master";
          auto node = intAt(r, *cols, who + " node");
          if (!node) return node.error();
          auto code = intAt(r, *cols, who + " direction");
          if (!code) return code.error();
          auto dof = dofFromUff(*node, *code);
          if (!dof) {
            return parseError(who + " direction must be a UFF code +/-1..6", source, t.rowLines[r],
                              static_cast<int>(cols->index.at(who + " direction") + 1));
          }
          dofs[k] = *dof;
        }
        const double weight = t.rows[r][cols->index.at("weight")];
        // Rows of one slave are consecutive in files Mozzi writes; any order is read.
        auto it =
            std::find_if(doc.slaves.begin(), doc.slaves.end(), [&](const SlavedDof& s) { return s.slave == dofs[0]; });
        if (it == doc.slaves.end()) {
          doc.slaves.push_back({dofs[0], {}});
          it = doc.slaves.end() - 1;
        }
        it->masters.push_back({dofs[1], weight});
      }
    }
  }
  if (mesh.nodes.empty()) return parseError("no nodes (a nodes section or a node, x, y, z table)", source, 1);
  return doc;
}

Result<MeshDocument> importMeshCsv(const std::string& path) {
  auto text = readWholeFile(path);
  if (!text) return text.error();
  return readMeshCsv(*text, path);
}

Result<void> exportMeshCsv(const MeshDocument& document, const std::string& path) {
  std::ostringstream out;
  if (auto r = writeMeshCsv(document, out); !r) return makeError(r.error().code, r.error().message, path);
  return writeFile(path, out.str());
}

// --- files ----------------------------------------------------------------------------------

Result<TimeTable> importTimeCsv(const std::string& path) {
  auto text = readWholeFile(path);
  if (!text) return text.error();
  return readTimeCsv(*text, path);
}

Result<FrfMatrix> importFrfCsv(const std::string& path) {
  auto text = readWholeFile(path);
  if (!text) return text.error();
  return readFrfCsv(*text, path);
}

Result<ModalTable> importModalCsv(const std::string& path) {
  auto text = readWholeFile(path);
  if (!text) return text.error();
  return readModalCsv(*text, path);
}

Result<void> exportTimeCsv(const TimeTable& table, const std::string& path) {
  std::ostringstream out;
  if (auto r = writeTimeCsv(table, out); !r) return makeError(r.error().code, r.error().message, path);
  return writeFile(path, out.str());
}

Result<void> exportFrfCsv(const FrfMatrix& frf, const std::string& path) {
  std::ostringstream out;
  if (auto r = writeFrfCsv(frf, out); !r) return makeError(r.error().code, r.error().message, path);
  return writeFile(path, out.str());
}

Result<void> exportModalCsv(const ModalTable& table, const std::string& path) {
  std::ostringstream out;
  if (auto r = writeModalCsv(table, out); !r) return makeError(r.error().code, r.error().message, path);
  return writeFile(path, out.str());
}

}  // namespace mozzi::core::io::csv
