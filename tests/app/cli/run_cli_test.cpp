// mozzi-cli run (issue 23): a batch file over two projects, one with a broken
// input. The failing step is named with its project and file, the other
// project's results are there and right; a batch file with a mistake in any
// step is refused before anything runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli/batch_script.h"
#include "app/cli/command.h"
#include "cli_run.h"
#include "core/io/project_store.h"
#include "core/io/uff/uff.h"
#include "core/modal/synthetic_system.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test: the batch file's relative paths are relative to it.
fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::path(MOZZI_BINARY_DIR) / ("run_cli_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// The six-mode synthetic accelerances of tests/core/modal (analytic modes),
// 1 to 400 Hz, as UFF 58.
void writeSixModeUff(const fs::path& path) {
  const auto sys = core::modal::testing::sixModeSystem();
  const core::FrfMatrix frf = core::modal::testing::accelerances(sys, {2}, 1.0, 400.0, 0.1, 0.002, 3);
  auto records = core::io::uff::fromFrfMatrix(frf);
  ASSERT_TRUE(records.ok());
  core::io::uff::UffFile file;
  for (auto& r : *records) file.datasets.push_back(core::io::uff::makeDataset(std::move(r)));
  ASSERT_TRUE(core::io::uff::writeFile(path.string(), file).ok());
}

constexpr const char* kTwoProjects = R"({
  "format": "mozzi-batch/1",
  "projects": [
    {"file": "good.mozzi", "vars": {"hits": "six_modes.uff"}},
    {"file": "bad.mozzi", "vars": {"hits": "broken.uff"}}
  ],
  "steps": [
    {"name": "create", "run": ["project", "new", "{project}"]},
    {"name": "import", "run": ["project", "import", "{project}", "{hits}", "--specimen", "beam"]},
    {"name": "modes", "run": ["identify", "{project}", "--frf-set", "1", "--band", "20:380",
                              "--max-order", "40", "--store"]},
    {"name": "check", "run": ["project", "check", "{project}"]}
  ]
})";

TEST(RunCli, BrokenInputNamesItsStepAndTheOtherProjectIsDone) {
  const fs::path dir = freshFolder("two");
  writeSixModeUff(dir / "six_modes.uff");
  // A 58 record cut in its header: the UFF reader refuses it.
  writeText(dir / "broken.uff", "    -1\n    58\nHeader line 1\n");
  writeText(dir / "batch.json", kTwoProjects);

  const CliRun r = run({"run", (dir / "batch.json").string(), "--json"});
  EXPECT_EQ(r.code, kExitFailure) << r.err;
  EXPECT_NE(r.err.find("project bad.mozzi: step 2 'import'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("broken.uff"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("project good.mozzi"), std::string::npos) << r.err;

  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["projects"].size(), 2u);
  EXPECT_EQ(j["projects"][0]["status"], "done");
  EXPECT_EQ(j["projects"][0]["steps_run"], 4);
  EXPECT_EQ(j["projects"][1]["status"], "failed");
  EXPECT_EQ(j["projects"][1]["steps_run"], 2);  // identify and check not run after the failed import
  EXPECT_EQ(j["projects"][1]["steps"][1]["exit"], kExitFailure);

  // The good project holds the six modes of the synthetic system, within the
  // 0.1% in frequency that identify's own test asserts on the same data.
  auto store = core::io::ProjectStore::open((dir / "good.mozzi").string(), core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto results = store->modalResults();
  ASSERT_TRUE(results.ok());
  ASSERT_EQ(results->size(), 1u);
  auto table = store->modalResult(results->front().id);
  ASSERT_TRUE(table.ok()) << table.error().describe();
  const auto sys = core::modal::testing::sixModeSystem();
  ASSERT_EQ(table->modes.size(), 6u);
  for (std::size_t m = 0; m < 6; ++m) {
    EXPECT_LT(std::abs(table->modes[m].frequencyHz - sys.fn[static_cast<Eigen::Index>(m)]) /
                  sys.fn[static_cast<Eigen::Index>(m)],
              1e-3)
        << "mode " << m;
  }
  // The bad project was created by step 1 and left as the failed import found it.
  auto bad = core::io::ProjectStore::open((dir / "bad.mozzi").string(), core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(bad.ok()) << bad.error().describe();
  auto badSets = bad->frfSets();
  ASSERT_TRUE(badSets.ok());
  EXPECT_TRUE(badSets->empty());
}

// --project runs one project of the file (how a scheduler runs many at once).
TEST(RunCli, ProjectOptionRunsOnlyThatProject) {
  const fs::path dir = freshFolder("one");
  writeSixModeUff(dir / "six_modes.uff");
  writeText(dir / "batch.json", kTwoProjects);
  const CliRun r = run({"run", (dir / "batch.json").string(), "--project", "good.mozzi", "--quiet"});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  EXPECT_TRUE(fs::exists(dir / "good.mozzi"));
  EXPECT_FALSE(fs::exists(dir / "bad.mozzi"));
  const CliRun none = run({"run", (dir / "batch.json").string(), "--project", "other.mozzi"});
  EXPECT_EQ(none.code, kExitFailure);
  EXPECT_NE(none.err.find("lists no project 'other.mozzi'"), std::string::npos) << none.err;
}

// A mistake in the last step of the last project is found before the first
// step of the first project runs: no project file is created.
TEST(RunCli, MistakesAnywhereAreRefusedBeforeAnythingRuns) {
  struct Case {
    std::string lastStep;
    std::string expected;
  };
  const Case cases[] = {
      {R"(["identfy", "{project}"])", "steps[1] for project 'a.mozzi': unknown command 'identfy'"},
      {R"(["identify", "{project}", "--max-order", "1e308"])", "--max-order"},
      {R"(["identify", "{project}", "--colour", "red"])", "unknown option '--colour'"},
      {R"(["report", "{project}", "--out", "{stemm}.pdf"])", "unknown variable '{stemm}' (steps[1].run[3]"},
      {R"(["report", "{project", "--out", "x.pdf"])", "a '{' without its '}'"},
      {R"(["run", "other.json"])", "a batch step cannot be another batch run"},
  };
  for (const auto& c : cases) {
    const fs::path dir = freshFolder("mistake");
    writeText(dir / "batch.json", R"({"format": "mozzi-batch/1", "projects": ["a.mozzi", "b.mozzi"],
      "steps": [{"run": ["project", "new", "{project}"]}, {"run": )" +
                                      c.lastStep + "}]}");
    const CliRun r = run({"run", (dir / "batch.json").string()});
    EXPECT_EQ(r.code, kExitFailure) << c.lastStep;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.lastStep << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "a.mozzi")) << c.lastStep;
  }
}

// The file's structure: each mistake named by its place in the file.
TEST(RunCli, StructureErrorsNameTheirPlace) {
  struct Case {
    std::string text;
    std::string expected;
  };
  const Case cases[] = {
      {"{\"format\": \"mozzi-batch/1\",\n \"projects\": [\"a.mozzi\",]}", "not valid JSON (f.json: line 2, column"},
      {R"({"format": "mozzi-batch/2", "projects": ["a"], "steps": [{"run": ["project"]}]})", "f.json: format"},
      {R"({"format": "mozzi-batch/1", "projects": [], "steps": [{"run": ["project"]}]})", "f.json: projects"},
      {R"({"format": "mozzi-batch/1", "projects": ["a", "a"], "steps": [{"run": ["x"]}]})", "listed twice"},
      {R"({"format": "mozzi-batch/1", "projects": [{"fil": "a"}], "steps": [{"run": ["x"]}]})",
       "unknown key 'fil' (expected: file, vars) (f.json: projects[0].'fil')"},
      {R"({"format": "mozzi-batch/1", "projects": ["a"], "step": []})", "unknown key 'step'"},
      {R"({"format": "mozzi-batch/1", "projects": ["a"], "steps": [{"run": ["x", 3]}]})",
       "expected a string (f.json: steps[0].run[1])"},
      {R"({"format": "mozzi-batch/1", "projects": ["a"], "vars": {"stem": "x"}, "steps": [{"run": ["x"]}]})",
       "'stem' is a built-in variable"},
  };
  for (const auto& c : cases) {
    auto parsed = parseBatchScript(c.text, "f.json");
    ASSERT_FALSE(parsed.ok()) << c.text;
    EXPECT_NE(parsed.error().describe().find(c.expected), std::string::npos) << c.text << "\n"
                                                                             << parsed.error().describe();
  }
}

// Variables: built-ins from the project's path, the script's, the project's
// own over the script's; doubled braces are literal.
TEST(RunCli, VariablesExpand) {
  auto parsed = parseBatchScript(R"({"format": "mozzi-batch/1", "vars": {"band": "5:200", "out": "r"},
    "projects": [{"file": "labs/fork-a.mozzi", "vars": {"out": "fork"}}],
    "steps": [{"run": ["x", "{dir}/{stem}-{out}.pdf", "{name}", "{band}", "{{literal}}"]}]})",
                                 "f.json");
  ASSERT_TRUE(parsed.ok()) << parsed.error().describe();
  auto argv = expandBatchStep(*parsed, 0, parsed->projects[0]);
  ASSERT_TRUE(argv.ok()) << argv.error().describe();
  const std::vector<std::string> expected{"x", "labs/fork-a-fork.pdf", "fork-a.mozzi", "5:200", "{literal}"};
  EXPECT_EQ(*argv, expected);
}

}  // namespace
}  // namespace mozzi::cli
