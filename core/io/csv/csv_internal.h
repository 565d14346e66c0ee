#pragma once
// Private helpers of the CSV exchange (core/io/csv/csv_exchange.cpp defines
// them; csv_time.cpp, csv_frf.cpp, csv_modal.cpp and csv_mesh.cpp, one file
// per exchange kind, use them). Not part of core's public face.

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/dof.h"
#include "core/common/frf_type.h"
#include "core/common/result.h"

namespace mozzi::core::io::csv::detail {

inline constexpr const char* kMagic = "# mozzi-csv 1";
inline constexpr std::uintmax_t kMaxCsvBytes = std::uintmax_t{1} << 31;  // 2 GiB

// Leading and trailing blanks (and one pair of enclosing quotes) removed.
std::string trim(std::string_view s);
std::string lower(std::string s);
// 17 significant digits: enough to read back the same double (IEEE 754).
std::string num(double v);

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

Error parseError(const std::string& message, const std::string& source, int line, int column = 0);
std::vector<std::string_view> splitFields(std::string_view line, char sep);
Result<Table> parseTable(std::string_view text, const std::string& source, int lineOffset = 0);
// parseTable, then a file of another kind refused: "this is a '<kind>' file,
// not <what>" (a file without "# mozzi-csv 1, <kind>" is taken as it is).
Result<Table> parseTableOf(std::string_view text, const std::string& source, const char* kind, const char* what);
// What a writer returns: an error when the stream failed.
Result<void> written(const std::ostream& out);

// "accel 21:+Z [m/s^2]" -> name "accel 21:+Z", unit "m/s^2". A title without
// brackets has no unit (error for the caller to word).
struct Title {
  std::string name;
  std::optional<std::string> unit;
};
Title splitTitle(const std::string& title);

// Last whitespace-separated word of a name that parses as a DOF.
std::optional<Dof> dofInName(const std::string& name);

struct FrfUnit {
  FrfType type;
  double factor;
};

// FRF units: <response unit>/<force unit>, e.g. "m/s^2/N", "g/N", "mm/N".
Result<FrfUnit> frfUnit(const std::string& unit);
const char* frfUnitText(FrfType type);

// The whole file (at most kMaxCsvBytes), or an error naming the path.
Result<std::string> readWholeFile(const std::string& path);
// Temporary file renamed into place (core/io/output_file.h).
Result<void> writeFile(const std::string& path, const std::string& text);

// A whole file read by one kind's reader (readTimeCsv, ...), with the path as
// the source its errors name.
template <class T>
Result<T> importWith(const std::string& path, Result<T> (*read)(std::string_view, const std::string&)) {
  MOZZI_TRY_ASSIGN(auto text, readWholeFile(path));
  return read(text, path);
}

// One kind's writer (writeTimeCsv, ...) into a file; a refusal names the path.
template <class T>
Result<void> exportWith(const T& value, const std::string& path, Result<void> (*write)(const T&, std::ostream&)) {
  std::ostringstream out;
  if (auto r = write(value, out); !r) return makeError(r.error().code, r.error().message, path);
  return writeFile(path, out.str());
}

}  // namespace mozzi::core::io::csv::detail
