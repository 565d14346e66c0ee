// mozzi-cli project info / export as a user runs them (docs/cli/project.md):
// a project filled through the core API, its summary, and its FRFs exported
// as UFF (read back with the UFF reader) and as CSV (read back with the CSV
// reader). Binary UFF and CSV carry doubles exactly (tolerance 0); ASCII UFF
// 58 writes double-precision FRF values as E20.12/D25.16-type fields, so the
// read-back agrees to 1e-11 relative (12+ significant digits).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/command.h"
#include "cli_run.h"
#include "core/io/csv/csv_exchange.h"
#include "core/io/project_store.h"
#include "core/io/uff/uff.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;
using namespace mozzi::core;

FrfMatrix sdofFrf() {
  // Accelerance of m = 2 kg, fn = 60 Hz, zeta = 1.5 %: A = -w^2 / (m (wn^2 - w^2 + 2 i zeta wn w)).
  FrfMatrix f;
  f.type = FrfType::Accelerance;
  f.frequencyHz = Vector::LinSpaced(64, 1.0, 127.0);
  f.responses = {Dof{2, Direction::Z, false}, Dof{3, Direction::Z, false}};
  f.references = {Dof{1, Direction::Z, false}};
  ComplexMatrix h(64, 2);
  const double wn = 2 * M_PI * 60.0;
  for (int k = 0; k < 64; ++k) {
    const double w = 2 * M_PI * f.frequencyHz[k];
    h(k, 0) = -w * w / (2.0 * Complex(wn * wn - w * w, 2 * 0.015 * wn * w));
    h(k, 1) = -0.5 * h(k, 0);
  }
  f.h = {h};
  return f;
}

class ProjectCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(MOZZI_BINARY_DIR) / ("project_cli_" + std::to_string(::getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "p.mozzi").string();
    auto store = io::ProjectStore::create(path_, "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    auto sp = store->addSpecimen("Frame A", "frame", "");
    ASSERT_TRUE(sp.ok());
    io::StoredMesh mesh;
    for (int i = 1; i <= 3; ++i) mesh.nodes.push_back({0, i, 0, 0, Vector3(0.1 * i, 0.0, 0.05)});
    mesh.lines = {{1, 2}, {2, 3}};
    ASSERT_TRUE(store->setMesh(*sp, mesh).ok());
    io::StoredCampaign c;
    c.specimenId = *sp;
    c.name = "roving hammer";
    auto cid = store->addCampaign(c);
    ASSERT_TRUE(cid.ok());
    for (int k = 1; k <= 3; ++k) {
      io::StoredHit h;
      h.campaignId = *cid;
      h.sequence = k;
      h.point = Dof{1, Direction::Z, false};
      h.sampleRateHz = 1024;
      h.samples = Eigen::MatrixXf::Constant(128, 2, 0.5f);
      h.accepted = k != 2;
      ASSERT_TRUE(store->commitHit(h).ok());
    }
    io::FrfSetInfo info;
    info.specimenId = *sp;
    info.campaignId = *cid;
    info.name = "H1";
    auto fid = store->addFrfSet(info, sdofFrf());
    ASSERT_TRUE(fid.ok()) << fid.error().describe();
    io::ModalTable table;
    for (int n = 1; n <= 3; ++n) {
      for (Direction d : {Direction::X, Direction::Y, Direction::Z}) table.dofs.push_back(Dof{n, d, false});
    }
    io::StoredMode mode{60.0, 0.015, ComplexVector::Zero(9)};
    mode.shape[2] = 1.0;
    mode.shape[5] = 0.5;
    table.modes = {mode};
    io::ModalResultInfo mi;
    mi.specimenId = *sp;
    mi.frfSetId = *fid;
    mi.name = "SDOF fit";
    mi.method = "circle fit";
    ASSERT_TRUE(store->addModalResult(mi, table).ok());
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string path_;
};

TEST_F(ProjectCli, InfoListsCampaignsFrfSetsAndTables) {
  const auto r = run({"project", "info", path_, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema"], io::ProjectStore::currentSchemaVersion());
  ASSERT_EQ(j["campaigns"].size(), 1u);
  EXPECT_EQ(j["campaigns"][0]["hits_accepted"], 2);
  EXPECT_EQ(j["campaigns"][0]["hits_rejected"], 1);
  EXPECT_EQ(j["campaigns"][0]["stored_bytes"], 3 * 128 * 2 * 4);  // raw float32 blobs
  ASSERT_EQ(j["frf_sets"].size(), 1u);
  EXPECT_EQ(j["frf_sets"][0]["lines"], 64);
  EXPECT_EQ(j["frf_sets"][0]["type"], "accelerance");
  EXPECT_EQ(j["tables"]["mesh_node"], 3);
  EXPECT_EQ(j["tables"]["hit"], 3);
  EXPECT_EQ(j["modal_results"][0]["modes"], 1);

  const auto text = run({"project", "info", path_});
  ASSERT_EQ(text.code, 0);
  EXPECT_NE(text.out.find("2 accepted, 1 rejected hits"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("64 lines, 2 responses x 1 references"), std::string::npos) << text.out;
}

TEST_F(ProjectCli, ExportUffBinaryAndAsciiReadBack) {
  for (bool binary : {true, false}) {
    const std::string out = (dir_ / (binary ? "b.uff" : "a.uff")).string();
    std::vector<std::string> args = {"project", "export", path_, "--uff", out};
    if (binary) args.push_back("--binary");
    const auto r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("1 FRF sets, 1 modal results"), std::string::npos) << r.out;
    auto file = io::uff::readFile(out);
    ASSERT_TRUE(file.ok()) << file.error().describe();
    EXPECT_EQ(file->all<io::uff::NodeSet>().size(), 1u);
    EXPECT_EQ(file->all<io::uff::TraceLine82>().size(), 1u);
    auto frf = io::uff::toFrfMatrix(*file);
    ASSERT_TRUE(frf.ok()) << frf.error().describe();
    const FrfMatrix expected = sdofFrf();
    EXPECT_EQ(frf->type, FrfType::Accelerance);
    EXPECT_EQ(frf->responses, expected.responses);
    ASSERT_EQ(frf->lineCount(), 64);
    const double tol = binary ? 0.0 : 1e-11;
    for (int k = 0; k < 64; ++k) {
      EXPECT_LE(std::abs(frf->frequencyHz[k] - expected.frequencyHz[k]), tol * expected.frequencyHz[k]) << k;
      for (int o = 0; o < 2; ++o) {
        EXPECT_LE(std::abs(frf->h[0](k, o) - expected.h[0](k, o)), tol * std::abs(expected.h[0](k, o)))
            << "line " << k << " response " << o;
      }
    }
    auto modal = io::uff::toModalData(*file);
    ASSERT_TRUE(modal.ok()) << modal.error().describe();
    ASSERT_EQ(modal->frequencyHz.size(), 1);
    EXPECT_NEAR(modal->frequencyHz[0], 60.0, 60.0 * 1e-11);
    EXPECT_NEAR(modal->dampingRatio[0], 0.015, 0.015 * 1e-6);  // 55 stores damping in a single-precision-width field
  }
}

TEST_F(ProjectCli, ExportCsvIsExact) {
  const std::string out = (dir_ / "frf.csv").string();
  const auto r = run({"project", "export", path_, "--csv", out});
  ASSERT_EQ(r.code, 0) << r.err;
  auto frf = io::csv::importFrfCsv(out);
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  EXPECT_EQ(frf->h[0], sdofFrf().h[0]);
  EXPECT_EQ(frf->frequencyHz, sdofFrf().frequencyHz);
}

TEST_F(ProjectCli, UsageAndInputErrors) {
  EXPECT_EQ(run({"project", "export", path_}).code, 2);  // neither --uff nor --csv
  EXPECT_EQ(run({"project", "export", path_, "--uff", "a", "--csv", "b"}).code, 2);
  EXPECT_EQ(run({"project", "export", path_, "--csv", "x.csv", "--frf-set", "1.5"}).code, 1);  // out of range
  EXPECT_EQ(run({"project", "info", path_, "--bogus"}).code, 2);
  const auto missing = run({"project", "info", (dir_ / "none.mozzi").string()});
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
  const auto noSet = run({"project", "export", path_, "--uff", (dir_ / "x.uff").string(), "--frf-set", "42"});
  EXPECT_EQ(noSet.code, 1);
  EXPECT_NE(noSet.err.find("no FRF set with id 42"), std::string::npos) << noSet.err;
}

}  // namespace
}  // namespace mozzi::cli
