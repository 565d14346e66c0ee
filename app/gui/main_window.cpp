#include "app/gui/main_window.h"

#include <qwt_global.h>
#include <vtkVersion.h>
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLibraryInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTranslator>
#include <QTreeWidget>

#include "app/build_info.h"
#include "app/gui/project_document.h"
#include "core/common/versions.h"
#include "core/geometry/mesh_placement.h"
#include "devices/common/versions.h"
#include "views/gap/model_test_view.h"
#include "views/panels/project_overview.h"
#include "views/plots/frf_plot.h"
#include "views/scene/scene_view.h"

// Resources compiled into the static mozzi_app library must be registered by
// hand (the linker drops their unreferenced initialisers). Global scope: the
// macro declares functions that must not live in a namespace.
static void initMozziResources() {
  Q_INIT_RESOURCE(resources);
  Q_INIT_RESOURCE(i18n);
}

namespace mozzi {
namespace app {
namespace {

constexpr int kMaxRecentFiles = 8;
constexpr int kRoleTable = Qt::UserRole + 1;
constexpr int kRoleId = Qt::UserRole + 4;  // row id of a specimen, FRF set or modal result

const char* const kSettingsGeometry = "window/geometry";
const char* const kSettingsState = "window/state";
const char* const kSettingsRecent = "files/recent";
const char* const kSettingsLanguage = "ui/language";
const char* const kSettingsLastFolder = "files/lastFolder";

}  // namespace

QStringList MainWindow::availableLanguages() {
  QStringList codes;
  for (const QString& name : QDir(QStringLiteral(":/i18n")).entryList({QStringLiteral("mozzi_*.qm")})) {
    codes << name.mid(6, name.size() - 9);  // mozzi_<code>.qm
  }
  return codes;
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), document_(new ProjectDocument(this)) {
  initMozziResources();
  setObjectName(QStringLiteral("MozziMainWindow"));
  setWindowIcon(QIcon(QStringLiteral(":/icons/mozzi.svg")));
  translator_ = new QTranslator(this);

  tabs_ = new QTabWidget(this);
  tabs_->setObjectName(QStringLiteral("workArea"));
  tabs_->setDocumentMode(true);
  tabs_->setMovable(true);
  overview_ = new views::ProjectOverview(tabs_);
  overview_->setObjectName(QStringLiteral("overviewTab"));
  scene_ = new views::SceneView(tabs_);
  scene_->setObjectName(QStringLiteral("sceneTab"));
  tabs_->addTab(overview_, QString());
  tabs_->addTab(scene_, QString());
  setCentralWidget(tabs_);

  createActions();
  createMenus();
  createDocks();
  statusBar();
  defaultState_ = saveState();

  QSettings settings;
  recentFiles_ = settings.value(QLatin1String(kSettingsRecent)).toStringList();
  restoreGeometry(settings.value(QLatin1String(kSettingsGeometry)).toByteArray());
  restoreState(settings.value(QLatin1String(kSettingsState)).toByteArray());
  if (!geometry().isValid() || settings.value(QLatin1String(kSettingsGeometry)).isNull()) resize(1280, 800);

  QString lang = settings.value(QLatin1String(kSettingsLanguage)).toString();
  if (lang.isEmpty()) lang = QLocale::system().name().left(2);
  if (!availableLanguages().contains(lang)) lang = QStringLiteral("en");
  if (!setLanguage(lang)) retranslateUi();  // source strings are English

  connect(document_, &ProjectDocument::changed, this, &MainWindow::refreshFromDocument);
  refreshFromDocument();
  updateRecentMenu();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions() {
  newAction_ = new QAction(this);
  newAction_->setShortcut(QKeySequence::New);
  connect(newAction_, &QAction::triggered, this, &MainWindow::onNew);
  openAction_ = new QAction(this);
  openAction_->setShortcut(QKeySequence::Open);
  connect(openAction_, &QAction::triggered, this, &MainWindow::onOpen);
  saveAsAction_ = new QAction(this);
  saveAsAction_->setShortcut(QKeySequence::SaveAs);
  connect(saveAsAction_, &QAction::triggered, this, &MainWindow::onSaveAs);
  closeProjectAction_ = new QAction(this);
  connect(closeProjectAction_, &QAction::triggered, document_, &ProjectDocument::close);
  importUffAction_ = new QAction(this);
  connect(importUffAction_, &QAction::triggered, this, &MainWindow::onImportUff);
  exportImageAction_ = new QAction(this);
  connect(exportImageAction_, &QAction::triggered, this, &MainWindow::onExportImage);
  quitAction_ = new QAction(this);
  quitAction_->setShortcut(QKeySequence::Quit);
  quitAction_->setMenuRole(QAction::QuitRole);
  connect(quitAction_, &QAction::triggered, this, &QWidget::close);
  clearRecentAction_ = new QAction(this);
  connect(clearRecentAction_, &QAction::triggered, this, [this] {
    recentFiles_.clear();
    QSettings().setValue(QLatin1String(kSettingsRecent), recentFiles_);
    updateRecentMenu();
  });
  resetLayoutAction_ = new QAction(this);
  connect(resetLayoutAction_, &QAction::triggered, this, [this] { restoreState(defaultState_); });
  demoAction_ = new QAction(this);
  connect(demoAction_, &QAction::triggered, this, &MainWindow::onCreateDemo);
  integrityAction_ = new QAction(this);
  connect(integrityAction_, &QAction::triggered, this, &MainWindow::onCheckIntegrity);
  modelTestAction_ = new QAction(this);
  connect(modelTestAction_, &QAction::triggered, this, [this] { openModelTest(); });
  aboutAction_ = new QAction(this);
  aboutAction_->setMenuRole(QAction::AboutRole);
  connect(aboutAction_, &QAction::triggered, this, &MainWindow::onAbout);
  aboutQtAction_ = new QAction(this);
  aboutQtAction_->setMenuRole(QAction::AboutQtRole);
  connect(aboutQtAction_, &QAction::triggered, qApp, &QApplication::aboutQt);

  languageGroup_ = new QActionGroup(this);
  languageGroup_->setExclusive(true);
  for (const QString& code : availableLanguages()) {
    auto* action = new QAction(languageGroup_);
    action->setCheckable(true);
    action->setData(code);
    connect(action, &QAction::triggered, this, [this, code] { setLanguage(code); });
  }
}

void MainWindow::createMenus() {
  fileMenu_ = menuBar()->addMenu(QString());
  fileMenu_->addAction(newAction_);
  fileMenu_->addAction(openAction_);
  recentMenu_ = fileMenu_->addMenu(QString());
  fileMenu_->addAction(saveAsAction_);
  fileMenu_->addAction(closeProjectAction_);
  fileMenu_->addSeparator();
  importMenu_ = fileMenu_->addMenu(QString());
  importMenu_->addAction(importUffAction_);
  exportMenu_ = fileMenu_->addMenu(QString());
  exportMenu_->addAction(exportImageAction_);
  fileMenu_->addSeparator();
  fileMenu_->addAction(quitAction_);

  viewMenu_ = menuBar()->addMenu(QString());
  languageMenu_ = new QMenu(this);
  languageMenu_->addActions(languageGroup_->actions());

  toolsMenu_ = menuBar()->addMenu(QString());
  toolsMenu_->addAction(demoAction_);
  toolsMenu_->addAction(integrityAction_);
  toolsMenu_->addSeparator();
  toolsMenu_->addAction(modelTestAction_);

  helpMenu_ = menuBar()->addMenu(QString());
  helpMenu_->addAction(aboutAction_);
  helpMenu_->addAction(aboutQtAction_);
}

void MainWindow::createDocks() {
  projectTree_ = new QTreeWidget(this);
  projectTree_->setObjectName(QStringLiteral("projectTree"));
  projectTree_->setColumnCount(2);
  projectTree_->header()->setStretchLastSection(false);
  projectTree_->header()->setSectionResizeMode(0, QHeaderView::Stretch);
  projectTree_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  connect(projectTree_, &QTreeWidget::currentItemChanged, this,
          [this](QTreeWidgetItem* current) { showProperties(current); });
  // Double-click (or Enter) on an FRF set plots it.
  connect(projectTree_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
    if (item && item->data(0, kRoleTable).toString() == QLatin1String("frf-set")) {
      openFrfSet(item->data(0, kRoleId).toLongLong());
    }
  });
  projectDock_ = new QDockWidget(this);
  projectDock_->setObjectName(QStringLiteral("projectDock"));
  projectDock_->setWidget(projectTree_);
  addDockWidget(Qt::LeftDockWidgetArea, projectDock_);

  properties_ = new QTableWidget(0, 2, this);
  properties_->setObjectName(QStringLiteral("propertiesTable"));
  properties_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  properties_->horizontalHeader()->setStretchLastSection(true);
  properties_->verticalHeader()->setVisible(false);
  propertiesDock_ = new QDockWidget(this);
  propertiesDock_->setObjectName(QStringLiteral("propertiesDock"));
  propertiesDock_->setWidget(properties_);
  addDockWidget(Qt::LeftDockWidgetArea, propertiesDock_);

  log_ = new QPlainTextEdit(this);
  log_->setObjectName(QStringLiteral("logView"));
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(5000);
  logDock_ = new QDockWidget(this);
  logDock_->setObjectName(QStringLiteral("logDock"));
  logDock_->setWidget(log_);
  addDockWidget(Qt::BottomDockWidgetArea, logDock_);

  viewMenu_->addAction(projectDock_->toggleViewAction());
  viewMenu_->addAction(propertiesDock_->toggleViewAction());
  viewMenu_->addAction(logDock_->toggleViewAction());
  viewMenu_->addSeparator();
  viewMenu_->addAction(resetLayoutAction_);
  viewMenu_->addMenu(languageMenu_);
}

void MainWindow::retranslateUi() {
  fileMenu_->setTitle(tr("&File"));
  newAction_->setText(tr("&New Project..."));
  openAction_->setText(tr("&Open Project..."));
  recentMenu_->setTitle(tr("Open &Recent"));
  clearRecentAction_->setText(tr("Clear List"));
  saveAsAction_->setText(tr("Save Project &As..."));
  closeProjectAction_->setText(tr("&Close Project"));
  importMenu_->setTitle(tr("&Import"));
  exportMenu_->setTitle(tr("&Export"));
  exportImageAction_->setText(tr("Work Area as &Image..."));
  importUffAction_->setText(tr("&Universal File (UFF)..."));
  quitAction_->setText(tr("&Quit"));
  viewMenu_->setTitle(tr("&View"));
  projectDock_->setWindowTitle(tr("Project"));
  propertiesDock_->setWindowTitle(tr("Properties"));
  logDock_->setWindowTitle(tr("Log"));
  resetLayoutAction_->setText(tr("&Reset Layout"));
  languageMenu_->setTitle(tr("&Language"));
  for (QAction* action : languageGroup_->actions()) {
    const QString code = action->data().toString();
    // Each language is named in itself so a user can find theirs.
    action->setText(code == QLatin1String("it")   ? QStringLiteral("Italiano")
                    : code == QLatin1String("en") ? QStringLiteral("English")
                                                  : code);
    action->setChecked(code == language_);
  }
  toolsMenu_->setTitle(tr("&Tools"));
  demoAction_->setText(tr("Create &Demo Project..."));
  integrityAction_->setText(tr("Check Project &Integrity"));
  modelTestAction_->setText(tr("&Model vs Test..."));
  modelTestAction_->setStatusTip(
      tr("Diagnose where a model and a test disagree and which unmodelled effect explains it"));
  if (modelTest_) tabs_->setTabText(tabs_->indexOf(modelTest_), tr("Model vs Test"));
  helpMenu_->setTitle(tr("&Help"));
  aboutAction_->setText(tr("&About Mozzi"));
  aboutQtAction_->setText(tr("About &Qt"));
  tabs_->setTabText(tabs_->indexOf(overview_), tr("Overview"));
  tabs_->setTabText(tabs_->indexOf(scene_), tr("3-D View"));
  projectTree_->setHeaderLabels({tr("Item"), tr("Count")});
  properties_->setHorizontalHeaderLabels({tr("Property"), tr("Value")});
  updateRecentMenu();
  refreshFromDocument();
}

bool MainWindow::setLanguage(const QString& code) {
  if (!availableLanguages().contains(code)) return false;
  qApp->removeTranslator(translator_);
  if (!translator_->load(QStringLiteral(":/i18n/mozzi_%1.qm").arg(code))) return false;
  qApp->installTranslator(translator_);  // sends LanguageChange to every widget
  language_ = code;
  QSettings().setValue(QLatin1String(kSettingsLanguage), code);
  retranslateUi();
  return true;
}

void MainWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange && fileMenu_) retranslateUi();
  QMainWindow::changeEvent(event);
}

void MainWindow::refreshFromDocument() {
  projectTree_->clear();
  properties_->setRowCount(0);
  const bool open = document_->isOpen();
  saveAsAction_->setEnabled(open);
  importUffAction_->setEnabled(open && !document_->isReadOnly());
  closeProjectAction_->setEnabled(open);
  integrityAction_->setEnabled(open);
  if (!open) {
    overview_->clear();
    setWindowTitle(tr("Mozzi"));
    return;
  }
  const QString path = document_->path();
  setWindowTitle(tr("%1 - Mozzi").arg(QFileInfo(path).fileName()) +
                 (document_->isReadOnly() ? tr(" [read-only]") : QString()));
  auto summary = document_->summary();
  if (!summary) {
    showError(tr("Project"), tr("Could not read the project."), summary.error());
    return;
  }
  overview_->showSummary(path, *summary, document_->isReadOnly(), document_->readOnlyReason());

  auto* root = new QTreeWidgetItem(projectTree_, {QFileInfo(path).completeBaseName()});
  root->setData(0, kRoleTable, QStringLiteral("project"));
  auto* specimens = new QTreeWidgetItem(root, {tr("Specimens"), QString::number(summary->specimens.size())});
  specimens->setData(0, kRoleTable, QStringLiteral("specimen"));
  QTreeWidgetItem* selected = root;
  for (const auto& sp : summary->specimens) {
    auto* item = new QTreeWidgetItem(specimens, {QString::fromStdString(sp.name)});
    item->setData(0, kRoleTable, QStringLiteral("specimen-row"));
    item->setData(0, Qt::UserRole + 2, QString::fromStdString(sp.kind));
    item->setData(0, Qt::UserRole + 3, QString::fromStdString(sp.description));
    item->setData(0, kRoleId, QVariant::fromValue<qlonglong>(sp.id));
    if (sp.id == currentSpecimen_) selected = item;
  }
  if (auto sets = document_->frfSets(); sets && !sets->empty()) {
    auto* group = new QTreeWidgetItem(root, {tr("FRF sets"), QString::number(sets->size())});
    for (const auto& set : *sets) {
      auto* item = new QTreeWidgetItem(
          group, {QString::fromStdString(set.name), QString::number(set.responseCount * set.referenceCount)});
      item->setData(0, kRoleTable, QStringLiteral("frf-set"));
      item->setData(0, kRoleId, QVariant::fromValue<qlonglong>(set.id));
      item->setData(0, Qt::UserRole + 2, QString::fromStdString(set.source));
      item->setData(0, Qt::UserRole + 3, QStringLiteral("%1|%2").arg(set.lineCount).arg(static_cast<int>(set.type)));
    }
    projectTree_->expandItem(group);
  }
  if (auto results = document_->modalResults(); results && !results->empty()) {
    auto* group = new QTreeWidgetItem(root, {tr("Modal results"), QString::number(results->size())});
    for (const auto& result : *results) {
      auto* item = new QTreeWidgetItem(group, {QString::fromStdString(result.name), QString::number(result.modeCount)});
      item->setData(0, kRoleTable, QStringLiteral("modal-result"));
      item->setData(0, kRoleId, QVariant::fromValue<qlonglong>(result.id));
      item->setData(0, Qt::UserRole + 2, QString::fromStdString(result.method));
      item->setData(0, Qt::UserRole + 3,
                    QStringLiteral("%1 - %2 Hz").arg(result.bandLowHz, 0, 'f', 1).arg(result.bandHighHz, 0, 'f', 1));
    }
    projectTree_->expandItem(group);
  }
  auto* data = new QTreeWidgetItem(root, {tr("Data")});
  for (const auto& count : summary->counts) {
    if (count.table == "specimen") continue;
    auto* item = new QTreeWidgetItem(data, {QString::fromStdString(count.table), QString::number(count.rows)});
    item->setData(0, kRoleTable, QString::fromStdString(count.table));
  }
  projectTree_->expandItem(root);
  projectTree_->expandItem(specimens);
  projectTree_->setCurrentItem(selected);
}

void MainWindow::showProperties(QTreeWidgetItem* item) {
  properties_->setRowCount(0);
  if (!item) return;
  QList<QPair<QString, QString>> rows;
  const QString role = item->data(0, kRoleTable).toString();
  if (role == QLatin1String("project")) {
    rows << qMakePair(tr("File"), QDir::toNativeSeparators(document_->path()));
    rows << qMakePair(tr("Access"), document_->isReadOnly() ? tr("read-only: %1").arg(document_->readOnlyReason())
                                                            : tr("read-write"));
  } else if (role == QLatin1String("specimen-row")) {
    rows << qMakePair(tr("Name"), item->text(0));
    rows << qMakePair(tr("Kind"), item->data(0, Qt::UserRole + 2).toString());
    rows << qMakePair(tr("Description"), item->data(0, Qt::UserRole + 3).toString());
    showSpecimenMesh(item->data(0, kRoleId).toLongLong());
    rows << qMakePair(tr("Mesh"), tr("%1 nodes, %2 lines").arg(scene_->meshPointCount()).arg(scene_->meshLineCount()));
  } else if (role == QLatin1String("frf-set")) {
    const QStringList detail = item->data(0, Qt::UserRole + 3).toString().split(QLatin1Char('|'));
    rows << qMakePair(tr("Name"), item->text(0));
    rows << qMakePair(tr("Source"), item->data(0, Qt::UserRole + 2).toString());
    rows << qMakePair(tr("Frequency lines"), detail.value(0));
    rows << qMakePair(tr("Response/reference pairs"), item->text(1));
  } else if (role == QLatin1String("modal-result")) {
    rows << qMakePair(tr("Name"), item->text(0));
    rows << qMakePair(tr("Method"), item->data(0, Qt::UserRole + 2).toString());
    rows << qMakePair(tr("Band"), item->data(0, Qt::UserRole + 3).toString());
    rows << qMakePair(tr("Modes"), item->text(1));
  } else {
    rows << qMakePair(tr("Item"), item->text(0));
    if (!item->text(1).isEmpty()) rows << qMakePair(tr("Count"), item->text(1));
  }
  properties_->setRowCount(rows.size());
  for (int r = 0; r < rows.size(); ++r) {
    properties_->setItem(r, 0, new QTableWidgetItem(rows[r].first));
    properties_->setItem(r, 1, new QTableWidgetItem(rows[r].second));
  }
}

void MainWindow::log(const QString& line) {
  log_->appendPlainText(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss  ")) + line);
}

void MainWindow::showError(const QString& title, const QString& action, const core::Error& error) {
  // Non-blocking: the window stays usable and tests can read and close the box.
  if (errorBox_) errorBox_->close();
  errorBox_ = new QMessageBox(QMessageBox::Warning, title, action, QMessageBox::Ok, this);
  errorBox_->setAttribute(Qt::WA_DeleteOnClose);
  errorBox_->setObjectName(QStringLiteral("errorBox"));
  QString detail = QString::fromStdString(error.message);
  if (!error.where.empty()) detail += QLatin1Char('\n') + tr("Where: %1").arg(QString::fromStdString(error.where));
  errorBox_->setInformativeText(detail);
  errorBox_->open();
  log(action + QLatin1Char(' ') + QString::fromStdString(error.describe()));
}

void MainWindow::addRecentFile(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  recentFiles_.removeAll(absolute);
  recentFiles_.prepend(absolute);
  while (recentFiles_.size() > kMaxRecentFiles) recentFiles_.removeLast();
  QSettings settings;
  settings.setValue(QLatin1String(kSettingsRecent), recentFiles_);
  settings.setValue(QLatin1String(kSettingsLastFolder), QFileInfo(absolute).absolutePath());
  updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
  if (!recentMenu_) return;
  recentMenu_->clear();
  for (const QString& file : recentFiles_) {
    QAction* action = recentMenu_->addAction(QFileInfo(file).fileName());
    action->setToolTip(file);
    action->setData(file);
    connect(action, &QAction::triggered, this, [this, file] { openProject(file); });
  }
  if (!recentFiles_.isEmpty()) recentMenu_->addSeparator();
  recentMenu_->addAction(clearRecentAction_);
  clearRecentAction_->setEnabled(!recentFiles_.isEmpty());
}

QString MainWindow::projectFolder() const {
  const QString last = QSettings().value(QLatin1String(kSettingsLastFolder)).toString();
  return last.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) : last;
}

bool MainWindow::openProject(const QString& path) {
  if (auto r = document_->open(path); !r) {
    showError(tr("Open Project"), tr("Could not open %1.").arg(QDir::toNativeSeparators(path)), r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Opened %1").arg(QDir::toNativeSeparators(path)));
  if (document_->isReadOnly()) log(tr("Read-only: %1").arg(document_->readOnlyReason()));
  return true;
}

bool MainWindow::newProject(const QString& path) {
  if (auto r = document_->create(path); !r) {
    showError(tr("New Project"), tr("Could not create %1.").arg(QDir::toNativeSeparators(path)), r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Created %1").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::createDemoProject(const QString& path) {
  if (auto r = document_->createDemo(path); !r) {
    showError(tr("Demo Project"), tr("Could not create the demo project %1.").arg(QDir::toNativeSeparators(path)),
              r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Created demo project %1").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::saveProjectAs(const QString& path) {
  if (auto r = document_->saveAs(path); !r) {
    showError(tr("Save Project As"), tr("Could not save the project as %1.").arg(QDir::toNativeSeparators(path)),
              r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Saved a copy as %1 and opened it").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::exportWorkAreaImage(const QString& path) {
  const QPixmap image = tabs_->currentWidget() ? tabs_->currentWidget()->grab() : tabs_->grab();
  if (!image.save(path)) {
    showError(tr("Export Image"), tr("Could not write %1.").arg(QDir::toNativeSeparators(path)),
              core::makeError(core::ErrorCode::IoError, "the image could not be written (folder or format)",
                              path.toStdString()));
    return false;
  }
  log(tr("Exported the work area to %1").arg(QDir::toNativeSeparators(path)));
  return true;
}

void MainWindow::showSpecimenMesh(std::int64_t specimenId) {
  currentSpecimen_ = specimenId;
  auto mesh = document_->mesh(specimenId);
  if (!mesh) {
    scene_->clearMesh();
    log(tr("Cannot show the mesh: %1").arg(QString::fromStdString(mesh.error().describe())));
    return;
  }
  auto positions = core::geometry::globalNodePositions(*mesh);
  if (!positions) {
    scene_->clearMesh();
    log(tr("Cannot place the mesh: %1").arg(QString::fromStdString(positions.error().describe())));
    return;
  }
  scene_->showMesh(*mesh, *positions);
  if (scene_->skippedLineCount() > 0) {
    log(tr("%n trace line segment(s) name nodes the mesh does not have and are not drawn", nullptr,
           scene_->skippedLineCount()));
  }
}

bool MainWindow::selectSpecimen(std::int64_t specimenId) {
  for (QTreeWidgetItem* item : projectTree_->findItems(QStringLiteral("*"), Qt::MatchWildcard | Qt::MatchRecursive)) {
    if (item->data(0, kRoleTable).toString() == QLatin1String("specimen-row") &&
        item->data(0, kRoleId).toLongLong() == specimenId) {
      projectTree_->setCurrentItem(item);
      return true;
    }
  }
  return false;
}

bool MainWindow::openFrfSet(std::int64_t frfSetId) {
  const QString key = QStringLiteral("frf-%1").arg(frfSetId);
  for (int i = 0; i < tabs_->count(); ++i) {
    if (tabs_->widget(i)->property("mozziKey").toString() == key) {
      tabs_->setCurrentIndex(i);
      return true;
    }
  }
  auto frf = document_->frfSet(frfSetId);
  if (!frf) {
    showError(tr("FRF Set"), tr("Could not read the FRF set."), frf.error());
    return false;
  }
  QString name = QString::number(frfSetId);
  if (auto sets = document_->frfSets()) {
    for (const auto& set : *sets) {
      if (set.id == frfSetId) name = QString::fromStdString(set.name);
    }
  }
  auto* plot = new views::FrfPlot(tabs_);
  plot->setProperty("mozziKey", key);
  plot->setFrfs(std::make_shared<const core::FrfMatrix>(std::move(frf).value()));
  tabs_->setCurrentIndex(tabs_->addTab(plot, tr("FRF: %1").arg(name)));
  return true;
}

views::ModelTestView* MainWindow::openModelTest() {
  if (!modelTest_) {
    modelTest_ = new views::ModelTestView(tabs_);
    modelTest_->setObjectName(QStringLiteral("modelTestTab"));
    tabs_->addTab(modelTest_, tr("Model vs Test"));
    connect(modelTest_, &views::ModelTestView::finished, this, [this](bool ok) {
      log(ok ? tr("Model vs test: %1").arg(modelTest_->verdictText())
             : tr("Model vs test: %1").arg(modelTest_->statusText()));
    });
  }
  tabs_->setCurrentWidget(modelTest_);
  return modelTest_;
}

bool MainWindow::importUff(const QString& path) {
  if (!document_->isOpen()) return false;
  std::int64_t specimen = currentSpecimen_;
  auto summary = document_->summary();
  if (!summary) {
    showError(tr("Import"), tr("Could not read the project."), summary.error());
    return false;
  }
  bool known = false;
  for (const auto& sp : summary->specimens) known = known || sp.id == specimen;
  if (!known) specimen = summary->specimens.empty() ? 0 : summary->specimens.front().id;
  if (specimen == 0) {
    auto id = document_->addSpecimen(QFileInfo(path).completeBaseName(), QStringLiteral("imported"));
    if (!id) {
      showError(tr("Import"), tr("Could not add a specimen for %1.").arg(QDir::toNativeSeparators(path)), id.error());
      return false;
    }
    specimen = *id;
  }
  auto report = document_->importUff(path, specimen);
  if (!report) {
    showError(tr("Import"), tr("Could not import %1; the project is unchanged.").arg(QDir::toNativeSeparators(path)),
              report.error());
    return false;
  }
  currentSpecimen_ = specimen;
  refreshFromDocument();
  log(tr("Imported %1: %2 nodes, %3 lines, %4 FRFs, %5 modes")
          .arg(QDir::toNativeSeparators(path))
          .arg(report->nodes)
          .arg(report->lines)
          .arg(report->frfPairs)
          .arg(report->modes));
  for (const auto& note : report->notes) log(QStringLiteral("  ") + QString::fromStdString(note));
  if (report->frfSetId)
    openFrfSet(*report->frfSetId);
  else if (report->nodes > 0)
    tabs_->setCurrentWidget(scene_);
  return true;
}

void MainWindow::onImportUff() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Import Universal File"), projectFolder(),
                                                    tr("Universal files (*.uff *.unv);;All files (*)"));
  if (!path.isEmpty()) importUff(path);
}

void MainWindow::onNew() {
  const QString path =
      QFileDialog::getSaveFileName(this, tr("New Project"), projectFolder(), tr("Mozzi projects (*.mozzi)"));
  if (path.isEmpty()) return;
  newProject(path.endsWith(QLatin1String(".mozzi")) ? path : path + QStringLiteral(".mozzi"));
}

void MainWindow::onOpen() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open Project"), projectFolder(),
                                                    tr("Mozzi projects (*.mozzi);;All files (*)"));
  if (!path.isEmpty()) openProject(path);
}

void MainWindow::onSaveAs() {
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Save Project As"), projectFolder(), tr("Mozzi projects (*.mozzi)"));
  if (path.isEmpty()) return;
  saveProjectAs(path.endsWith(QLatin1String(".mozzi")) ? path : path + QStringLiteral(".mozzi"));
}

void MainWindow::onExportImage() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Export Work Area"), projectFolder(),
                                                    tr("PNG images (*.png);;JPEG images (*.jpg)"));
  if (!path.isEmpty()) exportWorkAreaImage(path);
}

void MainWindow::onCreateDemo() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Create Demo Project"),
                                                    QDir(projectFolder()).filePath(QStringLiteral("demo.mozzi")),
                                                    tr("Mozzi projects (*.mozzi)"));
  if (path.isEmpty()) return;
  createDemoProject(path.endsWith(QLatin1String(".mozzi")) ? path : path + QStringLiteral(".mozzi"));
}

void MainWindow::onCheckIntegrity() {
  if (!document_->isOpen()) return;
  // Re-opening read-only runs the same checks as opening (SQLite quick_check,
  // application id, schema version) without disturbing the open session.
  auto check =
      core::io::ProjectStore::open(document_->path().toStdString(), core::io::ProjectStore::OpenMode::ReadOnly);
  if (!check) {
    showError(tr("Check Project Integrity"), tr("The project failed its integrity check."), check.error());
    return;
  }
  log(tr("Integrity check passed: %1").arg(QDir::toNativeSeparators(document_->path())));
  statusBar()->showMessage(tr("Integrity check passed"), 5000);
}

QString MainWindow::aboutText() const {
  QString text = tr("<h3>Mozzi %1</h3><p>Structural dynamics workbench for two-wheeled-vehicle components: "
                    "impact-hammer campaigns, stiffness rigs, tyre tests, modal and twist-axis "
                    "identification, stability models.</p><p>Linked libraries:</p><ul>")
                     .arg(QString::fromLatin1(buildinfo::kMozziVersion));
  auto item = [](const QString& name, const QString& version) {
    return QStringLiteral("<li>%1 %2</li>").arg(name, version.toHtmlEscaped());
  };
  text += item(QStringLiteral("Qt"), QString::fromLatin1(qVersion()));
  text += item(QStringLiteral("Qwt"), QStringLiteral(QWT_VERSION_STR));
  text += item(QStringLiteral("VTK"), QString::fromLatin1(vtkVersion::GetVTKVersion()));
  for (const auto& [name, version] : core::coreLibraryVersions()) {
    text += item(QString::fromStdString(name), QString::fromStdString(version));
  }
  for (const auto& [name, version] : devices::deviceLibraryVersions()) {
    text += item(QString::fromStdString(name), QString::fromStdString(version));
  }
  text += QStringLiteral("</ul>");
  return text;
}

void MainWindow::onAbout() {
  QMessageBox::about(this, tr("About Mozzi"), aboutText());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  QSettings settings;
  settings.setValue(QLatin1String(kSettingsGeometry), saveGeometry());
  settings.setValue(QLatin1String(kSettingsState), saveState());
  event->accept();
}

}  // namespace app
}  // namespace mozzi
