// mozzi-cli gap as a user sees it: a small generated model (the swing arm of
// the structural benchmark) written as mozzi-model/1, its FRFs with a hidden
// 0.6 kg mass at the axle written as UFF 58; exit codes, the JSON fields of
// issue 10 and the readable table.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "app/cli/command.h"
#include "cli_run.h"
#include "core/gap/structural/model_file.h"
#include "core/io/uff/uff.h"
#include "validation/gap/structural_benchmark.h"

namespace mozzi::cli {
namespace {

std::string tempPath(const std::string& name) {
  return std::string(MOZZI_BINARY_DIR) + "/gap_cli_" + name;
}

struct Files {
  std::string model, frf;
};

Files writeFiles() {
  Files f{tempPath("swing_arm.json"), tempPath("swing_arm_mass.uff")};
  EXPECT_EQ(gap_bench::writeSwingArmWithHiddenMass(f.model, f.frf), "");
  return f;
}

// The hidden mass is found at its DOF with its size: 0.6 kg within 3 standard
// errors (and the SE below 20% of the size), the FRF gap shrinking by more
// than 80% (1% noise against a ~10x larger gap before).
TEST(GapCli, JsonFindsTheHiddenMass) {
  const Files f = writeFiles();
  const CliRun r = run({"gap", "--model", f.model, "--measured", f.frf, "--json", "--bootstrap", "20", "--seed", "3",
                        "--multistarts", "2", "--effects", "mass_loading,element_stiffness,exponential_window"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"gap_before", "where", "verdict", "ranking", "best"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["gap_before"].contains("frf_residual"));
  EXPECT_TRUE(j["gap_before"].contains("modes"));
  EXPECT_EQ(j["verdict"], "effect");
  const auto& best = j["best"];
  EXPECT_EQ(best["effect"], "mass_loading");
  EXPECT_EQ(best["location"], nlohmann::json::array({"3+X"}));
  const double size = best["parameters"]["added_mass"].get<double>();
  const double se = best["std_errors"]["added_mass"].get<double>();
  EXPECT_NEAR(size, 0.6, 3 * se);
  EXPECT_LT(se, 0.12);
  EXPECT_GT(best["shrink_pct"].get<double>(), 80.0);
  for (const auto& e : j["ranking"]) {
    EXPECT_TRUE(e.contains("effect") && e.contains("location") && e.contains("parameters") &&
                e.contains("std_errors") && e.contains("criterion"));
  }
}

TEST(GapCli, TableAndExitCodes) {
  const Files f = writeFiles();
  const CliRun table = run({"gap", "--model", f.model, "--measured", f.frf, "--bootstrap", "20", "--multistarts", "2",
                            "--effects", "mass_loading,hysteretic_damping", "--band", "5:300"});
  ASSERT_EQ(table.code, kExitOk) << table.err;
  EXPECT_NE(table.out.find("Gap before (frf_residual"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("Ranking"), std::string::npos);
  EXPECT_NE(table.out.find("Verdict: effect - mass_loading at 3+X"), std::string::npos) << table.out;

  EXPECT_EQ(run({"gap", "--model", f.model}).code, kExitUsage);
  // Values outside their range: exit 1 (docs/cli.md).
  EXPECT_EQ(run({"gap", "--model", f.model, "--measured", f.frf, "--band", "9:3"}).code, kExitFailure);
  EXPECT_EQ(run({"gap", "--model", f.model, "--measured", f.frf, "--bootstrap", "-1"}).code, kExitFailure);
  const CliRun unknown = run({"gap", "--model", f.model, "--measured", f.frf, "--effects", "tyre_magic"});
  EXPECT_EQ(unknown.code, kExitUsage);
  EXPECT_NE(unknown.err.find("mass_loading"), std::string::npos) << unknown.err;
  const CliRun missing = run({"gap", "--model", tempPath("nope.json"), "--measured", f.frf});
  EXPECT_EQ(missing.code, kExitFailure);
  // A model whose K is not symmetric: the error names the entry.
  std::ofstream(tempPath("bad.json")) << R"({"schema": "mozzi-model/1", "dofs": ["1+Z", "2+Z"], "M": [[1, 0], [0, 1]],
      "K": [[2, -1], [-1.5, 1]], "modal_damping": [0.01, 0.01]})";
  const CliRun bad = run({"gap", "--model", tempPath("bad.json"), "--measured", f.frf});
  EXPECT_EQ(bad.code, kExitFailure);
  EXPECT_NE(bad.err.find("K[0][1]"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace mozzi::cli
