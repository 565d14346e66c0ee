#pragma once
// Overview of an open project, the page a newcomer sees first: file, schema,
// creation; a start list of every page of the workbench grouped by the job it
// serves (WORKBENCH.md's three jobs), each with the record of this project it
// opens on, opened with a double-click; and the specimens with what each holds
// (mesh nodes, campaigns, FRF sets, modal results, rig and tyre tests,
// analyses). Shows what core's ProjectSummary and projectContents() say.

#include <QWidget>
#include <functional>
#include <vector>

#include "core/io/project_contents.h"
#include "core/io/project_store.h"
#include "views/common/page_registry.h"

class QLabel;
class QPushButton;
class QTableWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace mozzi {
namespace views {

class ProjectModel;

class ProjectOverview : public QWidget {
  Q_OBJECT
 public:
  explicit ProjectOverview(QWidget* parent = nullptr);

  // Shows the model's open project and follows its changes.
  void setModel(ProjectModel* model);
  // The pages the start list offers and how to open one (PageContext's
  // registry and openPage); without them the start list stays empty.
  void setPages(const PageRegistry* registry,
                std::function<QWidget*(const QString& pageId, const ProjectItem& item)> openPage);
  void refresh();

  void showSummary(const QString& path, const core::io::ProjectSummary& summary, bool readOnly,
                   const QString& readOnlyReason);
  // The data columns of the specimens table (matched to rows by specimen id).
  void showContents(const std::vector<core::io::SpecimenContents>& contents);
  void clear();
  int specimenRows() const;

  // One row of the start list: a page and the record it opens on.
  struct StartEntry {
    QString pageId;
    ProjectItem item;        // kind None: opened without a record
    bool available = false;  // false: the project holds nothing the page opens
  };
  const std::vector<StartEntry>& startEntries() const { return entries_; }
  // Opens entry `index` of startEntries() as a double-click does; the page or nullptr.
  QWidget* openStartEntry(int index);

 protected:
  void changeEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void retranslate();
  void buildStartEntries();
  void fillStartList();
  void fillSpecimenTable();
  void openCurrentStartItem();
  QString whereText(const StartEntry& entry) const;

  QLabel* title_ = nullptr;
  QLabel* details_ = nullptr;
  QLabel* startHeading_ = nullptr;
  QTreeWidget* start_ = nullptr;
  QPushButton* open_ = nullptr;
  QLabel* reportHint_ = nullptr;
  QLabel* specimensHeading_ = nullptr;
  QTableWidget* specimens_ = nullptr;
  QString path_;
  core::io::ProjectSummary summary_;
  std::vector<core::io::SpecimenContents> contents_;
  bool readOnly_ = false;
  QString readOnlyReason_;
  bool hasProject_ = false;
  bool stale_ = false;  // records changed since the last refresh
  ProjectModel* model_ = nullptr;
  const PageRegistry* registry_ = nullptr;
  std::function<QWidget*(const QString&, const ProjectItem&)> openPage_;
  std::vector<StartEntry> entries_;
};

}  // namespace views
}  // namespace mozzi
