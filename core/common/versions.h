#pragma once
// Versions of the libraries core is linked with, read at run time where the
// library can tell (FFTW, SQLite) and from the headers where it cannot (Eigen
// and Ceres are compiled in).

#include <string>
#include <utility>
#include <vector>

namespace mozzi::core {

using LibraryVersions = std::vector<std::pair<std::string, std::string>>;

LibraryVersions coreLibraryVersions();  // Eigen, Ceres, FFTW, SQLite, zlib, matio

}  // namespace mozzi::core
