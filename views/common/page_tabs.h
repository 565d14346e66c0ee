#pragma once
// The work area: pages of the registry as tabs, each in a scroll area. A singleton page has one tab
// (raised when opened again); any other page one tab per project item. Tab
// titles are the page's translated title, with the record's name for a page
// opened on an item ("FRF: hammer run 3"), and follow the language. Tabs of
// items close when the project is closed or replaced.

#include <QTabWidget>

#include "views/common/page_registry.h"

namespace mozzi {
namespace views {

class PageTabs : public QTabWidget {
  Q_OBJECT
 public:
  PageTabs(const PageRegistry* registry, ProjectModel* model, JobRunner* jobs, QWidget* parent = nullptr);

  void setLog(std::function<void(const QString&)> log) { log_ = std::move(log); }

  // Opens (or raises) page `pageId` on `item`; nullptr for an unknown page or
  // a page that does not open that item.
  QWidget* openPage(const QString& pageId, const ProjectItem& item = {});
  // Opens the default page of `item` (the first registered that opens it).
  QWidget* openItem(const ProjectItem& item);
  QWidget* findPage(const QString& pageId, const ProjectItem& item = {}) const;
  // Opens every page marked openAtStart.
  void openStartPages();
  // Shows `item` in every open singleton page that opens it and has showItem.
  void followSelection(const ProjectItem& item);

  // The page of tab `index` (each tab holds its page in a scroll area, so use
  // these rather than QTabWidget::widget()/currentWidget()).
  QWidget* page(int index) const;
  QWidget* currentPage() const;
  int indexOfPage(const QWidget* page) const;  // -1 if not open
  void setCurrentPage(QWidget* page);

  const PageSpec* specOf(const QWidget* page) const;
  ProjectItem itemOf(const QWidget* page) const;
  // Sets every tab's title again (after a language change or a rename).
  void retitle();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  PageContext context(const ProjectItem& item);
  QString tabTitle(const PageSpec& spec, const ProjectItem& item) const;
  void closeItemPages();

  const PageRegistry* registry_ = nullptr;
  ProjectModel* model_ = nullptr;
  JobRunner* jobs_ = nullptr;
  std::function<void(const QString&)> log_;
};

}  // namespace views
}  // namespace mozzi
