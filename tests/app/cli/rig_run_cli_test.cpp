// mozzi-cli rig run (issue 20): the JSON keys the issue lists with their
// uncertainties and the stored test's id, the test in the project (and in
// `project info`), --specimen as a catalogue key or a project specimen's name,
// and refusals (usage errors exit 2, set-points beyond the machine exit 1
// naming the limit, nothing stored). Bounded runs: short frequency lists.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "cli_run.h"
#include "core/io/project_store.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

class RigRunCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(MOZZI_BINARY_DIR) / ("rig_run_cli_" + std::to_string(::getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "p.mozzi").string();
    auto store = core::io::ProjectStore::create(path_, "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    ASSERT_TRUE(store->addSpecimen("Fork A (enduro) with wheel", "fork", "").ok());
    ASSERT_TRUE(store->addSpecimen("Frame A", "frame", "").ok());
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string path_;
};

TEST_F(RigRunCli, StaticTestPrintsTheResultsWithUncertaintiesAndTheStoredId) {
  const auto r = run({"rig", "run", path_, "--specimen", "Fork A (enduro) with wheel", "--rig", "sim-stiffness",
                      "--test", "static", "--seed", "3", "--json"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "complete");
  EXPECT_EQ(j.at("specimen").at("key"), "fork-a-with-wheel");
  EXPECT_FALSE(j.at("specimen").at("created").get<bool>());
  for (const char* key : {"k_lat", "k_tw", "a_tw", "axis_inclination_deg", "k_bend", "k_tors"}) {
    ASSERT_TRUE(j.at("results").contains(key)) << key << " in " << j.at("results").dump();
    EXPECT_GT(j["results"][key]["uncertainty"].get<double>(), 0.0) << key;
  }
  // Table 10: 56.1 kN/m, 45.5 deg (the 1% and 0.5 deg of the issue).
  EXPECT_NEAR(j["results"]["k_lat"]["value"].get<double>() / 56.1e3, 1.0, 0.01);
  EXPECT_NEAR(std::abs(j["results"]["axis_inclination_deg"]["value"].get<double>()), 45.5, 0.5);
  EXPECT_EQ(j["results"]["axis_inclination_deg"]["unit"], "deg");
  const auto id = j.at("stored_test_id").get<std::int64_t>();
  EXPECT_EQ(j.at("stored_in"), "rig_test");

  auto store = core::io::ProjectStore::open(path_, core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  auto t = store->rigTest(id);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->status, core::io::TestStatus::Complete);
  EXPECT_TRUE(store->rigTestRecord(id, 0).ok());

  const auto info = run({"project", "info", path_, "--json"});
  ASSERT_EQ(info.code, 0) << info.err;
  const auto ji = nlohmann::json::parse(info.out);
  ASSERT_EQ(ji.at("rig_tests").size(), 1u);
  EXPECT_EQ(ji["rig_tests"][0]["id"], id);
  EXPECT_EQ(ji["rig_tests"][0]["kind"], "static");
  EXPECT_EQ(ji["rig_tests"][0]["status"], "complete");
  EXPECT_EQ(ji["rig_tests"][0]["specimen"], "Fork A (enduro) with wheel");
  const auto text = run({"project", "info", path_});
  EXPECT_NE(text.out.find("rig tests:"), std::string::npos) << text.out;
}

TEST_F(RigRunCli, DynamicTestGivesTheAxisPerFrequency) {
  const auto r = run({"rig", "run", path_, "--specimen", "frame-a-front-constrained", "--rig", "sim-stiffness",
                      "--test", "dynamic", "--frequencies", "5,10", "--json"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  // The key maps to the project's "Frame A" (the demo's name for it).
  EXPECT_EQ(j.at("specimen").at("name"), "Frame A");
  ASSERT_EQ(j.at("steps").size(), 2u);
  EXPECT_EQ(j["steps"][1]["frequency"]["value"], 10.0);
  for (const auto& s : j["steps"]) {
    EXPECT_TRUE(s.at("ok").get<bool>()) << s.dump();
    EXPECT_TRUE(s.contains("axis_inclination_deg"));
    EXPECT_TRUE(s.contains("k_lat"));
  }
}

// --actuator sim-funcgen: the set-point through the simulated function
// generator; the stored set-up names both devices and the result is the one
// the rig's own drive gives with the same seed (the rig follows the
// generator's set-point exactly: 1e-9 relative on the printed JSON).
TEST_F(RigRunCli, TheActuatorSetPointThroughTheSimulatedFunctionGenerator) {
  auto runWith = [&](const char* actuator, const char* name) {
    return run({"rig", "run", path_, "--specimen", "fork-a-with-wheel", "--rig", "sim-stiffness", "--test", "dynamic",
                "--frequencies", "8", "--seed", "4", "--actuator", actuator, "--name", name, "--json"});
  };
  const auto gen = runWith("sim-funcgen", "through the generator");
  ASSERT_EQ(gen.code, 0) << gen.err << gen.out;
  const auto own = runWith("sim-stiffness", "own drive");
  ASSERT_EQ(own.code, 0) << own.err << own.out;
  const auto jg = nlohmann::json::parse(gen.out), jo = nlohmann::json::parse(own.out);
  const double a = jg.at("steps").at(0).at("axis_inclination_deg").at("value").get<double>();
  const double b = jo.at("steps").at(0).at("axis_inclination_deg").at("value").get<double>();
  EXPECT_NEAR(a, b, 1e-9 * std::abs(b));
  auto store = core::io::ProjectStore::open(path_, core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  auto t = store->rigTest(jg.at("stored_test_id").get<std::int64_t>());
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(store->rigSetup(*t->rigSetupId)->driver, "sim-stiffness + sim-funcgen");
  const auto bad = runWith("a-kettle", "no");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--actuator"), std::string::npos) << bad.err;
}

TEST_F(RigRunCli, TyreTestsGiveRelaxationLengthsAndTheMagicFormula) {
  auto r = run({"rig", "run", path_, "--specimen", "tyre-120-70-r17", "--rig", "sim-tyre-tester", "--test",
                "relaxation", "--frequencies", "0.84,1.26", "--json"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("specimen").at("created").get<bool>());  // added to the project for the test
  EXPECT_EQ(j.at("stored_in"), "tyre_test");
  ASSERT_EQ(j.at("steps").size(), 2u);
  for (const auto& s : j["steps"]) EXPECT_GT(s.at("relaxation_length_m").at("uncertainty").get<double>(), 0.0);
  EXPECT_TRUE(j.at("results").contains("relaxation_length_m"));

  r = run({"rig", "run", path_, "--specimen", "tyre-120-70-r17", "--rig", "sim-tyre-tester", "--test", "steady-state",
           "--speed", "1.3889", "--json"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.at("specimen").at("created").get<bool>());  // the same specimen as before
  for (const char* key : {"cornering_stiffness", "camber_stiffness", "aligning_stiffness"})
    EXPECT_TRUE(j.at("results").contains(key)) << key;
  ASSERT_TRUE(j["results"].contains("magic_formula")) << j.at("status_note");
  EXPECT_TRUE(j["results"]["magic_formula"].contains("pKy1"));
  EXPECT_GT(j["results"]["magic_formula"]["pKy1"]["uncertainty"].get<double>(), 0.0);

  const auto info = nlohmann::json::parse(run({"project", "info", path_, "--json"}).out);
  ASSERT_EQ(info.at("tyre_tests").size(), 2u);
  EXPECT_EQ(info["tyre_tests"][0]["kind"], "relaxation");
  EXPECT_EQ(info["tyre_tests"][1]["kind"], "steady-state");
}

TEST_F(RigRunCli, RefusalsNameWhatIsWrongAndStoreNothing) {
  // Usage errors: exit 2.
  EXPECT_EQ(run({"rig", "run", path_, "--rig", "sim-stiffness", "--test", "static"}).code, kExitUsage);
  EXPECT_EQ(run({"rig", "run", path_, "--specimen", "x", "--rig", "sim-hammer", "--test", "static"}).code, kExitUsage);
  EXPECT_EQ(
      run({"rig", "run", path_, "--specimen", "tyre-120-70-r17", "--rig", "sim-tyre-tester", "--test", "static"}).code,
      kExitUsage);
  EXPECT_EQ(run({"rig", "run", path_, "--specimen", "swing-arm-a", "--rig", "sim-stiffness", "--test", "static",
                 "--speed", "3"})
                .code,
            kExitUsage);
  // Beyond the machine: exit 1, the limit named, nothing stored.
  auto r = run({"rig", "run", path_, "--specimen", "tyre-120-70-r17", "--rig", "sim-tyre-tester", "--test",
                "relaxation", "--speed", "20"});  // 72 km/h
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("50 km/h"), std::string::npos) << r.err;
  r = run({"rig", "run", path_, "--specimen", "Frame A", "--rig", "sim-stiffness", "--test", "dynamic", "--frequencies",
           "10,50"});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("45 Hz"), std::string::npos) << r.err;
  r = run(
      {"rig", "run", path_, "--specimen", "Frame A", "--rig", "sim-stiffness", "--test", "static", "--force", "8000"});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("5000 N"), std::string::npos) << r.err;
  // A specimen the rig cannot test, and an unknown one.
  r = run({"rig", "run", path_, "--specimen", "bicycle-steel", "--rig", "sim-stiffness", "--test", "static"});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("no static test"), std::string::npos) << r.err;
  r = run({"rig", "run", path_, "--specimen", "Frame Z", "--rig", "sim-stiffness", "--test", "static"});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("Frame Z"), std::string::npos) << r.err;
  const auto info = nlohmann::json::parse(run({"project", "info", path_, "--json"}).out);
  EXPECT_TRUE(info.at("rig_tests").empty());
  EXPECT_TRUE(info.at("tyre_tests").empty());
  EXPECT_EQ(info.at("specimens").size(), 2u);
}

// rig run's numbers are on the command's option table (issue 17): --help
// states their ranges, the parser refuses a value outside them (exit 1, the
// option and its range named) before the project is opened, and run's
// options given to list or caps are usage errors.
TEST_F(RigRunCli, OptionRangesComeFromTheOptionTable) {
  const auto help = run({"rig", "--help"});
  ASSERT_EQ(help.code, 0);
  for (const char* o : {"--force", "--frequencies", "--speed", "--pressure", "--seed"})
    EXPECT_NE(help.out.find(o), std::string::npos) << o << " in\n" << help.out;
  EXPECT_NE(help.out.find("[0.5, 4] bar"), std::string::npos) << help.out;

  const std::vector<std::string> base = {
      "rig", "run", path_, "--specimen", "tyre-120-70-r17", "--rig", "sim-tyre-tester", "--test", "relaxation"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
  };
  for (const auto& [option, value, range] :
       std::vector<std::tuple<std::string, std::string, std::string>>{{"--pressure", "9", "[0.5, 4] bar"},
                                                                      {"--seed", "1.5", "whole number"},
                                                                      {"--seed", "-1", "whole number"},
                                                                      {"--speed", "nan", "(0, 100] m/s"},
                                                                      {"--frequencies", "1,,2", "(0, 1000] Hz"}}) {
    const auto r = with({option, value});
    EXPECT_EQ(r.code, kExitFailure) << option << " " << value << ": " << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(range), std::string::npos) << r.err;
  }
  EXPECT_EQ(run({"rig", "list", "--force", "3"}).code, kExitUsage);
  EXPECT_EQ(run({"rig", "caps", "sim-stiffness", "--seed", "3"}).code, kExitUsage);
  EXPECT_EQ(with({"--file", "x.uff"}).code, kExitUsage);
  const auto info = nlohmann::json::parse(run({"project", "info", path_, "--json"}).out);
  EXPECT_TRUE(info.at("tyre_tests").empty());
}

}  // namespace
}  // namespace mozzi::cli
