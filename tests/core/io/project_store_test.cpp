#include "core/io/project_store.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

class ProjectStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_store_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ProjectStoreTest, CreatesWalProjectWithSchemaAndSpecimens) {
  auto store = ProjectStore::create(file("a.mozzi"), "0.1.0");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  EXPECT_FALSE(store->isReadOnly());
  EXPECT_EQ(store->schemaVersion(), ProjectStore::currentSchemaVersion());
  ASSERT_TRUE(store->addSpecimen("Fork A", "fork", "thesis Table 11").ok());
  auto summary = store->summary();
  ASSERT_TRUE(summary.ok()) << summary.error().describe();
  ASSERT_EQ(summary->specimens.size(), 1u);
  EXPECT_EQ(summary->specimens[0].name, "Fork A");
  EXPECT_EQ(summary->mozziVersion, "0.1.0");

  sqlite3_stmt* stmt = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(store->connection(), "PRAGMA journal_mode", -1, &stmt, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0)), "wal");
  sqlite3_finalize(stmt);
}

TEST_F(ProjectStoreTest, RefusesToOverwriteOnCreate) {
  std::ofstream(file("x.mozzi")) << "keep me";
  auto store = ProjectStore::create(file("x.mozzi"), "0.1.0");
  ASSERT_FALSE(store.ok());
  std::ifstream in(file("x.mozzi"));
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "keep me");
}

TEST_F(ProjectStoreTest, MissingAndForeignFilesGiveClearErrors) {
  auto missing = ProjectStore::open(file("nope.mozzi"));
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
  EXPECT_NE(missing.error().where.find("nope.mozzi"), std::string::npos);

  std::ofstream(file("text.mozzi")) << "this is not a database\n";
  auto text = ProjectStore::open(file("text.mozzi"));
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().code, ErrorCode::Corrupt);
  EXPECT_NE(text.error().message.find("not a Mozzi project"), std::string::npos);

  sqlite3* other = nullptr;
  ASSERT_EQ(sqlite3_open(file("other.db").c_str(), &other), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(other, "CREATE TABLE t(x)", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(other);
  auto foreign = ProjectStore::open(file("other.db"));
  ASSERT_FALSE(foreign.ok());
  EXPECT_NE(foreign.error().message.find("another application"), std::string::npos);
}

TEST_F(ProjectStoreTest, TruncatedProjectIsReportedNotCrashed) {
  {
    auto store = ProjectStore::create(file("t.mozzi"), "0.1.0");
    ASSERT_TRUE(store.ok());
    for (int i = 0; i < 200; ++i)
      ASSERT_TRUE(store->addSpecimen("s" + std::to_string(i), "frame", std::string(500, 'x')).ok());
  }
  const auto size = fs::file_size(file("t.mozzi"));
  ASSERT_GT(size, 8192u);
  fs::resize_file(file("t.mozzi"), size / 2);
  auto broken = ProjectStore::open(file("t.mozzi"));
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.error().code, ErrorCode::Corrupt) << broken.error().describe();
}

TEST_F(ProjectStoreTest, SecondInstanceOpensReadOnlyAndCannotWrite) {
  auto first = ProjectStore::create(file("shared.mozzi"), "0.1.0");
  ASSERT_TRUE(first.ok());
  auto second = ProjectStore::open(file("shared.mozzi"));
  ASSERT_TRUE(second.ok()) << second.error().describe();
  EXPECT_TRUE(second->isReadOnly());
  EXPECT_NE(second->readOnlyReason().find("another Mozzi instance"), std::string::npos);
  auto write = second->addSpecimen("x", "frame", "");
  ASSERT_FALSE(write.ok());
  EXPECT_EQ(write.error().code, ErrorCode::Locked);
}

TEST_F(ProjectStoreTest, SaveAsCopiesEverythingAndKeepsTheOriginalOpen) {
  auto store = ProjectStore::create(file("orig.mozzi"), "0.1.0");
  ASSERT_TRUE(store.ok());
  ASSERT_TRUE(store->addSpecimen("Frame A", "frame", "").ok());
  ASSERT_TRUE(store->saveAs(file("copy.mozzi")).ok());
  ASSERT_TRUE(store->addSpecimen("Frame B", "frame", "").ok());
  auto copy = ProjectStore::open(file("copy.mozzi"));
  ASSERT_TRUE(copy.ok()) << copy.error().describe();
  auto summary = copy->summary();
  ASSERT_TRUE(summary.ok());
  ASSERT_EQ(summary->specimens.size(), 1u);
  EXPECT_EQ(summary->specimens[0].name, "Frame A");
  EXPECT_FALSE(fs::exists(file("copy.mozzi.part")));
}

TEST_F(ProjectStoreTest, SchemaVersionsAreEnforced) {
  {
    auto store = ProjectStore::create(file("v.mozzi"), "0.1.0");
    ASSERT_TRUE(store.ok());
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file("v.mozzi").c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version = 99", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  auto newer = ProjectStore::open(file("v.mozzi"));
  ASSERT_FALSE(newer.ok());
  EXPECT_EQ(newer.error().code, ErrorCode::Unsupported);
  EXPECT_NE(newer.error().message.find("schema 99"), std::string::npos) << newer.error().describe();

  // A Mozzi file whose creation never committed (user_version 0) is refused,
  // not silently re-created.
  ASSERT_EQ(sqlite3_open(file("v.mozzi").c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version = 0", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  auto unfinished = ProjectStore::open(file("v.mozzi"));
  ASSERT_FALSE(unfinished.ok());
  EXPECT_NE(unfinished.error().message.find("no schema"), std::string::npos) << unfinished.error().describe();
}

// A project of schema 4 (before the modes' standard errors): read-only it is
// read as it is, read-write it is migrated, and in both its kept modal result
// passes its checksum (the standard errors enter it only when present).
TEST_F(ProjectStoreTest, ASchema4ModalResultReadsAndMigratesWithItsChecksum) {
  ModalTable kept;
  kept.dofs = {Dof{1, Direction::X, false}, Dof{2, Direction::Z, true}};
  kept.modes.push_back({41.5, 0.012, ComplexVector::Constant(2, Complex(1.0, 0.1))});
  kept.modes.push_back({97.25, 0.0301, ComplexVector::Constant(2, Complex(-0.5, 0.0))});
  std::int64_t id = 0;
  {
    auto store = ProjectStore::create(file("v4.mozzi"), "0.1.0");
    ASSERT_TRUE(store.ok());
    auto specimen = store->addSpecimen("Frame A", "frame", "");
    ASSERT_TRUE(specimen.ok());
    ModalResultInfo info;
    info.specimenId = *specimen;
    info.name = "PolyMAX 20 .. 120 Hz";
    auto added = store->addModalResult(info, kept);
    ASSERT_TRUE(added.ok()) << added.error().describe();
    id = *added;
  }
  // Back to schema 4 as an older Mozzi wrote it: without the two columns.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file("v4.mozzi").c_str(), &db), SQLITE_OK);
  ASSERT_EQ(
      sqlite3_exec(db,
                   "ALTER TABLE mode DROP COLUMN frequency_std_hz; ALTER TABLE mode DROP COLUMN damping_ratio_std;"
                   " PRAGMA user_version = 4",
                   nullptr, nullptr, nullptr),
      SQLITE_OK)
      << sqlite3_errmsg(db);
  sqlite3_close(db);

  auto checkKept = [&](const ProjectStore& store) {
    auto table = store.modalResult(id);
    ASSERT_TRUE(table.ok()) << table.error().describe();  // its checksum verified
    ASSERT_EQ(table->modes.size(), 2u);
    EXPECT_EQ(table->modes[1].frequencyHz, 97.25);
    EXPECT_EQ(table->modes[0].shape, kept.modes[0].shape);
    EXPECT_FALSE(table->modes[0].frequencyStdHz.has_value());
    EXPECT_FALSE(table->modes[1].dampingRatioStd.has_value());
  };
  {
    auto readOnly = ProjectStore::open(file("v4.mozzi"), ProjectStore::OpenMode::ReadOnly);
    ASSERT_TRUE(readOnly.ok()) << readOnly.error().describe();
    EXPECT_EQ(readOnly->schemaVersion(), 4);
    checkKept(*readOnly);
  }
  auto migrated = ProjectStore::open(file("v4.mozzi"));
  ASSERT_TRUE(migrated.ok()) << migrated.error().describe();
  EXPECT_EQ(migrated->schemaVersion(), 5);
  checkKept(*migrated);
  // A change of its content after the migration is still caught.
  ASSERT_EQ(sqlite3_exec(migrated->connection(), "UPDATE mode SET frequency_std_hz = 0.01 WHERE mode_index = 0",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  auto tampered = migrated->modalResult(id);
  ASSERT_FALSE(tampered.ok());
  EXPECT_EQ(tampered.error().code, ErrorCode::Corrupt) << tampered.error().describe();
}

TEST_F(ProjectStoreTest, EveryTableOfTheSchemaIsCounted) {
  auto store = ProjectStore::create(file("t.mozzi"), "0.1.0");
  ASSERT_TRUE(store.ok());
  auto summary = store->summary();
  ASSERT_TRUE(summary.ok());
  // Schema 1 defines 26 tables, migration 2 adds campaign_point and migration 3
  // tyre_test_record; the summary counts all but `meta`.
  sqlite3_stmt* stmt = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(store->connection(),
                               "SELECT count(*) FROM sqlite_schema WHERE type = 'table' AND name <> 'meta'", -1, &stmt,
                               nullptr),
            SQLITE_OK);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(stmt, 0), 27);
  sqlite3_finalize(stmt);
  EXPECT_EQ(summary->counts.size(), 27u);
  // Foreign keys are enforced on every connection the store opens.
  ASSERT_EQ(sqlite3_prepare_v2(store->connection(), "PRAGMA foreign_keys", -1, &stmt, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(stmt, 0), 1);
  sqlite3_finalize(stmt);
}

}  // namespace
}  // namespace mozzi::core::io
