#pragma once
// The one observed document of the workbench (WORKBENCH.md "One document,
// observed"): owns the open core::io::ProjectStore and says what changed in it,
// with one signal per kind of record. app/ owns the instance and hands it to
// every page; pages read through store() and never open the file themselves.
//
// Writing: either a convenience mutator below (writes, then notifies), or a
// write through store() followed by notifyChanged(kind, id). Engines writing
// from a worker thread call notifyChanged() from that thread; receivers in the
// GUI thread get the signals queued. The store's own methods are internally
// locked; this class adds no lock around them.

#include <QMetaType>
#include <QObject>
#include <QString>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/io/project_contents.h"
#include "core/io/project_records.h"
#include "core/io/project_store.h"
#include "core/io/uff_import.h"

namespace mozzi {
namespace views {

// The kinds of record a project holds (and that a page can be opened on).
enum class RecordKind {
  None,  // nothing (a page opened from a menu)
  Project,
  Specimen,
  Mesh,  // id = specimen id
  Campaign,
  Hit,
  FrfSet,
  ModalResult,
  RigTest,
  TyreTest,
  Model,
  Analysis,
};

// Stable lower-case name, e.g. "frf-set" (logs, object names, tests).
const char* recordKindName(RecordKind kind);

class ProjectModel : public QObject {
  Q_OBJECT
 public:
  explicit ProjectModel(QObject* parent = nullptr);
  ~ProjectModel() override;

  // Written into projects this model creates (default: the application version).
  void setMozziVersion(const QString& version) { mozziVersion_ = version; }

  bool isOpen() const { return static_cast<bool>(store_); }
  QString path() const;  // empty when closed
  bool isReadOnly() const { return store_ && store_->isReadOnly(); }
  QString readOnlyReason() const;
  // The open store (nullptr when closed). Valid until projectChanged(); do not
  // keep it across that signal. A job that runs on a worker thread takes
  // storeHandle() instead, which keeps the store alive until the job ends even
  // if the user closes or replaces the project meanwhile.
  core::io::ProjectStore* store() const { return store_.get(); }
  std::shared_ptr<core::io::ProjectStore> storeHandle() const { return store_; }

  // Each returns the error and leaves the current project (if any) open and
  // untouched when it fails; on success projectChanged() is emitted.
  core::Result<void> open(const QString& path);
  core::Result<void> create(const QString& path);
  core::Result<void> createDemo(const QString& path);
  // Copies the project to `path` and opens the copy.
  core::Result<void> saveAs(const QString& path);
  void close();

  // Runs the checks of opening (SQLite quick_check, application id, schema
  // version) on the open project's file through a second, read-only
  // connection, without disturbing this session.
  core::Result<void> checkIntegrity() const;

  // Convenience reads (errors when no project is open).
  core::Result<core::io::ProjectSummary> summary() const;
  // What each specimen holds (core::io::projectContents: record ids by kind,
  // each analysis with its kind), read once after each change of the project
  // and shared by every reader (the Overview, the project tree). Empty when no
  // project is open or it cannot be read. GUI thread only; valid until the
  // next change signal.
  const std::vector<core::io::SpecimenContents>& contents() const;
  // A short display name for a record ("Frame A", "frf.uff"); empty if unknown.
  QString recordName(RecordKind kind, qint64 id) const;
  // The FRF set `id` as stored (ProjectStore::frfSet), read once and shared
  // by the pages that show it (the FRF plot, Identification, Mode Animation
  // open the same set one after the other: a demo set takes about 20 ms to
  // read and check) until the next change of the project. The last
  // kFrfSetsKept sets read are kept. GUI thread only.
  core::Result<std::shared_ptr<const core::FrfMatrix>> frfSet(qint64 id) const;
  static constexpr std::size_t kFrfSetsKept = 3;

  // Convenience writes: write through the store, then notify. Errors when no
  // project is open or the store refuses (read-only, unknown id, ...).
  core::Result<qint64> addSpecimen(const QString& name, const QString& kind, const QString& description = QString());
  core::Result<void> deleteSpecimen(qint64 specimenId);
  core::Result<void> setMesh(qint64 specimenId, const core::io::StoredMesh& mesh);
  core::Result<qint64> addCampaign(const core::io::StoredCampaign& campaign);
  core::Result<qint64> commitHit(const core::io::StoredHit& hit);
  core::Result<qint64> addFrfSet(const core::io::FrfSetInfo& info, const core::FrfMatrix& frf,
                                 const std::vector<std::int64_t>& hitIds = {});
  core::Result<qint64> addModalResult(const core::io::ModalResultInfo& info, const core::io::ModalTable& table);
  core::Result<qint64> addRigTest(const core::io::StoredRigTest& test);
  core::Result<qint64> addTyreTest(const core::io::StoredTyreTest& test);
  core::Result<qint64> addModel(const core::io::StoredModel& model);
  core::Result<qint64> addAnalysis(const core::io::StoredAnalysis& analysis);
  // Imports a UFF file into the specimen (core::io::importUff) and notifies
  // the mesh, FRF set and modal result it added.
  core::Result<core::io::UffImportReport> importUff(const QString& path, qint64 specimenId);

  // Tells every observer that records of `kind` changed (id: the record, or
  // the specimen for Mesh and Campaign, the campaign for Hit; 0 = several).
  // Thread-safe: from the GUI thread the signals are emitted before this
  // returns; from any other thread they are emitted later in the GUI thread.
  void notifyChanged(RecordKind kind, qint64 id = 0);

 signals:
  // Emitted just before the open store is released (close, or open/create/
  // saveAs replacing it): stop engines that write to it.
  void aboutToClose();
  // A project was opened, closed or replaced: re-read everything.
  void projectChanged();
  void specimensChanged();
  void meshChanged(qint64 specimenId);
  void campaignsChanged(qint64 specimenId);
  void hitsChanged(qint64 campaignId);
  void frfSetsChanged();
  void modalResultsChanged();
  void rigTestsChanged();
  void tyreTestsChanged();
  void modelsChanged();
  void analysesChanged();
  // Emitted with each of the signals above (after it), for observers of all kinds.
  void recordsChanged(mozzi::views::RecordKind kind, qint64 id);

 private:
  void emitChanged(RecordKind kind, qint64 id);
  // Drops what contents() and frfSet() keep (the project changed).
  void forgetReads();
  core::Result<void> replaceStore(core::Result<core::io::ProjectStore> opened);

  std::shared_ptr<core::io::ProjectStore> store_;
  QString mozziVersion_;
  mutable std::optional<std::vector<core::io::SpecimenContents>> contents_;  // contents(), until the next change
  // frfSet(): the sets read since the last change, the most recent last
  mutable std::vector<std::pair<qint64, std::shared_ptr<const core::FrfMatrix>>> frfSets_;
};

}  // namespace views
}  // namespace mozzi

Q_DECLARE_METATYPE(mozzi::views::RecordKind)
