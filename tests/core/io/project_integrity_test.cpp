// Issue 17: every stored record carries a checksum checked on read (the error
// names the record), checkIntegrity reports every damaged record, a project
// is created whole or not at all (also by two processes at once), and a
// read-only open works where the user cannot write and leaves no file behind.

#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

FrfMatrix sampleFrf() {
  FrfMatrix f;
  f.type = FrfType::Accelerance;
  f.frequencyHz = Vector::LinSpaced(201, 0.0, 400.0);
  f.responses = {Dof{1, Direction::X, false}, Dof{2, Direction::Z, true}};
  f.references = {Dof{1, Direction::X, false}};
  ComplexMatrix h(201, 2);
  Matrix c(201, 2);
  for (int k = 0; k < 201; ++k) {
    for (int o = 0; o < 2; ++o) {
      h(k, o) = Complex(std::cos(0.01 * k * (o + 1)), std::sin(0.02 * k) / (1.0 + o));
      c(k, o) = 0.5 + 0.4 * std::cos(0.03 * k + o);
    }
  }
  f.h = {h};
  f.coherence = {c};
  return f;
}

ModalTable sampleModes() {
  ModalTable t;
  t.dofs = {Dof{1, Direction::X, false}, Dof{2, Direction::Z, true}};
  t.modes.push_back({41.5, 0.012, ComplexVector(2)});
  t.modes.push_back({97.25, 0.0301, ComplexVector(2)});
  t.modes[0].shape << Complex(1.0, 0.01), Complex(-0.0, 0.0);  // -0.0 stored by SQLite as 0: still verifies
  t.modes[1].shape << Complex(0.2, -0.1), Complex(1.0, 0.0);
  return t;
}

class ProjectIntegrityTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_integrity_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    ::chmod(dir_.c_str(), 0755);
    fs::remove_all(dir_);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  // A project with one record of every checksummed kind.
  struct Ids {
    std::int64_t specimen, frfSet, modal, rigTest, tyreTest;
  };
  Ids fill(ProjectStore& store) {
    Ids ids{};
    ids.specimen = *store.addSpecimen("Frame A", "frame", "test");
    StoredMesh mesh;
    for (int i = 1; i <= 4; ++i) mesh.nodes.push_back({0, i, 0, 0, Vector3(0.1 * i, -0.0, 0.7)});
    mesh.lines = {{1, 2}, {2, 3}, {3, 4}};
    mesh.faces = {{1, 2, 3, 0}};
    EXPECT_TRUE(store.setMesh(ids.specimen, mesh).ok());
    FrfSetInfo info;
    info.specimenId = ids.specimen;
    info.name = "H1";
    ids.frfSet = *store.addFrfSet(info, sampleFrf());
    ModalResultInfo mi;
    mi.specimenId = ids.specimen;
    mi.name = "pLSCF";
    mi.bandHighHz = 200;
    ids.modal = *store.addModalResult(mi, sampleModes());
    StoredRigTest rt;
    rt.specimenId = ids.specimen;
    rt.name = "static";
    rt.parametersJson = R"({"load_n": 500})";
    rt.results = {{"lateral stiffness", 2.5e6, "N/m", 1e4}};
    ids.rigTest = *store.addRigTest(rt);
    EXPECT_TRUE(store.addRigTestRecord(ids.rigTest, 0, 1000.0, Eigen::MatrixXf::Random(256, 2)).ok());
    StoredTyreTest tt;
    tt.specimenId = ids.specimen;
    tt.name = "cornering";
    tt.kind = "cornering";
    tt.inflationPressurePa = 2.5e5;
    tt.verticalLoadN = 1500;
    tt.speedMps = 0.1;
    tt.points = {{0.01, 0.0, 210.0, 1.5, 0.0}};
    ids.tyreTest = *store.addTyreTest(tt);
    return ids;
  }

  static void sql(const std::string& path, const std::string& statement) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* msg = nullptr;
    EXPECT_EQ(sqlite3_exec(db, statement.c_str(), nullptr, nullptr, &msg), SQLITE_OK) << (msg ? msg : "");
    sqlite3_free(msg);
    sqlite3_close(db);
  }

  fs::path dir_;
};

TEST_F(ProjectIntegrityTest, EveryRecordKindRoundTripsWithItsChecksum) {
  auto store = ProjectStore::create(file("p.mozzi"), "test");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  EXPECT_EQ(store->schemaVersion(), ProjectStore::currentSchemaVersion());
  const Ids ids = fill(*store);
  EXPECT_TRUE(store->frfSet(ids.frfSet).ok());
  auto modes = store->modalResult(ids.modal);
  ASSERT_TRUE(modes.ok()) << modes.error().describe();
  EXPECT_EQ(modes->modes[0].shape[1], Complex(0.0, 0.0));
  EXPECT_TRUE(store->mesh(ids.specimen).ok());
  EXPECT_TRUE(store->rigTest(ids.rigTest).ok());
  EXPECT_TRUE(store->tyreTest(ids.tyreTest).ok());
  auto report = store->checkIntegrity();
  ASSERT_TRUE(report.ok()) << report.error().describe();
  EXPECT_TRUE(report->ok()) << report->problems.front().record << ": " << report->problems.front().message;
  // 1 rig-test record + 1 FRF set + 1 modal result + 1 mesh + 1 rig test + 1 tyre test
  EXPECT_EQ(report->recordsChecked, 6);
  EXPECT_EQ(report->recordsWithoutChecksum, 0);
}

// One damaged value in each kind: each read fails naming the record, and
// checkIntegrity lists all five, not just the first.
TEST_F(ProjectIntegrityTest, DamageIsReportedPerRecordAndAllAtOnce) {
  const std::string path = file("p.mozzi");
  Ids ids{};
  {
    auto store = ProjectStore::create(path, "test");
    ASSERT_TRUE(store.ok());
    ids = fill(*store);
  }
  sql(path,
      "UPDATE frf SET h = zeroblob(length(h)) WHERE response_index = 1;"
      "UPDATE mode SET frequency_hz = 41.6 WHERE mode_index = 0;"
      "UPDATE mesh_node SET x_m = 0.25 WHERE label = 2;"
      "UPDATE rig_test_result SET value = 2.6e6;"
      "UPDATE tyre_test_point SET lateral_force_n = 211.0;");
  auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto frf = store->frfSet(ids.frfSet);
  ASSERT_FALSE(frf.ok());
  EXPECT_EQ(frf.error().code, ErrorCode::Corrupt);
  EXPECT_NE(frf.error().message.find("checksum mismatch"), std::string::npos);
  EXPECT_NE(frf.error().where.find("FRF set " + std::to_string(ids.frfSet)), std::string::npos);
  EXPECT_NE(frf.error().where.find("FRF row 1/0"), std::string::npos) << frf.error().where;
  auto modes = store->modalResult(ids.modal);
  ASSERT_FALSE(modes.ok());
  EXPECT_NE(modes.error().where.find("modal result " + std::to_string(ids.modal)), std::string::npos);
  EXPECT_FALSE(store->mesh(ids.specimen).ok());
  EXPECT_FALSE(store->rigTest(ids.rigTest).ok());
  EXPECT_FALSE(store->tyreTest(ids.tyreTest).ok());
  auto report = store->checkIntegrity();
  ASSERT_TRUE(report.ok());
  ASSERT_EQ(report->problems.size(), 5u);
  for (const auto& p : report->problems) EXPECT_NE(p.message.find("checksum mismatch"), std::string::npos);
}

// The issue's bit-flip experiment: 100 copies of a project, one random bit
// flipped in each. A copy may fail to open or a read may fail, but a read
// that succeeds must return exactly the stored FRFs (before: 34 of 100 copies
// exported different FRFs without an error).
TEST_F(ProjectIntegrityTest, ABitFlipNeverChangesAnFrfSilently) {
  const std::string path = file("p.mozzi");
  Ids ids{};
  {
    auto store = ProjectStore::create(path, "test");
    ASSERT_TRUE(store.ok());
    ids = fill(*store);
  }
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    bytes = s.str();
  }
  ASSERT_GT(bytes.size(), 4096u);
  const FrfMatrix original = sampleFrf();
  std::mt19937 rng(17);  // fixed seed: reproducible
  // Flip bits in the pages after the schema (page 1): the data pages.
  std::uniform_int_distribution<std::size_t> at(4096, bytes.size() - 1);
  std::uniform_int_distribution<int> bit(0, 7);
  int silentlyWrong = 0, detected = 0, unchanged = 0;
  for (int copy = 0; copy < 100; ++copy) {
    std::string damaged = bytes;
    damaged[at(rng)] ^= static_cast<char>(1 << bit(rng));
    const std::string copyPath = file("copy" + std::to_string(copy) + ".mozzi");
    std::ofstream(copyPath, std::ios::binary) << damaged;
    auto store = ProjectStore::open(copyPath, ProjectStore::OpenMode::ReadOnly);
    if (!store) {
      ++detected;
      continue;
    }
    auto frf = store->frfSet(ids.frfSet);
    if (!frf) {
      ++detected;
      continue;
    }
    const bool same = frf->frequencyHz == original.frequencyHz && frf->h.size() == 1 && frf->h[0] == original.h[0] &&
                      frf->coherence.size() == 1 && frf->coherence[0] == original.coherence[0] &&
                      frf->responses == original.responses && frf->references == original.references &&
                      frf->type == original.type;
    if (same) {
      ++unchanged;
    } else {
      ++silentlyWrong;
    }
  }
  std::printf("bit flips: 100 copies, %d detected (open or read failed), %d read back unchanged, %d silently wrong\n",
              detected, unchanged, silentlyWrong);
  EXPECT_EQ(silentlyWrong, 0) << detected << " detected, " << unchanged << " unchanged";
}

TEST_F(ProjectIntegrityTest, TwoCreatorsAtOnceGiveOneProjectAndOneClearError) {
  for (int round = 0; round < 20; ++round) {
    const std::string path = file("race" + std::to_string(round) + ".mozzi");
    pid_t children[2];
    for (pid_t& child : children) {
      child = ::fork();
      ASSERT_GE(child, 0);
      if (child == 0) {
        int code = 20;
        {
          auto store = ProjectStore::create(path, "test");  // closed at the end of the block, as by the CLI
          if (store) {
            code = 0;
          } else if (store.error().message.find("exists already") != std::string::npos) {
            code = 10;
          }
        }
        _exit(code);
      }
    }
    std::multiset<int> codes;
    for (pid_t child : children) {
      int status = 0;
      ASSERT_EQ(::waitpid(child, &status, 0), child);
      ASSERT_TRUE(WIFEXITED(status));
      codes.insert(WEXITSTATUS(status));
    }
    // Exactly one wins; the other says the file exists (never "disk I/O error").
    EXPECT_EQ(codes.count(0), 1u) << "round " << round;
    EXPECT_EQ(codes.count(10), 1u) << "round " << round;
    auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
    ASSERT_TRUE(store.ok()) << store.error().describe();
  }
  // Nothing but the projects is left in the folder.
  for (const auto& e : fs::directory_iterator(dir_)) {
    EXPECT_EQ(e.path().extension(), ".mozzi") << e.path();
    EXPECT_EQ(e.path().filename().string().front(), 'r') << e.path();
  }
}

TEST_F(ProjectIntegrityTest, AStaleCreationNeverBlocksARerun) {
  const std::string path = file("demo.mozzi");
  // What a creation killed mid-way leaves: its temporary file (of a process
  // that no longer exists) and its WAL.
  const std::string stale = file(".demo.mozzi.creating-999999999-deadbeef");
  std::ofstream(stale) << "SQLite format 3";
  std::ofstream(stale + "-wal") << "partial";
  auto store = ProjectStore::create(path, "test");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_FALSE(fs::exists(stale + "-wal"));
}

// Read-only opening leaves nothing beside the project, also in a folder the
// user cannot write (run as 'nobody' when the test runs as root, since root
// ignores permissions); a read-write open there falls back to read-only.
TEST_F(ProjectIntegrityTest, ReadOnlyFolderProjectOpensAndLeavesNoFiles) {
  const std::string path = file("shared.mozzi");
  {
    auto store = ProjectStore::create(path, "test");
    ASSERT_TRUE(store.ok());
    fill(*store);
  }
  ASSERT_FALSE(fs::exists(path + "-wal"));
  {
    // In a writable folder: no -wal / -shm after a read-only session.
    auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
    ASSERT_TRUE(store.ok()) << store.error().describe();
    EXPECT_TRUE(store->summary().ok());
    EXPECT_FALSE(fs::exists(path + "-wal"));
    EXPECT_FALSE(fs::exists(path + "-shm"));
  }
  EXPECT_FALSE(fs::exists(path + "-wal"));
  EXPECT_FALSE(fs::exists(path + "-shm"));
  ::chmod(path.c_str(), 0644);
  ::chmod(dir_.c_str(), 0555);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) _exit(2);
    auto ro = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
    if (!ro || !ro->summary() || !ro->checkIntegrity() || !ro->checkIntegrity()->ok()) _exit(3);
    auto rw = ProjectStore::open(path, ProjectStore::OpenMode::ReadWrite);
    if (!rw || !rw->isReadOnly() || rw->readOnlyReason().empty() || !rw->frfSets()) _exit(4);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_FALSE(fs::exists(path + "-wal"));
  EXPECT_FALSE(fs::exists(path + "-shm"));
}

// A schema-1 project (before checksums) still opens read-only; its records
// are read but counted as unchecked.
// An FRF set whose rows do not make a full matrix is refused, naming what is
// wrong: a damaged index by its row's checksum, else the shape.
TEST_F(ProjectIntegrityTest, AnFrfSetOfTheWrongShapeIsRefusedNamingWhatIsWrong) {
  const auto readAfter = [&](const std::string& name, const std::string& damage) {
    const std::string path = file(name);
    std::int64_t set = 0;
    {
      auto store = ProjectStore::create(path, "test");
      EXPECT_TRUE(store.ok());
      set = fill(*store).frfSet;
    }
    sql(path, damage);
    auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
    EXPECT_TRUE(store.ok());
    return store->frfSet(set);
  };
  // The set is 2 responses x 1 reference with coherence (sampleFrf).
  auto moved = readAfter("moved.mozzi", "UPDATE frf SET response_index = 5 WHERE response_index = 1;");
  ASSERT_FALSE(moved.ok());
  EXPECT_NE(moved.error().message.find("checksum mismatch"), std::string::npos) << moved.error().describe();
  EXPECT_NE(moved.error().where.find("FRF row 5/0"), std::string::npos) << moved.error().where;
  auto missing = readAfter("missing.mozzi", "DELETE FROM frf WHERE response_index = 0;");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, ErrorCode::Corrupt);
  EXPECT_NE(missing.error().message.find("not a full responses x references matrix"), std::string::npos)
      << missing.error().describe();
  // Rows without checksums (an older file): the checks on the values themselves.
  auto noCoherence =
      readAfter("coherence.mozzi", "UPDATE frf SET coherence = NULL, content_crc32 = NULL WHERE response_index = 1;");
  ASSERT_FALSE(noCoherence.ok());
  EXPECT_NE(noCoherence.error().message.find("coherence missing for some FRFs"), std::string::npos)
      << noCoherence.error().describe();
  auto huge = readAfter("huge.mozzi",
                        "UPDATE frf SET response_index = 9223372036854775807, content_crc32 = NULL"
                        " WHERE response_index = 1;");
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error().message.find("FRF index out of range"), std::string::npos) << huge.error().describe();
}

TEST_F(ProjectIntegrityTest, OlderSchemaReadsWithoutChecksums) {
  const std::string path = file("old.mozzi");
  {
    auto store = ProjectStore::create(path, "test");
    ASSERT_TRUE(store.ok());
    fill(*store);
  }
  sql(path, "UPDATE frf_set SET content_crc32 = NULL; UPDATE frf SET content_crc32 = NULL;");
  auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  auto report = store->checkIntegrity();
  ASSERT_TRUE(report.ok());
  EXPECT_TRUE(report->ok());
  EXPECT_EQ(report->recordsWithoutChecksum, 3);  // the set and its two FRF rows
}

}  // namespace
}  // namespace mozzi::core::io
