// The main window as a user meets it, on a real X display (Xvfb) with VTK on
// Mesa's software OpenGL: docks, every menu action, project open errors,
// persistence, languages, the About box, and a screenshot for the record.
#include <qwt_global.h>
#include <qwt_plot.h>
#include <sqlite3.h>
#include <vtkVersion.h>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QtTest>

#include <atomic>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "app/gui/main_window.h"
#include "core/io/uff/uff.h"
#include "core/report/report_template.h"
#include "devices/sim/virtual_specimens.h"
#include "views/common/job_runner.h"
#include "views/common/job_status_widget.h"
#include "views/common/page_tabs.h"
#include "views/common/project_model.h"
#include "views/common/project_tree.h"
#include "views/gap/model_test_view.h"
#include "views/panels/project_overview.h"
#include "views/plots/frf_plot.h"
#include "views/report/report_dialog.h"
#include "views/scene/scene_view.h"

using mozzi::app::MainWindow;
using mozzi::views::ProjectItem;
using mozzi::views::RecordKind;

class MainWindowTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void docksOpenAndClose();
  void everyMenuActionOpensAndCloses();
  void missingAndCorruptFilesShowAClearMessageAndKeepTheWindowUsable();
  void demoProjectFillsTreeOverviewAndProperties();
  void recentFilesAndLayoutPersist();
  void saveAsCopiesAndOpensTheCopy();
  void languageSwitchesToItalianAndBack();
  void aboutListsTheLinkedLibraryVersions();
  void sceneRendersWithOpenGl();
  void importedGeometryIsDrawnInThe3dView();
  void importedFrfsOpenAPlotTab();
  void unreadableImportLeavesTheProjectUnchanged();
  void modelVsTestOpensOneTabThatFollowsTheLanguage();
  void everyMenuPageOfTheTableHasAnActionThatOpensIt();
  void treeOpensItemsInTheirPages();
  void runningJobsShowInTheStatusBar();
  void reportExportWritesThePdfAndRefusesTheProject();
  void reportDialogChoiceIsSavedAndWritten();
  void screenshot();
  void narrowDockAndEveryPageScreenshots();

 private:
  QString file(const QString& name) const { return QDir(dir_.path()).filePath(name); }
  std::unique_ptr<MainWindow> window_;
  QTemporaryDir dir_;
  QTemporaryDir settingsDir_;
};

void MainWindowTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
  QApplication::setOrganizationName(QStringLiteral("MozziTest"));
  QApplication::setApplicationName(QStringLiteral("MozziTest"));
  window_ = std::make_unique<MainWindow>();
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void MainWindowTest::docksOpenAndClose() {
  const auto docks = window_->findChildren<QDockWidget*>();
  QStringList names;
  for (auto* dock : docks) names << dock->objectName();
  names.sort();
  QCOMPARE(names,
           (QStringList{QStringLiteral("logDock"), QStringLiteral("projectDock"), QStringLiteral("propertiesDock")}));
  for (auto* dock : docks) {
    QVERIFY2(dock->isVisible(), qPrintable(dock->objectName()));
    dock->toggleViewAction()->trigger();
    QVERIFY2(!dock->isVisible(), qPrintable(dock->objectName()));
    dock->toggleViewAction()->trigger();
    QVERIFY2(dock->isVisible(), qPrintable(dock->objectName()));
  }
}

// Triggers every action of every menu. Actions that open a dialog get it
// closed again by a timer that rejects whatever modal window appears.
void MainWindowTest::everyMenuActionOpensAndCloses() {
  QVERIFY(window_->createDemoProject(file(QStringLiteral("menus.mozzi"))));
  int dialogsClosed = 0;
  QTimer closer;
  closer.setInterval(50);
  connect(&closer, &QTimer::timeout, [&] {
    if (QWidget* modal = QApplication::activeModalWidget()) {
      if (auto* dialog = qobject_cast<QDialog*>(modal))
        dialog->reject();
      else
        modal->close();
      ++dialogsClosed;
    }
  });
  closer.start();

  QStringList triggered;
  std::function<void(QMenu*)> walk = [&](QMenu* menu) {
    for (QAction* action : menu->actions()) {
      if (action->isSeparator()) continue;
      if (action->menu()) {
        walk(action->menu());
        continue;
      }
      if (action->menuRole() == QAction::QuitRole) continue;  // checked below, it would end the test
      if (!action->isEnabled()) continue;
      action->trigger();
      QCoreApplication::processEvents();
      triggered << action->text();
    }
  };
  for (QAction* top : window_->menuBar()->actions()) walk(top->menu());
  closer.stop();
  QVERIFY2(triggered.size() >= 14, qPrintable(triggered.join(QStringLiteral(", "))));
  // New, Open, Save As, Export image, Demo, About, About Qt open dialogs: all were closed.
  QVERIFY2(dialogsClosed >= 7, qPrintable(QString::number(dialogsClosed)));
  QVERIFY(QApplication::activeModalWidget() == nullptr);
  QVERIFY(window_->isVisible());
  QVERIFY(window_->setLanguage(QStringLiteral("en")));  // the walk may have switched language

  // Quit closes the window (checked on a second window so the test goes on).
  MainWindow other;
  other.show();
  QVERIFY(QTest::qWaitForWindowExposed(&other));
  QAction* quit = nullptr;
  for (QAction* a : other.findChildren<QAction*>()) {
    if (a->menuRole() == QAction::QuitRole) quit = a;
  }
  QVERIFY(quit);
  quit->trigger();
  QVERIFY(!other.isVisible());
}

void MainWindowTest::missingAndCorruptFilesShowAClearMessageAndKeepTheWindowUsable() {
  QVERIFY(window_->openProject(file(QStringLiteral("menus.mozzi"))));
  const QString missing = file(QStringLiteral("no-such-project.mozzi"));
  QVERIFY(!window_->openProject(missing));
  QVERIFY(window_->errorBox());
  QVERIFY(window_->errorBox()->isVisible());
  QVERIFY2(window_->errorBox()->text().contains(QStringLiteral("no-such-project.mozzi")),
           qPrintable(window_->errorBox()->text()));
  QVERIFY2(window_->errorBox()->informativeText().contains(QStringLiteral("does not exist")),
           qPrintable(window_->errorBox()->informativeText()));
  window_->errorBox()->close();
  // The project that was open stays open.
  QCOMPARE(window_->model()->path(), file(QStringLiteral("menus.mozzi")));

  QFile corrupt(file(QStringLiteral("corrupt.mozzi")));
  QVERIFY(corrupt.open(QIODevice::WriteOnly));
  corrupt.write("SQLite format 3\0 but truncated garbage after the header", 56);
  corrupt.close();
  QVERIFY(!window_->openProject(corrupt.fileName()));
  QVERIFY(window_->errorBox() && window_->errorBox()->isVisible());
  QVERIFY2(window_->errorBox()->text().contains(QStringLiteral("corrupt.mozzi")),
           qPrintable(window_->errorBox()->text()));
  window_->errorBox()->close();

  QFile text(file(QStringLiteral("notes.mozzi")));
  QVERIFY(text.open(QIODevice::WriteOnly));
  text.write("frame A notes\n");
  text.close();
  QVERIFY(!window_->openProject(text.fileName()));
  QVERIFY2(window_->errorBox()->informativeText().contains(QStringLiteral("not a Mozzi project")),
           qPrintable(window_->errorBox()->informativeText()));
  window_->errorBox()->close();
  // The file the user pointed at is left as it was.
  QVERIFY(text.open(QIODevice::ReadOnly));
  QCOMPARE(text.readAll(), QByteArray("frame A notes\n"));

  // Still usable: menus enabled, a good project opens.
  QVERIFY(window_->menuBar()->isEnabled());
  QVERIFY(window_->openProject(file(QStringLiteral("menus.mozzi"))));
  // Opening the project that is already open (Open Recent) keeps it writable.
  QVERIFY(window_->openProject(file(QStringLiteral("menus.mozzi"))));
  QVERIFY(!window_->model()->isReadOnly());
}

void MainWindowTest::demoProjectFillsTreeOverviewAndProperties() {
  const QString path = file(QStringLiteral("demo.mozzi"));
  QVERIFY(window_->createDemoProject(path));
  const int expected = static_cast<int>(mozzi::devices::sim::virtualSpecimens().size());
  auto* tree = window_->findChild<QTreeWidget*>(QStringLiteral("projectTree"));
  QVERIFY(tree);
  QCOMPARE(tree->topLevelItemCount(), 1);
  QTreeWidgetItem* specimens = tree->topLevelItem(0)->child(0);
  QCOMPARE(specimens->childCount(), expected);
  QCOMPARE(specimens->text(1).toInt(), expected);
  auto* overview = window_->findChild<mozzi::views::ProjectOverview*>();
  QVERIFY(overview);
  QCOMPARE(overview->specimenRows(), expected);

  // The specimens table's counts are the store's records, specimen by specimen.
  auto* table = overview->findChild<QTableWidget*>(QStringLiteral("overviewSpecimens"));
  QVERIFY(table);
  auto* store = window_->model()->store();
  const auto frfSets = store->frfSets();
  const auto modal = store->modalResults();
  QVERIFY(frfSets.ok() && modal.ok() && !frfSets->empty() && !modal->empty());
  int frfColumn = -1, modalColumn = -1;
  for (int c = 0; c < table->columnCount(); ++c) {
    if (table->horizontalHeaderItem(c)->text() == QStringLiteral("FRF sets")) frfColumn = c;
    if (table->horizontalHeaderItem(c)->text() == QStringLiteral("Modal results")) modalColumn = c;
  }
  QVERIFY(frfColumn > 0 && modalColumn > 0);
  int frfTotal = 0, modalTotal = 0;
  for (int r = 0; r < table->rowCount(); ++r) {
    frfTotal += table->item(r, frfColumn)->text().toInt();
    modalTotal += table->item(r, modalColumn)->text().toInt();
  }
  QCOMPARE(frfTotal, static_cast<int>(frfSets->size()));
  QCOMPARE(modalTotal, static_cast<int>(modal->size()));

  // The start list offers every page but the Overview, each on something the
  // demo holds, and opens it: the Mode Animation on a modal result.
  const auto& entries = overview->startEntries();
  QCOMPARE(static_cast<int>(entries.size()), static_cast<int>(window_->pages().pages().size()) - 1);
  int animation = -1;
  for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
    const auto& entry = entries[static_cast<std::size_t>(i)];
    QVERIFY2(entry.available, qPrintable(entry.pageId));
    if (entry.pageId == QStringLiteral("mode-animation")) animation = i;
  }
  QVERIFY(animation >= 0);
  QCOMPARE(entries[static_cast<std::size_t>(animation)].item.kind, mozzi::views::RecordKind::ModalResult);
  QWidget* opened = overview->openStartEntry(animation);
  QVERIFY(opened);
  QCOMPARE(window_->workArea()->currentPage(), opened);
  QCOMPARE(window_->workArea()->itemOf(opened).id, entries[static_cast<std::size_t>(animation)].item.id);

  tree->setCurrentItem(specimens->child(0));
  auto* properties = window_->findChild<QTableWidget*>(QStringLiteral("propertiesTable"));
  QVERIFY(properties);
  QCOMPARE(properties->rowCount(), 4);  // name, kind, description, mesh
  QCOMPARE(properties->item(0, 1)->text(), QString::fromStdString(mozzi::devices::sim::virtualSpecimens()[0].name));
  QCOMPARE(properties->item(3, 0)->text(), QStringLiteral("Mesh"));
  QVERIFY(window_->windowTitle().contains(QStringLiteral("demo.mozzi")));
}

void MainWindowTest::recentFilesAndLayoutPersist() {
  const QString a = file(QStringLiteral("recent-a.mozzi"));
  const QString b = file(QStringLiteral("recent-b.mozzi"));
  QVERIFY(window_->newProject(a));
  QVERIFY(window_->newProject(b));
  QCOMPARE(window_->recentFiles().value(0), QFileInfo(b).absoluteFilePath());
  QCOMPARE(window_->recentFiles().value(1), QFileInfo(a).absoluteFilePath());

  auto* log = window_->findChild<QDockWidget*>(QStringLiteral("logDock"));
  log->hide();
  window_->close();  // saves geometry and dock state
  window_->model()->close();

  MainWindow second;
  second.show();
  QVERIFY(QTest::qWaitForWindowExposed(&second));
  QCOMPARE(second.recentFiles().value(0), QFileInfo(b).absoluteFilePath());
  QVERIFY(!second.findChild<QDockWidget*>(QStringLiteral("logDock"))->isVisible());
  second.findChild<QDockWidget*>(QStringLiteral("logDock"))->show();
  second.close();

  window_->show();
  log->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void MainWindowTest::saveAsCopiesAndOpensTheCopy() {
  QVERIFY(window_->createDemoProject(file(QStringLiteral("original.mozzi"))));
  const QString copy = file(QStringLiteral("copy.mozzi"));
  QVERIFY(window_->saveProjectAs(copy));
  QCOMPARE(window_->model()->path(), copy);
  QVERIFY(!window_->model()->isReadOnly());
  auto summary = window_->model()->summary();
  QVERIFY(summary.ok());
  QCOMPARE(summary->specimens.size(), mozzi::devices::sim::virtualSpecimens().size());
  // Saving onto an existing project of another name is refused without touching it.
  QVERIFY(!window_->saveProjectAs(copy));
  window_->errorBox()->close();
}

void MainWindowTest::languageSwitchesToItalianAndBack() {
  QVERIFY(MainWindow::availableLanguages().contains(QStringLiteral("it")));
  QVERIFY(MainWindow::availableLanguages().contains(QStringLiteral("en")));
  QMenu* fileMenu = window_->menuBar()->actions().at(0)->menu();
  QVERIFY(window_->setLanguage(QStringLiteral("it")));
  QCOMPARE(window_->language(), QStringLiteral("it"));
  QStringList texts;
  for (QAction* a : fileMenu->actions()) texts << a->text();
  QVERIFY2(texts.contains(QStringLiteral("&Apri progetto...")), qPrintable(texts.join(QStringLiteral("|"))));
  // Tab titles come from the page table (context "Pages") and follow the language.
  QCOMPARE(window_->workArea()->tabText(0), QCoreApplication::translate("Pages", "Overview"));
  QCOMPARE(QSettings().value(QStringLiteral("ui/language")).toString(), QStringLiteral("it"));
  QVERIFY(window_->setLanguage(QStringLiteral("en")));
  texts.clear();
  for (QAction* a : fileMenu->actions()) texts << a->text();
  QVERIFY(texts.contains(QStringLiteral("&Open Project...")));
  QVERIFY(!window_->setLanguage(QStringLiteral("xx")));
}

void MainWindowTest::aboutListsTheLinkedLibraryVersions() {
  const QString about = window_->aboutText();
  for (const QString& expected :
       {QStringLiteral("Qt ") + QString::fromLatin1(qVersion()), QStringLiteral("Qwt " QWT_VERSION_STR),
        QStringLiteral("VTK ") + QString::fromLatin1(vtkVersion::GetVTKVersion()),
        QStringLiteral("SQLite ") + QString::fromLatin1(sqlite3_libversion()), QStringLiteral("Eigen 3.4"),
        QStringLiteral("Ceres 2.1"), QStringLiteral("FFTW 3."), QStringLiteral("libusb 1.0")}) {
    QVERIFY2(about.contains(expected), qPrintable(expected + QStringLiteral(" missing from: ") + about));
  }
}

void MainWindowTest::sceneRendersWithOpenGl() {
  auto* scene = window_->findChild<mozzi::views::SceneView*>(QStringLiteral("sceneTab"));
  QVERIFY(scene);
  window_->workArea()->setCurrentPage(scene);
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  QTRY_VERIFY(scene->isReady());  // the 3-D window is a native child: exposed a moment later
  const int before = scene->framesRendered();
  scene->render();
  QCOMPARE(scene->framesRendered(), before + 1);
  // The gradient background is drawn: the centre is neither black nor unpainted.
  const QImage image = scene->grab().toImage();
  const QColor centre = image.pixelColor(image.width() / 2, image.height() / 2);
  QVERIFY2(centre.lightness() > 150, qPrintable(centre.name()));
  window_->workArea()->setCurrentIndex(0);
}

// The TestLab file has 36 nodes in 36 local coordinate systems and three trace
// lines drawing 30 segments (counted by hand from the file).
void MainWindowTest::importedGeometryIsDrawnInThe3dView() {
  QVERIFY(window_->newProject(file(QStringLiteral("import-geometry.mozzi"))));
  const QString uff = QStringLiteral(MOZZI_SHARED_DATA_DIR "/uff/TestLab 161 164 18 15 82.uff");
  QVERIFY(window_->importUff(uff));
  auto* scene = window_->findChild<mozzi::views::SceneView*>(QStringLiteral("sceneTab"));
  QCOMPARE(window_->workArea()->currentPage(), static_cast<QWidget*>(scene));
  QCOMPARE(scene->meshPointCount(), 36);
  QCOMPARE(scene->meshLineCount(), 30);
  QCOMPARE(scene->skippedLineCount(), 0);
  // The specimen created for the file is selected and its properties say so.
  auto* properties = window_->findChild<QTableWidget*>(QStringLiteral("propertiesTable"));
  bool meshRow = false;
  for (int r = 0; r < properties->rowCount(); ++r) {
    meshRow = meshRow || properties->item(r, 1)->text() == QStringLiteral("36 nodes, 30 lines");
  }
  QVERIFY(meshRow);
  QTRY_VERIFY(scene->isReady());
  scene->render();
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  QVERIFY(window_->grab().save(QDir(folder).filePath(QStringLiteral("scene_testlab.png"))));
  window_->workArea()->setCurrentIndex(0);
}

void MainWindowTest::importedFrfsOpenAPlotTab() {
  QVERIFY(window_->createDemoProject(file(QStringLiteral("import-frf.mozzi"))));
  // A two-response FRF file written by Mozzi's own UFF writer.
  mozzi::core::FrfMatrix frf;
  const int n = 400;
  frf.frequencyHz = mozzi::core::Vector::LinSpaced(n, 1.0, 400.0);
  frf.responses = {{3, mozzi::core::Direction::Z, false}, {4, mozzi::core::Direction::Z, false}};
  frf.references = {{1, mozzi::core::Direction::Z, true}};
  frf.type = mozzi::core::FrfType::Accelerance;
  frf.h.emplace_back(n, 2);
  for (int k = 0; k < n; ++k) {
    const double w = 2 * M_PI * frf.frequencyHz[k];
    frf.h[0](k, 0) = -w * w / mozzi::core::Complex(1e6 - w * w, 20.0 * w);
    frf.h[0](k, 1) = 0.5 * frf.h[0](k, 0);
  }
  auto records = mozzi::core::io::uff::fromFrfMatrix(frf);
  QVERIFY(records.ok());
  mozzi::core::io::uff::UffFile uffFile;
  for (auto& r : *records) uffFile.datasets.push_back(mozzi::core::io::uff::makeDataset(std::move(r)));
  const QString path = file(QStringLiteral("frf.uff"));
  QVERIFY(mozzi::core::io::uff::writeFile(path.toStdString(), uffFile).ok());

  const int tabsBefore = window_->workArea()->count();
  QVERIFY(window_->importUff(path));
  QCOMPARE(window_->workArea()->count(), tabsBefore + 1);
  auto* plot = qobject_cast<mozzi::views::FrfPlot*>(window_->workArea()->currentPage());
  QVERIFY(plot);
  QCOMPARE(plot->pairCount(), 2);
  QCOMPARE(plot->shownSamples(), size_t(n));
  auto* tree = window_->findChild<QTreeWidget*>(QStringLiteral("projectTree"));
  const auto groups = tree->findItems(QStringLiteral("FRF sets"), Qt::MatchExactly | Qt::MatchRecursive);
  QCOMPARE(groups.size(), 1);
  // The imported set is listed once (the project may hold others, e.g. the demo's campaigns).
  QTreeWidgetItem* imported = nullptr;
  int named = 0;
  for (int i = 0; i < groups[0]->childCount(); ++i)
    if (groups[0]->child(i)->text(0) == QStringLiteral("frf.uff")) {
      imported = groups[0]->child(i);
      ++named;
    }
  QCOMPARE(named, 1);
  // Activating the set again raises the same tab instead of opening another.
  emit tree->itemActivated(imported, 0);
  QCOMPARE(window_->workArea()->count(), tabsBefore + 1);
}

void MainWindowTest::unreadableImportLeavesTheProjectUnchanged() {
  QVERIFY(window_->createDemoProject(file(QStringLiteral("import-bad.mozzi"))));
  auto before = window_->model()->summary();
  QVERIFY(before.ok());
  QFile bad(file(QStringLiteral("bad.uff")));
  QVERIFY(bad.open(QIODevice::WriteOnly));
  bad.write("    -1\n    58\nthis is not a dataset 58\n");
  bad.close();
  QVERIFY(!window_->importUff(bad.fileName()));
  QVERIFY(window_->errorBox() && window_->errorBox()->isVisible());
  QVERIFY2(window_->errorBox()->text().contains(QStringLiteral("unchanged")), qPrintable(window_->errorBox()->text()));
  window_->errorBox()->close();
  auto after = window_->model()->summary();
  QVERIFY(after.ok());
  QCOMPARE(after->counts.size(), before->counts.size());
  for (size_t i = 0; i < before->counts.size(); ++i) QCOMPARE(after->counts[i].rows, before->counts[i].rows);
}

// Tools > Model vs Test opens the gap view once (a second call raises it) and
// its tab title follows the interface language like every other tab.
void MainWindowTest::modelVsTestOpensOneTabThatFollowsTheLanguage() {
  auto* view = qobject_cast<mozzi::views::ModelTestView*>(window_->openPage(QStringLiteral("model-vs-test")));
  QVERIFY(view);
  QCOMPARE(window_->workArea()->currentPage(), view);
  const int tabs = window_->workArea()->count();
  window_->workArea()->setCurrentIndex(0);
  QCOMPARE(window_->openPage(QStringLiteral("model-vs-test")), view);
  QCOMPARE(window_->workArea()->count(), tabs);
  QCOMPARE(window_->workArea()->currentPage(), view);
  const int index = window_->workArea()->indexOfPage(view);
  QCOMPARE(window_->workArea()->tabText(index), QStringLiteral("Model vs Test"));
  QVERIFY(window_->setLanguage(QStringLiteral("it")));
  QCOMPARE(window_->workArea()->tabText(index), QCoreApplication::translate("Pages", "Model vs Test"));
  // Widgets get LanguageChange as a posted event: wait for it. The page shows
  // the project's newest kept diagnosis when there is one (the demo keeps one).
  const QString italian = view->storedDiagnosis() ? QStringLiteral("Verdetto:") : QStringLiteral("Nessuna diagnosi");
  QTRY_VERIFY2(view->verdictText().contains(italian), qPrintable(view->verdictText()));
  QVERIFY(window_->setLanguage(QStringLiteral("en")));
  QCOMPARE(window_->workArea()->tabText(index), QStringLiteral("Model vs Test"));
}

// The Pages and Tools menus are built from the page table: one action per page
// with a menu, and triggering it opens that page.
void MainWindowTest::everyMenuPageOfTheTableHasAnActionThatOpensIt() {
  int withMenu = 0;
  for (const auto& spec : window_->pages().pages()) {
    if (spec.menu == mozzi::views::PageMenu::None) continue;
    ++withMenu;
    auto* action = window_->findChild<QAction*>(QStringLiteral("page:") + spec.id);
    QVERIFY2(action, qPrintable(spec.id));
    QCOMPARE(action->text(), mozzi::views::PageRegistry::title(spec));
    action->trigger();
    QWidget* page = window_->workArea()->currentPage();
    QVERIFY2(page, qPrintable(spec.id));
    QCOMPARE(window_->workArea()->specOf(page)->id, spec.id);
  }
  QVERIFY(withMenu >= 3);  // overview, 3-D view, model vs test
  // The overview and the 3-D view open with the window.
  QVERIFY(window_->workArea()->findPage(QStringLiteral("overview")));
  QVERIFY(window_->workArea()->findPage(QStringLiteral("scene")));
  window_->workArea()->setCurrentIndex(0);
}

// Double-click in the tree opens an item in its default page; the tree's
// context menu offers every page that opens it.
void MainWindowTest::treeOpensItemsInTheirPages() {
  QVERIFY(window_->newProject(file(QStringLiteral("tree-open.mozzi"))));
  auto sp = window_->model()->addSpecimen(QStringLiteral("Fork A"), QStringLiteral("fork"));
  QVERIFY(sp.ok());
  mozzi::core::FrfMatrix frf;
  frf.frequencyHz = mozzi::core::Vector::LinSpaced(50, 1.0, 50.0);
  frf.responses = {{2, mozzi::core::Direction::X, false}};
  frf.references = {{1, mozzi::core::Direction::X, true}};
  frf.h.emplace_back(mozzi::core::ComplexMatrix::Constant(50, 1, mozzi::core::Complex(0.0, -1e-4)));
  mozzi::core::io::FrfSetInfo info;
  info.specimenId = *sp;
  info.name = "fork roving";
  auto set = window_->model()->addFrfSet(info, frf);
  QVERIFY(set.ok());
  const ProjectItem item{RecordKind::FrfSet, *set, *sp};
  QVERIFY(window_->selectItem(item));
  auto* tree = window_->projectTree();
  const int tabs = window_->workArea()->count();
  emit tree->itemActivated(tree->currentItem(), 0);
  QCOMPARE(window_->workArea()->count(), tabs + 1);
  auto* plot = qobject_cast<mozzi::views::FrfPlot*>(window_->workArea()->currentPage());
  QVERIFY(plot);
  QCOMPARE(plot->shownSamples(), size_t(50));
  QCOMPARE(window_->workArea()->tabText(window_->workArea()->currentIndex()), QStringLiteral("FRF: fork roving"));
  // The FRF plots carry the export action.
  QVERIFY(!plot->magnitudePlot()->actions().isEmpty());

  // The context menu lists "Open in <page>" for the pages of the row.
  QTimer::singleShot(0, [] {
    auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
    if (!menu) return;
    QStringList texts;
    for (QAction* a : menu->actions()) texts << a->text();
    menu->close();
    qApp->setProperty("treeMenuTexts", texts);
  });
  const QRect rect = tree->visualItemRect(tree->currentItem());
  emit tree->customContextMenuRequested(rect.center());
  QCOMPARE(qApp->property("treeMenuTexts").toStringList(),
           (QStringList{QStringLiteral("Open in FRF"), QStringLiteral("Open in Identification")}));
  // Closing the project closes the tabs of its records.
  window_->model()->close();
  QCOMPARE(window_->workArea()->count(), tabs);
}

void MainWindowTest::runningJobsShowInTheStatusBar() {
  auto* status = window_->findChild<mozzi::views::JobStatusWidget*>(QStringLiteral("jobStatus"));
  QVERIFY(status);
  QVERIFY(!status->isVisible());
  std::atomic<bool> release{false};
  bool done = false;
  window_->jobs()->run<int>(
      QStringLiteral("Long computation"),
      [&](mozzi::views::JobProgress& p) -> mozzi::core::Result<int> {
        p.report(0.5, "half way");
        while (!release.load()) QThread::msleep(1);
        return 1;
      },
      [&](mozzi::core::Result<int> r) { done = r.ok(); });
  QVERIFY(status->isVisible());
  QCOMPARE(status->text(), QStringLiteral("Long computation"));
  release = true;
  QTRY_VERIFY(done);
  QVERIFY(!status->isVisible());
}

// File > Export > Report (PDF): the same renderer as mozzi-cli report, in the
// background; the project itself is refused as the output and left intact.
void MainWindowTest::reportExportWritesThePdfAndRefusesTheProject() {
  const QString project = file(QStringLiteral("menus.mozzi"));
  QVERIFY(window_->openProject(project));
  QSignalSpy spy(window_.get(), &MainWindow::reportExported);
  const QString pdf = file(QStringLiteral("menus-report.pdf"));
  QVERIFY(window_->exportReport(pdf));
  QVERIFY(spy.wait(120000));
  QVERIFY2(spy.at(0).at(0).toBool(), qPrintable(spy.at(0).at(1).toString()));
  QFile written(pdf);
  QVERIFY(written.open(QIODevice::ReadOnly));
  QCOMPARE(written.read(5), QByteArray("%PDF-"));
  QVERIFY(written.size() > 10000);

  const qint64 size = QFileInfo(project).size();
  spy.clear();
  QVERIFY(window_->exportReport(QDir(dir_.path()).filePath(QStringLiteral("./menus.mozzi"))));
  QVERIFY(spy.wait(120000));
  QVERIFY(!spy.at(0).at(0).toBool());
  QVERIFY2(spy.at(0).at(1).toString().contains(QStringLiteral("menus.mozzi")), qPrintable(spy.at(0).at(1).toString()));
  // The renderer's reason only, without Qt's start-up warnings.
  QVERIFY2(!spy.at(0).at(1).toString().contains(QStringLiteral("QStandardPaths")),
           qPrintable(spy.at(0).at(1).toString()));
  QCOMPARE(QFileInfo(project).size(), size);
  QVERIFY(window_->openProject(project));
}

// File > Export > Report...: the dialog's choice (one section, Italian, HTML
// only) is saved as the project's template and written by the renderer;
// picture of the dialog over the window at 1280x800 (report_dialog_window.png,
// @2x under QT_SCALE_FACTOR=2, on an Xvfb screen of at least 2560x1600).
void MainWindowTest::reportDialogChoiceIsSavedAndWritten() {
  const QString project = file(QStringLiteral("dialog.mozzi"));
  {
    auto store = mozzi::core::io::ProjectStore::create(project.toStdString(), "test");
    QVERIFY(store.ok());
    QVERIFY(store->addSpecimen("Frame X", "frame", "a test frame").ok());
  }
  QVERIFY(window_->openProject(project));
  window_->showNormal();
  window_->resize(1280, 800);
  mozzi::views::ReportDialog dialog(window_->model(), window_.get());
  for (const auto& key : mozzi::core::report::reportSectionKeys()) dialog.sectionBox(key)->setChecked(key == "title");
  dialog.languageBox()->setCurrentIndex(1);  // Italiano
  dialog.setPdfPath(QString());
  dialog.setHtmlDir(file(QStringLiteral("dialog-html")));
  auto t = dialog.reportTemplate();
  t.pdf = false;
  t.html = true;
  dialog.setReportTemplate(t);
  dialog.show();
  QVERIFY(QTest::qWaitForWindowExposed(&dialog));
  QTest::qWait(100);
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  const bool hiDpi = window_->devicePixelRatioF() > 1.0;
  const QString shot = QDir(folder).filePath(hiDpi ? QStringLiteral("report_dialog_window@2x.png")
                                                   : QStringLiteral("report_dialog_window.png"));
  QVERIFY(window_->screen()
              ->grabWindow(0, window_->x(), window_->y(), window_->frameGeometry().width(),
                           window_->frameGeometry().height())
              .save(shot));
  dialog.accept();
  auto saved = mozzi::core::report::loadReportTemplate(*window_->model()->store());
  QVERIFY(saved.ok() && saved->has_value());
  QCOMPARE((*saved)->sections, std::vector<std::string>{"title"});
  QCOMPARE((*saved)->language, mozzi::core::report::Language::Italian);

  QSignalSpy spy(window_.get(), &MainWindow::reportExported);
  QVERIFY(window_->writeReport(dialog.pdfPath(), dialog.htmlDir(), dialog.reportTemplate()));
  QVERIFY(spy.wait(120000));
  QVERIFY2(spy.at(0).at(0).toBool(), qPrintable(spy.at(0).at(1).toString()));
  QFile index(file(QStringLiteral("dialog-html/index.html")));
  QVERIFY(index.open(QIODevice::ReadOnly));
  const QString html = QString::fromUtf8(index.readAll());
  QVERIFY(html.contains(QStringLiteral("<h2>Progetto e provini</h2>")));
  QVERIFY(html.contains(QStringLiteral("Frame X")));
  QVERIFY(!html.contains(QStringLiteral("<h2>Prove di rigidezza</h2>")));
}

void MainWindowTest::screenshot() {
  QVERIFY(window_->createDemoProject(file(QStringLiteral("screenshot.mozzi"))));
  window_->showNormal();
  window_->resize(1280, 800);
  window_->workArea()->setCurrentIndex(0);
  QTest::qWait(50);
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  // Run again with QT_SCALE_FACTOR=2 for the high-DPI picture.
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString name =
      scale.isEmpty() ? QStringLiteral("main_window.png") : QStringLiteral("main_window_scale%1.png").arg(scale);
  const QString path = QDir(folder).filePath(name);
  QVERIFY(window_->grab().save(path));
  QVERIFY(QFileInfo(path).size() > 10000);
  qInfo("screenshot: %s", qPrintable(path));

  // The demo's Model vs Test page shows the kept diagnosis of fork A as it was
  // stored (no run): the stored verdict and effect, ranking and overlay.
  auto* gap = qobject_cast<mozzi::views::ModelTestView*>(window_->openPage(QStringLiteral("model-vs-test")));
  QVERIFY(gap);
  const auto analyses = window_->model()->store()->analyses();
  QVERIFY(analyses.ok());
  nlohmann::json stored;
  for (const auto& a : *analyses)
    if (a.kind == "gap-diagnosis") stored = nlohmann::json::parse(a.resultJson);
  QVERIFY(stored.is_object());
  QVERIFY(gap->storedDiagnosis().has_value());
  // The demo's design model lacks fork A's out-of-band completion modes
  // (devices/sim/demo_gap.cpp): the diagnosis attributes the gap to two
  // residual modes fitted together, one seen by the Y accelerometer and one
  // by the Z accelerometers, and to nothing else.
  QCOMPARE(QString::fromStdString(stored["verdict"].get<std::string>()), QStringLiteral("effect"));
  QCOMPARE(stored["verdict_set"].size(), std::size_t{2});
  QStringList named;
  QString legend = QStringLiteral("model");  // the overlay's: each effect with its location
  for (const auto& r : stored["verdict_set"]) {
    const auto& effect = stored["ranking"][r.get<std::size_t>()];
    QCOMPARE(QString::fromStdString(effect["effect"].get<std::string>()), QStringLiteral("residual_mode"));
    QCOMPARE(gap->rankingTable()->item(r.get<int>(), 0)->text(), QStringLiteral("residual mode"));  // in words
    QVERIFY(gap->rankingTable()->item(r.get<int>(), 0)->font().bold());
    // A family of references whose residual modes change the FRFs alike
    // (core/gap/engine/families.h) is named with its other locations.
    QString text =
        QStringLiteral("residual mode at %1").arg(QString::fromStdString(effect["location"][0].get<std::string>()));
    legend += QStringLiteral(" + ") + text;
    const auto others = effect.value("equivalent_locations", nlohmann::json::array());
    if (others.size() == 1)
      text += QStringLiteral(" (equivalent at %1)").arg(QString::fromStdString(others[0][0].get<std::string>()));
    if (others.size() > 1) text += QStringLiteral(" (and %1 equivalent locations)").arg(others.size());
    named << text;
  }
  QCOMPARE(gap->verdictText(), QStringLiteral("Verdict: effect (%1 and %2)").arg(named[0], named[1]));
  QCOMPARE(gap->overlayPlot()->itemList(QwtPlotItem::Rtti_PlotCurve).value(2)->title().text(), legend);
  // The families share no reference, and the demo has some: fewer ranked rows than residual-mode references.
  std::set<std::string> references;
  std::size_t members = 0, modes = 0;
  for (const auto& effect : stored["ranking"]) {
    if (effect["effect"] != "residual_mode") continue;
    ++modes;
    references.insert(effect["location"][0].get<std::string>());
    ++members;
    for (const auto& other : effect.value("equivalent_locations", nlohmann::json::array())) {
      references.insert(other[0].get<std::string>());
      ++members;
    }
  }
  QCOMPARE(references.size(), members);
  QVERIFY2(modes < members, qPrintable(QStringLiteral("%1 rows for %2 references").arg(modes).arg(members)));
  QCOMPARE(gap->rankingTable()->rowCount(), static_cast<int>(stored["ranking"].size()));
  QCOMPARE(gap->overlayCurveCount(), static_cast<int>(stored["overlay"].size()));
  auto* results = gap->findChild<QTabWidget*>(QStringLiteral("gapResults"));
  QVERIFY(results);
  const QString suffix = scale.isEmpty() ? QString() : QStringLiteral("_scale%1").arg(scale);
  for (const auto& [tab, shotName] : {std::pair{1, QStringLiteral("model_vs_test_demo")},
                                      std::pair{2, QStringLiteral("model_vs_test_demo_overlay")}}) {
    results->setCurrentIndex(tab);
    QTest::qWait(50);
    const QString gapShot = QDir(folder).filePath(shotName + suffix + QStringLiteral(".png"));
    QVERIFY(window_->grab().save(gapShot));
    qInfo("screenshot: %s", qPrintable(gapShot));
  }
}

// On the demo the screenshot above made (making one takes minutes on a loaded
// machine, more than a test function may take): the project dock at 260
// pixels and every page, at this scale.
void MainWindowTest::narrowDockAndEveryPageScreenshots() {
  const QString demo = file(QStringLiteral("screenshot.mozzi"));
  // Run alone, a copy of the demo MOZZI_DEMO_PROJECT names (made by `mozzi-cli project demo`) saves the minutes.
  const QString made = qEnvironmentVariable("MOZZI_DEMO_PROJECT");
  if (!QFileInfo::exists(demo) && !made.isEmpty()) QVERIFY(QFile::copy(made, demo));
  QVERIFY(QFileInfo::exists(demo) ? window_->openProject(demo) : window_->createDemoProject(demo));
  window_->showNormal();
  window_->resize(1280, 800);
  QTest::qWait(50);
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString suffix = scale.isEmpty() ? QString() : QStringLiteral("_scale%1").arg(scale);

  // The project dock at 260 pixels: the second column holds counts only (the
  // analyses' kinds are group rows), so the names keep the width.
  auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("projectDock"));
  QVERIFY(dock);
  window_->resizeDocks({dock}, {260}, Qt::Horizontal);
  QTest::qWait(50);
  auto* tree = window_->projectTree();
  tree->expandAll();
  QTest::qWait(50);
  // An analysis kind there ("wheelchair manoeuvre") took half the dock.
  QVERIFY2(tree->columnWidth(1) <= tree->viewport()->width() / 3,
           qPrintable(QStringLiteral("%1 of %2").arg(tree->columnWidth(1)).arg(tree->viewport()->width())));
  for (QTreeWidgetItemIterator it(tree); *it; ++it)
    if (mozzi::views::ProjectTree::itemOf(*it).kind == RecordKind::Analysis) QVERIFY((*it)->text(1).isEmpty());
  const QString treeShot = QDir(folder).filePath(QStringLiteral("project_tree_260") + suffix + QStringLiteral(".png"));
  QVERIFY(dock->grab().save(treeShot));
  qInfo("screenshot: %s", qPrintable(treeShot));

  // Every page as the Overview's start list opens it on the demo, for a look
  // at this scale (text fits, plots show data).
  auto* overview = window_->findChild<mozzi::views::ProjectOverview*>();
  QVERIFY(overview);
  const auto entries = overview->startEntries();
  for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
    if (!entries[static_cast<std::size_t>(i)].available) continue;
    QWidget* page = overview->openStartEntry(i);
    if (!page) continue;
    QTest::qWait(200);
    if (entries[static_cast<std::size_t>(i)].pageId == QStringLiteral("model-vs-test")) {
      // The demo's kept diagnosis fits the tab area without a vertical
      // scroll: the scroll area sizes a page with word-wrapped labels by its
      // preferred height for the width, 767 px in 606 before the overlay
      // plot, the candidate list and the explanation gave up their hints.
      QScrollArea* holder = nullptr;
      for (QWidget* w = page->parentWidget(); w && !holder; w = w->parentWidget())
        holder = qobject_cast<QScrollArea*>(w);  // the tab's scroll area, above the page's holder
      QVERIFY(holder);
      QVERIFY2(
          !holder->verticalScrollBar()->isVisible(),
          qPrintable(QStringLiteral("page %1 px tall in %2 px").arg(page->height()).arg(holder->viewport()->height())));
    }
    const QString pageShot = QDir(folder).filePath(QStringLiteral("page_%1%2.png").arg(entries[i].pageId, suffix));
    QVERIFY(window_->grab().save(pageShot));
    qInfo("screenshot: %s", qPrintable(pageShot));
  }
}

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  MainWindowTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "main_window_test.moc"
