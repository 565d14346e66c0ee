// MATLAB .mat import. The files are written by libmatio itself (the reference
// implementation of the format) in v5, v7 (compressed) and, when this
// libmatio has HDF5, v7.3; the importer must return the written numbers
// exactly (doubles are stored as doubles: tolerance 0) apart from the unit
// factors, which are checked against hand-computed SI values.

#include "core/io/mat/mat_import.h"

#include <gtest/gtest.h>
#include <matio.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace mozzi::core::io::mat {
namespace {

namespace fs = std::filesystem;

class MatImportTest : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_mat_" + std::to_string(::getpid()) + "_" + std::to_string(GetParam()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Opens a new file in the parameter's format: 0 = v5, 1 = v7 compressed, 2 = v7.3.
  mat_t* create(const std::string& name) {
    path_ = (dir_ / name).string();
    const mat_ft version = GetParam() == 2 ? MAT_FT_MAT73 : MAT_FT_MAT5;
    return Mat_CreateVer(path_.c_str(), nullptr, version);
  }
  matio_compression compression() const { return GetParam() == 1 ? MAT_COMPRESSION_ZLIB : MAT_COMPRESSION_NONE; }

  void writeDouble(mat_t* mat, const char* name, std::vector<std::size_t> dims, std::vector<double> values) {
    matvar_t* v =
        Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, static_cast<int>(dims.size()), dims.data(), values.data(), 0);
    ASSERT_NE(v, nullptr);
    ASSERT_EQ(Mat_VarWrite(mat, v, compression()), 0);
    Mat_VarFree(v);
  }

  fs::path dir_;
  std::string path_;
};

TEST(MatSupport, V73FollowsTheLinkedLibmatio) {
  // Debian 12's libmatio 1.5.23 is built with HDF5 (libmatio11 depends on
  // libhdf5-103), so v7.3 must be available here; the importer reports it.
  EXPECT_TRUE(matV73Supported());
}

TEST_P(MatImportTest, TimeRecordWithChannelMapAndUnits) {
  if (GetParam() == 2) {
    ASSERT_TRUE(matV73Supported());
  }
  mat_t* mat = create("time.mat");
  ASSERT_NE(mat, nullptr);
  // 6 samples x 3 columns, column-major as MATLAB stores it.
  const std::size_t n = 6;
  std::vector<double> data(n * 3);
  for (std::size_t r = 0; r < n; ++r) {
    data[r] = 0.1 * static_cast<double>(r);               // column 0: force in kN
    data[r + n] = std::sin(static_cast<double>(r));       // column 1: acceleration in g
    data[r + 2 * n] = -1.0 * static_cast<double>(r * r);  // column 2: unused
  }
  writeDouble(mat, "data", {n, 3}, data);
  writeDouble(mat, "fs", {1, 1}, {2048.0});
  Mat_Close(mat);

  auto vars = listVariables(path_);
  ASSERT_TRUE(vars.ok()) << vars.error().describe();
  ASSERT_EQ(vars->size(), 2u);
  EXPECT_EQ((*vars)[0].name, "data");
  EXPECT_EQ((*vars)[0].dims, (std::vector<std::size_t>{6, 3}));

  TimeImportOptions options;
  options.dataVariable = "data";
  options.sampleRateVariable = "fs";
  // Channel map: file column 1 first (accelerometer at 21:-Z in g), then column 0 (hammer in kN).
  options.channels = {{1, "accel", Dof{21, Direction::Z, true}, "g"}, {0, "hammer", Dof{1, Direction::Z, false}, "kN"}};
  auto t = importTimeRecord(path_, options);
  ASSERT_TRUE(t.ok()) << t.error().describe();
  EXPECT_EQ(t->sampleRateHz, 2048.0);
  ASSERT_EQ(t->samples.rows(), 6);
  ASSERT_EQ(t->samples.cols(), 2);
  for (std::size_t r = 0; r < n; ++r) {
    EXPECT_DOUBLE_EQ(t->samples(static_cast<Eigen::Index>(r), 0), 9.80665 * std::sin(static_cast<double>(r)));
    EXPECT_DOUBLE_EQ(t->samples(static_cast<Eigen::Index>(r), 1), 1e3 * 0.1 * static_cast<double>(r));
  }
  EXPECT_EQ(t->channels[0].dof, (Dof{21, Direction::Z, true}));
  EXPECT_EQ(t->channels[0].unit, "m/s^2");
  EXPECT_EQ(t->channels[1].quantity, "force");

  options.channels = {{3, "x", std::nullopt, "N"}};
  auto bad = importTimeRecord(path_, options);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("column 3 of 3"), std::string::npos) << bad.error().describe();
}

TEST_P(MatImportTest, TransposedDataWithTimeVectorAndSingles) {
  if (GetParam() == 2) {
    ASSERT_TRUE(matV73Supported());
  }
  mat_t* mat = create("rows.mat");
  ASSERT_NE(mat, nullptr);
  // 2 channels x 5 samples, single precision, with a time vector at 1 kHz.
  std::vector<float> rows = {1, 2, 3, 4, 5, 10, 20, 30, 40, 50};  // column-major 2x5: (0,0)=1,(1,0)=2,...
  std::size_t dims[2] = {2, 5};
  matvar_t* v = Mat_VarCreate("y", MAT_C_SINGLE, MAT_T_SINGLE, 2, dims, rows.data(), 0);
  ASSERT_EQ(Mat_VarWrite(mat, v, compression()), 0);
  Mat_VarFree(v);
  writeDouble(mat, "t", {5, 1}, {0.0, 0.001, 0.002, 0.003, 0.004});
  Mat_Close(mat);

  TimeImportOptions options;
  options.dataVariable = "y";
  options.timeVariable = "t";
  auto t = importTimeRecord(path_, options);
  ASSERT_TRUE(t.ok()) << t.error().describe();
  EXPECT_NEAR(t->sampleRateHz, 1000.0, 1e-9);  // 1/(0.004/4): one rounding of 0.004 in binary
  ASSERT_EQ(t->samples.rows(), 5);
  ASSERT_EQ(t->samples.cols(), 2);
  // Row k of the file is channel k: y(0, c) = rows[2c], y(1, c) = rows[2c + 1].
  EXPECT_EQ(t->samples(0, 0), 1.0);
  EXPECT_EQ(t->samples(1, 0), 3.0);
  EXPECT_EQ(t->samples(4, 1), 50.0);
}

TEST_P(MatImportTest, FrfMatrixWithReferencePagesAndMapping) {
  if (GetParam() == 2) {
    ASSERT_TRUE(matV73Supported());
  }
  mat_t* mat = create("frf.mat");
  ASSERT_NE(mat, nullptr);
  const std::size_t nf = 4, no = 3, ni = 2;
  std::vector<double> re(nf * no * ni), im(nf * no * ni), coh(nf * no * ni);
  for (std::size_t i = 0; i < ni; ++i) {
    for (std::size_t o = 0; o < no; ++o) {
      for (std::size_t k = 0; k < nf; ++k) {
        const std::size_t idx = k + nf * (o + no * i);
        re[idx] = 100.0 * static_cast<double>(i) + 10.0 * static_cast<double>(o) + static_cast<double>(k);
        im[idx] = -re[idx] / 2.0;
        coh[idx] = 0.9;
      }
    }
  }
  mat_complex_split_t split{re.data(), im.data()};
  std::size_t dims[3] = {nf, no, ni};
  matvar_t* v = Mat_VarCreate("H", MAT_C_DOUBLE, MAT_T_DOUBLE, 3, dims, &split, MAT_F_COMPLEX);
  ASSERT_NE(v, nullptr);
  ASSERT_EQ(Mat_VarWrite(mat, v, compression()), 0);
  Mat_VarFree(v);
  writeDouble(mat, "coh", {nf, no, ni}, coh);
  writeDouble(mat, "f", {1, nf}, {5.0, 10.0, 15.0, 20.0});
  Mat_Close(mat);

  FrfImportOptions options;
  options.frfVariable = "H";
  options.frequencyVariable = "f";
  options.coherenceVariable = "coh";
  // Channel map: take file responses 2 and 0 (in that order), reference page 1 only.
  options.responses = {Dof{7, Direction::X, false}, Dof{5, Direction::Y, true}};
  options.responseColumns = {2, 0};
  options.references = {Dof{1, Direction::Z, false}};
  options.referenceColumns = {1};
  options.unit = "g/N";
  auto frf = importFrfMatrix(path_, options);
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  EXPECT_EQ(frf->type, FrfType::Accelerance);
  ASSERT_EQ(frf->lineCount(), 4);
  EXPECT_EQ(frf->frequencyHz[3], 20.0);
  ASSERT_EQ(frf->h.size(), 1u);
  // (k = 3, file response 2, file reference 1): re = 100 + 20 + 3 = 123 g/N.
  EXPECT_DOUBLE_EQ(frf->h[0](3, 0).real(), 123.0 * 9.80665);
  EXPECT_DOUBLE_EQ(frf->h[0](3, 0).imag(), -61.5 * 9.80665);
  EXPECT_DOUBLE_EQ(frf->h[0](1, 1).real(), 101.0 * 9.80665);
  ASSERT_EQ(frf->coherence.size(), 1u);
  EXPECT_EQ(frf->coherence[0](2, 1), 0.9);

  options.frequencyVariable = "nope";
  auto missing = importFrfMatrix(path_, options);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
  EXPECT_NE(missing.error().where.find("'nope'"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Formats, MatImportTest, ::testing::Values(0, 1, 2), [](const auto& info) {
  return std::string(info.param == 0 ? "v5" : info.param == 1 ? "v7_compressed" : "v7_3");
});

TEST(MatImport, NonMatFilesGiveClearErrors) {
  const auto path = fs::temp_directory_path() / ("mozzi_mat_bad_" + std::to_string(::getpid()) + ".mat");
  {
    std::FILE* f = std::fopen(path.string().c_str(), "wb");
    std::fputs("MATLAB 5.0 MAT-file, but then garbage follows and nothing else", f);
    std::fclose(f);
  }
  TimeImportOptions options;
  options.dataVariable = "x";
  options.sampleRateHz = 100.0;
  auto r = importTimeRecord(path.string(), options);
  ASSERT_FALSE(r.ok());
  fs::remove(path);
  auto none = listVariables("/nonexistent/file.mat");
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().code, ErrorCode::NotFound);
}

}  // namespace
}  // namespace mozzi::core::io::mat
