// projectContents() lists each specimen's records by kind: the ids the store
// returned when they were added, nothing of another specimen, static and
// dynamic rig tests apart; each analysis with its kind and name, read without
// its result JSON.
#include "core/io/project_contents.h"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>

#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

TEST(ProjectContents, ListsEachSpecimensRecordsByKind) {
  const fs::path dir = fs::temp_directory_path() / ("mozzi_contents_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto store = ProjectStore::create((dir / "p.mozzi").string(), "0.1.0");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto fork = store->addSpecimen("Fork A", "fork", "");
  auto frame = store->addSpecimen("Frame A", "frame", "");
  ASSERT_TRUE(fork.ok() && frame.ok());

  StoredMesh mesh;
  for (int i = 1; i <= 3; ++i) {
    StoredNode node;
    node.label = i;
    node.position = Vector3(0.1 * i, 0.0, 0.0);
    mesh.nodes.push_back(node);
  }
  ASSERT_TRUE(store->setMesh(*frame, mesh).ok());

  StoredCampaign campaign;
  campaign.specimenId = *frame;
  campaign.name = "run 1";
  auto campaignId = store->addCampaign(campaign);
  ASSERT_TRUE(campaignId.ok()) << campaignId.error().describe();

  ModalResultInfo info;
  info.specimenId = *fork;
  info.name = "modes";
  info.method = "LSCE";
  ModalTable table;
  table.modes.push_back(StoredMode{42.0, 0.01, {}});
  auto modalId = store->addModalResult(info, table);
  ASSERT_TRUE(modalId.ok()) << modalId.error().describe();

  StoredRigTest staticTest;
  staticTest.specimenId = *fork;
  staticTest.name = "static";
  StoredRigTest sweep = staticTest;
  sweep.kind = StoredRigTest::Kind::Dynamic;
  sweep.name = "sweep";
  auto sweepId = store->addRigTest(sweep);
  auto staticId = store->addRigTest(staticTest);
  ASSERT_TRUE(sweepId.ok() && staticId.ok());

  auto contents = projectContents(*store);
  ASSERT_TRUE(contents.ok()) << contents.error().describe();
  ASSERT_EQ(contents->size(), 2u);
  const SpecimenContents& f = (*contents)[0];
  const SpecimenContents& a = (*contents)[1];
  EXPECT_EQ(f.name, "Fork A");
  EXPECT_EQ(f.meshNodes, 0);
  EXPECT_TRUE(f.campaigns.empty());
  EXPECT_EQ(f.modalResults, std::vector<std::int64_t>{*modalId});
  EXPECT_EQ(f.staticRigTests, std::vector<std::int64_t>{*staticId});
  EXPECT_EQ(f.dynamicRigTests, std::vector<std::int64_t>{*sweepId});
  EXPECT_EQ(a.name, "Frame A");
  EXPECT_EQ(a.meshNodes, 3);
  EXPECT_EQ(a.campaigns, std::vector<std::int64_t>{*campaignId});
  EXPECT_TRUE(a.modalResults.empty() && a.staticRigTests.empty() && a.tyreTests.empty() && a.analyses.empty());
  fs::remove_all(dir);
}

TEST(ProjectContents, ListsEachAnalysisWithItsKindWithoutReadingItsResult) {
  const fs::path dir = fs::temp_directory_path() / ("mozzi_contents_analyses_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "p.mozzi").string();
  auto store = ProjectStore::create(path, "0.1.0");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto fork = store->addSpecimen("Fork A", "fork", "");
  auto chair = store->addSpecimen("Chair", "wheelchair", "");
  ASSERT_TRUE(fork.ok() && chair.ok());

  StoredAnalysis gap;
  gap.specimenId = *fork;
  gap.kind = "gap-diagnosis";
  gap.name = "fork A vs design model";
  // Eight megabytes that are not JSON: a listing must not care.
  gap.resultJson = "{\"overlay\": [" + std::string(8u << 20, '[');
  StoredAnalysis sweep;
  sweep.specimenId = *fork;
  sweep.kind = "stability";
  sweep.name = "weave sweep";
  StoredAnalysis turn;
  turn.specimenId = *chair;
  turn.kind = "wheelchair";
  turn.name = "turn on the spot";
  auto gapId = store->addAnalysis(gap);
  auto turnId = store->addAnalysis(turn);
  auto sweepId = store->addAnalysis(sweep);
  ASSERT_TRUE(gapId.ok() && turnId.ok() && sweepId.ok());

  const auto check = [&](const std::vector<SpecimenContents>& contents) {
    ASSERT_EQ(contents.size(), 2u);
    const auto& f = contents[0].analyses;
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(f[0].id, *gapId);
    EXPECT_EQ(f[0].specimenId, *fork);
    EXPECT_EQ(f[0].kind, "gap-diagnosis");
    EXPECT_EQ(f[0].name, "fork A vs design model");
    EXPECT_EQ(f[1].id, *sweepId);
    EXPECT_EQ(f[1].kind, "stability");
    EXPECT_EQ(f[1].name, "weave sweep");
    const auto& c = contents[1].analyses;
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].id, *turnId);
    EXPECT_EQ(c[0].specimenId, *chair);
    EXPECT_EQ(c[0].kind, "wheelchair");
  };
  auto contents = projectContents(*store);
  ASSERT_TRUE(contents.ok()) << contents.error().describe();
  check(*contents);
  // The kinds are those the store reads back whole.
  for (const auto& a : (*contents)[0].analyses) {
    auto whole = store->analysis(a.id);
    ASSERT_TRUE(whole.ok()) << whole.error().describe();
    EXPECT_EQ(whole->kind, a.kind);
    EXPECT_EQ(whole->name, a.name);
  }

  // Without the result_json column (dropped through a second connection) the
  // listing reads as before, while reading an analysis whole cannot.
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  char* message = nullptr;
  const int rc = sqlite3_exec(raw, "ALTER TABLE analysis DROP COLUMN result_json", nullptr, nullptr, &message);
  const std::string error = message ? message : "";
  sqlite3_free(message);
  sqlite3_close(raw);
  ASSERT_EQ(rc, SQLITE_OK) << error;
  EXPECT_FALSE(store->analysis(*gapId).ok());
  auto listed = projectContents(*store);
  ASSERT_TRUE(listed.ok()) << listed.error().describe();
  check(*listed);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mozzi::core::io
