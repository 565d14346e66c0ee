#include "app/gui/project_document.h"

#include <QFileInfo>

#include "app/build_info.h"
#include "devices/sim/virtual_specimens.h"

namespace mozzi {
namespace app {

namespace {
core::Error noProject() {
  return core::makeError(core::ErrorCode::NotFound, "no project is open");
}
}  // namespace

ProjectDocument::ProjectDocument(QObject* parent) : QObject(parent) {}

QString ProjectDocument::path() const {
  return store_ ? QString::fromStdString(store_->path()) : QString();
}

QString ProjectDocument::readOnlyReason() const {
  return store_ ? QString::fromStdString(store_->readOnlyReason()) : QString();
}

core::Result<core::io::ProjectSummary> ProjectDocument::summary() const {
  if (!store_) return noProject();
  return store_->summary();
}

core::Result<void> ProjectDocument::open(const QString& path) {
  // The project already open here: opening it again would meet our own lock
  // and come back read-only, so just show it again.
  if (store_ && QFileInfo(path).canonicalFilePath() == QFileInfo(this->path()).canonicalFilePath() &&
      !QFileInfo(path).canonicalFilePath().isEmpty()) {
    emit changed();
    return {};
  }
  auto store = core::io::ProjectStore::open(path.toStdString());
  if (!store) return store.error();
  store_.reset();  // release our lock on the old file before keeping the new one
  store_.emplace(std::move(store).value());
  emit changed();
  return {};
}

core::Result<void> ProjectDocument::create(const QString& path) {
  auto store = core::io::ProjectStore::create(path.toStdString(), buildinfo::kMozziVersion);
  if (!store) return store.error();
  store_.reset();
  store_.emplace(std::move(store).value());
  emit changed();
  return {};
}

core::Result<void> ProjectDocument::createDemo(const QString& path) {
  if (auto r = devices::sim::createDemoProject(path.toStdString(), buildinfo::kMozziVersion); !r) return r;
  return open(path);
}

core::Result<void> ProjectDocument::saveAs(const QString& path) {
  if (!store_) return noProject();
  if (auto r = store_->saveAs(path.toStdString()); !r) return r;
  return open(path);
}

core::Result<core::io::UffImportReport> ProjectDocument::importUff(const QString& path, std::int64_t specimenId) {
  if (!store_) return noProject();
  auto report = core::io::importUff(*store_, path.toStdString(), specimenId);
  if (report) emit changed();
  return report;
}

core::Result<std::int64_t> ProjectDocument::addSpecimen(const QString& name, const QString& kind) {
  if (!store_) return noProject();
  auto id = store_->addSpecimen(name.toStdString(), kind.toStdString(), "");
  if (id) emit changed();
  return id;
}

core::Result<core::io::StoredMesh> ProjectDocument::mesh(std::int64_t specimenId) const {
  if (!store_) return noProject();
  return store_->mesh(specimenId);
}

core::Result<std::vector<core::io::FrfSetInfo>> ProjectDocument::frfSets() const {
  if (!store_) return noProject();
  return store_->frfSets();
}

core::Result<core::FrfMatrix> ProjectDocument::frfSet(std::int64_t id) const {
  if (!store_) return noProject();
  return store_->frfSet(id);
}

core::Result<std::vector<core::io::ModalResultInfo>> ProjectDocument::modalResults() const {
  if (!store_) return noProject();
  return store_->modalResults();
}

void ProjectDocument::close() {
  if (!store_) return;
  store_.reset();
  emit changed();
}

}  // namespace app
}  // namespace mozzi
