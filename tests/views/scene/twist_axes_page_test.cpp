// The twist-axes page (issue 22) on a project holding a static ramp and a
// sine sweep of frame A front-constrained, run by the stiffness-rig sequences
// on the simulated rig (devices/rigtests, as the demo builds its tests).
// Checked against independent sources:
//  - the drawn static axis against the result the project stores for the
//    test (read here straight from the store): its inclination and the
//    stored foot on the drawn line, both to 1e-9, and within one pixel at
//    the plotted scale (the criterion);
//  - the drawn dynamic axis at each slider position against the axis core
//    computes for that frequency from the stored laser phasors and the laser
//    layout the simulated rig was built with (core::stiffness::phasorTwistAxis);
//    the trace through each axis's foot from the load point;
//  - the view's equal aspect, the labels, the table's k_lat;
//  - every static virtual specimen has a silhouette.
// Screenshots: twist_axes (1 Hz), twist_axes_20hz (and @2x under QT_SCALE_FACTOR=2, tests/views/screenshot.h).
#include "views/scene/twist_axes_page.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_scale_map.h>
#include <qwt_text.h>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QProcess>
#include <QSlider>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/io/project_store.h"
#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/silhouettes.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/marker_labels.h"
#include "views/screenshot.h"

using mozzi::views::JobRunner;
using mozzi::views::PageContext;
using mozzi::views::ProjectModel;
using mozzi::views::RecordKind;
using mozzi::views::TwistAxesPage;
namespace rt = mozzi::devices::rigtests;
namespace st = mozzi::core::stiffness;
using mozzi::core::Vector2;

namespace {

constexpr double kPi = 3.14159265358979323846;
const char* const kSpecimen = "frame-a-front-constrained";
constexpr std::uint64_t kSeed = 11;
const std::vector<double> kFrequencies{1, 5, 10, 15, 20};

// Every pair of label rectangles on the plot apart (markerLabelRect: where
// Qwt paints them); the pairs that touch are printed.
bool noLabelOverlaps(TwistAxesPage& page) {
  const auto pairs = mozzi::views::overlappingMarkerLabels(page.plot());
  for (const auto& [a, b] : pairs)
    qWarning("labels overlap: %s / %s", qPrintable(a->label().text()), qPrintable(b->label().text()));
  return pairs.empty();
}

void saveShot(QWidget& page, const QString& name) {
  // Results posted just before are laid out first.
  mozzi::views::test::saveShot(page, name, 200);
}

// The whole-test (or one step's) stored value of `key`.
double stored(const mozzi::core::io::StoredRigTest& t, const std::string& key, std::optional<int> step = {}) {
  for (const auto& r : t.results)
    if (r.quantity == key && r.step == step) return r.value;
  return std::nan("");
}

// The drawn line's inclination from +v towards +u, folded into (-pi/2, pi/2].
double inclination(const QPointF& a, const QPointF& b) {
  double beta = std::atan2(b.x() - a.x(), b.y() - a.y());
  if (beta > kPi / 2) beta -= kPi;
  if (beta <= -kPi / 2) beta += kPi;
  return beta;
}

double angleDifference(double a, double b) {  // lines: modulo pi
  double d = std::fmod(a - b, kPi);
  if (d > kPi / 2) d -= kPi;
  if (d < -kPi / 2) d += kPi;
  return std::abs(d);
}

double distanceFromLine(const QPointF& p, const QPointF& a, const QPointF& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  return std::abs((p.x() - a.x()) * dy - (p.y() - a.y()) * dx) / std::hypot(dx, dy);
}

}  // namespace

class TwistAxesPageTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    auto created = model_.create(dir_.filePath(QStringLiteral("twist.mozzi")));
    QVERIFY2(created.ok(), created.ok() ? "" : created.error().describe().c_str());
    auto& store = *model_.store();
    auto who = rt::resolveSpecimen(store, kSpecimen);
    QVERIFY(who.ok());
    auto setup = rt::simulatedStiffnessSetup(kSpecimen, kSeed, false);
    QVERIFY(setup.ok());
    setup_ = *setup;
    auto dev = mozzi::devices::sim::makeStiffnessRigDriver()->create(
        mozzi::devices::DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
    QVERIFY(dev.ok());
    rt::StaticTestSettings statics;
    statics.periodS = 4.0;
    auto s = rt::runStaticStiffnessTest(**dev, nullptr, *setup, statics,
                                        rt::StoreTarget{&store, who->specimenId, "static ramp"});
    QVERIFY2(s.ok(), s.ok() ? "" : s.error().describe().c_str());
    QVERIFY(s->testId.has_value());
    staticId_ = *s->testId;
    rt::DynamicTestSettings sine;
    sine.frequenciesHz = kFrequencies;
    auto d = rt::runDynamicStiffnessTest(**dev, nullptr, *setup, sine,
                                         rt::StoreTarget{&store, who->specimenId, "sine sweep"});
    QVERIFY2(d.ok(), d.ok() ? "" : d.error().describe().c_str());
    QVERIFY(d->testId.has_value());
    dynamicId_ = *d->testId;
    model_.notifyChanged(RecordKind::RigTest);
  }

  void drawsTheStoredStaticAxisAndTheDynamicAxisCoreComputes() {
    PageContext ctx{&model_, &jobs_, {RecordKind::RigTest, dynamicId_, 0}, nullptr, {}};
    TwistAxesPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    QTest::qWait(50);  // the queued re-clip after the layout's resize
    // Opened on the sweep, the page shows it and the specimen's static test.
    QCOMPARE(page.dynamicBox()->currentData().toLongLong(), dynamicId_);
    QCOMPARE(page.staticBox()->currentData().toLongLong(), staticId_);
    QVERIFY2(page.statusText().isEmpty(), qPrintable(page.statusText()));

    auto test = model_.store()->rigTest(staticId_);
    QVERIFY(test.ok());
    const double beta = stored(*test, "axis_inclination");
    const QPointF foot(stored(*test, "axis_point_u"), stored(*test, "axis_point_v"));
    QVERIFY(std::isfinite(beta) && std::isfinite(foot.x()));
    qInfo("stored static axis: foot (%.6f, %.6f) m, inclination %.4f deg", foot.x(), foot.y(), beta * 180 / kPi);

    auto* plot = page.plot();
    const QwtScaleMap xMap = plot->canvasMap(QwtPlot::xBottom), yMap = plot->canvasMap(QwtPlot::yLeft);
    // Equal aspect: one metre as many pixels across as up.
    const double pxPerMetreX = std::abs(xMap.pDist() / xMap.sDist()),
                 pxPerMetreY = std::abs(yMap.pDist() / yMap.sDist());
    QVERIFY2(std::abs(pxPerMetreX / pxPerMetreY - 1.0) < 0.01,
             qPrintable(QStringLiteral("%1 vs %2 px/m").arg(pxPerMetreX).arg(pxPerMetreY)));

    // The static axis: the stored foot on the drawn line, the stored inclination.
    auto* axis = page.staticAxisCurve();
    QCOMPARE(axis->dataSize(), size_t{2});
    const QPointF a = axis->sample(0), b = axis->sample(1);
    QVERIFY2(angleDifference(inclination(a, b), beta) < 1e-9,
             qPrintable(QString::number(inclination(a, b) - beta, 'g', 3)));
    QVERIFY2(distanceFromLine(foot, a, b) < 1e-9, qPrintable(QString::number(distanceFromLine(foot, a, b))));
    // ... within one pixel where it is drawn.
    const QPointF fp(xMap.transform(foot.x()), yMap.transform(foot.y()));
    const QPointF ap(xMap.transform(a.x()), yMap.transform(a.y())), bp(xMap.transform(b.x()), yMap.transform(b.y()));
    QVERIFY(distanceFromLine(fp, ap, bp) < 1.0);
    // The line runs across the whole view: its ends on the view's edges.
    const QwtInterval xi = plot->axisInterval(QwtPlot::xBottom), yi = plot->axisInterval(QwtPlot::yLeft);
    auto onEdge = [&](const QPointF& p) {
      const double tol = 1e-9 * std::max(xi.width(), yi.width());
      return std::abs(p.x() - xi.minValue()) < tol || std::abs(p.x() - xi.maxValue()) < tol ||
             std::abs(p.y() - yi.minValue()) < tol || std::abs(p.y() - yi.maxValue()) < tol;
    };
    QVERIFY(onEdge(a) && onEdge(b));
    // The view holds the load point, the lasers and the static axis's foot.
    for (const auto& p : setup_.laserPoints) QVERIFY(xi.contains(p(0)) && yi.contains(p(1)));
    QVERIFY(xi.contains(foot.x()) && yi.contains(foot.y()));

    // The dynamic axis at every slider position: the axis core computes from
    // the stored laser phasors of that frequency and the rig's laser layout.
    QSlider* slider = page.frequencySlider();
    QCOMPARE(slider->maximum() + 1, static_cast<int>(kFrequencies.size()));
    auto dtest = model_.store()->rigTest(dynamicId_);
    QVERIFY(dtest.ok());
    std::vector<QPointF> feet;
    for (int k = 0; k <= slider->maximum(); ++k) {
      slider->setValue(k);
      QCOMPARE(*page.shownFrequencyHz(), kFrequencies[static_cast<std::size_t>(k)]);
      mozzi::core::ComplexVector y(4);
      for (int i = 0; i < 4; ++i) {
        const std::string key = "laser_" + std::to_string(i + 1);
        y(i) = std::polar(stored(*dtest, key + "_amplitude", k), stored(*dtest, key + "_phase", k));
      }
      auto expected = st::phasorTwistAxis(setup_.laserPoints, y, setup_.loadPoint);
      QVERIFY2(expected.ok(), expected.ok() ? "" : expected.error().describe().c_str());
      const auto& e = expected->axis.axis;
      auto* dyn = page.dynamicAxisCurve();
      QCOMPARE(dyn->dataSize(), size_t{2});
      const QPointF da = dyn->sample(0), db = dyn->sample(1);
      const QPointF ef(e.point(0), e.point(1));
      qInfo("%5.1f Hz: core axis foot (%.6f, %.6f) m, inclination %.4f deg; drawn %.4f deg", kFrequencies[k], ef.x(),
            ef.y(), e.beta * 180 / kPi, inclination(da, db) * 180 / kPi);
      QVERIFY2(angleDifference(inclination(da, db), e.beta) < 1e-9, qPrintable(QString::number(k)));
      QVERIFY2(distanceFromLine(ef, da, db) < 1e-9, qPrintable(QString::number(distanceFromLine(ef, da, db))));
      // Its foot from the load point is the trace's k-th point.
      const Vector2 f = e.point - e.direction * (e.point - setup_.loadPoint).dot(e.direction);
      const QPointF traced = page.pathCurve()->sample(static_cast<size_t>(k));
      QVERIFY(std::hypot(traced.x() - f(0), traced.y() - f(1)) < 1e-9);
      feet.push_back(traced);
      QVERIFY(page.plotLabels().contains(
          QStringLiteral("dynamic twist axis, %1 Hz").arg(kFrequencies[static_cast<std::size_t>(k)], 0, 'g', 4)));
      QVERIFY(page.resultsTable()->horizontalHeaderItem(2)->text().contains(
          QString::number(kFrequencies[static_cast<std::size_t>(k)], 'g', 4)));
      // No label covers another, at every frequency (the axes' labels move with it).
      QTest::qWait(20);  // the labels are placed once the view has settled
      QVERIFY2(noLabelOverlaps(page), qPrintable(QString::number(k)));
      if (k == 0) saveShot(page, QStringLiteral("twist_axes"));
    }
    QCOMPARE(page.pathCurve()->dataSize(), kFrequencies.size());
    // The axis moves with frequency (towards the bending axis as 26.5 Hz nears).
    QVERIFY(std::hypot(feet.back().x() - feet.front().x(), feet.back().y() - feet.front().y()) > 0.01);

    // Labels: the load point, the constrained end, the centre of gravity, the axes.
    const QStringList labels = page.plotLabels();
    for (const QString& l :
         {QStringLiteral("load point (swing-arm pivot)"), QStringLiteral("steering head (constrained)"),
          QStringLiteral("centre of gravity (estimated)"), QStringLiteral("static twist axis"),
          QStringLiteral("bending axis (set-up)"), QStringLiteral("torsion axis (set-up)"), QStringLiteral("L1")})
      QVERIFY2(labels.contains(l), qPrintable(l + QStringLiteral(" not in ") + labels.join(QStringLiteral(" | "))));
    QVERIFY(page.silhouetteText().startsWith(QStringLiteral("Frame A")));

    // The table: the stored k_lat with its uncertainty, in kN/m.
    auto* table = page.resultsTable();
    QCOMPARE(table->item(0, 0)->data(Qt::UserRole).toString(), QStringLiteral("k_lat"));
    const QString kLat = QString::number(stored(*test, "k_lat") * 1e-3, 'f', 1);
    QVERIFY2(table->item(0, 1)->text().startsWith(kLat + QStringLiteral(" ± ")), qPrintable(table->item(0, 1)->text()));
    QVERIFY(table->item(0, 1)->text().endsWith(QStringLiteral("kN/m")));
    QVERIFY(table->item(3, 1)->text().endsWith(QStringLiteral("°")));
    QVERIFY(table->item(0, 2)->text().endsWith(QStringLiteral("kN/m")));  // the 20 Hz step's k_lat
    saveShot(page, QStringLiteral("twist_axes_20hz"));

    // Only the static test: no dynamic axis, no trace.
    QVERIFY(page.selectTests(staticId_, std::nullopt));
    QCOMPARE(page.dynamicAxisCurve()->dataSize(), size_t{0});
    QCOMPARE(page.pathCurve()->dataSize(), size_t{0});
    QVERIFY(!page.frequencySlider()->isEnabled());
    QCOMPARE(page.staticAxisCurve()->dataSize(), size_t{2});
  }

  // Fork A with wheel, as the demo holds it (thesis Fig. 28, 29): the fork and
  // its wheel, the sweep of 1 to 15 Hz traced as the axis moves.
  void forkAOverItsWheel() {
    auto& store = *model_.store();
    const std::string key = "fork-a-with-wheel";
    auto who = rt::resolveSpecimen(store, key);
    QVERIFY(who.ok());
    auto setup = rt::simulatedStiffnessSetup(key, kSeed, false);
    QVERIFY(setup.ok());
    auto dev = mozzi::devices::sim::makeStiffnessRigDriver()->create(
        mozzi::devices::DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
    QVERIFY(dev.ok());
    rt::StaticTestSettings statics;
    statics.periodS = 4.0;
    auto s = rt::runStaticStiffnessTest(**dev, nullptr, *setup, statics, rt::StoreTarget{&store, who->specimenId, ""});
    QVERIFY(s.ok() && s->testId);
    rt::DynamicTestSettings sine;
    sine.frequenciesHz = {1, 3, 5, 8, 10, 12, 15};
    auto d = rt::runDynamicStiffnessTest(**dev, nullptr, *setup, sine, rt::StoreTarget{&store, who->specimenId, ""});
    QVERIFY(d.ok() && d->testId);
    model_.notifyChanged(RecordKind::RigTest);

    PageContext ctx{&model_, &jobs_, {}, nullptr, {}};
    TwistAxesPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    page.showRigTest(*s->testId);
    QCOMPARE(page.staticBox()->currentData().toLongLong(), *s->testId);
    QCOMPARE(page.dynamicBox()->currentData().toLongLong(), *d->testId);
    QVERIFY(page.silhouetteText().startsWith(QStringLiteral("Fork A")));
    QCOMPARE(page.pathCurve()->dataSize(), size_t{7});
    QVERIFY(page.plotLabels().contains(QStringLiteral("steering head (constrained)")));
    QVERIFY(page.plotLabels().contains(QStringLiteral("load point (wheel contact point)")));
    QVERIFY(!page.plotLabels().contains(QStringLiteral("centre of gravity (estimated)")));  // none known for forks
    page.frequencySlider()->setValue(page.frequencySlider()->maximum());
    QCOMPARE(*page.shownFrequencyHz(), 15.0);
    QTest::qWait(20);
    QVERIFY(noLabelOverlaps(page));
    saveShot(page, QStringLiteral("twist_axes_fork_a"));
  }

  // The demo project (scripts/run.sh opens it) holds a static and a sine test
  // of fork A with wheel and of frame A: the page shows both specimens.
  void theDemoProjectShowsItsTests() {
    const QString demo = dir_.filePath(QStringLiteral("demo.mozzi"));
    QProcess cli;
    cli.start(QStringLiteral(MOZZI_CLI_PATH), {QStringLiteral("project"), QStringLiteral("demo"), demo});
    QVERIFY(cli.waitForFinished(120000));
    QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
    ProjectModel model;
    QVERIFY(model.open(demo).ok());
    PageContext ctx{&model, &jobs_, {}, nullptr, {}};
    TwistAxesPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    QStringList silhouettes;
    for (int i = 0; i < page.specimenBox()->count(); ++i) {
      page.specimenBox()->setCurrentIndex(i);
      QVERIFY2(page.statusText().isEmpty(), qPrintable(page.statusText()));
      QCOMPARE(page.staticAxisCurve()->dataSize(), size_t{2});
      QVERIFY(page.pathCurve()->dataSize() >= 5);
      silhouettes << page.silhouetteText().section(QLatin1Char(':'), 0, 0);
      if (silhouettes.last().startsWith(QStringLiteral("Frame A"))) saveShot(page, QStringLiteral("twist_axes_demo"));
    }
    silhouettes.sort();
    QCOMPARE(silhouettes, QStringList({QStringLiteral("Fork A (enduro)"), QStringLiteral("Frame A (steel, enduro)")}));
  }

  void anEmptyProjectSaysSo() {
    ProjectModel empty;
    QTemporaryDir dir;
    QVERIFY(empty.create(dir.filePath(QStringLiteral("empty.mozzi"))).ok());
    PageContext ctx{&empty, &jobs_, {}, nullptr, {}};
    TwistAxesPage page(ctx);
    QVERIFY(page.statusText().contains(QStringLiteral("No stiffness-rig test")));
    QCOMPARE(page.staticAxisCurve()->dataSize(), size_t{0});
  }

  void everyStaticSpecimenHasASilhouette() {
    std::ifstream in(std::string(MOZZI_SOURCE_DIR) + "/resources/silhouettes/silhouettes.json");
    std::stringstream text;
    text << in.rdbuf();
    auto catalogue = st::parseSilhouettes(text.str());
    QVERIFY(catalogue.ok());
    for (const auto& key : mozzi::devices::sim::staticSpecimenKeys())
      QVERIFY2(catalogue->placement(key) != nullptr, key.c_str());
    for (const auto& e : mozzi::devices::sim::specimenCatalogue())
      if (e.kind == "bicycle-fork") QVERIFY2(catalogue->placement(e.key) != nullptr, e.key.c_str());
  }

 private:
  QTemporaryDir dir_;
  ProjectModel model_;
  JobRunner jobs_;
  rt::StiffnessRigSetup setup_;
  qint64 staticId_ = 0, dynamicId_ = 0;
};

QTEST_MAIN(TwistAxesPageTest)
#include "twist_axes_page_test.moc"
