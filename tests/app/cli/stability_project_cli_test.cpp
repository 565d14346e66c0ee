// `mozzi-cli stability ... --project` and `mozzi-cli wheelchair slalom
// --project` keep what they print in the project (issue 22): the kept
// record's critical speeds are the printed ones (the published benchmark
// weave speed 4.29238253634110 m/s of Meijaard et al. 2007, printed
// 4.292383), its name is --store's, a second run gets "NAME (2)"; the
// wheelchair's kept slalom is the history --out writes; bad combinations are
// usage errors and an unknown specimen is an error naming it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "cli_run.h"
#include "core/io/project_store.h"
#include "core/stability/stability_record.h"
#include "core/stability/wheelchair_record.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;
namespace st = core::stability;

class StabilityProjectCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi-stability-project-cli-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "p.mozzi").string();
    auto store = core::io::ProjectStore::create(path_, "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    ASSERT_TRUE(store->addSpecimen("Frame", "frame", "test").ok());
    ASSERT_TRUE(store->addSpecimen("Steel bicycle fork", "bicycle-fork", "test").ok());
    ASSERT_TRUE(store->addSpecimen("Wheelchair tyres", "wheelchair-tyre", "test").ok());
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string path_;
};

TEST_F(StabilityProjectCli, KeepsWhatItPrints) {
  const CliRun r = run({"stability", "bicycle", "--speeds", "0:10:0.05", "--project", path_, "--store", "benchmark"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("weave stabilises at 4.292383 m/s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("as analysis 1 'benchmark'"), std::string::npos) << r.out;
  const CliRun again =
      run({"stability", "bicycle", "--speeds", "0:10:0.05", "--project", path_, "--store", "benchmark", "--json"});
  ASSERT_EQ(again.code, kExitOk) << again.err;
  const auto j = nlohmann::json::parse(again.out);
  EXPECT_EQ(j["stored_analysis"]["name"], "benchmark (2)");
  auto store = core::io::ProjectStore::open(path_, core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  auto kept = st::storedStabilityRecord(*store, 1);
  ASSERT_TRUE(kept.ok()) << kept.error().describe();
  EXPECT_EQ(kept->specimenId, 2);  // the project's bicycle fork
  EXPECT_EQ(kept->record.vehicle, "bicycle");
  ASSERT_TRUE(kept->record.sweep.criticalSpeed("weave"));
  EXPECT_EQ(st::criticalSpeedText(*kept->record.sweep.criticalSpeed("weave")), "4.292383");
  EXPECT_NEAR(*kept->record.sweep.criticalSpeed("weave"), 4.29238253634110, 1e-10);
  // The JSON printed is the sweep kept: same critical speed, bit for bit.
  EXPECT_EQ(j["critical_speeds"]["weave"].get<double>(), *kept->record.sweep.criticalSpeed("weave"));
}

TEST_F(StabilityProjectCli, Refusals) {
  const CliRun noProject = run({"stability", "bicycle", "--speeds", "0:1:0.5", "--store", "x"});
  EXPECT_EQ(noProject.code, kExitUsage);
  EXPECT_NE(noProject.err.find("--project"), std::string::npos) << noProject.err;
  const CliRun unknown =
      run({"stability", "bicycle", "--speeds", "0:1:0.5", "--project", path_, "--specimen", "Nobody"});
  EXPECT_EQ(unknown.code, kExitFailure);
  EXPECT_NE(unknown.err.find("Nobody"), std::string::npos) << unknown.err;
  const CliRun steady = run({"wheelchair", "steady", "--project", path_});
  EXPECT_EQ(steady.code, kExitUsage);
}

TEST_F(StabilityProjectCli, WheelchairSlalomKeepsItsHistory) {
  const std::string csv = (dir_ / "h.csv").string();
  const CliRun r = run({"wheelchair", "slalom", "--duration", "12", "--out", csv, "--project", path_});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("as analysis 1 'slalom'"), std::string::npos) << r.out;
  auto store = core::io::ProjectStore::open(path_, core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  auto kept = st::storedWheelchairRecord(*store, 1);
  ASSERT_TRUE(kept.ok()) << kept.error().describe();
  EXPECT_EQ(kept->specimenId, 3);  // the wheelchair tyres
  ASSERT_EQ(kept->record.runs.size(), 1u);
  // The CSV's rows (12 significant digits) are the kept history's.
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::size_t n = 0;
  const auto& h = kept->record.runs[0].history;
  while (std::getline(in, line)) {
    ASSERT_LT(n, h.size());
    double t = 0, x = 0, y = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &x, &y), 3);
    EXPECT_NEAR(t, h[n].t, 1e-11 * (1 + std::abs(h[n].t)));
    EXPECT_NEAR(y, h[n].y, 1e-11 * (1 + std::abs(h[n].y)));
    ++n;
  }
  EXPECT_EQ(n, h.size());
}

}  // namespace
}  // namespace mozzi::cli
