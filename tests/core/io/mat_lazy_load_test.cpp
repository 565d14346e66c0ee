// libmatio is opened only when a MAT file is read (issue 19: it pulls in HDF5,
// curl, gnutls, krb5 and ldap, start-up time every command would pay). This
// test links mozzi_core without libmatio: at start the library is not in the
// process; reading a MAT file (written here byte by byte in the level-5
// format, MathWorks "MAT-File Format" R2023b, ch. 1) loads it and returns the
// written numbers exactly.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/io/mat/mat_import.h"
#include "core/io/mat/matio_library.h"

namespace mozzi::core::io::mat {
namespace {

bool matioMapped() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    if (line.find("libmatio") != std::string::npos) return true;
  }
  return false;
}

void put32(std::string& out, std::uint32_t v) {
  out.append(reinterpret_cast<const char*>(&v), 4);  // little-endian host, "IM" header below
}

// miMATRIX element of a real double array `name` (rows x cols, column-major).
std::string doubleMatrix(const std::string& name, std::uint32_t rows, std::uint32_t cols,
                         const std::vector<double>& values) {
  std::string body;
  put32(body, 6);  // miUINT32: array flags
  put32(body, 8);
  put32(body, 6);  // mxDOUBLE_CLASS, no flags
  put32(body, 0);
  put32(body, 5);  // miINT32: dimensions
  put32(body, 8);
  put32(body, rows);
  put32(body, cols);
  put32(body, 1);  // miINT8: name, padded to 8 bytes
  put32(body, static_cast<std::uint32_t>(name.size()));
  body += name;
  body.append((8 - name.size() % 8) % 8, '\0');
  put32(body, 9);  // miDOUBLE: real part
  put32(body, static_cast<std::uint32_t>(8 * values.size()));
  body.append(reinterpret_cast<const char*>(values.data()), 8 * values.size());
  std::string element;
  put32(element, 14);  // miMATRIX
  put32(element, static_cast<std::uint32_t>(body.size()));
  return element + body;
}

TEST(MatLazyLoad, LibmatioIsOpenedOnlyWhenAMatFileIsRead) {
  ASSERT_FALSE(matioMapped()) << "libmatio is linked into the process (it must be opened with dlopen)";

  std::string header = "MATLAB 5.0 MAT-file, written by mozzi mat_lazy_load_test";
  header.resize(116, ' ');
  header.append(8, '\0');                // no subsystem data
  header += std::string("\x00\x01", 2);  // version 0x0100, little-endian
  header += "IM";
  const std::vector<double> x = {0.5, -1.25, 3.0, 4.0e-3, 7.0, -8.5};  // 3 samples x 2 channels
  const std::string bytes = header + doubleMatrix("x", 3, 2, x) + doubleMatrix("fs", 1, 1, {2048.0});
  const auto path = std::filesystem::temp_directory_path() / ("mozzi_lazy_" + std::to_string(::getpid()) + ".mat");
  std::ofstream(path, std::ios::binary) << bytes;

  TimeImportOptions opt;
  opt.dataVariable = "x";
  opt.sampleRateVariable = "fs";
  auto table = importTimeRecord(path.string(), opt);
  std::filesystem::remove(path);
  ASSERT_TRUE(table.ok()) << table.error().describe();
  EXPECT_TRUE(matioMapped());
  EXPECT_EQ(table->sampleRateHz, 2048.0);
  ASSERT_EQ(table->samples.rows(), 3);
  ASSERT_EQ(table->samples.cols(), 2);
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(table->samples(k, c), x[static_cast<std::size_t>(3 * c + k)]);
  EXPECT_NE(std::string(matioSoname()).find("libmatio.so"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::io::mat
