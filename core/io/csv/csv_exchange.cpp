// The CSV exchange (docs/formats/csv.md): what every kind shares (the table
// parser, titles and units, whole-file reads and writes) and the unit table.
// One file per exchange kind: csv_time.cpp, csv_frf.cpp, csv_modal.cpp,
// csv_mesh.cpp.

#include "core/io/csv/csv_exchange.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/common/enum_names.h"
#include "core/io/csv/csv_internal.h"
#include "core/io/output_file.h"

namespace mozzi::core::io::csv {
namespace detail {

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

Error parseError(const std::string& message, const std::string& source, int line, int column) {
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

Result<Table> parseTable(std::string_view text, const std::string& source, int lineOffset) {
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

// FRF units: <response unit>/<force unit>, e.g. "m/s^2/N", "g/N", "mm/N".
Result<FrfUnit> frfUnit(const std::string& unit) {
  const std::size_t slash = unit.rfind('/');
  if (slash == std::string::npos) return makeError(ErrorCode::ParseError, "FRF unit '" + unit + "' has no '/N'");
  auto force = siUnit(std::string_view(unit).substr(slash + 1));
  auto response = siUnit(std::string_view(unit).substr(0, slash));
  if (!force || force->quantity != "force" || !response) {
    return makeError(ErrorCode::ParseError, "FRF unit '" + unit + "' is not a translational response per force");
  }
  static constexpr auto kResponseQuantities = enumTable<FrfType>(
      {{FrfType::Receptance, "displacement"}, {FrfType::Mobility, "velocity"}, {FrfType::Accelerance, "acceleration"}},
      "");
  const auto type = kResponseQuantities.find(response->quantity.c_str());
  if (!type) {
    return makeError(ErrorCode::ParseError,
                     "FRF unit '" + unit + "' is not displacement, velocity or acceleration per force");
  }
  return FrfUnit{*type, response->factor / force->factor};
}

const char* frfUnitText(FrfType type) {
  static constexpr auto kUnits = enumTable<FrfType>(
      {{FrfType::Receptance, "m/N"}, {FrfType::Mobility, "m/s/N"}, {FrfType::Accelerance, "m/s^2/N"}}, "m/s^2/N");
  return kUnits.of(type);
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

Result<Table> parseTableOf(std::string_view text, const std::string& source, const char* kind, const char* what) {
  MOZZI_TRY_ASSIGN(Table t, parseTable(text, source));
  if (!t.kind.empty() && t.kind != kind) {
    return parseError("this is a '" + t.kind + "' file, not " + std::string(what), source, 1);
  }
  return t;
}

Result<void> written(const std::ostream& out) {
  if (!out) return makeError(ErrorCode::IoError, "cannot write the CSV text", "CSV export");
  return {};
}

}  // namespace detail

using detail::lower;
using detail::trim;

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

// --- files ----------------------------------------------------------------------------------

Result<TimeTable> importTimeCsv(const std::string& path) {
  return detail::importWith<TimeTable>(path, readTimeCsv);
}

Result<FrfMatrix> importFrfCsv(const std::string& path) {
  return detail::importWith<FrfMatrix>(path, readFrfCsv);
}

Result<ModalTable> importModalCsv(const std::string& path) {
  return detail::importWith<ModalTable>(path, readModalCsv);
}

Result<MeshDocument> importMeshCsv(const std::string& path) {
  return detail::importWith<MeshDocument>(path, readMeshCsv);
}

Result<void> exportTimeCsv(const TimeTable& table, const std::string& path) {
  return detail::exportWith<TimeTable>(table, path, writeTimeCsv);
}

Result<void> exportFrfCsv(const FrfMatrix& frf, const std::string& path) {
  return detail::exportWith<FrfMatrix>(frf, path, writeFrfCsv);
}

Result<void> exportModalCsv(const ModalTable& table, const std::string& path) {
  return detail::exportWith<ModalTable>(table, path, writeModalCsv);
}

Result<void> exportMeshCsv(const MeshDocument& document, const std::string& path) {
  return detail::exportWith<MeshDocument>(document, path, writeMeshCsv);
}

}  // namespace mozzi::core::io::csv
