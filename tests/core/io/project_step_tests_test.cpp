// Schema 3 (issue 20): rig and tyre tests stored step by step, with a status,
// a note saying what is missing, results tied to their step and tyre-test
// records; and the migration of a schema-1 file (its tests read "complete").
#include <gtest/gtest.h>

#include <filesystem>

#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

class StepTests : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_steps_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(StepTests, RigTestStepsCommitOneByOneAndTheEndSetsTheStatus) {
  auto store = ProjectStore::create(file("a.mozzi"), "test");
  ASSERT_TRUE(store.ok());
  const auto sp = store->addSpecimen("Fork A", "fork", "").value();
  StoredRigTest t;
  t.specimenId = sp;
  t.kind = StoredRigTest::Kind::Dynamic;
  t.name = "sine";
  t.status = TestStatus::Running;
  t.statusNote = "nothing yet";
  const auto id = store->addRigTest(t).value();
  const Eigen::MatrixXf rec = Eigen::MatrixXf::Constant(100, 5, 0.25f);
  ASSERT_TRUE(store->commitRigTestStep(id, 0, 1000.0, rec, {{"k_lat", 5e4, "N/m", 10.0, 0}}, "step 1 missing").ok());
  {
    auto list = store->rigTests();
    ASSERT_TRUE(list.ok());
    ASSERT_EQ(list->size(), 1u);
    EXPECT_EQ(list->front().status, TestStatus::Running);
    EXPECT_EQ(list->front().statusNote, "step 1 missing");
    EXPECT_EQ(list->front().recordCount, 1);
    EXPECT_EQ(list->front().resultCount, 1);
    EXPECT_EQ(list->front().specimenName, "Fork A");
    EXPECT_EQ(list->front().kind, "dynamic");
  }
  // A step with the same index again is refused and changes nothing.
  EXPECT_FALSE(store->commitRigTestStep(id, 0, 1000.0, rec, {{"k_lat", 1.0, "N/m", 0.0, 0}}).ok());
  ASSERT_TRUE(store
                  ->finishRigTest(id, TestStatus::Interrupted, "unplugged during step 1",
                                  {{"steps_with_axis", 1, "", 0, std::nullopt}})
                  .ok());
  auto back = store->rigTest(id);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->status, TestStatus::Interrupted);
  EXPECT_EQ(back->statusNote, "unplugged during step 1");
  ASSERT_EQ(back->results.size(), 2u);
  EXPECT_EQ(back->results[0].step, 0);
  EXPECT_DOUBLE_EQ(back->results[0].value, 5e4);
  EXPECT_FALSE(back->results[1].step.has_value());
  EXPECT_FALSE(back->recordedUtc.empty());
  double fs = 0;
  auto r = store->rigTestRecord(id, 0, &fs);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(*r, rec);
  EXPECT_FALSE(store->finishRigTest(id + 7, TestStatus::Complete, "", {}).ok());  // no such test
  // Uncertainties are standard deviations: negative ones are refused.
  EXPECT_FALSE(store->commitRigTestStep(id, 1, 1000.0, rec, {{"k_lat", 1.0, "N/m", -1.0, 1}}).ok());
}

TEST_F(StepTests, TyreTestStepsAppendPointsRecordsAndParameters) {
  auto store = ProjectStore::create(file("t.mozzi"), "test");
  ASSERT_TRUE(store.ok());
  const auto sp = store->addSpecimen("Tyre", "tyre", "").value();
  StoredTyreTest t;
  t.specimenId = sp;
  t.name = "sweeps";
  t.kind = "steady-state";
  t.verticalLoadN = 1500;
  t.status = TestStatus::Running;
  t.parametersJson = R"({"steps":[]})";
  const auto id = store->addTyreTest(t).value();
  const Eigen::MatrixXf rec = Eigen::MatrixXf::Constant(50, 6, -1.5f);
  for (int k = 0; k < 3; ++k) {
    StoredTyreTest::Point p{0.01 * k, 0.0, 100.0 * k, -2.0 * k, 0.0};
    ASSERT_TRUE(store->commitTyreTestStep(id, k, 200.0, rec, {p}, {{"lateral_force", 100.0 * k, "N", 0.1, k}}).ok());
  }
  // A step without a record (samples empty) still stores its parameters.
  ASSERT_TRUE(store->commitTyreTestStep(id, 3, 200.0, Eigen::MatrixXf(), {}, {{"note", 1, "", 0, 3}}).ok());
  ASSERT_TRUE(
      store->finishTyreTest(id, TestStatus::Complete, "", {{"cornering_stiffness", 2e4, "N/rad", 50, {}}}).ok());
  auto back = store->tyreTest(id);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->status, TestStatus::Complete);
  EXPECT_EQ(back->parametersJson, R"({"steps":[]})");
  ASSERT_EQ(back->points.size(), 3u);
  EXPECT_DOUBLE_EQ(back->points[2].lateralForceN, 200.0);
  ASSERT_EQ(back->parameters.size(), 5u);
  EXPECT_EQ(back->parameters[2].step, 2);
  EXPECT_FALSE(back->parameters[4].step.has_value());
  EXPECT_TRUE(store->tyreTestRecord(id, 2).ok());
  EXPECT_FALSE(store->tyreTestRecord(id, 3).ok());
  auto list = store->tyreTests();
  ASSERT_TRUE(list.ok());
  ASSERT_EQ(list->size(), 1u);
  EXPECT_EQ(list->front().recordCount, 3);
  EXPECT_EQ(list->front().resultCount, 5);
  // Deleting the specimen takes the records with it.
  ASSERT_TRUE(store->deleteSpecimen(sp).ok());
  EXPECT_FALSE(store->tyreTestRecord(id, 0).ok());
}

// A schema-1 project (the fuzz seed written at schema 1) migrates to the current schema:
// its rig and tyre tests read as complete, their results as whole-test ones.
TEST_F(StepTests, ASchemaOneProjectMigratesAndItsTestsReadComplete) {
  const fs::path seed = fs::path(MOZZI_SOURCE_DIR) / "tests/fuzz/corpus/project_open_fuzz/full_rollback_journal.mozzi";
  fs::copy_file(seed, file("old.mozzi"));
  auto store = ProjectStore::open(file("old.mozzi"));
  ASSERT_TRUE(store.ok()) << store.error().describe();
  EXPECT_EQ(store->schemaVersion(), ProjectStore::currentSchemaVersion());
  auto rig = store->rigTest(1);
  ASSERT_TRUE(rig.ok()) << rig.error().describe();
  EXPECT_EQ(rig->status, TestStatus::Complete);
  for (const auto& r : rig->results) EXPECT_FALSE(r.step.has_value());
  auto tyre = store->tyreTest(1);
  ASSERT_TRUE(tyre.ok());
  EXPECT_EQ(tyre->status, TestStatus::Complete);
  EXPECT_EQ(tyre->parametersJson, "{}");
  EXPECT_EQ(testStatusName(parseTestStatus("interrupted")), std::string("interrupted"));
  EXPECT_EQ(parseTestStatus("garbage"), TestStatus::Failed);
}

}  // namespace
}  // namespace mozzi::core::io
