// The report's "stability" and "wheelchair" sections (core/report/
// stability_report.cpp), built from analyses kept in a project written here:
// the headings; the critical-speed table's numbers are those of a sweep
// computed here independently of the stored one and are the published
// benchmark values (Meijaard et al. 2007 README: weave 4.29238253634110,
// capsize 6.02426201538836 m/s) in the CLI's printed digits (6 decimals);
// the figures name the analysis; the gap section does not list them; a
// project without them has neither section.
#include "core/report/stability_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/report/project_report.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/stability_record.h"
#include "core/stability/wheelchair_record.h"

namespace mozzi::core::report {
namespace {

namespace fs = std::filesystem;
namespace st = core::stability;

class StabilityReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi-stability-report-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "p.mozzi").string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string path_;
};

const Table* firstTable(const Section& s) {
  for (const auto& b : s.blocks)
    if (const auto* t = std::get_if<Table>(&b)) return t;
  return nullptr;
}

TEST_F(StabilityReportTest, SectionsFromKeptAnalyses) {
  auto store = io::ProjectStore::create(path_, "test");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto fork = store->addSpecimen("Steel bicycle fork", "bicycle-fork", "test");
  auto chair = store->addSpecimen("Wheelchair tyres", "wheelchair-tyre", "test");
  ASSERT_TRUE(fork.ok() && chair.ok());

  // Before anything is kept: neither section.
  auto empty = buildProjectReport(*store, {});
  ASSERT_TRUE(empty.ok()) << empty.error().describe();
  EXPECT_EQ(empty->section("stability"), nullptr);
  EXPECT_EQ(empty->section("wheelchair"), nullptr);

  st::StabilityRequest request;  // benchmark bicycle 0-10 m/s every 0.05 m/s
  auto rec = st::computeStabilityRecord(request);
  ASSERT_TRUE(rec.ok()) << rec.error().describe();
  auto id = st::storeStabilityRecord(*store, *fork, "benchmark", *rec);
  ASSERT_TRUE(id.ok()) << id.error().describe();
  st::WheelchairStudy study;
  study.duration = 12.0;
  auto run = st::runWheelchairStudy(study);
  ASSERT_TRUE(run.ok()) << run.error().describe();
  auto wid = st::storeWheelchairRecord(*store, *chair, "slalom", *run);
  ASSERT_TRUE(wid.ok()) << wid.error().describe();

  auto report = buildProjectReport(*store, {});
  ASSERT_TRUE(report.ok()) << report.error().describe();
  const Section* s = report->section("stability");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->heading, "Stability against speed");
  EXPECT_EQ(sectionHeading("wheelchair"), "Wheelchair manoeuvres");
  // Independent of the stored record: the benchmark model swept here.
  auto model = st::benchmarkModel(st::meijaard2007Parameters());
  ASSERT_TRUE(model.ok());
  auto speeds = st::speedGrid(0.0, 10.0, 0.05);
  auto sweep = st::sweepSpeeds(st::bicycleSystem(*model), *speeds);
  ASSERT_TRUE(sweep.ok());
  const Table* t = firstTable(*s);
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->rows.size(), 2u);  // weave stabilises, capsize destabilises
  EXPECT_EQ(t->rows[0][0].text, "weave");
  EXPECT_EQ(t->rows[0][1].text, "stabilises");
  EXPECT_EQ(t->rows[0][2].text, st::criticalSpeedText(*sweep->criticalSpeed("weave")));
  EXPECT_EQ(t->rows[0][2].text, "4.292383");  // 4.29238253634110 to 6 decimals
  EXPECT_NEAR(*t->rows[0][2].value, 4.29238253634110, 1e-10);
  EXPECT_EQ(t->rows[1][0].text, "capsize");
  EXPECT_EQ(t->rows[1][2].text, "6.024262");  // 6.02426201538836
  EXPECT_NEAR(*t->rows[1][2].value, 6.02426201538836, 1e-10);
  EXPECT_EQ(t->rows[1][3].text, "0.000");  // capsize is a real root
  int figures = 0;
  for (const auto& b : s->blocks)
    if (const auto* f = std::get_if<Figure>(&b)) {
      EXPECT_EQ(f->recordId, *id);
      EXPECT_TRUE(f->view == "stability-real" || f->view == "stability-imaginary") << f->view;
      ++figures;
    }
  EXPECT_EQ(figures, 2);

  const Section* w = report->section("wheelchair");
  ASSERT_NE(w, nullptr);
  const Table* wt = firstTable(*w);
  ASSERT_NE(wt, nullptr);
  ASSERT_EQ(wt->rows.size(), 1u);
  auto summary = st::summariseSlalom(run->runs[0].history, 2.0 / study.frequency, study.frequency);
  ASSERT_TRUE(summary.ok());
  EXPECT_NEAR(*wt->rows[0][1].value, summary->lateralAmplitude, 0.0);

  // Not gap diagnoses.
  EXPECT_EQ(report->section("gap"), nullptr);
  // The sections can be chosen, and a specimen filter leaves the other out.
  ReportOptions only;
  only.sections = {"stability"};
  only.specimen = "Wheelchair tyres";
  auto filtered = buildProjectReport(*store, only);
  ASSERT_TRUE(filtered.ok());
  EXPECT_EQ(filtered->section("stability"), nullptr);
}

}  // namespace
}  // namespace mozzi::core::report
