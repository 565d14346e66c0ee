// Every vendor file in shared/data/uff is read and matches what the reference
// reader (pyuff) extracted from it (expected.json), plus the vendor quirks the
// README names and the streaming interface.
#include "core/io/uff/uff.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace mozzi::core::io::uff {
namespace {

namespace fs = std::filesystem;
const fs::path kDir = fs::path(MOZZI_SHARED_DATA_DIR) / "uff";

nlohmann::json expected() {
  std::ifstream in(kDir / "expected.json");
  return nlohmann::json::parse(in);
}

// Relative tolerance of a printed value: ASCII single precision is written
// E13.5 (6 significant digits, half-ulp 5e-6 relative); pyuff and we parse the
// same text, so values agree far below that; binary values are the same IEEE
// numbers in both readers, compared to 1e-12 (double round-off only).
double tolerance(const Function58& f) {
  return f.binary ? 1e-12 : 5e-6;
}

void expectNear(double actual, double want, double rel, const std::string& what) {
  EXPECT_LE(std::abs(actual - want), rel * std::max(1.0, std::abs(want)) + 1e-300)
      << what << ": read " << actual << ", expected " << want;
}

Complex jsonComplex(const nlohmann::json& j) {
  if (j.is_array()) return {j[0].get<double>(), j[1].get<double>()};
  return {j.get<double>(), 0.0};
}

TEST(UffReader, EveryVendorFileMatchesTheReferenceReader) {
  const nlohmann::json all = expected();
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kDir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".uff") continue;
    ASSERT_TRUE(all.contains(name)) << name << " has no entry in expected.json";
    ++files;
    SCOPED_TRACE(name);
    const auto file = readFile(entry.path().string());
    ASSERT_TRUE(file.ok()) << file.error().describe();
    const auto& want = all[name];
    std::vector<int> types;
    for (const auto& d : file->datasets) types.push_back(d.type);
    EXPECT_EQ(types, want["set_types"].get<std::vector<int>>());
    ASSERT_EQ(file->datasets.size(), want["sets"].size());
    for (std::size_t k = 0; k < file->datasets.size(); ++k) {
      const Dataset& d = file->datasets[k];
      const auto& w = want["sets"][k];
      SCOPED_TRACE("dataset " + std::to_string(k) + " type " + std::to_string(d.type));
      switch (d.type) {
        case 151:
          ASSERT_NE(d.get<Header151>(), nullptr);
          EXPECT_EQ(d.get<Header151>()->modelName, w["model_name"].get<std::string>());
          break;
        case 164: {
          const auto* u = d.get<Units164>();
          ASSERT_NE(u, nullptr);
          EXPECT_EQ(u->unitsCode, w["units_code"].get<int>());
          EXPECT_DOUBLE_EQ(u->lengthFactor, w["length"].get<double>());
          break;
        }
        case 18: {
          const auto* c = d.get<CoordinateSystemSet>();
          ASSERT_NE(c, nullptr);
          EXPECT_EQ(static_cast<int>(c->systems.size()), w["count"].get<int>());
          break;
        }
        case 15:
        case 2411: {
          const auto* n = d.get<NodeSet>();
          ASSERT_NE(n, nullptr);
          ASSERT_EQ(static_cast<int>(n->nodes.size()), w["num_nodes"].get<int>());
          EXPECT_EQ(n->nodes.front().label, w["first_node"].get<int>());
          const auto xyz = w["first_xyz"].get<std::vector<double>>();
          // 15 prints E13.5, 2411 D25.16: both readers parse the same text.
          for (int i = 0; i < 3; ++i)
            expectNear(n->nodes.front().xyz[i], xyz[static_cast<std::size_t>(i)], 1e-12, "xyz");
          break;
        }
        case 82: {
          const auto* t = d.get<TraceLine82>();
          ASSERT_NE(t, nullptr);
          EXPECT_EQ(t->traceNumber, w["trace_num"].get<int>());
          EXPECT_EQ(static_cast<int>(t->nodes.size()), w["n_nodes"].get<int>());
          break;
        }
        case 55: {
          const auto* m = d.get<ModalData55>();
          ASSERT_NE(m, nullptr);
          EXPECT_EQ(static_cast<int>(m->nodes.size()), w["num_nodes"].get<int>());
          if (w.contains("freq")) {
            ASSERT_GE(m->realValues.size(), 3u);
            EXPECT_DOUBLE_EQ(m->realValues[0], w["freq"].get<double>());
            EXPECT_DOUBLE_EQ(m->realValues[1], w["modal_m"].get<double>());
            EXPECT_DOUBLE_EQ(m->realValues[2], w["modal_damp_vis"].get<double>());
          }
          if (w.contains("eig")) {
            ASSERT_GE(m->realValues.size(), 2u);
            EXPECT_DOUBLE_EQ(m->realValues[0], w["eig"][0].get<double>());
            EXPECT_DOUBLE_EQ(m->realValues[1], w["eig"][1].get<double>());
          }
          break;
        }
        case 58: {
          const auto* f = d.get<Function58>();
          ASSERT_NE(f, nullptr);
          const double tol = tolerance(*f);
          EXPECT_EQ(static_cast<int>(f->functionType), w["func_type"].get<int>());
          EXPECT_EQ(f->response.node, w["rsp_node"].get<int>());
          EXPECT_EQ(f->response.direction, w["rsp_dir"].get<int>());
          EXPECT_EQ(f->reference.node, w["ref_node"].get<int>());
          EXPECT_EQ(f->reference.direction, w["ref_dir"].get<int>());
          const Eigen::Index n = f->pointCount();
          ASSERT_EQ(n, w["num_pts"].get<Eigen::Index>());
          EXPECT_EQ(isComplex(f->ordinateType), w["complex"].get<bool>());
          const Vector x = f->abscissaValues();
          // The abscissa of even records is min + k * increment, computed in
          // double by both readers.
          expectNear(x[0], w["x_first"].get<double>(), 1e-12, "x_first");
          expectNear(x[n - 1], w["x_last"].get<double>(), 1e-12, "x_last");
          auto at = [&](Eigen::Index i) {
            return isComplex(f->ordinateType) ? f->complex[i] : Complex(f->real[i], 0.0);
          };
          for (Eigen::Index i = 0; i < 3; ++i) {
            const Complex z = jsonComplex(w["data_first"][static_cast<std::size_t>(i)]);
            expectNear(at(i).real(), z.real(), tol, "data_first re");
            expectNear(at(i).imag(), z.imag(), tol, "data_first im");
          }
          for (Eigen::Index i = 0; i < 2; ++i) {
            const Complex z = jsonComplex(w["data_last"][static_cast<std::size_t>(i)]);
            expectNear(at(n - 2 + i).real(), z.real(), tol, "data_last re");
            expectNear(at(n - 2 + i).imag(), z.imag(), tol, "data_last im");
          }
          double sum = 0.0;
          for (Eigen::Index i = 0; i < n; ++i) sum += std::abs(at(i));
          // A sum of n values each exact to `tol`: the sum is exact to tol too.
          expectNear(sum, w["abs_sum"].get<double>(), tol, "abs_sum");
          break;
        }
        default:
          EXPECT_NE(d.get<SkippedDataset>(), nullptr) << "dataset " << d.type << " should be skipped";
          EXPECT_EQ(w.size(), 1u);  // the reference lists unused types by type only
      }
    }
    // Every skipped dataset is announced as a warning naming its type.
    for (const auto& d : file->datasets) {
      if (!d.get<SkippedDataset>()) continue;
      bool warned = false;
      for (const auto& wr : file->warnings) warned = warned || (wr.datasetType == d.type && wr.line == d.line);
      EXPECT_TRUE(warned) << "no warning for skipped dataset " << d.type << " at line " << d.line;
    }
  }
  EXPECT_EQ(files, static_cast<int>(all.size()));
}

TEST(UffReader, VendorQuirksAreReadWithWarnings) {
  // CR/LF line ends (Sample_UFF58b_bin.uff, written by Simcenter TestLab).
  auto crlf = readFile((kDir / "Sample_UFF58b_bin.uff").string());
  ASSERT_TRUE(crlf.ok()) << crlf.error().describe();
  bool sawCrLf = false;
  for (const auto& w : crlf->warnings) sawCrLf = sawCrLf || w.message.find("CR/LF") != std::string::npos;
  EXPECT_TRUE(sawCrLf);
  const auto* bin = crlf->datasets.at(0).get<Function58>();
  ASSERT_NE(bin, nullptr);
  EXPECT_TRUE(bin->binary);
  EXPECT_EQ(bin->ordinateType, OrdinateType::RealSingle);
  EXPECT_EQ(bin->response.entityName, "Mic 01");
  EXPECT_EQ(bin->ordinateNumerator.unitsLabel, "Pa");

  // A header declaring 2508876 points over 42 values: read with a warning
  // naming dataset 58 and the line of record 7 (line 9).
  auto milestone = readFile((kDir / "dataset_milestone_in_header.uff").string());
  ASSERT_TRUE(milestone.ok()) << milestone.error().describe();
  ASSERT_FALSE(milestone->warnings.empty());
  EXPECT_EQ(milestone->warnings.front().datasetType, 58);
  EXPECT_EQ(milestone->warnings.front().line, 9);
  EXPECT_NE(milestone->warnings.front().message.find("2508876"), std::string::npos);

  // Non-ASCII bytes (Latin-1 superscript two) are kept as they are.
  auto latin = readFile((kDir / "non_ascii_header.uff").string());
  ASSERT_TRUE(latin.ok()) << latin.error().describe();
  EXPECT_EQ(latin->datasets.at(0).get<Function58>()->ordinateNumerator.unitsLabel, "(1/N)*(m/s\xb2)");

  // Lone CR line ends and a short last data line.
  std::ifstream in(kDir / "time-history-not-all-columns-filled.uff", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string cr = text;
  for (char& c : cr)
    if (c == '\n') c = '\r';
  auto a = readBytes(text);
  auto b = readBytes(cr);
  ASSERT_TRUE(a.ok() && b.ok());
  const auto* fa = a->datasets.at(0).get<Function58>();
  const auto* fb = b->datasets.at(0).get<Function58>();
  ASSERT_TRUE(fa && fb);
  EXPECT_EQ(fa->real, fb->real);
  bool loneCr = false;
  for (const auto& w : b->warnings) loneCr = loneCr || w.message.find("lone CR") != std::string::npos;
  EXPECT_TRUE(loneCr);
}

TEST(UffReader, StreamingReaderYieldsOneDatasetPerCallInFileOrder) {
  auto reader = DatasetReader::open((kDir / "TestLab 161 164 18 15 82.uff").string());
  ASSERT_TRUE(reader.ok()) << reader.error().describe();
  std::vector<int> types;
  std::vector<std::int64_t> lines;
  for (;;) {
    auto d = reader->next();
    ASSERT_TRUE(d.ok()) << d.error().describe();
    if (!d->has_value()) break;
    types.push_back((*d)->type);
    lines.push_back((*d)->line);
  }
  EXPECT_EQ(types, (std::vector<int>{151, 164, 18, 15, 82, 82, 82}));
  EXPECT_EQ(lines.front(), 2);  // "   151" is the second line of the file
  EXPECT_EQ(reader->bytesRead(), fs::file_size(kDir / "TestLab 161 164 18 15 82.uff"));
  // At the end, next() keeps saying "no more".
  auto after = reader->next();
  ASSERT_TRUE(after.ok());
  EXPECT_FALSE(after->has_value());
}

TEST(UffReader, CoordinateSystemAxesFollowFromTheDefinitionPoints) {
  auto file = readFile((kDir / "TestLab 161 164 18 15 82.uff").string());
  ASSERT_TRUE(file.ok());
  const auto* cs = file->datasets.at(2).get<CoordinateSystemSet>();
  ASSERT_NE(cs, nullptr);
  // SYS1: origin O = (-2.4, -0.95, 0), +x point (-3.4, -0.95, ~0), +xz point
  // (-3.4, -0.95, -1). x = (-1, 0, 0); y = (P_xz - O) x x = (-1, 0, -1) x
  // (-1, 0, 0) = (0, 1, 0); z = x x y = (0, 0, -1).
  const Matrix3& a = cs->systems.front().axes;
  EXPECT_EQ(cs->systems.front().name, "SYS1");
  EXPECT_NEAR(a(0, 0), -1.0, 1e-7);  // 8.7e-8 tilt printed in the file
  EXPECT_NEAR(a(1, 1), 1.0, 1e-7);
  EXPECT_NEAR(a(2, 2), -1.0, 1e-7);
  EXPECT_NEAR(a.row(0).dot(a.row(1).cross(a.row(2))), 1.0, 1e-12);
  EXPECT_NEAR((a * a.transpose() - Matrix3::Identity()).norm(), 0.0, 1e-12);
}

// Issue 17: skip58Data reads the headers of 58 records and skips the samples
// unread (a replay's capabilities, a summary of a file of any size); the
// point count comes from record 7, the data vectors stay empty.
TEST(UffReaderHeadersOnly, Skip58DataKeepsHeadersAndPointCount) {
  for (bool binary : {false, true}) {
    UffFile file;
    for (int c = 1; c <= 2; ++c) {
      Function58 f;
      f.functionType = FunctionType::TimeResponse;
      f.loadCase = 1;
      f.response = Channel58::fromDof(Dof{c, Direction::Z, false});
      f.ordinateType = OrdinateType::RealDouble;
      f.abscissaIncrement = 1.0 / 2048.0;
      f.ordinateNumerator.unitsLabel = "m/s^2";
      f.real = Vector::LinSpaced(5000, -1.0, 1.0);
      f.binary = binary;
      file.datasets.push_back(makeDataset(f));
    }
    auto bytes = writeBytes(file);
    ASSERT_TRUE(bytes.ok());
    ReadOptions options;
    options.skip58Data = true;
    auto reader = DatasetReader::fromBytes(*bytes, options);
    int records = 0;
    for (;;) {
      auto d = reader.next();
      ASSERT_TRUE(d.ok()) << d.error().describe();
      if (!d->has_value()) break;
      const auto* f = (*d)->get<Function58>();
      ASSERT_NE(f, nullptr);
      EXPECT_EQ(f->pointCount(), 5000);
      EXPECT_EQ(f->real.size(), 0);
      EXPECT_EQ(f->ordinateNumerator.unitsLabel, "m/s^2");
      EXPECT_EQ(f->response.dof()->node, records + 1);
      ++records;
    }
    EXPECT_EQ(records, 2) << (binary ? "58b" : "58");
  }
}

}  // namespace
}  // namespace mozzi::core::io::uff
