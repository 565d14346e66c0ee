#include "core/common/versions.h"

#include <ceres/version.h>
#include <fftw3.h>
#include <matio_pubconf.h>  // the version built against: libmatio itself is loaded only to read a MAT file
#include <sqlite3.h>
#include <zlib.h>
#include <Eigen/Core>

namespace mozzi::core {

LibraryVersions coreLibraryVersions() {
  std::string fftw = fftw_version;  // "fftw-3.3.10-sse2-avx"
  if (fftw.rfind("fftw-", 0) == 0) fftw = fftw.substr(5);
  return {
      {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                    std::to_string(EIGEN_MINOR_VERSION)},
      {"Ceres", CERES_VERSION_STRING},
      {"FFTW", fftw},
      {"SQLite", sqlite3_libversion()},
      {"zlib", zlibVersion()},
      {"matio", MATIO_VERSION_STR},
  };
}

}  // namespace mozzi::core
