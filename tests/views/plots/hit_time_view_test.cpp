// The time view of a campaign's stored hits (issue 18): a short campaign on
// the simulated station with a force window (10 ms, 5 ms half-cosine taper)
// and an exponential window (tau 0.5 s); the view must draw the stored samples
// as they are in the project and the windows as core/signal/window.h defines
// them, checked at moments where their value is known in closed form.
#include "views/plots/hit_time_view.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_item.h>
#include <QComboBox>
#include <QDir>
#include <QtTest>
#include <chrono>
#include <cmath>

#include "devices/campaign/campaign_engine.h"
#include "devices/campaign/campaign_store.h"
#include "devices/campaign/virtual_campaign.h"
#include "devices/common/driver.h"

using mozzi::views::HitTimeView;
namespace cp = mozzi::devices::campaign;

namespace {

QwtPlotCurve* curveTitled(QwtPlot* plot, const QString& title) {
  for (QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve))
    if (item->title().text() == title) return static_cast<QwtPlotCurve*>(item);
  return nullptr;
}

// y of the curve at sample k (the view draws one point per sample).
double at(const QwtPlotCurve* c, std::size_t k) {
  return c->sample(k).y();
}

}  // namespace

class HitTimeViewTest : public QObject {
  Q_OBJECT
 private slots:
  void drawsTheStoredHitAndItsWindows() {
    QTemporaryDir dir;
    auto store = mozzi::core::io::ProjectStore::create(dir.filePath(QStringLiteral("h.mozzi")).toStdString(), "test");
    QVERIFY(store.ok());
    auto specimen = store->addSpecimen("Fork A without wheel", "fork", "virtual");
    QVERIFY(specimen.ok());
    cp::VirtualCampaignOptions o;
    o.hitsPerPoint = 2;
    o.doubleHitProbability = 0.0;
    o.overloadProbability = 0.0;
    auto def = cp::virtualSpecimenCampaign("fork-a-without-wheel", o);
    QVERIFY(def.ok());
    def->points.resize(2);
    def->windows.forceWidthS = 0.010;
    def->windows.forceTaperS = 0.005;
    def->windows.exponentialTauS = 0.5;
    auto campaign = cp::createCampaign(*store, *specimen, "windows", *def);
    QVERIFY(campaign.ok());
    cp::EngineOptions eo;
    eo.autoDecide = true;
    eo.autoArm = true;
    eo.deviceOverrides["sim.realtime"] = false;
    auto engine = cp::CampaignEngine::open(*store, *campaign,
                                           cp::makeDriverStation(mozzi::devices::builtinDrivers(), "sim-hammer"), eo);
    QVERIFY2(engine.ok(), engine ? "" : engine.error().describe().c_str());
    (*engine)->start();
    QVERIFY((*engine)->waitUntilFinished(std::chrono::seconds(120)));
    const auto setId = (*engine)->progress().frfSetId;
    (*engine)->stop();
    QVERIFY(setId.has_value());

    HitTimeView view;
    view.resize(1000, 600);
    view.show();
    const auto set = view.setFrfSet(*store, *setId);
    QVERIFY2(set.ok(), set ? "" : set.error().describe().c_str());
    QCOMPARE(view.hitCount(), 4);  // two points, two accepted hits each
    QVERIFY(view.showHit(3, 1));
    const auto ids = store->frfSetHits(*setId).value();
    const auto hit = store->hit(ids[3]).value();
    const int force = def->forceChannel();
    const int response = 2;  // the second non-force channel: the accelerometer on input 2
    QVERIFY(force == 0);
    auto* f = curveTitled(view.plot(), QStringLiteral("force"));
    auto* r = curveTitled(view.plot(), QStringLiteral("response"));
    auto* fw = curveTitled(view.plot(), QStringLiteral("force window (x peak force)"));
    auto* rw = curveTitled(view.plot(), QStringLiteral("response window (x peak response)"));
    QVERIFY(f && r && fw && rw);
    const auto n = static_cast<std::size_t>(hit.sampleCount());
    QCOMPARE(f->dataSize(), n);
    QCOMPARE(rw->dataSize(), n);
    double peakF = 0.0, peakR = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      // The samples as stored (float32 in the project, drawn as double).
      QCOMPARE(at(f, k), static_cast<double>(hit.samples(static_cast<Eigen::Index>(k), force)));
      QCOMPARE(at(r, k), static_cast<double>(hit.samples(static_cast<Eigen::Index>(k), response)));
      peakF = std::max(peakF, std::abs(at(f, k)));
      peakR = std::max(peakR, std::abs(at(r, k)));
    }
    // The windows start at the trigger (the pre-trigger's end): before it 1;
    // the force window is exp(-t/tau) up to 10 ms after it, 0 after the taper;
    // the response window exp(-t/tau) throughout.
    const double fs = hit.sampleRateHz;
    const auto trigger = static_cast<std::size_t>(def->preTriggerScans());
    auto sampleAfter = [&](double s) { return trigger + static_cast<std::size_t>(std::lround(s * fs)); };
    QVERIFY(std::abs(at(fw, trigger / 2) - peakF) <= 1e-9 * peakF);
    const std::size_t k5 = sampleAfter(0.005), k16 = sampleAfter(0.016), k200 = sampleAfter(0.2);
    const double t5 = static_cast<double>(k5 - trigger) / fs, t200 = static_cast<double>(k200 - trigger) / fs;
    QVERIFY2(std::abs(at(fw, k5) - peakF * std::exp(-t5 / 0.5)) <= 1e-9 * peakF,
             qPrintable(QStringLiteral("%1 vs %2").arg(at(fw, k5)).arg(peakF * std::exp(-t5 / 0.5))));
    QCOMPARE(at(fw, k16), 0.0);
    QVERIFY(std::abs(at(rw, k200) - peakR * std::exp(-t200 / 0.5)) <= 1e-9 * peakR);
    QVERIFY(view.hitText().contains(QStringLiteral("force window 10 ms")));
    QDir().mkpath(qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath()));
    const QDir shots(qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath()));
    QVERIFY(view.grab().save(shots.filePath(QStringLiteral("hit_time_view.png"))));
  }
};

QTEST_MAIN(HitTimeViewTest)
#include "hit_time_view_test.moc"
