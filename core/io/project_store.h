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

class ProjectStore {
 public:
  enum class OpenMode { ReadWrite, ReadOnly };

  // Creates a new, empty project; fails if the file exists.
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
  // Copies committed WAL pages into the database file (PASSIVE checkpoint,
  // never blocks readers). Meant for the idle time between hits: with it the
  // WAL never reaches SQLite's auto-checkpoint size during a campaign, so no
  // commit pays for a checkpoint (docs/performance/project.md).
  Result<void> checkpoint();
  // synchronous = FULL (the default: every commit fsync'd) or OFF (no fsync:
  // a power cut may lose recent commits). OFF only while bulk-writing content
  // that can be made again (the demo project's campaigns).
  Result<void> setDurable(bool durable);
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

  Result<std::int64_t> addModel(const StoredModel& model);
  Result<std::int64_t> addAnalysis(const StoredAnalysis& analysis);
  Result<StoredAnalysis> analysis(std::int64_t analysisId) const;

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

  SampleEncoding hitEncoding_ = SampleEncoding::Raw;

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
