// The demo project's analysis pages as a newcomer meets them in the first
// five minutes (scripts/run.sh), in the main window at 1280x800 (and at
// QT_SCALE_FACTOR=2): the project dock at 260 pixels shows every specimen's
// whole name; the FRF page fits its tab and its axis titles their axes; the
// Identification page shows the set's sum and the kept modes with their
// synthesis before any run, against the stored set and table; the Mode
// Animation page keeps the shape inside the 3-D viewport over the cycle; the
// Twist Axes page's labels do not cover each other. Each page is saved as
// demo_<id>[_scale2].png in MOZZI_SCREENSHOT_DIR after its checks.
// MOZZI_DEMO_PROJECT may name a demo made by `mozzi-cli project demo` (a
// copy is opened); otherwise the test makes one (minutes).
#include <qwt_plot.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_scale_widget.h>
#include <qwt_text.h>
#include <vtkPoints.h>
#include <vtkRenderer.h>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QtTest>
#include <cmath>
#include <memory>

#include "app/gui/main_window.h"
#include "core/io/project_store.h"
#include "views/common/project_model.h"
#include "views/common/project_tree.h"
#include "views/modal/identification_page.h"
#include "views/panels/project_overview.h"
#include "views/plots/decimating_curve.h"
#include "views/plots/frf_plot.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/marker_labels.h"
#include "views/plots/stabilization_plot.h"
#include "views/scene/mode_animation_page.h"
#include "views/scene/mode_animation_view.h"
#include "views/scene/scene_view.h"
#include "views/scene/twist_axes_page.h"

using mozzi::app::MainWindow;
using mozzi::views::ProjectItem;
using mozzi::views::RecordKind;

class DemoPagesTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void projectDockShowsWholeNames();
  void frfPage();
  void identificationPage();
  void modeAnimationPage();
  void twistAxesPage();

 private:
  // Opens page `id` as the Overview's start list does, and the checks' screenshot afterwards.
  QWidget* open(const QString& id);
  void shot(const QString& id);
  void checkFrfPage(QWidget* page);
  void checkIdentificationPage(QWidget* page);
  void checkModeAnimationPage(QWidget* page);
  void checkTwistAxesPage(QWidget* page);
  std::unique_ptr<MainWindow> window_;
  QTemporaryDir dir_;
  QTemporaryDir settingsDir_;
};

void DemoPagesTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
  QApplication::setOrganizationName(QStringLiteral("MozziDemoPagesTest"));
  QApplication::setApplicationName(QStringLiteral("MozziDemoPagesTest"));
  window_ = std::make_unique<MainWindow>();
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  const QString demo = QDir(dir_.path()).filePath(QStringLiteral("demo.mozzi"));
  const QString made = qEnvironmentVariable("MOZZI_DEMO_PROJECT");
  if (!made.isEmpty()) QVERIFY(QFile::copy(made, demo));
  QVERIFY(made.isEmpty() ? window_->createDemoProject(demo) : window_->openProject(demo));
  window_->showNormal();
  window_->resize(1280, 800);
  auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("projectDock"));
  QVERIFY(dock);
  window_->resizeDocks({dock}, {260}, Qt::Horizontal);
  QTest::qWait(100);
}

QWidget* DemoPagesTest::open(const QString& id) {
  auto* overview = window_->findChild<mozzi::views::ProjectOverview*>();
  if (!overview) return nullptr;
  const auto entries = overview->startEntries();
  for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
    if (entries[static_cast<std::size_t>(i)].pageId != id) continue;
    QElapsedTimer clock;
    clock.start();
    QWidget* page = overview->openStartEntry(i);
    qInfo("%s opened in %.1f ms (GUI thread)", qPrintable(id), static_cast<double>(clock.nsecsElapsed()) * 1e-6);
    QTest::qWait(200);
    return page;
  }
  return nullptr;
}

void DemoPagesTest::shot(const QString& id) {
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString suffix = scale.isEmpty() ? QString() : QStringLiteral("_scale%1").arg(scale);
  const QString path = QDir(folder).filePath(QStringLiteral("demo_%1%2.png").arg(id, suffix));
  QVERIFY(window_->grab().save(path));
  qInfo("screenshot: %s", qPrintable(path));
}

// The project dock at 260 pixels.
void DemoPagesTest::projectDockShowsWholeNames() {
  auto* tree = window_->projectTree();
  tree->expandAll();
  QTest::qWait(50);
  // Names too long for the dock's line wrap onto more lines, the row as tall
  // as they need: every specimen's whole name is shown (the tyres' and forks'
  // names differ at their ends) and is the row's tooltip.
  {
    const QFontMetrics fm(tree->font());
    int wrapped = 0;
    for (QTreeWidgetItemIterator it(tree); *it; ++it) {
      const ProjectItem item = mozzi::views::ProjectTree::itemOf(*it);
      if (item.kind == RecordKind::None) continue;
      const QString name = (*it)->text(0);
      QVERIFY2((*it)->toolTip(0).contains(name), qPrintable(name));
      if (item.kind != RecordKind::Specimen) continue;
      const QStringList lines = tree->shownLines(*it);
      QCOMPARE(lines.join(QLatin1Char(' ')), name);  // nothing cut
      if (lines.size() > 1) ++wrapped;
      int depth = 0;
      for (QTreeWidgetItem* up = (*it)->parent(); up; up = up->parent()) ++depth;
      const int cell = tree->columnWidth(0) - tree->indentation() * (depth + 1);
      for (const QString& line : lines) QVERIFY2(fm.horizontalAdvance(line) <= cell, qPrintable(line));
      tree->scrollToItem(*it);
      const QRect row = tree->visualItemRect(*it);
      QVERIFY2(row.height() >= fm.height() * lines.size(),
               qPrintable(QStringLiteral("%1: row %2 px for %3 lines").arg(name).arg(row.height()).arg(lines.size())));
    }
    QVERIFY(wrapped > 0);  // the demo's names do not all fit 260 pixels on one line: the check above bites
    tree->scrollToTop();
    qInfo("project dock at 260 px: %d specimen names on two lines or more, each whole", wrapped);
  }
  auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("projectDock"));
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString path =
      QDir(folder).filePath(scale.isEmpty() ? QStringLiteral("demo_project_dock.png")
                                            : QStringLiteral("demo_project_dock_scale%1.png").arg(scale));
  QVERIFY(dock->grab().save(path));
  qInfo("screenshot: %s", qPrintable(path));
}

void DemoPagesTest::frfPage() {
  QWidget* page = open(QStringLiteral("frf-plot"));
  QVERIFY(page);
  checkFrfPage(page);
  shot(QStringLiteral("frf-plot"));
}

void DemoPagesTest::identificationPage() {
  QWidget* page = open(QStringLiteral("identification"));
  QVERIFY(page);
  checkIdentificationPage(page);
  shot(QStringLiteral("identification"));
}

void DemoPagesTest::modeAnimationPage() {
  QWidget* page = open(QStringLiteral("mode-animation"));
  QVERIFY(page);
  checkModeAnimationPage(page);
  shot(QStringLiteral("mode-animation"));
}

void DemoPagesTest::twistAxesPage() {
  QWidget* page = open(QStringLiteral("twist-axes"));
  QVERIFY(page);
  checkTwistAxesPage(page);
  shot(QStringLiteral("twist-axes"));
}

namespace {

// The scroll area the window holds a page in.
QScrollArea* holderOf(QWidget* page) {
  for (QWidget* w = page->parentWidget(); w; w = w->parentWidget())
    if (auto* area = qobject_cast<QScrollArea*>(w)) return area;
  return nullptr;
}

// The page fits its tab at 1280x800: no page scroll, everything in view.
bool fitsItsTab(QWidget* page) {
  QScrollArea* holder = holderOf(page);
  if (holder)
    qInfo("%s: least %dx%d in a viewport of %dx%d", qPrintable(page->objectName()), page->minimumSizeHint().width(),
          page->minimumSizeHint().height(), holder->viewport()->width(), holder->viewport()->height());
  return holder && !holder->verticalScrollBar()->isVisible() && !holder->horizontalScrollBar()->isVisible();
}

// An axis title is wrapped at spaces to the axis's length: a word longer
// than the axis is cut at both ends ("oherenc").
bool titleFits(const QwtPlot* plot, int axis) {
  const QwtScaleWidget* w = plot->axisWidget(axis);
  const double length = axis == QwtPlot::yLeft || axis == QwtPlot::yRight ? w->height() : w->width();
  QwtText word = w->title();
  for (const QString& part : w->title().text().split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
    word.setText(part);
    if (word.textSize(w->font()).width() > length) return false;
  }
  return true;
}

}  // namespace

void DemoPagesTest::checkFrfPage(QWidget* page) {
  auto* frf = page->findChild<mozzi::views::FrfPlot*>();
  QVERIFY(frf);
  QVERIFY2(fitsItsTab(page), "the FRF page scrolls");
  int shown = 0;
  for (mozzi::views::InteractivePlot* plot : {frf->mainPlot(), frf->secondaryPlot(), frf->coherencePlot()}) {
    if (!plot->isVisible()) continue;
    ++shown;
    QVERIFY2(titleFits(plot, QwtPlot::yLeft),
             qPrintable(QStringLiteral("%1: '%2' on %3 px")
                            .arg(plot->objectName(), plot->axisTitle(QwtPlot::yLeft).text())
                            .arg(plot->axisWidget(QwtPlot::yLeft)->height())));
  }
  QCOMPARE(shown, 3);  // Bode over the coherence: the demo's sets have coherence
  // The readout under the plots is in view.
  auto* readout = frf->findChild<QLabel*>(QStringLiteral("frfReadout"));
  QVERIFY(readout && readout->isVisible());
  QVERIFY(holderOf(page)->viewport()->rect().contains(
      QRect(readout->mapTo(holderOf(page)->viewport(), QPoint(0, 0)), readout->size())));
}

// Opened on an FRF set, before any run: the set's sum in the diagram, and the
// modes of the modal result the demo keeps for the set with their synthesis,
// against the stored set and table.
void DemoPagesTest::checkIdentificationPage(QWidget* page) {
  auto* ident = qobject_cast<mozzi::views::IdentificationPage*>(page);
  QVERIFY(ident);
  QVERIFY2(fitsItsTab(page), "the Identification page scrolls");
  auto* store = window_->model()->store();
  auto frf = store->frfSet(ident->frfSetId());
  QVERIFY(frf.ok());
  // Backdrop: 20 log10 |sum of every FRF| on every line above 0 Hz.
  const auto* backdrop = ident->diagramPlot()->backdropCurve();
  Eigen::Index first = 0;
  while (!(frf->frequencyHz[first] > 0.0)) ++first;
  QCOMPARE(static_cast<Eigen::Index>(backdrop->dataSize()), frf->lineCount() - first);
  double worstDb = 0.0;
  for (Eigen::Index k = first; k < frf->lineCount(); ++k) {
    mozzi::core::Complex sum = 0.0;
    for (const auto& h : frf->h) sum += h.row(k).sum();
    const QPointF p = backdrop->sample(static_cast<std::size_t>(k - first));
    QCOMPARE(p.x(), frf->frequencyHz[k]);
    worstDb = std::max(worstDb, std::abs(p.y() - 20.0 * std::log10(std::abs(sum))));
  }
  QVERIFY2(worstDb < 1e-9, qPrintable(QString::number(worstDb)));
  QCOMPARE(ident->diagramPlot()->drawnPoleCount(), 0);  // no run yet
  // The kept identification: the demo's latest modal result of this set.
  auto results = store->modalResults();
  QVERIFY(results.ok());
  const mozzi::core::io::ModalResultInfo* kept = nullptr;
  for (const auto& r : *results)
    if (r.frfSetId && *r.frfSetId == ident->frfSetId() && (!kept || r.id > kept->id)) kept = &r;
  QVERIFY(kept);
  QVERIFY(ident->keptResult());
  QCOMPARE(ident->keptResult()->id, kept->id);
  auto table = store->modalResult(kept->id);
  QVERIFY(table.ok());
  const std::size_t modes = table->modes.size();
  QVERIFY(modes > 0);
  QCOMPARE(ident->chosenPoles().size(), modes);
  QCOMPARE(ident->diagramPlot()->modeLineFrequencies().size(), modes);
  QCOMPARE(ident->tableRows().size(), modes);
  QCOMPARE(ident->modalTable()->rowCount(), static_cast<int>(modes));
  {  // every kept mode's row in view (the demo keeps three)
    QTableWidget* t = ident->modalTable();
    const int last = static_cast<int>(modes) - 1;
    QVERIFY2(t->rowViewportPosition(last) + t->rowHeight(last) <= t->viewport()->height(),
             qPrintable(QStringLiteral("row %1 ends at %2 of %3 px")
                            .arg(last)
                            .arg(t->rowViewportPosition(last) + t->rowHeight(last))
                            .arg(t->viewport()->height())));
  }
  // The table gives back the stored f and zeta (the window's decay put back
  // for the fit and removed again): 1e-9 relative.
  for (std::size_t m = 0; m < modes; ++m) {
    const auto& row = ident->tableRows()[m];
    QVERIFY2(std::abs(row.frequencyHz - table->modes[m].frequencyHz) <= 1e-9 * table->modes[m].frequencyHz,
             qPrintable(QStringLiteral("%1 vs %2").arg(row.frequencyHz).arg(table->modes[m].frequencyHz)));
    QVERIFY2(std::abs(row.zeta - table->modes[m].dampingRatio) <= 1e-9 * table->modes[m].dampingRatio + 1e-12,
             qPrintable(QStringLiteral("%1 vs %2").arg(row.zeta).arg(table->modes[m].dampingRatio)));
  }
  // The synthesis of the strongest FRF over the kept band, beside the measured one.
  const auto curves = ident->synthesisPlot()->itemList(QwtPlotItem::Rtti_PlotCurve);
  QCOMPARE(curves.size(), 2);
  std::size_t bandLines = 0;
  for (Eigen::Index k = 0; k < frf->lineCount(); ++k)
    if (frf->frequencyHz[k] >= kept->bandLowHz && frf->frequencyHz[k] <= kept->bandHighHz) ++bandLines;
  for (const QwtPlotItem* c : curves) QCOMPARE(static_cast<const QwtPlotCurve*>(c)->dataSize(), bandLines);
  QCOMPARE(ident->residualTable()->rowCount(), static_cast<int>(frf->responseCount() * frf->referenceCount()));
  qInfo("identification on set %lld: backdrop %zu lines, kept result %lld with %zu modes, synthesis on %zu lines",
        static_cast<long long>(ident->frfSetId()), backdrop->dataSize(), static_cast<long long>(kept->id), modes,
        bandLines);
}

// The shape animated on the demo stays in the 3-D view over the whole cycle:
// the corners of the box it sweeps and every deformed point at eight phases
// fall inside the viewport (VTK's world to display transform).
void DemoPagesTest::checkModeAnimationPage(QWidget* page) {
  auto* animation = qobject_cast<mozzi::views::ModeAnimationPage*>(page);
  QVERIFY(animation);
  QVERIFY2(fitsItsTab(page), "the Mode Animation page scrolls");
  mozzi::views::ModeAnimationView* view = animation->view();
  mozzi::views::SceneView* scene = view->scene();
  QVERIFY(scene->hasShape());
  QTRY_VERIFY(scene->isReady());
  QTest::qWait(100);  // the reframing after the last resize
  QScrollArea* holder = holderOf(page);
  QVERIFY(holder->viewport()->rect().contains(QRect(scene->mapTo(holder->viewport(), QPoint(0, 0)), scene->size())));
  vtkRenderer* renderer = scene->renderer();
  const int* size = renderer->GetSize();
  auto inView = [&](double x, double y, double z) {
    renderer->SetWorldPoint(x, y, z, 1.0);
    renderer->WorldToDisplay();
    double d[3];
    renderer->GetDisplayPoint(d);
    return d[0] >= 0.0 && d[0] <= size[0] && d[1] >= 0.0 && d[1] <= size[1];
  };
  const auto b = scene->drawnBounds();
  for (int corner = 0; corner < 8; ++corner) {
    const double x = b[corner & 1], y = b[2 + ((corner >> 1) & 1)], z = b[4 + ((corner >> 2) & 1)];
    QVERIFY2(inView(x, y, z), qPrintable(QStringLiteral("corner %1 (%2, %3, %4) out of %5 x %6")
                                             .arg(corner)
                                             .arg(x)
                                             .arg(y)
                                             .arg(z)
                                             .arg(size[0])
                                             .arg(size[1])));
  }
  for (int k = 0; k < 8; ++k) {
    view->setPhase(k * M_PI / 4.0);
    vtkPoints* points = scene->deformedPoints();
    QVERIFY(points->GetNumberOfPoints() > 0);
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
      double p[3];
      points->GetPoint(i, p);
      QVERIFY2(inView(p[0], p[1], p[2]), qPrintable(QStringLiteral("node row %1 at phase %2").arg(i).arg(k)));
    }
  }
  view->setPhase(0.0);
}

// Twist axes over Frame A: no label covers another.
void DemoPagesTest::checkTwistAxesPage(QWidget* page) {
  auto* twist = qobject_cast<mozzi::views::TwistAxesPage*>(page);
  QVERIFY(twist);
  QTest::qWait(50);  // the labels are placed after the view settles
  const auto overlaps = mozzi::views::overlappingMarkerLabels(twist->plot());
  QStringList pairs;
  for (const auto& [a, b] : overlaps) pairs << a->label().text() + QStringLiteral(" / ") + b->label().text();
  QVERIFY2(overlaps.empty(), qPrintable(pairs.join(QStringLiteral("; "))));
  QVERIFY(twist->plotLabels().size() >= 8);  // load point, constrained end, CoG, L1..L4, a_tw, the axes
  const QRectF canvas = twist->plot()->canvas()->contentsRect();
  for (const QwtPlotItem* item : twist->plot()->itemList(QwtPlotItem::Rtti_PlotMarker)) {
    const auto* m = static_cast<const QwtPlotMarker*>(item);
    if (!m->isVisible() || m->label().isEmpty()) continue;
    QVERIFY2(canvas.contains(mozzi::views::markerLabelRect(twist->plot(), m)), qPrintable(m->label().text()));
  }
}

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  DemoPagesTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "demo_pages_test.moc"
