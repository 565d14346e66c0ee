#pragma once
// The project file: one SQLite database per project (.mozzi), WAL mode, foreign
// keys on, application_id 'MOZZ' and user_version = schema version (the tables
// are in project_schema.cpp, the format in docs/formats/project.md). Opening
// checks that the file is a Mozzi project and passes PRAGMA quick_check; a file
// another instance holds open for writing opens read-only.
//
// Durability: every write runs in one explicit BEGIN IMMEDIATE ... COMMIT
// transaction, with synchronous = FULL, so a method that returns success has
// its data in the WAL on disk (fsync'd) and a process crash, a kill or a power
// cut afterwards loses nothing of it. commitHit is the campaign's hot path:
// one hit, one transaction, the row id returned only after COMMIT.

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/io/sample_codec.h"

struct sqlite3;

namespace mozzi::core::io {

inline constexpr std::int32_t kProjectApplicationId = 0x4D4F5A5A;  // "MOZZ"

// "running", "complete", "interrupted", "failed" (the schema's words).
const char* testStatusName(TestStatus status);
// The status of a name; Failed for a word the schema does not know.
TestStatus parseTestStatus(const std::string& name);

struct ProjectSummary {
  int schemaVersion = 0;
  std::string createdUtc;
  std::string mozziVersion;  // version of Mozzi that created the file
  struct Specimen {
    std::int64_t id = 0;
    std::string name;
    std::string kind;         // "frame", "swing-arm", "fork", "tyre", "bicycle", ...
    std::string description;  // what it is and where its parameters come from
  };
  std::vector<Specimen> specimens;
  struct TableCount {
    std::string table;
    std::int64_t rows = 0;
  };
  std::vector<TableCount> counts;  // rows per data table, for the project tree
};

// Builds a new project under a temporary name in the folder of `path`
// (".NAME.creating-PID-XXXX"): `build` receives that name, creates the project
// there (ProjectStore::create or anything calling it) and closes it. Then the
// file is fsync'd and moved to `path` with a rename that never replaces an
// existing file. A creation killed at any moment leaves no file under `path`
// or a whole project; its temporary file is removed by the next creation in
// that folder (its process is gone), so it never blocks a re-run.
Result<void> createProjectAtomically(const std::string& path,
                                     const std::function<Result<void>(const std::string& tempPath)>& build);

// What ProjectStore::checkIntegrity found: every damaged record, not just the first.
struct IntegrityReport {
  struct Problem {
    std::string record;   // e.g. "P.mozzi, FRF set 3, FRF row 0/0 (response 12, reference 1)"
    std::string message;  // e.g. "checksum mismatch: the FRF was damaged after it was written (...)"
  };
  std::vector<Problem> problems;
  std::int64_t recordsChecked = 0;          // records read back and verified
  std::int64_t recordsWithoutChecksum = 0;  // written before schema 4: read, but no checksum to verify
  bool ok() const { return problems.empty(); }
};

class ProjectStore {
 public:
  enum class OpenMode { ReadWrite, ReadOnly };

  // Creates a new, empty project; fails if the file exists. Built under a
  // temporary name and moved into place (createProjectAtomically), so two
  // processes creating the same name get one project and one clear error.
  static Result<ProjectStore> create(const std::string& path, const std::string& mozziVersion);
  // Opens an existing project. ReadWrite falls back to read-only when another
  // process holds the project; readOnlyReason() then says why.
  static Result<ProjectStore> open(const std::string& path, OpenMode mode = OpenMode::ReadWrite);

  ProjectStore(ProjectStore&&) noexcept;
  ProjectStore& operator=(ProjectStore&&) noexcept;
  ~ProjectStore();

  const std::string& path() const { return path_; }
  bool isReadOnly() const { return readOnly_; }
  const std::string& readOnlyReason() const { return readOnlyReason_; }
  int schemaVersion() const;

  Result<ProjectSummary> summary() const;
  Result<std::int64_t> addSpecimen(const std::string& name, const std::string& kind, const std::string& description);
  // Deletes a specimen and everything it owns (mesh, set-ups, campaigns, hits,
  // FRFs, results, tests, models, analyses) in one transaction.
  Result<void> deleteSpecimen(std::int64_t specimenId);

  // Mesh of a specimen. setMesh replaces the whole mesh; lines and faces name
  // nodes by label, which must exist in the same mesh.
  Result<void> setMesh(std::int64_t specimenId, const StoredMesh& mesh);
  Result<StoredMesh> mesh(std::int64_t specimenId) const;

  Result<std::int64_t> addRigSetup(const StoredRigSetup& setup);
  Result<StoredRigSetup> rigSetup(std::int64_t rigSetupId) const;

  // Adds a campaign and, in the same transaction, its roving schedule
  // (positions 0..n-1, distinct DOFs; may be empty).
  Result<std::int64_t> addCampaign(const StoredCampaign& campaign, const std::vector<StoredCampaignPoint>& points = {});
  Result<std::vector<StoredCampaign>> campaigns(std::int64_t specimenId) const;
  Result<StoredCampaign> campaign(std::int64_t campaignId) const;
  // The roving schedule (project_campaign.cpp). setCampaignPoints replaces
  // it; positions must be 0..n-1 and DOFs distinct.
  Result<void> setCampaignPoints(std::int64_t campaignId, const std::vector<StoredCampaignPoint>& points);
  Result<std::vector<StoredCampaignPoint>> campaignPoints(std::int64_t campaignId) const;
  Result<void> setCampaignPointSkipped(std::int64_t campaignId, int position, bool skipped, const std::string& reason);
  // Redo a point: in one transaction its accepted hits become rejected
  // (kHitManualReject, `reason` appended) and its skip is cleared. Returns
  // how many hits were set aside.
  Result<int> redoCampaignPoint(std::int64_t campaignId, int position, const std::string& reason);
  // The hits an FRF set was estimated from (frf_hit), in hit id order.
  Result<std::vector<std::int64_t>> frfSetHits(std::int64_t frfSetId) const;

  // Commits one hit (accepted or rejected) in its own transaction and returns
  // its row id only after COMMIT has returned: when this returns a value the
  // hit survives a crash of the process or the machine. The sample blob is
  // encoded with hitEncoding() and carries a CRC-32 of the raw floats.
  Result<std::int64_t> commitHit(const StoredHit& hit);
  Result<StoredHit> hit(std::int64_t hitId) const;
  Result<std::vector<HitInfo>> hits(std::int64_t campaignId) const;
  // The technician's later verdict on a hit (re-accept, reject with reasons).
  Result<void> setHitAcceptance(std::int64_t hitId, bool accepted, std::uint32_t qualityFlags,
                                const std::string& reasons);
  // Power-loss durability of each commit: on (the default, PRAGMA synchronous
  // = FULL) every COMMIT fsyncs; off (NORMAL in WAL mode) a commit survives a
  // crash of the program but may be lost with a power cut. Off only for bulk
  // writes of data that can be generated again (the demo project's tests).
  Result<void> setPowerLossDurable(bool durable);
  // Copies committed WAL pages into the database file (PASSIVE checkpoint,
  // never blocks readers). Meant for the idle time between hits: with it the
  // WAL never reaches SQLite's auto-checkpoint size during a campaign, so no
  // commit pays for a checkpoint (docs/performance/project.md).
  Result<void> checkpoint();
  SampleEncoding hitEncoding() const {
    const std::lock_guard<std::recursive_mutex> lock(*mutex_);
    return hitEncoding_;
  }
  void setHitEncoding(SampleEncoding encoding) {
    const std::lock_guard<std::recursive_mutex> lock(*mutex_);
    hitEncoding_ = encoding;
  }

  // FRF sets: one FrfMatrix each, optionally tied to the campaign and hits it
  // was estimated from. info.id/lineCount/... are filled from `frf`.
  Result<std::int64_t> addFrfSet(const FrfSetInfo& info, const FrfMatrix& frf,
                                 const std::vector<std::int64_t>& hitIds = {});
  Result<std::vector<FrfSetInfo>> frfSets() const;
  Result<FrfMatrix> frfSet(std::int64_t frfSetId) const;

  Result<std::int64_t> addModalResult(const ModalResultInfo& info, const ModalTable& table);
  Result<std::vector<ModalResultInfo>> modalResults() const;
  Result<ModalTable> modalResult(std::int64_t modalResultId) const;

  Result<std::int64_t> addRigTest(const StoredRigTest& test);
  Result<StoredRigTest> rigTest(std::int64_t rigTestId) const;
  // Time data of one step of a rig test (same blob layout as hits).
  Result<std::int64_t> addRigTestRecord(std::int64_t rigTestId, int step, double sampleRateHz,
                                        const Eigen::MatrixXf& samples);
  Result<Eigen::MatrixXf> rigTestRecord(std::int64_t rigTestId, int step, double* sampleRateHz = nullptr) const;

  Result<std::int64_t> addTyreTest(const StoredTyreTest& test);
  Result<StoredTyreTest> tyreTest(std::int64_t tyreTestId) const;

  // Tests run step by step (devices/rigtests; project_tests.cpp). The test is
  // added with status Running; each step commits its raw record and its
  // results in one transaction (a crash loses at most the step in flight); the
  // end sets the final status, the note and the whole-test results in one more.
  // A step may also set the status note (what a crash right after it would
  // leave missing); an empty `runningNote` leaves the note as it is.
  Result<void> commitRigTestStep(std::int64_t rigTestId, int step, double sampleRateHz, const Eigen::MatrixXf& samples,
                                 const std::vector<StoredRigTest::Result>& results,
                                 const std::string& runningNote = {});
  Result<void> finishRigTest(std::int64_t rigTestId, TestStatus status, const std::string& note,
                             const std::vector<StoredRigTest::Result>& results);
  Result<std::vector<TestInfo>> rigTests() const;
  // A step of a tyre test: its record (none when `samples` is empty), the
  // measured points it adds and the parameters identified from it.
  Result<void> commitTyreTestStep(std::int64_t tyreTestId, int step, double sampleRateHz,
                                  const Eigen::MatrixXf& samples, const std::vector<StoredTyreTest::Point>& points,
                                  const std::vector<StoredTyreTest::Parameter>& parameters,
                                  const std::string& runningNote = {});
  Result<void> finishTyreTest(std::int64_t tyreTestId, TestStatus status, const std::string& note,
                              const std::vector<StoredTyreTest::Parameter>& parameters);
  Result<Eigen::MatrixXf> tyreTestRecord(std::int64_t tyreTestId, int step, double* sampleRateHz = nullptr) const;
  Result<std::vector<TestInfo>> tyreTests() const;

  Result<std::int64_t> addModel(const StoredModel& model);
  Result<std::int64_t> addAnalysis(const StoredAnalysis& analysis);
  Result<StoredAnalysis> analysis(std::int64_t analysisId) const;
  Result<std::vector<StoredAnalysis>> analyses() const;  // every analysis, in id order
  // Every analysis's id, specimen, kind and name, in id order (one query; no result JSON, no findings).
  Result<std::vector<AnalysisInfo>> analysisInfos() const;

  // Reads every stored record back (hits, rig-test records, FRF sets, modal
  // results, meshes, rig tests, tyre tests), verifying its checksum, and runs
  // SQLite's full integrity_check; reports every problem it finds.
  Result<IntegrityReport> checkIntegrity() const;

  // Writes a consistent copy of the whole project to `path` (SQLite online
  // backup), leaving this store open on its own file.
  Result<void> saveAs(const std::string& path) const;

  // The raw connection for the io layer's own tables; never exposed past core.
  // Hold mutex() while using it from a program with several threads.
  sqlite3* connection() const { return db_; }
  // Every public method holds this lock for its whole run, so one store can be
  // shared between threads (the GUI reads while the campaign engine commits).
  // Recursive: a method may call another. Reads wait for a commit in progress.
  std::recursive_mutex& mutex() const { return *mutex_; }

  static int currentSchemaVersion();

 private:
  ProjectStore() = default;
  void close();
  Result<void> requireWritable() const;
  // The frame of a write: holds the lock, refuses a read-only project, runs
  // body inside one BEGIN IMMEDIATE ... COMMIT (rolled back when body fails).
  Result<void> writeInTransaction(const std::string& where, const std::function<Result<void>()>& body);
  // The same for a write that adds a record: body returns its row id.
  Result<std::int64_t> insertInTransaction(const std::string& where, const std::function<Result<std::int64_t>()>& body);
  // Inside an open transaction: an FRF set (checked by addFrfSet), its FRFs and its hit links.
  Result<std::int64_t> insertFrfSet(const FrfSetInfo& info, const FrfMatrix& frf,
                                    const std::vector<std::int64_t>& hitIds, const std::string& where);
  // Inside an open transaction: a modal result (checked by addModalResult), its modes and shapes.
  Result<std::int64_t> insertModalResult(const ModalResultInfo& info, const ModalTable& table,
                                         const std::string& where);
  // Inside an open transaction: replaces the mesh of a specimen.
  Result<void> insertMesh(std::int64_t specimenId, const StoredMesh& mesh, const std::string& where);
  // Inside an open transaction: a rig test's results, a tyre test's points
  // (indices from firstPoint) and parameters.
  Result<void> insertRigResults(std::int64_t rigTestId, const std::vector<StoredRigTest::Result>& results,
                                const std::string& where);
  // The stored test; verify = false skips the content checksum (used to compute it again).
  Result<StoredRigTest> readRigTest(std::int64_t rigTestId, bool verify) const;
  Result<StoredTyreTest> readTyreTest(std::int64_t tyreTestId, bool verify) const;
  Result<void> insertTyreData(std::int64_t tyreTestId, std::int64_t firstPoint,
                              const std::vector<StoredTyreTest::Point>& points,
                              const std::vector<StoredTyreTest::Parameter>& parameters, const std::string& where);

  SampleEncoding hitEncoding_ = SampleEncoding::Raw;
  // The file has the checksum columns of schema 4 (false only for an older
  // file opened read-only, which cannot be migrated).
  bool checksums_ = true;
  // "name" when the file has the checksum column, else "NULL" (no check).
  std::string crcColumn(const char* name) const { return checksums_ ? name : "NULL"; }
  // The file has the modes' standard-error columns of schema 5 (false only for
  // an older file opened read-only).
  bool modeUncertainty_ = true;

  // On the heap so that the store stays movable; moves happen before sharing.
  std::unique_ptr<std::recursive_mutex> mutex_ = std::make_unique<std::recursive_mutex>();
  sqlite3* db_ = nullptr;
  std::string path_;
  bool readOnly_ = false;
  std::string readOnlyReason_;
  // flock() on the database file for the life of a read-write session, so a
  // second instance sees it and opens read-only; the kernel drops it if we crash.
  int lockFd_ = -1;
};

}  // namespace mozzi::core::io
