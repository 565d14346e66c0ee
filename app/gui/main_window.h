#pragma once
// Mozzi's main window, a frame (WORKBENCH.md): menus, the project tree,
// properties and log docks, the work area of page tabs, the running jobs in the
// status bar, settings. It owns the one ProjectModel and JobRunner and knows
// pages only through the page registry (app/gui/builtin_pages.cpp).

#include <QMainWindow>
#include <QMessageBox>
#include <QPointer>
#include <QStringList>

#include "core/report/report_template.h"
#include "views/common/page_registry.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QMenu;
class QPlainTextEdit;
class QTableWidget;
class QTranslator;

namespace mozzi {
namespace core {
struct Error;
}  // namespace core
namespace views {
class JobRunner;
class JobStatusWidget;
class PageTabs;
class ProjectModel;
class ProjectTree;
}  // namespace views
}  // namespace mozzi

namespace mozzi {
namespace app {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // What the menu actions do once a file name is known; the GUI tests call
  // these directly. Each returns false and shows a message when it fails.
  bool openProject(const QString& path);
  bool newProject(const QString& path);
  bool createDemoProject(const QString& path);
  bool saveProjectAs(const QString& path);
  bool exportWorkAreaImage(const QString& path);
  // Writes the open project's report as PDF (File > Export > Report): runs
  // the renderer mozzi-report, the program behind `mozzi-cli report`, in the
  // background. False when no project is open or the renderer cannot start;
  // reportExported() says how it ended.
  bool exportReport(const QString& pdfPath);
  // The report the Report dialog chose: PDF and/or HTML (an empty path: not
  // that one) with the template's sections, specimen and language.
  bool writeReport(const QString& pdfPath, const QString& htmlDir, const core::report::ReportTemplate& t);
  // Imports a UFF file into the selected specimen (a new specimen named after
  // the file when the project has none), then shows what it brought.
  bool importUff(const QString& path);

  // Opens (or raises) a registered page, on an item or from a menu; nullptr
  // when the page is unknown, does not open the item, or could not be built.
  QWidget* openPage(const QString& pageId, const views::ProjectItem& item = {});
  // Opens an item in its default page (as a double-click in the tree does).
  QWidget* openItem(const views::ProjectItem& item);
  // Selects the item's row in the project tree; false if it has none.
  bool selectItem(const views::ProjectItem& item);

  // Switches the interface language ("en", "it"); returns false if unknown.
  bool setLanguage(const QString& code);
  QString language() const { return language_; }

  QStringList recentFiles() const { return recentFiles_; }
  views::ProjectModel* model() const { return model_; }
  views::JobRunner* jobs() const { return jobs_; }
  const views::PageRegistry& pages() const { return pages_; }
  views::PageTabs* workArea() const { return tabs_; }
  views::ProjectTree* projectTree() const { return projectTree_; }
  QString aboutText() const;
  // The message box showing the last error, while it is open.
  QMessageBox* errorBox() const { return errorBox_; }
  void log(const QString& line);

  static QStringList availableLanguages();  // codes with an embedded .qm

 signals:
  // A report started by exportReport() is written (ok) or failed; `message`
  // is the line written to the log.
  void reportExported(bool ok, const QString& message);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void createActions();
  void createMenus();
  void createDocks();
  void applyDefaultDockSizes();
  void retranslateUi();
  void onProjectChanged();
  void showProperties();
  void showTreeMenu(const QPoint& pos);
  void updateRecentMenu();
  void addRecentFile(const QString& path);
  void showError(const QString& title, const QString& action, const core::Error& error);
  QString projectFolder() const;
  QString askProjectFile(const QString& title, const QString& suggested, bool save);

  void onCheckIntegrity();
  void onAbout();

  views::PageRegistry pages_;
  views::ProjectModel* model_ = nullptr;
  views::JobRunner* jobs_ = nullptr;
  views::PageTabs* tabs_ = nullptr;
  views::ProjectTree* projectTree_ = nullptr;
  views::JobStatusWidget* jobStatus_ = nullptr;

  QDockWidget* projectDock_ = nullptr;
  QDockWidget* propertiesDock_ = nullptr;
  QDockWidget* logDock_ = nullptr;
  QTableWidget* properties_ = nullptr;
  QPlainTextEdit* log_ = nullptr;

  QMenu* fileMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* importMenu_ = nullptr;
  QMenu* exportMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* pagesMenu_ = nullptr;
  QMenu* languageMenu_ = nullptr;
  QMenu* toolsMenu_ = nullptr;
  QMenu* helpMenu_ = nullptr;

  QAction* newAction_ = nullptr;
  QAction* openAction_ = nullptr;
  QAction* saveAsAction_ = nullptr;
  QAction* closeProjectAction_ = nullptr;
  QAction* exportImageAction_ = nullptr;
  QAction* exportReportAction_ = nullptr;
  bool startReport(const QString& what, const QStringList& arguments);
  QAction* importUffAction_ = nullptr;
  QAction* quitAction_ = nullptr;
  QAction* clearRecentAction_ = nullptr;
  QAction* resetLayoutAction_ = nullptr;
  QAction* demoAction_ = nullptr;
  QAction* integrityAction_ = nullptr;
  QAction* aboutAction_ = nullptr;
  QAction* aboutQtAction_ = nullptr;
  QActionGroup* languageGroup_ = nullptr;
  // One action per page of the registry that has a menu (text set in retranslateUi).
  QList<QPair<QAction*, const views::PageSpec*>> pageActions_;

  QStringList recentFiles_;
  QString language_;
  QTranslator* translator_ = nullptr;
  QByteArray defaultState_;
  QPointer<QMessageBox> errorBox_;
};

}  // namespace app
}  // namespace mozzi
