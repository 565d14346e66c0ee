#pragma once
// The project open in the main window: owns the core ProjectStore and tells the
// views when it changes. Errors come back as core::Error for the window to show.

#include <QObject>
#include <QString>
#include <optional>

#include "core/common/result.h"
#include "core/io/project_store.h"

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

 signals:
  void changed();

 private:
  std::optional<core::io::ProjectStore> store_;
};

}  // namespace app
}  // namespace mozzi
