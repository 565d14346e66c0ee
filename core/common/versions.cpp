#include "core/common/versions.h"

#include <ceres/version.h>
#include <fftw3.h>
#include <matio.h>
#include <sqlite3.h>
#include <zlib.h>
#include <Eigen/Core>

namespace mozzi::core {

LibraryVersions coreLibraryVersions() {
  int matMajor = 0, matMinor = 0, matRelease = 0;
  Mat_GetLibraryVersion(&matMajor, &matMinor, &matRelease);
  std::string fftw = fftw_version;  // "fftw-3.3.10-sse2-avx"
  if (fftw.rfind("fftw-", 0) == 0) fftw = fftw.substr(5);
  return {
      {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                    std::to_string(EIGEN_MINOR_VERSION)},
      {"Ceres", CERES_VERSION_STRING},
      {"FFTW", fftw},
      {"SQLite", sqlite3_libversion()},
      {"zlib", zlibVersion()},
      {"matio", std::to_string(matMajor) + "." + std::to_string(matMinor) + "." + std::to_string(matRelease)},
  };
}

}  // namespace mozzi::core
