#include "views/common/project_model.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QThread>
#include <algorithm>

#include "devices/sim/virtual_specimens.h"

namespace mozzi {
namespace views {

namespace {

core::Error noProject() {
  return core::makeError(core::ErrorCode::NotFound, "no project is open");
}

// Runs a store write and notifies `kind` on success; `id` picks the id to notify.
template <class T, class Write, class Id>
core::Result<T> writeAndNotify(ProjectModel* model, core::io::ProjectStore* store, RecordKind kind, Write write,
                               Id id) {
  if (!store) return noProject();
  auto result = write(*store);
  if (result) model->notifyChanged(kind, id(result.value()));
  return result;
}

}  // namespace

const char* recordKindName(RecordKind kind) {
  switch (kind) {
    case RecordKind::None: return "none";
    case RecordKind::Project: return "project";
    case RecordKind::Specimen: return "specimen";
    case RecordKind::Mesh: return "mesh";
    case RecordKind::Campaign: return "campaign";
    case RecordKind::Hit: return "hit";
    case RecordKind::FrfSet: return "frf-set";
    case RecordKind::ModalResult: return "modal-result";
    case RecordKind::RigTest: return "rig-test";
    case RecordKind::TyreTest: return "tyre-test";
    case RecordKind::Model: return "model";
    case RecordKind::Analysis: return "analysis";
  }
  return "unknown";
}

ProjectModel::ProjectModel(QObject* parent) : QObject(parent), mozziVersion_(QCoreApplication::applicationVersion()) {
  qRegisterMetaType<mozzi::views::RecordKind>("mozzi::views::RecordKind");
}

ProjectModel::~ProjectModel() = default;

QString ProjectModel::path() const {
  return store_ ? QString::fromStdString(store_->path()) : QString();
}

QString ProjectModel::readOnlyReason() const {
  return store_ ? QString::fromStdString(store_->readOnlyReason()) : QString();
}

core::Result<void> ProjectModel::checkIntegrity() const {
  if (!store_) return noProject();
  auto check = core::io::ProjectStore::open(store_->path(), core::io::ProjectStore::OpenMode::ReadOnly);
  if (!check) return check.error();
  return {};
}

core::Result<core::io::ProjectSummary> ProjectModel::summary() const {
  if (!store_) return noProject();
  return store_->summary();
}

core::Result<void> ProjectModel::replaceStore(core::Result<core::io::ProjectStore> opened) {
  if (!opened) return opened.error();
  auto next = std::make_shared<core::io::ProjectStore>(std::move(opened).value());
  if (store_) emit aboutToClose();
  store_ = std::move(next);
  forgetReads();
  emit projectChanged();
  return {};
}

core::Result<void> ProjectModel::open(const QString& path) {
  // The project already open here: opening it again would meet our own lock
  // and come back read-only, so just show it again.
  const QString canonical = QFileInfo(path).canonicalFilePath();
  if (store_ && !canonical.isEmpty() && canonical == QFileInfo(this->path()).canonicalFilePath()) {
    forgetReads();
    emit projectChanged();
    return {};
  }
  auto opened = core::io::ProjectStore::open(path.toStdString());
  if (!opened) return opened.error();
  // Release our lock on the old file before keeping the new one (a file
  // reopened under another name would otherwise come back read-only).
  if (store_) emit aboutToClose();
  store_.reset();
  return replaceStore(std::move(opened));
}

core::Result<void> ProjectModel::create(const QString& path) {
  return replaceStore(core::io::ProjectStore::create(path.toStdString(), mozziVersion_.toStdString()));
}

core::Result<void> ProjectModel::createDemo(const QString& path) {
  if (auto r = devices::sim::createDemoProject(path.toStdString(), mozziVersion_.toStdString()); !r) return r;
  return open(path);
}

core::Result<void> ProjectModel::saveAs(const QString& path) {
  if (!store_) return noProject();
  if (auto r = store_->saveAs(path.toStdString()); !r) return r;
  return open(path);
}

void ProjectModel::close() {
  if (!store_) return;
  emit aboutToClose();
  store_.reset();
  forgetReads();
  emit projectChanged();
}

const std::vector<core::io::SpecimenContents>& ProjectModel::contents() const {
  if (!contents_) {
    contents_.emplace();
    if (store_)
      if (auto read = core::io::projectContents(*store_)) contents_ = std::move(read).value();
  }
  return *contents_;
}

void ProjectModel::forgetReads() {
  contents_.reset();
  frfSets_.clear();
}

core::Result<std::shared_ptr<const core::FrfMatrix>> ProjectModel::frfSet(qint64 id) const {
  if (!store_) return noProject();
  auto kept = std::find_if(frfSets_.begin(), frfSets_.end(), [id](const auto& e) { return e.first == id; });
  if (kept != frfSets_.end()) {
    std::rotate(kept, kept + 1, frfSets_.end());  // the most recent last
    return frfSets_.back().second;
  }
  auto read = store_->frfSet(id);
  if (!read) return read.error();
  if (frfSets_.size() >= kFrfSetsKept) frfSets_.erase(frfSets_.begin());
  frfSets_.emplace_back(id, std::make_shared<const core::FrfMatrix>(std::move(read).value()));
  return frfSets_.back().second;
}

QString ProjectModel::recordName(RecordKind kind, qint64 id) const {
  if (!store_ || id == 0) return {};
  auto text = [](const std::string& s) { return QString::fromStdString(s); };
  switch (kind) {
    case RecordKind::Project: return QFileInfo(path()).completeBaseName();
    case RecordKind::Specimen:
    case RecordKind::Mesh:
      if (auto s = store_->summary()) {
        for (const auto& sp : s->specimens) {
          if (sp.id == id) return text(sp.name);
        }
      }
      return {};
    case RecordKind::FrfSet:
      if (auto sets = store_->frfSets()) {
        for (const auto& set : *sets) {
          if (set.id == id) return text(set.name);
        }
      }
      return {};
    case RecordKind::ModalResult:
      if (auto results = store_->modalResults()) {
        for (const auto& result : *results) {
          if (result.id == id) return text(result.name);
        }
      }
      return {};
    case RecordKind::RigTest:
      if (auto test = store_->rigTest(id)) return text(test->name);
      return {};
    case RecordKind::TyreTest:
      if (auto test = store_->tyreTest(id)) return text(test->name);
      return {};
    case RecordKind::Analysis:
      if (auto analysis = store_->analysis(id)) return text(analysis->name);
      return {};
    case RecordKind::Campaign:
      if (auto campaign = store_->campaign(id)) return text(campaign->name);
      return {};
    case RecordKind::None:
    case RecordKind::Hit:
    case RecordKind::Model: break;
  }
  return {};
}

core::Result<qint64> ProjectModel::addSpecimen(const QString& name, const QString& kind, const QString& description) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::Specimen,
      [&](core::io::ProjectStore& s) -> core::Result<qint64> {
        auto id = s.addSpecimen(name.toStdString(), kind.toStdString(), description.toStdString());
        if (!id) return id.error();
        return static_cast<qint64>(*id);
      },
      [](qint64 id) { return id; });
}

core::Result<void> ProjectModel::deleteSpecimen(qint64 specimenId) {
  if (!store_) return noProject();
  if (auto r = store_->deleteSpecimen(specimenId); !r) return r;
  // The specimen took everything it owned with it.
  notifyChanged(RecordKind::Specimen, specimenId);
  notifyChanged(RecordKind::Mesh, specimenId);
  notifyChanged(RecordKind::Campaign, specimenId);
  for (RecordKind kind : {RecordKind::FrfSet, RecordKind::ModalResult, RecordKind::RigTest, RecordKind::TyreTest,
                          RecordKind::Model, RecordKind::Analysis}) {
    notifyChanged(kind, 0);
  }
  return {};
}

core::Result<void> ProjectModel::setMesh(qint64 specimenId, const core::io::StoredMesh& mesh) {
  if (!store_) return noProject();
  if (auto r = store_->setMesh(specimenId, mesh); !r) return r;
  notifyChanged(RecordKind::Mesh, specimenId);
  return {};
}

namespace {
template <class R>
core::Result<qint64> widen(R r) {
  if (!r) return r.error();
  return static_cast<qint64>(r.value());
}
}  // namespace

core::Result<qint64> ProjectModel::addCampaign(const core::io::StoredCampaign& campaign) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::Campaign, [&](core::io::ProjectStore& s) { return widen(s.addCampaign(campaign)); },
      [&](qint64) { return static_cast<qint64>(campaign.specimenId); });
}

core::Result<qint64> ProjectModel::commitHit(const core::io::StoredHit& hit) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::Hit, [&](core::io::ProjectStore& s) { return widen(s.commitHit(hit)); },
      [&](qint64) { return static_cast<qint64>(hit.campaignId); });
}

core::Result<qint64> ProjectModel::addFrfSet(const core::io::FrfSetInfo& info, const core::FrfMatrix& frf,
                                             const std::vector<std::int64_t>& hitIds) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::FrfSet,
      [&](core::io::ProjectStore& s) { return widen(s.addFrfSet(info, frf, hitIds)); }, [](qint64 id) { return id; });
}

core::Result<qint64> ProjectModel::addModalResult(const core::io::ModalResultInfo& info,
                                                  const core::io::ModalTable& table) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::ModalResult,
      [&](core::io::ProjectStore& s) { return widen(s.addModalResult(info, table)); }, [](qint64 id) { return id; });
}

core::Result<qint64> ProjectModel::addRigTest(const core::io::StoredRigTest& test) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::RigTest, [&](core::io::ProjectStore& s) { return widen(s.addRigTest(test)); },
      [](qint64 id) { return id; });
}

core::Result<qint64> ProjectModel::addTyreTest(const core::io::StoredTyreTest& test) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::TyreTest, [&](core::io::ProjectStore& s) { return widen(s.addTyreTest(test)); },
      [](qint64 id) { return id; });
}

core::Result<qint64> ProjectModel::addModel(const core::io::StoredModel& model) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::Model, [&](core::io::ProjectStore& s) { return widen(s.addModel(model)); },
      [](qint64 id) { return id; });
}

core::Result<qint64> ProjectModel::addAnalysis(const core::io::StoredAnalysis& analysis) {
  return writeAndNotify<qint64>(
      this, store(), RecordKind::Analysis, [&](core::io::ProjectStore& s) { return widen(s.addAnalysis(analysis)); },
      [](qint64 id) { return id; });
}

core::Result<core::io::UffImportReport> ProjectModel::importUff(const QString& path, qint64 specimenId) {
  if (!store_) return noProject();
  auto report = core::io::importUff(*store_, path.toStdString(), specimenId);
  if (!report) return report;
  if (report->nodes > 0) notifyChanged(RecordKind::Mesh, report->specimenId);
  if (report->frfSetId) notifyChanged(RecordKind::FrfSet, *report->frfSetId);
  if (report->modalResultId) notifyChanged(RecordKind::ModalResult, *report->modalResultId);
  return report;
}

void ProjectModel::notifyChanged(RecordKind kind, qint64 id) {
  if (QThread::currentThread() == thread()) {
    emitChanged(kind, id);
    return;
  }
  // From a worker: emit in the model's thread. The model outlives every job
  // (the JobRunner waits for its workers), so `this` is valid when it runs.
  QMetaObject::invokeMethod(
      this, [this, kind, id] { emitChanged(kind, id); }, Qt::QueuedConnection);
}

void ProjectModel::emitChanged(RecordKind kind, qint64 id) {
  // A hit changes no specimen's contents (the campaign is listed, not its
  // hits), but it may come with its FRF set's new average.
  frfSets_.clear();
  if (kind != RecordKind::Hit) contents_.reset();
  switch (kind) {
    case RecordKind::None: return;
    case RecordKind::Project: emit projectChanged(); break;
    case RecordKind::Specimen: emit specimensChanged(); break;
    case RecordKind::Mesh: emit meshChanged(id); break;
    case RecordKind::Campaign: emit campaignsChanged(id); break;
    case RecordKind::Hit: emit hitsChanged(id); break;
    case RecordKind::FrfSet: emit frfSetsChanged(); break;
    case RecordKind::ModalResult: emit modalResultsChanged(); break;
    case RecordKind::RigTest: emit rigTestsChanged(); break;
    case RecordKind::TyreTest: emit tyreTestsChanged(); break;
    case RecordKind::Model: emit modelsChanged(); break;
    case RecordKind::Analysis: emit analysesChanged(); break;
  }
  emit recordsChanged(kind, id);
}

}  // namespace views
}  // namespace mozzi
