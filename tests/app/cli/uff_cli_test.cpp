// mozzi-cli uff info / convert as a user or a script sees them.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/command.h"
#include "cli_run.h"
#include "core/io/uff/uff.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

std::string data(const std::string& name) {
  return std::string(MOZZI_SHARED_DATA_DIR) + "/uff/" + name;
}

fs::path tempDir() {
  const fs::path d = fs::temp_directory_path() / ("mozzi_uff_cli_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

TEST(UffCli, InfoJsonListsDatasetsWithFunctionTypeAndDofs) {
  const CliRun r = run({"uff", "info", data("dataset_milestone_in_header.uff"), "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["datasets"].size(), 1u);
  const auto& d = j["datasets"][0];
  // expected.json: func_type 1, 42 points, response node 1 dir 1 (+X),
  // reference node -1 dir 0 (no direction).
  EXPECT_EQ(d["type"], 58);
  EXPECT_EQ(d["function_type"], 1);
  EXPECT_EQ(d["points"], 42);
  EXPECT_EQ(d["response"], "1:+X");
  EXPECT_EQ(d["reference"], "-1:0");
  EXPECT_EQ(d["ordinate_units"], "Pa");
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0]["line"], 9);
}

TEST(UffCli, InfoJsonOfAMixedFileCountsEveryType) {
  const CliRun r = run({"uff", "info", data("TestLab 161 164 18 15 82.uff"), "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::vector<int> types;
  for (const auto& d : j["datasets"]) types.push_back(d["type"].get<int>());
  EXPECT_EQ(types, (std::vector<int>{151, 164, 18, 15, 82, 82, 82}));
  EXPECT_EQ(j["counts"]["82"], 3);
  EXPECT_EQ(j["datasets"][1]["units_code"], 9);
  EXPECT_EQ(j["datasets"][3]["nodes"], 36);
  // Latin-1 text in a vendor file still gives valid JSON.
  const CliRun latin = run({"uff", "info", data("non_ascii_header.uff"), "--json"});
  ASSERT_EQ(latin.code, kExitOk) << latin.err;
  EXPECT_TRUE(nlohmann::json::accept(latin.out));
}

TEST(UffCli, InfoTextNamesSkippedDatasetsAndUnits) {
  const CliRun r = run({"uff", "info", data("heat_engine_housing.uff")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("5 datasets"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2414 (line 60) skipped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("units: code 5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dataset 2412, line 41: dataset type 2412 is not used by Mozzi"), std::string::npos) << r.out;
}

TEST(UffCli, ConvertBinaryToAsciiAndBack) {
  const fs::path dir = tempDir();
  const std::string ascii = (dir / "a.uff").string();
  const std::string binary = (dir / "b.uff").string();
  CliRun r = run({"uff", "convert", data("binary8byte.uff"), ascii, "--ascii"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("wrote 1 datasets"), std::string::npos);
  r = run({"uff", "convert", ascii, binary, "--binary"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  auto src = core::io::uff::readFile(data("binary8byte.uff"));
  auto a = core::io::uff::readFile(ascii);
  auto b = core::io::uff::readFile(binary);
  ASSERT_TRUE(src.ok() && a.ok() && b.ok());
  const auto* fs0 = src->datasets.at(0).get<core::io::uff::Function58>();
  const auto* fa = a->datasets.at(0).get<core::io::uff::Function58>();
  const auto* fb = b->datasets.at(0).get<core::io::uff::Function58>();
  EXPECT_FALSE(fa->binary);
  EXPECT_TRUE(fb->binary);
  // Real double: ASCII keeps 13 digits (E20.12), relative 0.5e-12; the
  // binary leg returns exactly what the ASCII file held.
  for (Eigen::Index i = 0; i < fs0->real.size(); ++i) {
    EXPECT_LE(std::abs(fa->real[i] - fs0->real[i]), 0.5e-12 * std::abs(fs0->real[i])) << i;
  }
  EXPECT_EQ(fb->real, fa->real);
  fs::remove_all(dir);
}

TEST(UffCli, UsageAndInputErrors) {
  EXPECT_EQ(run({"uff"}).code, kExitUsage);
  EXPECT_EQ(run({"uff", "frobnicate", "x"}).code, kExitUsage);
  EXPECT_EQ(run({"uff", "info"}).code, kExitUsage);
  EXPECT_EQ(run({"uff", "convert", "a"}).code, kExitUsage);
  EXPECT_EQ(run({"uff", "convert", "a", "b", "--binary", "--ascii"}).code, kExitUsage);
  EXPECT_EQ(run({"uff", "info", "x", "--bogus"}).code, kExitUsage);
  const CliRun missing = run({"uff", "info", "/nonexistent/file.uff"});
  EXPECT_EQ(missing.code, kExitFailure);
  EXPECT_NE(missing.err.find("/nonexistent/file.uff"), std::string::npos);
  // A malformed file: exit 1 and the message names dataset and line.
  const fs::path dir = tempDir();
  const std::string bad = (dir / "bad.uff").string();
  std::ofstream(bad) << "    -1\n    15\n         1         0         0         1  1.0E+00  nan  2.0E+00\n    -1\n";
  const CliRun r = run({"uff", "info", bad});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("dataset 15"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 3"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(UffCli, ExecutableExitCodes) {
  const std::string cli = MOZZI_CLI_PATH;
  int status = std::system((cli + " uff info '" + data("uff55_translation.uff") + "' --json > /dev/null").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  status = std::system((cli + " uff info > /dev/null 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

}  // namespace
}  // namespace mozzi::cli
