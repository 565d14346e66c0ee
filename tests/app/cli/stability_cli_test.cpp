// mozzi-cli stability as a user (or a script) runs it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/command.h"
#include "cli_run.h"

namespace mozzi::cli {
namespace {

const std::string kSharp = std::string(MOZZI_SHARED_DATA_DIR) + "/motorcycle/sharp1971-parameters.csv";

TEST(StabilityCli, BenchmarkBicycleJson) {
  const CliRun r = run({"stability", "bicycle", "--speeds", "0:10:0.5", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["speeds"].size(), 21u);
  const auto& at5 = j["speeds"][10];
  EXPECT_DOUBLE_EQ(at5["v"].get<double>(), 5.0);
  bool weaveSeen = false;
  for (const auto& m : at5["modes"]) {
    if (m["name"] == "weave") {
      weaveSeen = true;
      // Meijaard et al. (2007) Table 2 at 5 m/s; JSON keeps full precision.
      EXPECT_NEAR(m["re"].get<double>(), -0.77534188219585, 1e-12);
      EXPECT_NEAR(m["im"].get<double>(), 4.46486771378823, 1e-12);
    }
  }
  EXPECT_TRUE(weaveSeen);
  // README critical speeds (exact), Brent to ~1e-14.
  EXPECT_NEAR(j["critical_speeds"]["weave"].get<double>(), 4.29238253634110, 1e-12);
  EXPECT_NEAR(j["critical_speeds"]["capsize"].get<double>(), 6.02426201538836, 1e-12);
  EXPECT_TRUE(j["critical_speeds"]["wobble"].is_null());
}

TEST(StabilityCli, ForkTorsionAddsTheTorsionMode) {
  const CliRun r = run({"stability", "bicycle", "--fork-torsion", "1938,0.3", "--speeds", "5:5:1", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  int torsion = 0;
  for (const auto& m : j["speeds"][0]["modes"]) torsion += m["name"] == "fork torsion";
  EXPECT_EQ(torsion, 1);
  const CliRun text = run({"stability", "bicycle", "--fork-bending", "5635,0.8,0.21", "--speeds", "0:8:1"});
  ASSERT_EQ(text.code, kExitOk) << text.err;
  EXPECT_NE(text.out.find("fork bending"), std::string::npos);
  EXPECT_NE(text.out.find("weave stabilises at 4.35"), std::string::npos);
}

TEST(StabilityCli, MotorcycleWithLumpedFork) {
  const CliRun r =
      run({"stability", "motorcycle", "--params", kSharp, "--fork-model", "1", "--speeds", "5:40:5", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["speeds"].size(), 8u);
  std::set<std::string> names;
  for (const auto& m : j["speeds"][7]["modes"]) names.insert(m["name"].get<std::string>());
  EXPECT_TRUE(names.count("wobble") && names.count("weave") && names.count("fork bending") && names.count("capsize"));
  EXPECT_TRUE(j["critical_speeds"]["wobble"].is_null());
  EXPECT_TRUE(j["critical_speeds"]["capsize"].is_number());
}

TEST(StabilityCli, UsageAndInputErrors) {
  EXPECT_EQ(run({"stability"}).code, kExitUsage);
  EXPECT_EQ(run({"stability", "tricycle", "--speeds", "0:1:1"}).code, kExitUsage);
  EXPECT_EQ(run({"stability", "bicycle"}).code, kExitUsage);
  // A value outside its declared range is an input error, exit 1 (docs/cli.md).
  EXPECT_EQ(run({"stability", "bicycle", "--speeds", "0:10"}).code, kExitFailure);
  EXPECT_EQ(run({"stability", "bicycle", "--speeds", "0:10:0"}).code, kExitFailure);
  const CliRun both =
      run({"stability", "bicycle", "--fork-bending", "1,1,0.2", "--fork-torsion", "1,1", "--speeds", "0:1:1"});
  EXPECT_EQ(both.code, kExitUsage);
  EXPECT_NE(both.err.find("not both"), std::string::npos);
  const CliRun bad = run({"stability", "bicycle", "--fork-bending", "1,x,0.2", "--speeds", "0:1:1"});
  EXPECT_EQ(bad.code, kExitFailure);
  EXPECT_NE(bad.err.find("--fork-bending"), std::string::npos);
  EXPECT_EQ(run({"stability", "bicycle", "--fork-torsion", "-5,1", "--speeds", "0:1:1"}).code, kExitFailure);
  EXPECT_EQ(run({"stability", "motorcycle", "--speeds", "5:10:1"}).code, kExitUsage);
  EXPECT_EQ(run({"stability", "motorcycle", "--params", kSharp, "--fork-model", "4", "--speeds", "5:10:1"}).code,
            kExitUsage);
  EXPECT_EQ(run({"stability", "motorcycle", "--params", kSharp, "--speeds", "0:10:1"}).code, kExitFailure);
  const CliRun missing = run({"stability", "motorcycle", "--params", "/nonexistent.csv", "--speeds", "5:10:1"});
  EXPECT_EQ(missing.code, kExitFailure);
  EXPECT_NE(missing.err.find("/nonexistent.csv"), std::string::npos);
}

// The real executable, as a shell would run it.
TEST(StabilityCli, ExecutableRuns) {
  const std::string cli = MOZZI_CLI_PATH;
  EXPECT_EQ(std::system((cli + " stability bicycle --speeds 0:10:1 --json > /dev/null").c_str()), 0);
}

}  // namespace
}  // namespace mozzi::cli
