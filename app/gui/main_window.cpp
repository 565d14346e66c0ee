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
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTranslator>
#include <QTreeWidget>

#include "app/build_info.h"
#include "app/gui/builtin_pages.h"
#include "core/common/versions.h"
#include "devices/common/versions.h"
#include "views/common/job_runner.h"
#include "views/common/job_status_widget.h"
#include "views/common/page_tabs.h"
#include "views/common/project_model.h"
#include "views/common/project_tree.h"
#include "views/report/report_dialog.h"

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

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), model_(new views::ProjectModel(this)), jobs_(new views::JobRunner(this)) {
  initMozziResources();
  setObjectName(QStringLiteral("MozziMainWindow"));
  setWindowIcon(QIcon(QStringLiteral(":/icons/mozzi.svg")));
  translator_ = new QTranslator(this);
  model_->setMozziVersion(QString::fromLatin1(buildinfo::kMozziVersion));
  registerBuiltinPages(pages_);

  tabs_ = new views::PageTabs(&pages_, model_, jobs_, this);
  tabs_->setLog([this](const QString& line) { log(line); });
  setCentralWidget(tabs_);

  createActions();
  createMenus();
  createDocks();
  jobStatus_ = new views::JobStatusWidget(jobs_, statusBar());
  statusBar()->addPermanentWidget(jobStatus_);
  jobStatus_->hide();
  connect(jobs_, &views::JobRunner::jobFinished, this, [this](int, bool ok) {
    if (!ok) statusBar()->showMessage(tr("A job stopped before its end; see its page"), 5000);
  });
  defaultState_ = saveState();
  applyDefaultDockSizes();

  QSettings settings;
  recentFiles_ = settings.value(QLatin1String(kSettingsRecent)).toStringList();
  restoreGeometry(settings.value(QLatin1String(kSettingsGeometry)).toByteArray());
  restoreState(settings.value(QLatin1String(kSettingsState)).toByteArray());
  if (!geometry().isValid() || settings.value(QLatin1String(kSettingsGeometry)).isNull()) resize(1280, 800);

  connect(model_, &views::ProjectModel::projectChanged, this, &MainWindow::onProjectChanged);
  connect(model_, &views::ProjectModel::recordsChanged, this, [this](views::RecordKind kind) {
    if (kind != views::RecordKind::Hit) showProperties();  // a campaign commits a hit every few seconds
  });
  tabs_->openStartPages();

  QString lang = settings.value(QLatin1String(kSettingsLanguage)).toString();
  if (lang.isEmpty()) lang = QLocale::system().name().left(2);
  if (!availableLanguages().contains(lang)) lang = QStringLiteral("en");
  if (!setLanguage(lang)) retranslateUi();  // source strings are English

  onProjectChanged();
  updateRecentMenu();
}

MainWindow::~MainWindow() {
  // Workers may still write to the project or notify the model: stop them first.
  jobs_->cancelAll();
  jobs_->waitForDone();
  delete tabs_;  // pages before the model they observe
  tabs_ = nullptr;
}

void MainWindow::createActions() {
  newAction_ = new QAction(this);
  newAction_->setShortcut(QKeySequence::New);
  connect(newAction_, &QAction::triggered, this, [this] {
    const QString path = askProjectFile(tr("New Project"), QString(), true);
    if (!path.isEmpty()) newProject(path);
  });
  openAction_ = new QAction(this);
  openAction_->setShortcut(QKeySequence::Open);
  connect(openAction_, &QAction::triggered, this, [this] {
    const QString path = askProjectFile(tr("Open Project"), QString(), false);
    if (!path.isEmpty()) openProject(path);
  });
  saveAsAction_ = new QAction(this);
  saveAsAction_->setShortcut(QKeySequence::SaveAs);
  connect(saveAsAction_, &QAction::triggered, this, [this] {
    const QString path = askProjectFile(tr("Save Project As"), QString(), true);
    if (!path.isEmpty()) saveProjectAs(path);
  });
  closeProjectAction_ = new QAction(this);
  connect(closeProjectAction_, &QAction::triggered, model_, &views::ProjectModel::close);
  importUffAction_ = new QAction(this);
  connect(importUffAction_, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Universal File"), projectFolder(),
                                                      tr("Universal files (*.uff *.unv);;All files (*)"));
    if (!path.isEmpty()) importUff(path);
  });
  exportImageAction_ = new QAction(this);
  connect(exportImageAction_, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Work Area"), projectFolder(),
                                                      tr("PNG images (*.png);;JPEG images (*.jpg)"));
    if (!path.isEmpty()) exportWorkAreaImage(path);
  });
  exportReportAction_ = new QAction(this);
  connect(exportReportAction_, &QAction::triggered, this, [this] {
    const QString stem = QDir(projectFolder()).filePath(QFileInfo(model_->path()).completeBaseName());
    views::ReportDialog dialog(model_, this);
    dialog.setPdfPath(stem + QStringLiteral("-report.pdf"));
    dialog.setHtmlDir(stem + QStringLiteral("-report"));
    if (dialog.exec() == QDialog::Accepted) writeReport(dialog.pdfPath(), dialog.htmlDir(), dialog.reportTemplate());
  });
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
  connect(resetLayoutAction_, &QAction::triggered, this, [this] {
    restoreState(defaultState_);
    applyDefaultDockSizes();
  });
  demoAction_ = new QAction(this);
  connect(demoAction_, &QAction::triggered, this, [this] {
    const QString path =
        askProjectFile(tr("Create Demo Project"), QDir(projectFolder()).filePath(QStringLiteral("demo.mozzi")), true);
    if (!path.isEmpty()) createDemoProject(path);
  });
  integrityAction_ = new QAction(this);
  connect(integrityAction_, &QAction::triggered, this, &MainWindow::onCheckIntegrity);
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

  // One action per page that opens from a menu, in the order of the table.
  for (const views::PageSpec& spec : pages_.pages()) {
    if (spec.menu == views::PageMenu::None) continue;
    auto* action = new QAction(this);
    action->setObjectName(QStringLiteral("page:") + spec.id);
    if (!spec.iconPath.isEmpty()) action->setIcon(QIcon(spec.iconPath));
    const QString id = spec.id;
    connect(action, &QAction::triggered, this, [this, id] { openPage(id); });
    pageActions_.append(qMakePair(action, &spec));
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
  exportMenu_->addAction(exportReportAction_);
  fileMenu_->addSeparator();
  fileMenu_->addAction(quitAction_);

  viewMenu_ = menuBar()->addMenu(QString());
  languageMenu_ = new QMenu(this);
  languageMenu_->addActions(languageGroup_->actions());

  pagesMenu_ = menuBar()->addMenu(QString());
  toolsMenu_ = menuBar()->addMenu(QString());
  toolsMenu_->addAction(demoAction_);
  toolsMenu_->addAction(integrityAction_);
  toolsMenu_->addSeparator();
  for (const auto& [action, spec] : pageActions_) {
    (spec->menu == views::PageMenu::Tools ? toolsMenu_ : pagesMenu_)->addAction(action);
  }

  helpMenu_ = menuBar()->addMenu(QString());
  helpMenu_->addAction(aboutAction_);
  helpMenu_->addAction(aboutQtAction_);
}

void MainWindow::createDocks() {
  projectTree_ = new views::ProjectTree(model_, this);
  connect(projectTree_, &views::ProjectTree::currentProjectItemChanged, this, [this](const views::ProjectItem& item) {
    showProperties();
    tabs_->followSelection(item);
  });
  // The tree rebuilds its rows when the language changes, after this window
  // retranslated: the properties are read again then.
  connect(projectTree_, &views::ProjectTree::retranslated, this, &MainWindow::showProperties);
  connect(projectTree_, &views::ProjectTree::openRequested, this, &MainWindow::openItem);
  connect(projectTree_, &QWidget::customContextMenuRequested, this, &MainWindow::showTreeMenu);
  projectDock_ = new QDockWidget(this);
  projectDock_->setObjectName(QStringLiteral("projectDock"));
  projectDock_->setWidget(projectTree_);
  addDockWidget(Qt::LeftDockWidgetArea, projectDock_);

  properties_ = new QTableWidget(0, 2, this);
  properties_->setObjectName(QStringLiteral("propertiesTable"));
  properties_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  properties_->horizontalHeader()->setStretchLastSection(true);
  properties_->verticalHeader()->setVisible(false);
  properties_->setTextElideMode(Qt::ElideMiddle);  // a path keeps its file name in the narrow dock
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

// The tree wide enough for specimen names, the log a few lines high.
void MainWindow::applyDefaultDockSizes() {
  resizeDocks({projectDock_}, {fontMetrics().averageCharWidth() * 42}, Qt::Horizontal);
  resizeDocks({logDock_}, {fontMetrics().lineSpacing() * 7}, Qt::Vertical);
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
  exportReportAction_->setText(tr("&Report..."));
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
  pagesMenu_->setTitle(tr("&Pages"));
  toolsMenu_->setTitle(tr("&Tools"));
  demoAction_->setText(tr("Create &Demo Project..."));
  integrityAction_->setText(tr("Check Project &Integrity"));
  for (const auto& [action, spec] : pageActions_) {
    action->setText(views::PageRegistry::title(*spec));
    action->setStatusTip(views::PageRegistry::summary(*spec));
  }
  helpMenu_->setTitle(tr("&Help"));
  aboutAction_->setText(tr("&About Mozzi"));
  aboutQtAction_->setText(tr("About &Qt"));
  tabs_->retitle();
  properties_->setHorizontalHeaderLabels({tr("Property"), tr("Value")});
  updateRecentMenu();
  onProjectChanged();
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

void MainWindow::onProjectChanged() {
  const bool open = model_->isOpen();
  saveAsAction_->setEnabled(open);
  importUffAction_->setEnabled(open && !model_->isReadOnly());
  closeProjectAction_->setEnabled(open);
  exportReportAction_->setEnabled(open);
  integrityAction_->setEnabled(open);
  if (!open) {
    setWindowTitle(tr("Mozzi"));
  } else {
    setWindowTitle(tr("%1 - Mozzi").arg(QFileInfo(model_->path()).fileName()) +
                   (model_->isReadOnly() ? tr(" [read-only]") : QString()));
  }
  showProperties();
}

void MainWindow::showProperties() {
  const auto rows = projectTree_->currentProperties();
  properties_->setRowCount(rows.size());
  for (int r = 0; r < rows.size(); ++r) {
    properties_->setItem(r, 0, new QTableWidgetItem(rows[r].first));
    auto* value = new QTableWidgetItem(rows[r].second);
    value->setToolTip(rows[r].second);  // long paths and descriptions are cut in the cell
    properties_->setItem(r, 1, value);
  }
}

// The tree's context menu: "Open in <page>" for every page that opens the item.
void MainWindow::showTreeMenu(const QPoint& pos) {
  const views::ProjectItem item = views::ProjectTree::itemOf(projectTree_->itemAt(pos));
  const auto pages = pages_.pagesFor(item);
  if (pages.empty()) return;
  QMenu menu(this);
  for (const views::PageSpec* spec : pages) {
    QAction* action = menu.addAction(tr("Open in %1").arg(views::PageRegistry::title(*spec)));
    const QString id = spec->id;
    connect(action, &QAction::triggered, this, [this, id, item] { openPage(id, item); });
  }
  menu.exec(projectTree_->viewport()->mapToGlobal(pos));
}

QWidget* MainWindow::openPage(const QString& pageId, const views::ProjectItem& item) {
  return tabs_->openPage(pageId, item);
}

QWidget* MainWindow::openItem(const views::ProjectItem& item) {
  return tabs_->openItem(item);
}

bool MainWindow::selectItem(const views::ProjectItem& item) {
  return projectTree_->selectItem(item);
}

bool MainWindow::exportReport(const QString& pdfPath) {
  // PROJECT PDF HTMLDIR SECTIONS SPECIMEN (app/report/report_main.cpp): the project's template.
  return startReport(pdfPath, {model_->path(), pdfPath, QStringLiteral("-"), QStringLiteral("-"), QStringLiteral("-")});
}

bool MainWindow::writeReport(const QString& pdfPath, const QString& htmlDir, const core::report::ReportTemplate& t) {
  if (pdfPath.isEmpty() && htmlDir.isEmpty()) return false;
  QStringList sections;
  for (const auto& key : t.sections) sections << QString::fromStdString(key);
  // PROJECT PDF HTMLDIR SECTIONS SPECIMEN LANG (app/report/report_main.cpp).
  const auto dash = [](const QString& v) { return v.isEmpty() ? QStringLiteral("-") : v; };
  return startReport(
      pdfPath.isEmpty() ? htmlDir : pdfPath,
      {model_->path(), dash(pdfPath), dash(htmlDir), dash(sections.join(QLatin1Char(','))),
       dash(QString::fromStdString(t.specimen)), QString::fromLatin1(core::report::languageCode(t.language))});
}

bool MainWindow::startReport(const QString& pdfPath, const QStringList& arguments) {
  if (!model_->isOpen()) return false;
  // The renderer beside this program (as beside mozzi-cli), else where the
  // build put it.
  QString renderer = QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("mozzi-report"));
#ifdef MOZZI_REPORT_RENDERER
  if (!QFileInfo(renderer).isExecutable()) renderer = QStringLiteral(MOZZI_REPORT_RENDERER);
#endif
  if (!QFileInfo(renderer).isExecutable()) {
    const QString message = tr("Cannot write the report: the renderer mozzi-report is not installed.");
    log(message);
    emit reportExported(false, message);
    return false;
  }
  auto* process = new QProcess(this);
  process->setProgram(renderer);
  process->setArguments(arguments);
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
  process->setProcessEnvironment(environment);
  connect(process, QOverload<int, QProcess::ExitStatus>::of(&QProcess::finished), this,
          [this, process, pdfPath](int code, QProcess::ExitStatus status) {
            const bool ok = status == QProcess::NormalExit && code == 0;
            // The renderer's own message; Qt's start-up warnings (a missing
            // XDG_RUNTIME_DIR, platform plugin notes) are not the user's concern.
            QStringList lines;
            for (const QString& line : QString::fromUtf8(process->readAllStandardError()).split(QLatin1Char('\n')))
              if (!line.startsWith(QLatin1String("QStandardPaths:")) && !line.startsWith(QLatin1String("qt.")) &&
                  !line.trimmed().isEmpty())
                lines << line;
            const QString detail = lines.join(QLatin1Char('\n')).trimmed();
            const QString message =
                ok ? tr("Report written: %1").arg(pdfPath) : tr("The report was not written: %1").arg(detail);
            log(message);
            statusBar()->showMessage(message, 5000);
            process->deleteLater();
            emit reportExported(ok, message);
          });
  log(tr("Writing the report %1...").arg(pdfPath));
  process->start();
  return true;
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

// A .mozzi file name from a file dialog ("" when cancelled); saving adds the extension.
QString MainWindow::askProjectFile(const QString& title, const QString& suggested, bool save) {
  const QString start = suggested.isEmpty() ? projectFolder() : suggested;
  if (!save) {
    return QFileDialog::getOpenFileName(this, title, start, tr("Mozzi projects (*.mozzi);;All files (*)"));
  }
  const QString path = QFileDialog::getSaveFileName(this, title, start, tr("Mozzi projects (*.mozzi)"));
  if (path.isEmpty() || path.endsWith(QLatin1String(".mozzi"))) return path;
  return path + QStringLiteral(".mozzi");
}

bool MainWindow::openProject(const QString& path) {
  if (auto r = model_->open(path); !r) {
    showError(tr("Open Project"), tr("Could not open %1.").arg(QDir::toNativeSeparators(path)), r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Opened %1").arg(QDir::toNativeSeparators(path)));
  if (model_->isReadOnly()) log(tr("Read-only: %1").arg(model_->readOnlyReason()));
  return true;
}

bool MainWindow::newProject(const QString& path) {
  if (auto r = model_->create(path); !r) {
    showError(tr("New Project"), tr("Could not create %1.").arg(QDir::toNativeSeparators(path)), r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Created %1").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::createDemoProject(const QString& path) {
  if (auto r = model_->createDemo(path); !r) {
    showError(tr("Demo Project"), tr("Could not create the demo project %1.").arg(QDir::toNativeSeparators(path)),
              r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Created demo project %1").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::saveProjectAs(const QString& path) {
  if (auto r = model_->saveAs(path); !r) {
    showError(tr("Save Project As"), tr("Could not save the project as %1.").arg(QDir::toNativeSeparators(path)),
              r.error());
    return false;
  }
  addRecentFile(path);
  log(tr("Saved a copy as %1 and opened it").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::exportWorkAreaImage(const QString& path) {
  const QPixmap image = tabs_->currentPage() ? tabs_->currentPage()->grab() : tabs_->grab();
  if (!image.save(path)) {
    showError(tr("Export Image"), tr("Could not write %1.").arg(QDir::toNativeSeparators(path)),
              core::makeError(core::ErrorCode::IoError, "the image could not be written (folder or format)",
                              path.toStdString()));
    return false;
  }
  log(tr("Exported the work area to %1").arg(QDir::toNativeSeparators(path)));
  return true;
}

bool MainWindow::importUff(const QString& path) {
  if (!model_->isOpen()) return false;
  auto summary = model_->summary();
  if (!summary) {
    showError(tr("Import"), tr("Could not read the project."), summary.error());
    return false;
  }
  // The selected item's specimen, else the first, else a new one named after the file.
  qint64 specimen = projectTree_->currentProjectItem().specimenId;
  bool known = false;
  for (const auto& sp : summary->specimens) known = known || sp.id == specimen;
  if (!known) specimen = summary->specimens.empty() ? 0 : summary->specimens.front().id;
  if (specimen == 0) {
    auto id = model_->addSpecimen(QFileInfo(path).completeBaseName(), QStringLiteral("imported"));
    if (!id) {
      showError(tr("Import"), tr("Could not add a specimen for %1.").arg(QDir::toNativeSeparators(path)), id.error());
      return false;
    }
    specimen = *id;
  }
  auto report = model_->importUff(path, specimen);
  if (!report) {
    showError(tr("Import"), tr("Could not import %1; the project is unchanged.").arg(QDir::toNativeSeparators(path)),
              report.error());
    return false;
  }
  log(tr("Imported %1: %2 nodes, %3 lines, %4 FRFs, %5 modes")
          .arg(QDir::toNativeSeparators(path))
          .arg(report->nodes)
          .arg(report->lines)
          .arg(report->frfPairs)
          .arg(report->modes));
  for (const auto& note : report->notes) log(QStringLiteral("  ") + QString::fromStdString(note));
  const views::ProjectItem specimenItem{views::RecordKind::Specimen, specimen, specimen};
  selectItem(specimenItem);
  if (report->frfSetId) {
    openItem({views::RecordKind::FrfSet, *report->frfSetId, specimen});
  } else if (report->nodes > 0) {
    openItem(specimenItem);
  }
  return true;
}

void MainWindow::onCheckIntegrity() {
  if (!model_->isOpen()) return;
  if (auto check = model_->checkIntegrity(); !check) {
    showError(tr("Check Project Integrity"), tr("The project failed its integrity check."), check.error());
    return;
  }
  log(tr("Integrity check passed: %1").arg(QDir::toNativeSeparators(model_->path())));
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
