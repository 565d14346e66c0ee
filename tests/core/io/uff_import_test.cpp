// Importing vendor UFF files into a project: counts and coordinates checked
// against the reference reader's extraction (shared/data/uff/expected.json) and
// against trace-line segments counted by hand from the file.
#include "core/io/uff_import.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(MOZZI_SHARED_DATA_DIR) + "/uff/";

nlohmann::json expected(const std::string& file) {
  std::ifstream in(kData + "expected.json");
  return nlohmann::json::parse(in).at(file);
}

class UffImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_uff_import_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    auto store = ProjectStore::create((dir_ / "p.mozzi").string(), "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    store_.emplace(std::move(store).value());
    auto id = store_->addSpecimen("Stator", "frame", "");
    ASSERT_TRUE(id.ok());
    specimen_ = *id;
  }
  void TearDown() override {
    store_.reset();
    fs::remove_all(dir_);
  }
  fs::path dir_;
  std::optional<ProjectStore> store_;
  std::int64_t specimen_ = 0;
};

TEST_F(UffImportTest, TestLabGeometryBecomesTheSpecimenMesh) {
  const std::string file = "TestLab 161 164 18 15 82.uff";
  auto report = importUff(*store_, kData + file, specimen_);
  ASSERT_TRUE(report.ok()) << report.error().describe();
  const auto ref = expected(file);
  const auto& nodes = ref.at("sets").at(3);
  EXPECT_EQ(report->nodes, nodes.at("num_nodes").get<int>());
  EXPECT_EQ(report->coordinateSystems, ref.at("sets").at(2).at("count").get<int>());
  // Trace lines 1, 2 and 3 of the file draw 7, 16 and 7 segments between pen lifts
  // (counted by hand from the node lists).
  EXPECT_EQ(report->lines, 30);
  EXPECT_FALSE(report->frfSetId.has_value());

  auto mesh = store_->mesh(specimen_);
  ASSERT_TRUE(mesh.ok()) << mesh.error().describe();
  ASSERT_EQ(static_cast<int>(mesh->nodes.size()), report->nodes);
  // Units code 9 with length factor 1.0: SI value = file value / 1.0.
  const double lengthFactor = ref.at("sets").at(1).at("length").get<double>();
  const auto xyz = nodes.at("first_xyz");
  EXPECT_EQ(mesh->nodes.front().label, nodes.at("first_node").get<int>());
  for (int i = 0; i < 3; ++i) {
    // The file prints coordinates with 5 significant digits.
    EXPECT_NEAR(mesh->nodes.front().position[i], xyz.at(i).get<double>() / lengthFactor, 1e-5);
  }

  // A second import keeps the mesh the specimen has.
  auto again = importUff(*store_, kData + file, specimen_);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->nodes, 0);
  ASSERT_FALSE(again->notes.empty());
  EXPECT_NE(again->notes.back().find("already has a mesh"), std::string::npos);
}

TEST_F(UffImportTest, ModalDataBecomesAModalResult) {
  const std::string file = "uff55_translation.uff";
  auto report = importUff(*store_, kData + file, specimen_);
  ASSERT_TRUE(report.ok()) << report.error().describe();
  ASSERT_TRUE(report->modalResultId.has_value());
  const auto sets = expected(file).at("sets");
  EXPECT_EQ(report->modes, static_cast<int>(sets.size()));
  auto table = store_->modalResult(*report->modalResultId);
  ASSERT_TRUE(table.ok()) << table.error().describe();
  ASSERT_EQ(table->modes.size(), sets.size());
  for (std::size_t m = 0; m < sets.size(); ++m) {
    EXPECT_NEAR(table->modes[m].frequencyHz, sets[m].at("freq").get<double>(), 1e-9);
  }
}

TEST_F(UffImportTest, TimeDataOnlyFileIsRefusedAndTheProjectIsUntouched) {
  auto before = store_->summary();
  ASSERT_TRUE(before.ok());
  auto report = importUff(*store_, kData + "binary8byte.uff", specimen_);  // one time record, nothing to import
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.error().code, ErrorCode::NotFound);

  const auto notUff = dir_ / "notes.uff";
  std::ofstream(notUff) << "this is not a universal file\n";
  EXPECT_FALSE(importUff(*store_, notUff.string(), specimen_).ok());

  auto after = store_->summary();
  ASSERT_TRUE(after.ok());
  ASSERT_EQ(before->counts.size(), after->counts.size());
  for (std::size_t i = 0; i < before->counts.size(); ++i) {
    EXPECT_EQ(before->counts[i].rows, after->counts[i].rows) << before->counts[i].table;
  }
}

}  // namespace
}  // namespace mozzi::core::io
