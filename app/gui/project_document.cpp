#include "app/gui/project_document.h"

#include "app/build_info.h"
#include "devices/sim/virtual_specimens.h"

namespace mozzi {
namespace app {

ProjectDocument::ProjectDocument(QObject* parent) : QObject(parent) {}

QString ProjectDocument::path() const { return store_ ? QString::fromStdString(store_->path()) : QString(); }

QString ProjectDocument::readOnlyReason() const {
  return store_ ? QString::fromStdString(store_->readOnlyReason()) : QString();
}

core::Result<core::io::ProjectSummary> ProjectDocument::summary() const {
  if (!store_) return core::makeError(core::ErrorCode::NotFound, "no project is open");
  return store_->summary();
}

core::Result<void> ProjectDocument::open(const QString& path) {
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
  if (!store_) return core::makeError(core::ErrorCode::NotFound, "no project is open");
  if (auto r = store_->saveAs(path.toStdString()); !r) return r;
  return open(path);
}

void ProjectDocument::close() {
  if (!store_) return;
  store_.reset();
  emit changed();
}

}  // namespace app
}  // namespace mozzi
