// The report content model (core/report): built from a small project written
// here, its tables carry the stored numbers; sections without data are left
// out; unknown sections and specimens are errors; the "best effect" rule.

#include "core/report/project_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/io/project_meta.h"
#include "core/report/gap_report.h"
#include "core/report/report_html.h"
#include "core/report/report_template.h"

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

// The Italian report: headings, captions and table headers from the
// catalogue, the stored numbers with a decimal comma (56099.25 -> "56099,2",
// six significant digits as in English), symbols unchanged.
TEST_F(ProjectReportTest, ItalianTextAndNumbers) {
  auto store = io::ProjectStore::open(path_, io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  ReportOptions options;
  options.language = Language::Italian;
  options.generatedUtc = "2026-11-28T03:28:10Z";
  auto report = buildProjectReport(*store, options);
  ASSERT_TRUE(report.ok()) << report.error().describe();
  EXPECT_EQ(report->language, "it");
  std::vector<std::string> headings;
  for (const auto& s : report->sections) headings.push_back(s.heading);
  EXPECT_EQ(headings, (std::vector<std::string>{"Progetto e provini", "Parametri modali", "Prove di rigidezza",
                                                "Diagnosi dello scarto modello-prova"}));
  for (const auto& s : report->sections) EXPECT_EQ(s.heading, sectionHeading(s.key, Language::Italian));
  const Table* stiffness = firstTable(*report->section("stiffness"));
  ASSERT_NE(stiffness, nullptr);
  EXPECT_EQ(stiffness->headers, (std::vector<std::string>{"Grandezza", "Valore", "Unità"}));
  EXPECT_EQ(stiffness->rows[0][0].text, "k_lat");
  EXPECT_EQ(stiffness->rows[0][1].text, "56099,2 \u00b1 1,1");
  EXPECT_EQ(*stiffness->rows[0][1].value, 56099.25);  // the value itself is the stored one
  const Table* modes = firstTable(*report->section("modal"));
  ASSERT_NE(modes, nullptr);
  EXPECT_EQ(modes->headers[1], "Frequenza");
  EXPECT_EQ(modes->rows[1][1].text, "117,25");
  const std::string html = toHtml(*report, {});
  EXPECT_NE(html.find("lang=\"it\""), std::string::npos);
  EXPECT_NE(html.find("Relazione generata il 28/11/2026 03:28 UTC."), std::string::npos);
  EXPECT_NE(html.find("Verdetto: effect (mass_loading)"), std::string::npos);
  // No English caption left in the Italian report's tables.
  for (const auto& s : report->sections)
    for (const auto& b : s.blocks)
      if (const auto* t = std::get_if<Table>(&b)) {
        EXPECT_EQ(t->caption.find("Results of"), std::string::npos) << t->caption;
        EXPECT_EQ(t->caption.find("Modes of"), std::string::npos) << t->caption;
      }
}

TEST(ReportText, LanguagesPlaceholdersAndDates) {
  EXPECT_EQ(*parseLanguage("it"), Language::Italian);
  EXPECT_EQ(*parseLanguage("EN"), Language::English);
  auto bad = parseLanguage("fr");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("unknown report language 'fr'"), std::string::npos);
  const Texts it(Language::Italian), en;
  EXPECT_EQ(it("Campaign %1 (%2)", {"hammer 1", "Frame A"}), "Campagna hammer 1 (Frame A)");
  EXPECT_EQ(en("Campaign %1 (%2)", {"%2", "x"}), "Campaign %2 (x)");  // an argument is not expanded again
  EXPECT_EQ(it.number(0.0412, 3), "0,0412");
  EXPECT_EQ(en.number(0.0412, 3), "0.0412");
  EXPECT_EQ(it.date("2026-01-05T07:08:09Z"), "05/01/2026 07:08 UTC");
  EXPECT_EQ(en.date("2026-01-05 07:08 UTC"), "2026-01-05 07:08 UTC");
  EXPECT_EQ(it.date("yesterday"), "yesterday");
  // Every section has an Italian heading different from the English one.
  for (const auto& key : reportSectionKeys())
    EXPECT_NE(sectionHeading(key, Language::Italian), sectionHeading(key, Language::English)) << key;
}

TEST_F(ProjectReportTest, TemplateRoundTripInTheProject) {
  auto store = io::ProjectStore::open(path_);
  ASSERT_TRUE(store.ok());
  auto none = loadReportTemplate(*store);
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none->has_value());
  ReportTemplate t;
  t.sections = {"title", "stiffness"};
  t.specimen = "Frame X";
  t.language = Language::Italian;
  t.pdf = false;
  t.html = true;
  ASSERT_TRUE(saveReportTemplate(*store, t).ok());
  t.sections = {"modal"};  // saved again: replaced, not added
  ASSERT_TRUE(saveReportTemplate(*store, t).ok());
  store = io::ProjectStore::open(path_, io::ProjectStore::OpenMode::ReadOnly);  // reopened from the file
  ASSERT_TRUE(store.ok());
  auto loaded = loadReportTemplate(*store);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  ASSERT_TRUE(loaded->has_value());
  EXPECT_EQ(**loaded, t);
  // The store's own keys are untouched and refused.
  auto summary = store->summary();
  ASSERT_TRUE(summary.ok());
  EXPECT_FALSE(summary->createdUtc.empty());
  auto writable = io::ProjectStore::open(path_);
  ASSERT_TRUE(writable.ok());
  EXPECT_FALSE(io::setMetaValue(*writable, "mozzi_version", "0").ok());
  // A read-only project cannot keep a template.
  EXPECT_FALSE(saveReportTemplate(*store, t).ok());
  // A malformed template says which field.
  auto bad = templateFromJson(R"({"sections":["title","stifness"]})");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("unknown report section 'stifness' in sections[1]"), std::string::npos);
  bad = templateFromJson(R"({"language":"de"})");
  ASSERT_FALSE(bad.ok());
  bad = templateFromJson(R"({"pdf":"yes"})");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("\"pdf\""), std::string::npos);
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

// The ranking table names a family's other locations (one: "equivalent at";
// more: a count), in the report's language; the overlay's legend names an
// effect with its location.
TEST(GapReport, RankingNamesFamiliesAndTheLegendLocations) {
  gap::Diagnosis d;
  d.ranking.resize(3);
  d.ranking[0].candidate.effect = "residual_mode";
  d.ranking[0].candidate.location = {"9+Z"};
  d.ranking[0].candidate.equivalent = {{"10+Z"}};
  d.ranking[1].candidate.effect = "residual_mode";
  d.ranking[1].candidate.location = {"1+Y"};
  d.ranking[1].candidate.equivalent = {{"2+Y"}, {"3+Y"}, {"4+Y"}};
  d.ranking[2].candidate.effect = "hysteretic_damping";
  auto locations = [&](Language language) {
    const Section s = gapDiagnosisSection(d, "model.json", "test.uff", Texts(language));
    std::vector<std::string> out;
    for (const Block& b : s.blocks) {
      const auto* t = std::get_if<Table>(&b);
      if (!t || t->headers.size() < 2 || t->rows.size() != 3) continue;
      for (const auto& row : t->rows) out.push_back(row[1].text);
    }
    return out;
  };
  EXPECT_EQ(locations(Language::English),
            (std::vector<std::string>{"9+Z (equivalent at 10+Z)", "1+Y (and 3 equivalent locations)", "(global)"}));
  EXPECT_EQ(
      locations(Language::Italian),
      (std::vector<std::string>{"9+Z (equivalente in 10+Z)", "1+Y (e altre 3 posizioni equivalenti)", "(global)"}));
  EXPECT_EQ(effectAtLocation(d.ranking[1].candidate), "residual_mode at 1+Y");
  EXPECT_EQ(effectAtLocation(d.ranking[2].candidate), "hysteretic_damping");
}

}  // namespace
}  // namespace mozzi::core::report
