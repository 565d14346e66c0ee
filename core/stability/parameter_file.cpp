#include "core/stability/parameter_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace mozzi::core::stability {

Result<ParameterFile> readParameterFile(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) return makeError(ErrorCode::IoError, "cannot open " + what + " parameter file", path);
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
    if (end == value.c_str() || *end != '\0' || !std::isfinite(x)) {
      return makeError(ErrorCode::ParseError, "value of '" + name + "' is not a number: '" + value + "'",
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
