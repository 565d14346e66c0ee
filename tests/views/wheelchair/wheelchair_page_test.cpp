// The Wheelchair page: the slalom trajectories it draws for the cornering
// stiffness study (thesis Figure 58) are those `mozzi-cli wheelchair slalom
// --out` writes for the same chair with that stiffness: every point of the
// plotted path and slip angles against the CLI's CSV (12 significant digits
// written: 1e-9 relative, 1e-12 m absolute near zero). The steady-turning
// manoeuvre ends on the steady turn core's closed form gives (0.5% of the
// radius, the end of a 20 s run). Screenshots for the user guide.
#include "views/wheelchair/wheelchair_page.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "views/screenshot.h"

#include "core/stability/wheelchair_model.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/panels/parameter_form.h"

using mozzi::views::WheelchairPage;
namespace st = mozzi::core::stability;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

QwtPlotCurve* curveTitled(QwtPlot* plot, const QString& title) {
  for (QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve))
    if (item->title().text() == title) return static_cast<QwtPlotCurve*>(item);
  return nullptr;
}

bool close(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)) + 1e-12;
}

}  // namespace

class WheelchairPageTest : public QObject {
  Q_OBJECT
 private slots:
  void slalomStudyEqualsTheCli() {
    mozzi::views::JobRunner jobs;
    WheelchairPage page(nullptr, &jobs);
    page.resize(1280, 800);
    page.show();
    QVERIFY(page.form()
                ->setValues({{"manoeuvre", std::string("slalom")},
                             {"study", std::string("cornering stiffness")},
                             {"speed", 1.2},
                             {"torque", 8.0},
                             {"frequency", 0.3},
                             {"duration", 12.0}})
                .ok());
    QSignalSpy finished(&page, &WheelchairPage::finished);
    page.run();
    QVERIFY(finished.wait(120000));
    QVERIFY2(finished.first().first().toBool(), qPrintable(page.summaryText()));
    QCOMPARE(page.runs().size(), size_t{3});
    const st::WheelchairParameters chair;
    QTemporaryDir dir;
    int checked = 0;
    for (double factor : {0.5, 1.0, 2.0}) {
      const QString csv = dir.filePath(QStringLiteral("slalom_%1.csv").arg(factor));
      QProcess cli;
      cli.start(
          QStringLiteral(MOZZI_CLI_PATH),
          {QStringLiteral("wheelchair"), QStringLiteral("slalom"), QStringLiteral("--speed"), QStringLiteral("1.2"),
           QStringLiteral("--torque"), QStringLiteral("8"), QStringLiteral("--frequency"), QStringLiteral("0.3"),
           QStringLiteral("--duration"), QStringLiteral("12"), QStringLiteral("--cornering-stiffness"),
           QString::number(chair.rearCorneringStiffness * factor, 'g', 17), QStringLiteral("--out"), csv});
      QVERIFY(cli.waitForFinished(120000));
      QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
      QFile file(csv);
      QVERIFY(file.open(QIODevice::ReadOnly));
      const QStringList rows = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
      QVERIFY(rows.size() > 100);
      QVERIFY(rows.first().startsWith(QLatin1String("t_s,x_m,y_m")));
      const QString name = QStringLiteral("C_α × %1").arg(factor);
      QwtPlotCurve* path = curveTitled(page.trajectoryPlot(), name);
      QwtPlotCurve* right = curveTitled(page.slipRightPlot(), name);
      QwtPlotCurve* left = curveTitled(page.slipLeftPlot(), name);
      QVERIFY2(path && right && left, qPrintable(name));
      QCOMPARE(path->dataSize(), size_t(rows.size() - 1));
      for (int i = 1; i < rows.size(); ++i) {
        const QStringList c = rows[i].split(QLatin1Char(','));
        const QPointF p = path->sample(i - 1);
        QVERIFY2(close(p.x(), c[1].toDouble()) && close(p.y(), c[2].toDouble()),
                 qPrintable(QStringLiteral("%1, row %2: page (%3, %4), CLI (%5, %6)")
                                .arg(name)
                                .arg(i)
                                .arg(p.x(), 0, 'g', 15)
                                .arg(p.y(), 0, 'g', 15)
                                .arg(c[1], c[2])));
        QVERIFY(close(right->sample(i - 1).x(), c[0].toDouble()));
        QVERIFY(close(right->sample(i - 1).y() * kDeg, c[9].toDouble()));
        QVERIFY(close(left->sample(i - 1).y() * kDeg, c[10].toDouble()));
        ++checked;
      }
    }
    qInfo("%d trajectory points checked against mozzi-cli wheelchair slalom --out", checked);
    // Figure 58: a stiffer tyre, a larger slalom (§7.3).
    QVERIFY2(page.summaryText().contains(QStringLiteral("lateral amplitude")), qPrintable(page.summaryText()));
    QVERIFY(mozzi::views::test::saveShot(page, QStringLiteral("wheelchair_slalom_cornering")));
  }

  void steadyTurningEndsOnTheSteadyTurn() {
    WheelchairPage page(nullptr, nullptr);  // no job runner: at once
    page.resize(1280, 800);
    page.show();
    QVERIFY(page.form()
                ->setValues({{"manoeuvre", std::string("steady turning")},
                             {"study", std::string("aligning stiffness")},
                             {"torque", 6.0},
                             {"duration", 20.0}})
                .ok());
    page.run();
    QCOMPARE(page.runs().size(), size_t{3});
    for (const auto& run : page.runs()) {
      st::WheelchairParameters p;
      p.rearAligningStiffness *= run.factor;
      const auto steady = st::steadyTurn(p, 4.0 / 3.6, 6.0);
      QVERIFY(steady.ok());
      const auto& end = run.history.back();
      const double radius = std::hypot(end.u, end.v) / std::abs(end.r);
      QVERIFY2(std::abs(radius / steady->radius - 1.0) < 5e-3,
               qPrintable(QStringLiteral("x%1: %2 m, steady %3 m").arg(run.factor).arg(radius).arg(steady->radius)));
      QVERIFY(std::abs(end.slipRight - steady->slipRight) < 5e-3 * std::abs(steady->slipRight) + 1e-9);
    }
    QVERIFY2(page.summaryText().contains(QStringLiteral("C_M × 2: radius")), qPrintable(page.summaryText()));
    QVERIFY(mozzi::views::test::saveShot(page, QStringLiteral("wheelchair_steady_aligning")));
  }

  // With a project open each simulation is kept (analysis of kind
  // "wheelchair") under the wheelchair-tyre specimen, listed, and shown again
  // identically: every plotted point of every run bit for bit.
  void keptRunsReloadIdentically() {
    QTemporaryDir dir;
    mozzi::views::ProjectModel project;
    QVERIFY(project.create(dir.filePath(QStringLiteral("chair.mozzi"))).ok());
    QVERIFY(project.addSpecimen(QStringLiteral("Frame"), QStringLiteral("frame")).ok());
    auto tyres = project.addSpecimen(QStringLiteral("Wheelchair tyres"), QStringLiteral("wheelchair-tyre"));
    QVERIFY(tyres.ok());
    mozzi::views::JobRunner jobs;
    WheelchairPage page(nullptr, &jobs);
    page.resize(1280, 800);
    page.show();
    page.setProjectModel(&project);
    QVERIFY(page.storedResults().empty());
    QVERIFY(page.form()
                ->setValues({{"manoeuvre", std::string("slalom")},
                             {"study", std::string("aligning stiffness")},
                             {"duration", 12.0}})
                .ok());
    QSignalSpy finished(&page, &WheelchairPage::finished);
    page.run();
    QVERIFY(finished.wait(60000));
    QVERIFY2(finished.first().first().toBool(), qPrintable(page.summaryText()));
    const qint64 first = page.lastStoredId();
    QVERIFY2(first > 0, qPrintable(page.summaryText()));
    QCOMPARE(page.storedResults(), std::vector<qint64>{first});
    auto stored = project.store()->analysis(first);
    QVERIFY(stored.ok());
    QCOMPARE(stored->specimenId, *tyres);
    QCOMPARE(stored->kind, std::string("wheelchair"));
    auto points = [&page] {
      std::vector<std::vector<QPointF>> out;
      for (QwtPlot* plot : {page.trajectoryPlot(), page.slipRightPlot(), page.slipLeftPlot()})
        for (QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
          auto* c = static_cast<QwtPlotCurve*>(item);
          std::vector<QPointF> p;
          for (size_t i = 0; i < c->dataSize(); ++i) p.push_back(c->sample(static_cast<int>(i)));
          out.push_back(std::move(p));
        }
      return out;
    };
    const auto computed = points();
    QCOMPARE(computed.size(), size_t{9});  // 3 runs x 3 plots
    QVERIFY(page.form()->setValues({{"study", std::string("none")}}).ok());
    page.run();
    QVERIFY(finished.wait(60000));
    QCOMPARE(page.storedResults().size(), size_t{2});
    QVERIFY(points() != computed);
    QVERIFY(page.showStored(first));
    QVERIFY(points() == computed);
    QVERIFY(mozzi::views::test::saveShot(page, QStringLiteral("wheelchair_kept_aligning")));
  }
};

QTEST_MAIN(WheelchairPageTest)
#include "wheelchair_page_test.moc"
