#pragma once
// Vehicle parameter files: CSV rows "name,value[,...]" in SI units, an optional
// "name,..." header, '#' lines as comments (kept: they say how far values can be
// trusted). Shared by the benchmark bicycle and the motorcycle loaders.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::stability {

struct ParameterFile {
  std::map<std::string, double> values;
  std::string comments;  // the '#' lines joined by spaces, without the '#'
};

// Errors name the file and line: a row without a value, a value that is not a
// finite number.
Result<ParameterFile> readParameterFile(const std::string& path, const std::string& what);

// Copies each named parameter into its field; a missing one is an error naming it.
Result<void> takeParameters(const ParameterFile& file, const std::vector<std::pair<const char*, double*>>& fields,
                            const std::string& path);

}  // namespace mozzi::core::stability
