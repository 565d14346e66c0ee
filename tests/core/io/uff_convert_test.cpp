// Dataset 58 <-> FrfMatrix and dataset 55 <-> ModalData.
#include "core/io/uff/uff.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>

namespace mozzi::core::io::uff {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Two-DOF chain receptance (m = 1 kg, k = 1e4 N/m, c = 2 N s/m per element),
// H = (K - w^2 M + i w C)^-1, responses 1:+X and 2:+X, reference 1:+X and 2:-X.
FrfMatrix analyticFrf(bool evenAxis) {
  FrfMatrix m;
  const int nf = 64;
  m.frequencyHz.resize(nf);
  for (int k = 0; k < nf; ++k) m.frequencyHz[k] = evenAxis ? 1.0 + 0.5 * k : 1.0 + 0.5 * k + 0.01 * k * k;
  m.responses = {Dof{1, Direction::X, false}, Dof{2, Direction::X, false}};
  m.references = {Dof{1, Direction::X, false}, Dof{2, Direction::X, true}};
  m.type = FrfType::Receptance;
  Eigen::Matrix2d K, M, C;
  K << 2e4, -1e4, -1e4, 1e4;
  M << 1, 0, 0, 1;
  C << 4, -2, -2, 2;
  m.h.assign(2, ComplexMatrix(nf, 2));
  m.coherence.assign(2, Matrix(nf, 2));
  for (int k = 0; k < nf; ++k) {
    const double w = 2 * kPi * m.frequencyHz[k];
    const Eigen::Matrix2cd H =
        (K.cast<Complex>() - w * w * M.cast<Complex>() + Complex(0, w) * C.cast<Complex>()).inverse();
    for (int i = 0; i < 2; ++i) {
      const double sign = i == 1 ? -1.0 : 1.0;  // reference 2 is along -X
      for (int o = 0; o < 2; ++o) {
        m.h[static_cast<std::size_t>(i)](k, o) = sign * H(o, i);
        m.coherence[static_cast<std::size_t>(i)](k, o) = 0.9 + 0.0015 * k * (o + 1) / (2.0 * (i + 1.0));  // <= 0.995
      }
    }
  }
  return m;
}

TEST(UffConvert, FrfMatrixSurvivesBinaryUffExactly) {
  for (bool even : {true, false}) {
    SCOPED_TRACE(even ? "even axis" : "uneven axis");
    const FrfMatrix in = analyticFrf(even);
    auto records = fromFrfMatrix(in);
    ASSERT_TRUE(records.ok()) << records.error().describe();
    ASSERT_EQ(records->size(), 8u);  // 4 FRFs + 4 coherences
    EXPECT_EQ((*records)[0].functionType, FunctionType::Frf);
    EXPECT_EQ((*records)[0].evenSpacing, even);
    EXPECT_EQ((*records)[0].ordinateNumerator.specificDataType, 8);  // displacement / force
    EXPECT_EQ((*records)[7].functionType, FunctionType::Coherence);
    EXPECT_EQ((*records)[1].reference.direction, 1);
    EXPECT_EQ((*records)[2].reference.direction, -1);
    UffFile file;
    for (auto& r : *records) file.datasets.push_back(makeDataset(r));
    WriteOptions opt;
    opt.encoding = Encoding58::Binary;
    auto bytes = writeBytes(file, opt);
    ASSERT_TRUE(bytes.ok());
    auto back = readBytes(*bytes);
    ASSERT_TRUE(back.ok()) << back.error().describe();
    auto out = toFrfMatrix(*back);
    ASSERT_TRUE(out.ok()) << out.error().describe();
    EXPECT_EQ(out->type, FrfType::Receptance);
    EXPECT_EQ(out->responses, in.responses);
    EXPECT_EQ(out->references, in.references);
    ASSERT_EQ(out->h.size(), 2u);
    ASSERT_EQ(out->coherence.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(out->h[i], in.h[i]);  // binary doubles: exact
      EXPECT_EQ(out->coherence[i], in.coherence[i]);
    }
    // Uneven: the abscissa is stored as doubles; even: f_0 = 1 and df = 0.5
    // pass through record 7 (E13.5) exactly.
    EXPECT_EQ(out->frequencyHz, in.frequencyHz);
  }
}

TEST(UffConvert, FrfMatrixThroughAsciiKeepsThirteenDigits) {
  const FrfMatrix in = analyticFrf(true);
  auto records = fromFrfMatrix(in);
  ASSERT_TRUE(records.ok());
  UffFile file;
  for (auto& r : *records) file.datasets.push_back(makeDataset(r));
  WriteOptions opt;
  opt.encoding = Encoding58::Ascii;
  auto back = readBytes(*writeBytes(file, opt));
  ASSERT_TRUE(back.ok()) << back.error().describe();
  auto out = toFrfMatrix(*back);
  ASSERT_TRUE(out.ok()) << out.error().describe();
  // E20.12 keeps 13 significant digits: relative error <= 0.5e-12 per part.
  for (std::size_t i = 0; i < 2; ++i) {
    const ComplexMatrix d = out->h[i] - in.h[i];
    for (Eigen::Index k = 0; k < d.rows(); ++k) {
      for (Eigen::Index o = 0; o < d.cols(); ++o) {
        EXPECT_LE(std::abs(d(k, o).real()), 0.5e-12 * std::abs(in.h[i](k, o).real()) + 1e-300);
        EXPECT_LE(std::abs(d(k, o).imag()), 0.5e-12 * std::abs(in.h[i](k, o).imag()) + 1e-300);
      }
    }
  }
}

TEST(UffConvert, IncompleteMatricesAndMismatchedAxesAreErrors) {
  const FrfMatrix in = analyticFrf(true);
  auto records = *fromFrfMatrix(in);
  // Drop the FRF for response 2, reference 2 (index 3): the matrix has a hole.
  std::vector<Function58> holed = records;
  holed.erase(holed.begin() + 3);
  auto r = toFrfMatrix(holed);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("no FRF record for response 2:+X, reference 2:-X"), std::string::npos)
      << r.error().message;
  // A coherence missing: the FRFs convert, without coherence.
  std::vector<Function58> noCoh = records;
  noCoh.pop_back();
  auto c = toFrfMatrix(noCoh);
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_TRUE(c->coherence.empty());
  // Another frequency axis in one record.
  std::vector<Function58> shifted = records;
  shifted[1].abscissaMin = 2.0;
  auto s = toFrfMatrix(shifted);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("another frequency axis"), std::string::npos);
  // A scalar channel (direction 0) is not a DOF.
  std::vector<Function58> scalar = records;
  scalar[0].response.direction = 0;
  EXPECT_FALSE(toFrfMatrix(scalar).ok());
}

TEST(UffConvert, VendorFrfFileConverts) {
  // non_ascii_header.uff: one FRF (type 4) of 6 lines with both DOFs "0:0":
  // no direction, so it cannot become an FrfMatrix; the error says why.
  auto file = readFile(std::string(MOZZI_SHARED_DATA_DIR) + "/uff/non_ascii_header.uff");
  ASSERT_TRUE(file.ok());
  auto m = toFrfMatrix(*file);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("direction code 0"), std::string::npos) << m.error().message;
}

TEST(UffConvert, NormalModesFromVendorFile) {
  auto file = readFile(std::string(MOZZI_SHARED_DATA_DIR) + "/uff/uff55_translation.uff");
  ASSERT_TRUE(file.ok());
  auto md = toModalData(*file);
  ASSERT_TRUE(md.ok()) << md.error().describe();
  // Three modes at 10, 12 and 13 Hz (record 8 of each dataset), 4 nodes x 3 DOFs.
  EXPECT_EQ(md->frequencyHz, (Vector(3) << 10.0, 12.0, 13.0).finished());
  ASSERT_EQ(md->dofs.size(), 12u);
  EXPECT_EQ(md->dofs[0], (Dof{1, Direction::X, false}));
  EXPECT_EQ(md->dofs[11], (Dof{4, Direction::Z, false}));
  EXPECT_FALSE(md->complexShapes);
  // Node 1 of mode 1 holds -1.46518 in all three directions; node 4 of mode 2 1.98289.
  EXPECT_EQ(md->shapes(0, 0), Complex(-1.46518, 0));
  EXPECT_EQ(md->shapes(2, 0), Complex(-1.46518, 0));
  EXPECT_EQ(md->shapes(9, 1), Complex(1.98289, 0));

  // ModalData -> 55 -> text -> 55 -> ModalData keeps the digits (E13.5).
  auto records = fromModalData(*md);
  ASSERT_TRUE(records.ok());
  UffFile out;
  for (auto& r : *records) out.datasets.push_back(makeDataset(r));
  auto back = readBytes(*writeBytes(out));
  ASSERT_TRUE(back.ok()) << back.error().describe();
  auto md2 = toModalData(*back);
  ASSERT_TRUE(md2.ok());
  EXPECT_EQ(md2->frequencyHz, md->frequencyHz);
  EXPECT_EQ(md2->shapes, md->shapes);  // values already 6 digits: exact
  EXPECT_EQ(md2->dofs, md->dofs);
}

TEST(UffConvert, ComplexEigenvalueGivesFrequencyAndDamping) {
  auto file = readFile(std::string(MOZZI_SHARED_DATA_DIR) + "/uff/uff55 sample_test record10.uff");
  ASSERT_TRUE(file.ok());
  auto md = toModalData(*file);
  ASSERT_TRUE(md.ok()) << md.error().describe();
  // lambda = -0.1111111 + 41.11111 i rad/s: omega_n = |lambda|,
  // f = omega_n / 2 pi, zeta = 0.1111111 / omega_n.
  const double wn = std::hypot(0.1111111, 41.11111);
  EXPECT_NEAR(md->frequencyHz[0], wn / (2 * kPi), 1e-12);
  EXPECT_NEAR(md->dampingRatio[0], 0.1111111 / wn, 1e-15);
  EXPECT_TRUE(md->complexShapes);
  ASSERT_EQ(md->dofs.size(), 6u);
  EXPECT_EQ(md->dofs[3].node, 60101);
  EXPECT_EQ(md->shapes(1, 0), Complex(0.1111111, 0.09111111));

  // Round trip through a complex 55: f and zeta come back from lambda.
  auto records = fromModalData(*md);
  ASSERT_TRUE(records.ok());
  EXPECT_EQ((*records)[0].analysisType, AnalysisType::ComplexEigenSecondOrder);
  auto md2 = toModalData(*records);
  ASSERT_TRUE(md2.ok());
  EXPECT_NEAR(md2->frequencyHz[0], md->frequencyHz[0], 1e-12);
  EXPECT_NEAR(md2->dampingRatio[0], md->dampingRatio[0], 1e-15);
  EXPECT_EQ(md2->shapes, md->shapes);
}

TEST(UffConvert, NegativeDirectionsFoldIntoNodeVectors) {
  ModalData md;
  md.dofs = {Dof{5, Direction::Y, true}, Dof{5, Direction::RZ, false}};
  md.frequencyHz = Vector::Constant(1, 18.4);
  md.dampingRatio = Vector::Constant(1, 0.02);
  md.shapes = ComplexMatrix::Zero(2, 1);
  md.shapes(0, 0) = 0.5;   // along -Y
  md.shapes(1, 0) = 0.25;  // about +Z
  auto r = fromModalData(md);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ((*r)[0].valuesPerNode, 6);  // a rotation makes it a 6-DOF record
  EXPECT_EQ((*r)[0].nodes[0].values[1], Complex(-0.5, 0));
  EXPECT_EQ((*r)[0].nodes[0].values[5], Complex(0.25, 0));
  EXPECT_EQ((*r)[0].realValues[2], 0.02);  // viscous damping ratio in record 8
}

}  // namespace
}  // namespace mozzi::core::io::uff
