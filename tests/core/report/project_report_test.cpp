// The report content model (core/report): built from a small project written
// here, its tables carry the stored numbers; sections without data are left
// out; unknown sections and specimens are errors; the "best effect" rule.

#include "core/report/project_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/report/gap_report.h"
#include "core/report/report_html.h"

namespace mozzi::core::report {
namespace {

namespace fs = std::filesystem;

class ProjectReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi-report-test-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    path_ = (dir_ / "p.mozzi").string();
    fs::remove(path_);
    auto store = io::ProjectStore::create(path_, "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    auto frame = store->addSpecimen("Frame X", "frame", "a test frame");
    auto fork = store->addSpecimen("Fork Y", "fork", "a test fork");
    ASSERT_TRUE(frame.ok() && fork.ok());
    frameId_ = *frame;

    io::StoredRigSetup rig;
    rig.specimenId = *frame;
    rig.name = "stiffness rig";
    rig.rigKind = "static-stiffness";
    rig.driver = "sim:test";
    io::StoredTransducer load;
    load.channel = 0;
    load.quantity = "force";
    load.unit = "N";
    load.sensitivity = 0.0051;
    load.model = "load cell";
    load.serial = "LC-42";
    rig.transducers.push_back(load);
    auto rigId = store->addRigSetup(rig);
    ASSERT_TRUE(rigId.ok()) << rigId.error().describe();

    io::StoredRigTest test;
    test.specimenId = *frame;
    test.rigSetupId = *rigId;
    test.name = "static test";
    test.results = {{"k_lat", 56099.25, "N/m", 1.14}, {"k_tw", 14994.66, "N m/rad", 10.0}};
    ASSERT_TRUE(store->addRigTest(test).ok());

    io::ModalResultInfo info;
    info.specimenId = *frame;
    info.name = "LSCE 1";
    info.method = "LSCE";
    info.bandLowHz = 10;
    info.bandHighHz = 400;
    io::ModalTable modes;
    modes.modes = {{42.5, 0.012, {}}, {117.25, 0.0205, {}}};
    ASSERT_TRUE(store->addModalResult(info, modes).ok());

    io::StoredAnalysis analysis;
    analysis.specimenId = *fork;
    analysis.name = "fork gap";
    analysis.resultJson = R"({"verdict":"effect","best":{"effect":"mass_loading"}})";
    io::StoredAnalysis::Finding finding;
    finding.bandLowHz = 100;
    finding.bandHighHz = 200;
    finding.effect = "mass_loading";
    finding.size = 0.05;
    finding.unit = "kg";
    finding.uncertainty = 0.002;
    finding.remainingGap = 0.1;
    analysis.findings.push_back(finding);
    ASSERT_TRUE(store->addAnalysis(analysis).ok());
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  std::string path_;
  std::int64_t frameId_ = 0;
};

const Table* firstTable(const Section& s) {
  for (const auto& b : s.blocks)
    if (const auto* t = std::get_if<Table>(&b)) return t;
  return nullptr;
}

TEST_F(ProjectReportTest, TablesCarryTheStoredNumbers) {
  auto store = io::ProjectStore::open(path_, io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  auto report = buildProjectReport(*store, {});
  ASSERT_TRUE(report.ok()) << report.error().describe();
  // No FRF sets and no tyre tests: those sections are left out.
  std::vector<std::string> keys;
  for (const auto& s : report->sections) keys.push_back(s.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"title", "modal", "stiffness", "gap"}));

  const Table* modes = firstTable(*report->section("modal"));
  ASSERT_NE(modes, nullptr);
  ASSERT_EQ(modes->rows.size(), 2u);
  EXPECT_EQ(*modes->rows[1][1].value, 117.25);
  EXPECT_DOUBLE_EQ(*modes->rows[1][2].value, 2.05);  // percent
  EXPECT_DOUBLE_EQ(*modes->rows[1][3].value, 4.10);  // eta = 2 zeta, percent

  const Table* stiffness = firstTable(*report->section("stiffness"));
  ASSERT_NE(stiffness, nullptr);
  ASSERT_EQ(stiffness->rows.size(), 2u);
  EXPECT_EQ(stiffness->rows[0][0].text, "k_lat");
  EXPECT_EQ(*stiffness->rows[0][1].value, 56099.25);
  EXPECT_EQ(*stiffness->rows[0][1].uncertainty, 1.14);
  EXPECT_EQ(stiffness->rows[0][1].text, "56099.2 \u00b1 1.1");

  // The rig's transducer with its serial and sensitivity, in the title block.
  const std::string html = toHtml(*report, {});
  EXPECT_NE(html.find("LC-42"), std::string::npos);
  EXPECT_NE(html.find("0.0051"), std::string::npos);
  EXPECT_NE(html.find("<h2>Gap diagnoses</h2>"), std::string::npos);
  EXPECT_NE(html.find("Verdict: effect (mass_loading)"), std::string::npos);
}

TEST_F(ProjectReportTest, SpecimenAndSectionsFilter) {
  auto store = io::ProjectStore::open(path_, io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  ReportOptions options;
  options.specimen = "Fork Y";
  auto report = buildProjectReport(*store, options);
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(report->section("modal"), nullptr);  // the modes are the frame's
  EXPECT_NE(report->section("gap"), nullptr);

  options = {};
  options.sections = {"stiffness"};
  report = buildProjectReport(*store, options);
  ASSERT_TRUE(report.ok());
  ASSERT_EQ(report->sections.size(), 1u);
  EXPECT_EQ(report->sections[0].heading, "Stiffness tests");

  options.sections = {"stifness"};
  report = buildProjectReport(*store, options);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.error().message.find("unknown report section 'stifness'"), std::string::npos);

  options = {};
  options.specimen = "Nobody";
  report = buildProjectReport(*store, options);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.error().code, ErrorCode::NotFound);
}

TEST(BestEffect, VerdictFirstElseTopRankedPairWhenBothNamed) {
  gap::Diagnosis d;
  EXPECT_EQ(bestEffect(d).single, nullptr);
  d.ranking.resize(3);
  d.ranking[0].candidate.effect = "a";
  d.ranking[2].candidate.effect = "c";
  // No verdict: the top-ranked, outside the verdict.
  EXPECT_EQ(bestEffect(d).single, &d.ranking[0]);
  EXPECT_FALSE(bestEffect(d).inVerdict);
  d.verdict = gap::Verdict::Effect;
  d.verdictSet = {2};
  EXPECT_EQ(bestEffect(d).single, &d.ranking[2]);
  EXPECT_TRUE(bestEffect(d).inVerdict);
  EXPECT_EQ(bestEffect(d).pair, nullptr);
  d.verdictSet = {2, 0};
  d.pairFitted = true;
  d.pair.effects.resize(2);
  EXPECT_EQ(bestEffect(d).pair, &d.pair);
  d.verdict = gap::Verdict::Ambiguous;  // an ambiguous set is not a pair
  EXPECT_EQ(bestEffect(d).pair, nullptr);
}

}  // namespace
}  // namespace mozzi::core::report
