// The demo project's rig and review pages as a newcomer meets them in the
// first five minutes, in the main window on a real X display (Xvfb): at
// 1280x800 with the project dock at its default width each page fits the tab
// area; the Stiffness Rig and the Tyre Tester plot the demo's stored tests on
// open (as many points as the project stores); the Stiffness Rig's status
// follows the language. Screenshots fit_<page>.png and stored_*.png (with
// _scale2 under QT_SCALE_FACTOR=2) in MOZZI_SCREENSHOT_DIR.
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_item.h>
#include <qwt_scale_widget.h>
#include <qwt_text.h>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFontMetrics>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "app/gui/main_window.h"
#include "core/io/project_store.h"
#include "views/common/page_tabs.h"
#include "views/common/project_model.h"
#include "views/rigs/rig_test_page.h"
#include "views/scene/scene_view.h"

using mozzi::app::MainWindow;

class DemoPagesTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void rigAndReviewPagesFitTheTabArea();
  void rigPagesPlotTheDemosStoredTestsOnOpen();
  void stiffnessRigStatusFollowsTheLanguage();

 private:
  // The demo, at 1280x800 with the project dock at its default width
  // (View > Reset Layout: 42 average characters), in English.
  void openDemoAt1280WithTheDock();
  QString demo() const { return QDir(dir_.path()).filePath(QStringLiteral("demo.mozzi")); }
  std::unique_ptr<MainWindow> window_;
  QTemporaryDir dir_;
  QTemporaryDir settingsDir_;
};

// The demo is made once (a minute or more on a loaded machine).
void DemoPagesTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
  QApplication::setOrganizationName(QStringLiteral("MozziTest"));
  QApplication::setApplicationName(QStringLiteral("MozziTest"));
  window_ = std::make_unique<MainWindow>();
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  QVERIFY(window_->createDemoProject(demo()));
}

void DemoPagesTest::openDemoAt1280WithTheDock() {
  QVERIFY(window_->openProject(demo()));
  QVERIFY(window_->setLanguage(QStringLiteral("en")));
  window_->showNormal();
  window_->resize(1280, 800);
  auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("projectDock"));
  QVERIFY(dock);
  dock->show();
  window_->resizeDocks({dock}, {window_->fontMetrics().averageCharWidth() * 42}, Qt::Horizontal);
  QTest::qWait(100);
}

// The pages of the rigs and of the reviews, opened as the Pages and Tools
// menus open them: each fits the tab area at 1280x800 with the project dock
// open (no horizontal scroll bar, nothing wider than the viewport; the
// Stability, Hammer Station, Stiffness Rig and Tyre Tester pages did not).
void DemoPagesTest::rigAndReviewPagesFitTheTabArea() {
  openDemoAt1280WithTheDock();
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString suffix = scale.isEmpty() ? QString() : QStringLiteral("_scale%1").arg(scale);
  const QStringList pages = {QStringLiteral("stability"),        QStringLiteral("hammer-station"),
                             QStringLiteral("stiffness-rig"),    QStringLiteral("tyre-tester"),
                             QStringLiteral("stiffness-tables"), QStringLiteral("lumped-fork"),
                             QStringLiteral("tyre-relaxation"),  QStringLiteral("wheelchair")};
  for (const QString& id : pages) {
    QWidget* page = window_->openPage(id);
    QVERIFY2(page, qPrintable(id));
    QTest::qWait(200);
    auto* holder = qobject_cast<QScrollArea*>(window_->workArea()->currentWidget());
    QVERIFY2(holder && holder->widget() == page, qPrintable(id));
    const int available = holder->viewport()->width();
    // The tab area itself: the window less the dock (about 940 pixels here).
    QVERIFY2(available >= 900, qPrintable(QStringLiteral("%1: %2").arg(id).arg(available)));
    const QString widths = QStringLiteral("%1: minimum %2, width %3, available %4")
                               .arg(id)
                               .arg(page->minimumSizeHint().width())
                               .arg(page->width())
                               .arg(available);
    QVERIFY2(page->minimumSizeHint().width() <= available, qPrintable(widths));
    QVERIFY2(page->width() <= available, qPrintable(widths));
    QVERIFY2(!holder->horizontalScrollBar()->isVisible(), qPrintable(widths));
    // The Stability page's two plots both in view: its wrapped summary made
    // the scroll area size the page to its preferred height, the
    // imaginary-part plot below the fold.
    if (id == QLatin1String("stability"))
      QVERIFY2(
          !holder->verticalScrollBar()->isVisible(),
          qPrintable(QStringLiteral("stability: %1 high in %2").arg(page->height()).arg(holder->viewport()->height())));
    // The rig pages' controls start as wide as their form: no scroll bar under them either.
    if (auto* controls = page->findChild<QScrollArea*>(QStringLiteral("controls")))
      QVERIFY2(!controls->horizontalScrollBar()->isVisible(),
               qPrintable(QStringLiteral("%1: controls %2 wide, their form %3")
                              .arg(id)
                              .arg(controls->viewport()->width())
                              .arg(controls->widget()->minimumSizeHint().width())));
    const QString shot = QDir(folder).filePath(QStringLiteral("fit_%1%2.png").arg(id, suffix));
    QVERIFY(window_->grab().save(shot));
    qInfo("screenshot: %s (%s)", qPrintable(shot), qPrintable(widths));
  }
}

namespace {

QwtPlotCurve* curveTitled(QwtPlot* plot, const QString& title) {
  for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve))
    if (item->title().text() == title) return static_cast<QwtPlotCurve*>(item);
  return nullptr;
}

}  // namespace

// Opened on the demo, the Stiffness Rig and the Tyre Tester plot the latest
// test the project holds for their default specimen (fork A with wheel, the
// 120/70 R17 tyre): the demo's sine sweep and steady-state sweeps, with as
// many points as the project stores.
void DemoPagesTest::rigPagesPlotTheDemosStoredTestsOnOpen() {
  openDemoAt1280WithTheDock();
  auto* store = window_->model()->store();
  QVERIFY(store);
  // The latest of each rig's tests on the default specimen, by the demo's
  // specimen names (devices/sim/virtual_specimens.cpp).
  const auto rigTests = store->rigTests();
  QVERIFY(rigTests.ok());
  std::int64_t rigLatest = 0;
  for (const auto& t : *rigTests)
    if (QString::fromStdString(t.specimenName).startsWith(QLatin1String("Fork A")) &&
        QString::fromStdString(t.specimenName).contains(QLatin1String("with wheel")))
      rigLatest = std::max(rigLatest, t.id);
  const auto tyreTests = store->tyreTests();
  QVERIFY(tyreTests.ok());
  std::int64_t tyreLatest = 0;
  for (const auto& t : *tyreTests)
    if (QString::fromStdString(t.specimenName).contains(QLatin1String("120/70 R17")))
      tyreLatest = std::max(tyreLatest, t.id);
  QVERIFY(rigLatest > 0 && tyreLatest > 0);

  // Stiffness rig: the demo's last test of fork A is the sine sweep; one
  // twist-axis point per stored frequency, and the last frequency's sine-fit loop.
  auto* stiff = qobject_cast<mozzi::views::RigTestPage*>(window_->openPage(QStringLiteral("stiffness-rig")));
  QVERIFY(stiff);
  QTest::qWait(100);
  QCOMPARE(stiff->lastTestId().value_or(0), rigLatest);
  const auto rig = store->rigTest(rigLatest);
  QVERIFY(rig.ok());
  QCOMPARE(rig->kind, mozzi::core::io::StoredRigTest::Kind::Dynamic);
  QCOMPARE(stiff->testBox()->currentData().toString(), QStringLiteral("dynamic"));
  std::size_t frequencies = 0;
  for (const auto& r : rig->results) frequencies += r.step && r.quantity == "frequency";
  QVERIFY(frequencies >= 5);
  auto* inclination = curveTitled(stiff->axisPlot(), QStringLiteral("inclination ± 1σ"));
  QVERIFY(inclination);
  QCOMPARE(inclination->dataSize(), frequencies);
  QVERIFY(stiff->axisPlot()->isVisible());
  auto* loop = curveTitled(stiff->resultPlot(), QStringLiteral("sine fit, last frequency"));
  QVERIFY(loop);
  QVERIFY(loop->dataSize() > 100);  // 121 points of the fitted loop (devices/rigtests fittedSineLoop)
  QCOMPARE(stiff->resultsTable()->rowCount(), static_cast<int>(rig->results.size()));

  // Picking the static ramp shows the demo's static test of fork A: its
  // stored k_lat as the line F = k_lat x over +-F_peak / k_lat.
  QVERIFY(stiff->selectTest(QStringLiteral("static")));
  QTest::qWait(50);
  const auto staticId = stiff->lastTestId();
  QVERIFY(staticId && *staticId < rigLatest);
  const auto statics = store->rigTest(*staticId);
  QVERIFY(statics.ok());
  QCOMPARE(statics->kind, mozzi::core::io::StoredRigTest::Kind::Static);
  double kLat = 0.0, peak = 0.0;
  for (const auto& r : statics->results) {
    if (!r.step && r.quantity == "k_lat") kLat = r.value;
    if (!r.step && r.quantity == "peak_force") peak = r.value;
  }
  // Fork A with wheel: 56.1 kN/m (Table 10), within 1%.
  QVERIFY2(std::abs(kLat - 56.1e3) <= 0.01 * 56.1e3, qPrintable(QString::number(kLat)));
  auto* line = curveTitled(stiff->resultPlot(), QStringLiteral("F = k_lat x (stored k_lat)"));
  QVERIFY(line);
  QCOMPARE(line->dataSize(), std::size_t{2});
  const QPointF end = line->sample(1);
  QVERIFY(std::abs(end.y() - peak) <= 1e-9 * peak);
  QVERIFY(std::abs(end.x() - peak / kLat * 1e3) <= 1e-9 * end.x());
  QVERIFY(stiff->selectTest(QStringLiteral("dynamic")));
  QCOMPARE(stiff->lastTestId().value_or(0), rigLatest);

  // Tyre tester: the demo's last test of the tyre is the steady-state
  // sweeps; every stored point is drawn, each in its sweep, with the Magic Formula.
  auto* tyre = qobject_cast<mozzi::views::RigTestPage*>(window_->openPage(QStringLiteral("tyre-tester")));
  QVERIFY(tyre);
  QTest::qWait(100);
  QCOMPARE(tyre->lastTestId().value_or(0), tyreLatest);
  const auto tyreTest = store->tyreTest(tyreLatest);
  QVERIFY(tyreTest.ok());
  QCOMPARE(tyre->testBox()->currentData().toString(), QStringLiteral("steady-state"));
  auto* slip = curveTitled(tyre->resultPlot(), QStringLiteral("F_y vs side-slip"));
  auto* camber = curveTitled(tyre->resultPlot(), QStringLiteral("F_y vs camber"));
  auto* mf = curveTitled(tyre->resultPlot(), QStringLiteral("Magic Formula vs side-slip"));
  QVERIFY(slip && camber && mf);
  QVERIFY(tyreTest->points.size() >= 8);
  QCOMPARE(slip->dataSize() + camber->dataSize(), tyreTest->points.size());
  QVERIFY(slip->dataSize() > 0 && camber->dataSize() > 0);
  QCOMPARE(mf->dataSize(), std::size_t{201});
  // Stored points as plotted: F_y of the first side-slip point.
  bool found = false;
  for (const auto& p : tyreTest->points)
    found = found || (std::abs(p.lateralForceN - slip->sample(0).y()) <= 1e-9 * std::abs(p.lateralForceN) &&
                      std::abs(p.slipAngleRad * 180.0 / 3.14159265358979323846 - slip->sample(0).x()) <= 1e-9);
  QVERIFY(found);

  // Every vertical axis title of the plots shown on one line (at scale 2 the
  // wrapped titles lay over the tick labels): its height for the axis's
  // length is one line's; a horizontal one may take two.
  for (auto* page : {stiff, tyre}) {
    window_->workArea()->setCurrentPage(page);
    QTest::qWait(100);
    for (QwtPlot* plot : {page->livePlot(), page->resultPlot(), page->axisPlot()}) {
      if (!plot->isVisible()) continue;
      for (int axis : {QwtPlot::yLeft, QwtPlot::yRight, QwtPlot::xBottom}) {
        if (!plot->axisEnabled(axis)) continue;
        const QwtText title = plot->axisTitle(axis);
        if (title.isEmpty()) continue;
        auto* scale = plot->axisWidget(axis);
        const int length = axis == QwtPlot::xBottom ? scale->width() : scale->height();
        const int oneLine = QFontMetrics(title.font()).lineSpacing();
        const int lines = axis == QwtPlot::xBottom ? 2 : 1;
        QVERIFY2(scale->titleHeightForWidth(length) <= oneLine * lines + oneLine / 2,
                 qPrintable(QStringLiteral("%1 axis %2: %3 px for a %4 px line")
                                .arg(title.text())
                                .arg(axis)
                                .arg(scale->titleHeightForWidth(length))
                                .arg(oneLine)));
      }
    }
  }

  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString suffix = scale.isEmpty() ? QString() : QStringLiteral("_scale%1").arg(scale);
  for (const auto& [page, name] : {std::pair<QWidget*, QString>{stiff, QStringLiteral("stored_stiffness_rig")},
                                   std::pair<QWidget*, QString>{tyre, QStringLiteral("stored_tyre_tester")}}) {
    window_->workArea()->setCurrentPage(page);
    QTest::qWait(200);
    const QString shot = QDir(folder).filePath(name + suffix + QStringLiteral(".png"));
    QVERIFY(window_->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));
  }
}

// The Stiffness Rig opened in Italian says its status in Italian, and in
// English after the switch (it stayed Italian).
void DemoPagesTest::stiffnessRigStatusFollowsTheLanguage() {
  openDemoAt1280WithTheDock();
  // A fresh page, made while the language is Italian.
  for (int i = window_->workArea()->count() - 1; i >= 0; --i)
    if (qobject_cast<mozzi::views::RigTestPage*>(window_->workArea()->page(i)))
      emit window_->workArea()->tabCloseRequested(i);  // as the tab's close button does
  QTest::qWait(50);
  QVERIFY(!window_->workArea()->findPage(QStringLiteral("stiffness-rig")));
  QVERIFY(window_->setLanguage(QStringLiteral("it")));
  auto* stiff = qobject_cast<mozzi::views::RigTestPage*>(window_->openPage(QStringLiteral("stiffness-rig")));
  QVERIFY(stiff);
  QTest::qWait(50);
  QCOMPARE(stiff->statusText(), QStringLiteral("Pronto. Scegli una prova e premi Esegui."));
  QVERIFY(window_->setLanguage(QStringLiteral("en")));
  QTRY_COMPARE(stiff->statusText(), QStringLiteral("Ready. Pick a test and press Run."));
  QCOMPARE(stiff->runButton()->text(), QStringLiteral("Run (F5)"));
  // The stored test's table follows too: the whole-test rows say so in English.
  QVERIFY(stiff->resultsTable()->rowCount() > 0);
  QCOMPARE(stiff->resultsTable()->item(0, 0)->text(), QStringLiteral("whole test"));  // whole-test rows first
}

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  DemoPagesTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "demo_pages_test.moc"
