#pragma once
// Overview of an open project: file, schema, creation, specimens and the
// amount of data of each kind. Shows what core's ProjectSummary says.

#include <QWidget>

#include "core/io/project_store.h"

class QLabel;
class QTableWidget;

namespace mozzi {
namespace views {

class ProjectModel;

class ProjectOverview : public QWidget {
  Q_OBJECT
 public:
  explicit ProjectOverview(QWidget* parent = nullptr);

  // Shows the model's open project and follows its changes.
  void setModel(ProjectModel* model);
  void refresh();

  void showSummary(const QString& path, const core::io::ProjectSummary& summary, bool readOnly,
                   const QString& readOnlyReason);
  void clear();
  int specimenRows() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  QLabel* title_ = nullptr;
  QLabel* details_ = nullptr;
  QTableWidget* specimens_ = nullptr;
  QString path_;
  core::io::ProjectSummary summary_;
  bool readOnly_ = false;
  QString readOnlyReason_;
  bool hasProject_ = false;
  ProjectModel* model_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
