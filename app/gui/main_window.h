#pragma once
// Mozzi's main window: project tree, properties and log docks around a tabbed
// work area; File, View, Tools and Help menus. Layout, language and recent
// files persist in QSettings.

#include <QMainWindow>
#include <QMessageBox>
#include <QPointer>
#include <QStringList>
#include <cstdint>

class QAction;
class QActionGroup;
class QDockWidget;
class QMenu;

class QPlainTextEdit;
class QTabWidget;
class QTableWidget;
class QTranslator;
class QTreeWidget;
class QTreeWidgetItem;

namespace mozzi {
namespace core {
struct Error;
}  // namespace core
namespace views {
class ModelTestView;
class ProjectOverview;
class SceneView;
}  // namespace views
}  // namespace mozzi

namespace mozzi {
namespace app {

class ProjectDocument;

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
  // Imports a UFF file into the selected specimen (a new specimen named after
  // the file when the project has none).
  bool importUff(const QString& path);
  // Selects a specimen in the tree: its mesh goes to the 3-D view.
  bool selectSpecimen(std::int64_t specimenId);
  // Opens (or raises) a tab plotting a stored FRF set.
  bool openFrfSet(std::int64_t frfSetId);
  std::int64_t currentSpecimen() const { return currentSpecimen_; }
  // Opens (or raises) the "Model vs test" gap-diagnosis tab.
  views::ModelTestView* openModelTest();

  // Switches the interface language ("en", "it"); returns false if unknown.
  bool setLanguage(const QString& code);
  QString language() const { return language_; }

  QStringList recentFiles() const { return recentFiles_; }
  ProjectDocument* document() const { return document_; }
  QTabWidget* workArea() const { return tabs_; }
  QString aboutText() const;
  // The message box showing the last error, while it is open.
  QMessageBox* errorBox() const { return errorBox_; }
  void log(const QString& line);

  static QStringList availableLanguages();  // codes with an embedded .qm

 protected:
  void closeEvent(QCloseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void createActions();
  void createMenus();
  void createDocks();
  void retranslateUi();
  void refreshFromDocument();
  void updateRecentMenu();
  void addRecentFile(const QString& path);
  void showError(const QString& title, const QString& action, const core::Error& error);
  void showProperties(QTreeWidgetItem* item);
  QString projectFolder() const;

  void onNew();
  void onOpen();
  void onSaveAs();
  void onExportImage();
  void onImportUff();
  void showSpecimenMesh(std::int64_t specimenId);
  void onCreateDemo();
  void onCheckIntegrity();
  void onAbout();

  ProjectDocument* document_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  views::ProjectOverview* overview_ = nullptr;
  views::SceneView* scene_ = nullptr;
  QPointer<views::ModelTestView> modelTest_;

  QDockWidget* projectDock_ = nullptr;
  QDockWidget* propertiesDock_ = nullptr;
  QDockWidget* logDock_ = nullptr;
  QTreeWidget* projectTree_ = nullptr;
  QTableWidget* properties_ = nullptr;
  QPlainTextEdit* log_ = nullptr;

  QMenu* fileMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* importMenu_ = nullptr;
  QMenu* exportMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* languageMenu_ = nullptr;
  QMenu* toolsMenu_ = nullptr;
  QMenu* helpMenu_ = nullptr;

  QAction* newAction_ = nullptr;
  QAction* openAction_ = nullptr;
  QAction* saveAsAction_ = nullptr;
  QAction* closeProjectAction_ = nullptr;
  QAction* exportImageAction_ = nullptr;
  QAction* importUffAction_ = nullptr;
  QAction* quitAction_ = nullptr;
  QAction* clearRecentAction_ = nullptr;
  QAction* resetLayoutAction_ = nullptr;
  QAction* demoAction_ = nullptr;
  QAction* integrityAction_ = nullptr;
  QAction* modelTestAction_ = nullptr;
  QAction* aboutAction_ = nullptr;
  QAction* aboutQtAction_ = nullptr;
  QActionGroup* languageGroup_ = nullptr;

  QStringList recentFiles_;
  QString language_;
  QTranslator* translator_ = nullptr;
  QByteArray defaultState_;
  QPointer<QMessageBox> errorBox_;
  std::int64_t currentSpecimen_ = 0;
};

}  // namespace app
}  // namespace mozzi
