// projectContents() lists each specimen's records by kind: the ids the store
// returned when they were added, nothing of another specimen, static and
// dynamic rig tests apart.
#include "core/io/project_contents.h"

#include <gtest/gtest.h>
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

}  // namespace
}  // namespace mozzi::core::io
