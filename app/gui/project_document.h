#pragma once
// The project open in the main window: owns the core ProjectStore and tells the
// views when it changes. Errors come back as core::Error for the window to show.

#include <QObject>
#include <QString>
#include <optional>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "core/io/uff_import.h"

namespace mozzi {
namespace app {

class ProjectDocument : public QObject {
  Q_OBJECT
 public:
  explicit ProjectDocument(QObject* parent = nullptr);

  bool isOpen() const { return store_.has_value(); }
  QString path() const;
  bool isReadOnly() const { return store_ && store_->isReadOnly(); }
  QString readOnlyReason() const;
  core::Result<core::io::ProjectSummary> summary() const;

  // On failure the current project (if any) stays open and untouched.
  core::Result<void> open(const QString& path);
  core::Result<void> create(const QString& path);
  core::Result<void> createDemo(const QString& path);
  core::Result<void> saveAs(const QString& path);
  void close();

  // Imports a UFF file into the specimen (see core::io::importUff).
  core::Result<core::io::UffImportReport> importUff(const QString& path, std::int64_t specimenId);
  core::Result<std::int64_t> addSpecimen(const QString& name, const QString& kind);
  // Read access for the views; each fails cleanly when no project is open.
  core::Result<core::io::StoredMesh> mesh(std::int64_t specimenId) const;
  core::Result<std::vector<core::io::FrfSetInfo>> frfSets() const;
  core::Result<core::FrfMatrix> frfSet(std::int64_t id) const;
  core::Result<std::vector<core::io::ModalResultInfo>> modalResults() const;

 signals:
  void changed();

 private:
  std::optional<core::io::ProjectStore> store_;
};

}  // namespace app
}  // namespace mozzi
