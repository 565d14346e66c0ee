// mozzi-cli gap with a tyre model (mozzi-tire-gap/1) and measured relaxation
// lengths (CSV): the worked example of docs/gap.md (c) from the command line,
// its JSON (issue 10 "Command line"), and the errors a user meets.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run.h"

namespace mozzi::cli {
namespace {

const std::string kDocs = std::string(MOZZI_SOURCE_DIR) + "/docs/gap/";

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "mozzi_gap_tire_cli_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(GapTireCli, ScooterTyreJson) {
  const auto r = run({"gap", "--model", kDocs + "tyre-110-70-16.json", "--measured", kDocs + "tyre-110-70-16-sigma.csv",
                      "--json", "--bootstrap", "100", "--seed", "3"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["data_kind"], "relaxation");
  // gap_before: one condition row per pressure of the CSV, and the overall figure.
  ASSERT_TRUE(j["gap_before"].contains("conditions"));
  ASSERT_EQ(j["gap_before"]["conditions"].size(), 7u);
  EXPECT_EQ(j["gap_before"]["conditions"][0]["label"], "0.5 bar");
  EXPECT_TRUE(j["gap_before"].contains("relaxation_residual"));
  // Every catalogue effect is ranked, each with the issue's fields.
  ASSERT_EQ(j["ranking"].size(), 5u);
  for (const auto& e : j["ranking"])
    for (const char* key : {"effect", "location", "parameters", "std_errors", "criterion", "gap_after", "shrink_pct"})
      EXPECT_TRUE(e.contains(key)) << key;
  // The same verdict as tests/validation/gap_thesis_tire_test.cpp (docs/gap.md (c)).
  EXPECT_EQ(j["verdict"], "effect");
  EXPECT_EQ(j["ranking"][0]["effect"], "contact_patch_fraction");
  EXPECT_EQ(j["best"]["effect"], "contact_patch_fraction");
  // patch_scale 1.94 +- 0.07 in the worked example; 4 standard errors.
  const double s = j["ranking"][0]["parameters"]["patch_scale"];
  const double se = j["ranking"][0]["std_errors"]["patch_scale"];
  EXPECT_NEAR(s, 1.94, 4 * se);
  EXPECT_GT(j["ranking"][0]["shrink_pct"].get<double>(), 80.0);
}

TEST(GapTireCli, RadialTyreTextSaysItCannotTell) {
  const auto r = run({"gap", "--model", kDocs + "tyre-120-70-R17.json", "--measured",
                      kDocs + "tyre-120-70-R17-sigma.csv", "--bootstrap", "100", "--seed", "3"});
  ASSERT_EQ(r.code, 0) << r.err;
  // Human-readable report: the verdict word and both members of the set.
  EXPECT_NE(r.out.find("ambiguous"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("belt_modes"), std::string::npos);
  EXPECT_NE(r.out.find("contact_patch_fraction"), std::string::npos);
}

TEST(GapTireCli, EffectsOptionRestrictsTheCatalogue) {
  const auto r = run({"gap", "--model", kDocs + "tyre-110-70-16.json", "--measured", kDocs + "tyre-110-70-16-sigma.csv",
                      "--json", "--bootstrap", "50", "--effects", "belt_modes,trail_feedback"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["ranking"].size(), 2u);
  for (const auto& e : j["ranking"]) EXPECT_TRUE(e["effect"] == "belt_modes" || e["effect"] == "trail_feedback");
}

// The stability schema goes through the same command (benchmark bicycle, so
// the mode sweeps stay cheap): rigid-fork weave frequencies are a no-gap control.
TEST(GapTireCli, StabilityModelThroughTheSameCommand) {
  const auto model = writeTemp("bicycle.json", R"({"schema": "mozzi-stability-gap/1", "vehicle": "bicycle"})");
  // Weave of the rigid benchmark bicycle, Meijaard et al. (2007) Table 2
  // (shared/data/benchmark-bicycle/eigenvalues.csv): Im = 4.46486771 rad/s at
  // 5 m/s and 5.87673061 rad/s at 6 m/s, as Hz to 5 decimals, 1% uncertainty.
  const auto csv = writeTemp(
      "weave.csv", "speed_m_s,mode,frequency_hz,uncertainty_hz\n5,weave,0.71061,0.0071\n6,weave,0.93531,0.0094\n");
  const auto r = run({"gap", "--model", model, "--measured", csv, "--json", "--bootstrap", "50"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["data_kind"], "stability");
  ASSERT_EQ(j["gap_before"]["conditions"].size(), 2u);
  EXPECT_EQ(j["gap_before"]["conditions"][0]["label"], "weave 5 m/s");
  EXPECT_EQ(j["verdict"], "none");
}

TEST(GapTireCli, BadFilesFailWithTheirPlace) {
  // A pressure outside the contact-patch table (0.5-4 bar): data error, exit 1.
  const auto csv = writeTemp("outside.csv", "pressure_bar,sigma_m,uncertainty_m\n6,0.15,0.01\n");
  auto r = run({"gap", "--model", kDocs + "tyre-110-70-16.json", "--measured", csv});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("extrapolated"), std::string::npos) << r.err;
  // A malformed CSV row names file and line.
  const auto bad = writeTemp("bad.csv", "pressure_bar,sigma_m,uncertainty_m\n1,0.2,oops\n");
  r = run({"gap", "--model", kDocs + "tyre-110-70-16.json", "--measured", bad});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("bad.csv:2"), std::string::npos) << r.err;
  // An unknown thesis tyre in the model file.
  const auto model = writeTemp("m.json", R"({"schema": "mozzi-tire-gap/1", "thesis_tyre": "100/90-10"})");
  r = run({"gap", "--model", model, "--measured", kDocs + "tyre-110-70-16-sigma.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown thesis tyre"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mozzi::cli
