#pragma once
// The project dock's tree over the ProjectModel: the project, its specimens
// (with their campaigns), FRF sets, modal results and a count of every data
// table. Each row carries the ProjectItem it stands for; the window opens
// pages on it through the page registry. Rebuilt when the model changes, the
// selection kept.

#include <QList>
#include <QPair>
#include <QTreeWidget>

#include "views/common/page_registry.h"

namespace mozzi {
namespace views {

class ProjectTree : public QTreeWidget {
  Q_OBJECT
 public:
  explicit ProjectTree(ProjectModel* model, QWidget* parent = nullptr);

  static ProjectItem itemOf(const QTreeWidgetItem* row);
  ProjectItem currentProjectItem() const { return itemOf(currentItem()); }
  // Selects the row of `item`; false when the tree has none.
  bool selectItem(const ProjectItem& item);
  // Property/value rows describing the current row (the properties dock).
  QList<QPair<QString, QString>> currentProperties() const;
  void refresh();
  // Wide enough for a specimen's name (the dock takes its width from this).
  QSize sizeHint() const override;
  // The lines the first column draws for `row` at the present width: its
  // name wrapped at spaces, a word wider than the column cut in the middle.
  QStringList shownLines(const QTreeWidgetItem* row) const;

 signals:
  void currentProjectItemChanged(const mozzi::views::ProjectItem& item);
  // Double-click or Enter on a row.
  void openRequested(const mozzi::views::ProjectItem& item);
  // The rows (and the properties of the current one) were rebuilt in a new
  // language; the current item is the same.
  void retranslated();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  QTreeWidgetItem* addRow(QTreeWidgetItem* parent, const QStringList& texts, const ProjectItem& item);

  ProjectModel* model_ = nullptr;
  bool rebuilding_ = false;
  bool projectReplaced_ = false;
};

}  // namespace views
}  // namespace mozzi
