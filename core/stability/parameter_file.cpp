#include "core/stability/parameter_file.h"

#include "core/io/text_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace mozzi::core::stability {

namespace {
constexpr double kMaxParameterMagnitude = 1e9;
}  // namespace

Result<ParameterFile> readParameterFile(const std::string& path, const std::string& what) {
  MOZZI_TRY_ASSIGN(const std::string text, io::readTextFile(path, what + " parameter", io::kMaxParameterFileBytes));
  std::istringstream in(text);
  ParameterFile file;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line[0] == '#') {
      const auto start = line.find_first_not_of("# ");
      if (start != std::string::npos) file.comments += (file.comments.empty() ? "" : " ") + line.substr(start);
      continue;
    }
    std::istringstream row(line);
    std::string name, value;
    if (!std::getline(row, name, ',') || !std::getline(row, value, ',')) {
      return makeError(ErrorCode::ParseError, "expected name,value", path + ":" + std::to_string(lineNo));
    }
    if (name == "name") continue;  // header
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    auto shown = [](const std::string& t) { return t.size() <= 40 ? t : t.substr(0, 40) + "..."; };
    if (end == value.c_str() || *end != '\0' || !std::isfinite(x)) {
      return makeError(ErrorCode::ParseError,
                       "value of '" + shown(name) + "' is not a finite number: '" + shown(value) + "'",
                       path + ":" + std::to_string(lineNo));
    }
    // Every parameter of a vehicle model in SI units lies well within 1e9
    // (the stiffest fork joint is ~1e12 N m/rad but enters through options,
    // not files); beyond that the state matrix overflows.
    if (std::abs(x) > kMaxParameterMagnitude) {
      return makeError(ErrorCode::ParseError,
                       "value of '" + shown(name) + "' = " + shown(value) + " is out of range; valid: [-1e+09, 1e+09]",
                       path + ":" + std::to_string(lineNo));
    }
    file.values[name] = x;
  }
  return file;
}

Result<void> takeParameters(const ParameterFile& file, const std::vector<std::pair<const char*, double*>>& fields,
                            const std::string& path) {
  for (const auto& [name, field] : fields) {
    const auto it = file.values.find(name);
    if (it == file.values.end()) {
      return makeError(ErrorCode::ParseError, std::string("missing parameter '") + name + "'", path);
    }
    *field = it->second;
  }
  return {};
}

}  // namespace mozzi::core::stability
