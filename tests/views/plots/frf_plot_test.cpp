// FrfPlot draws what core computes: the curves hold 20 log10|H| and arg H of an
// analytic SDOF receptance at every line, for the pair that is selected.
#include "views/plots/frf_plot.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <QApplication>
#include <QComboBox>
#include <QtTest>

#include <cmath>

using mozzi::core::Complex;
using mozzi::core::Direction;
using mozzi::core::Dof;
using mozzi::core::FrfMatrix;

namespace {

// Receptance of m x'' + c x' + k x = f: H = 1 / (k - m w^2 + i c w) [m/N].
Complex sdof(double fHz, double m, double k, double c) {
  const double w = 2.0 * M_PI * fHz;
  return 1.0 / Complex(k - m * w * w, c * w);
}

std::shared_ptr<FrfMatrix> twoResponses() {
  auto frf = std::make_shared<FrfMatrix>();
  const int n = 801;
  frf->frequencyHz = mozzi::core::Vector::LinSpaced(n, 1.0, 201.0);
  frf->responses = {Dof{1, Direction::Z, false}, Dof{2, Direction::Y, true}};
  frf->references = {Dof{1, Direction::Z, false}};
  frf->type = mozzi::core::FrfType::Receptance;
  frf->h.emplace_back(n, 2);
  frf->coherence.emplace_back(n, 2);
  for (int k = 0; k < n; ++k) {
    frf->h[0](k, 0) = sdof(frf->frequencyHz[k], 2.0, 2.0 * std::pow(2 * M_PI * 50.0, 2), 20.0);
    frf->h[0](k, 1) = sdof(frf->frequencyHz[k], 1.0, std::pow(2 * M_PI * 120.0, 2), 5.0);
    frf->coherence[0](k, 0) = 0.99;
    frf->coherence[0](k, 1) = 0.5;
  }
  return frf;
}

QwtPlotCurve* firstCurve(QwtPlot* plot) {
  for (QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) return static_cast<QwtPlotCurve*>(item);
  return nullptr;
}

}  // namespace

class FrfPlotTest : public QObject {
  Q_OBJECT
 private slots:
  void curvesHoldMagnitudePhaseAndCoherence() {
    mozzi::views::FrfPlot plot;
    auto frf = twoResponses();
    plot.setFrfs(frf);
    QCOMPARE(plot.pairCount(), 2);
    QCOMPARE(plot.shownSamples(), size_t(801));
    auto* magnitude = firstCurve(plot.magnitudePlot());
    auto* phase = firstCurve(plot.phasePlot());
    auto* coherence = firstCurve(plot.coherencePlot());
    QVERIFY(magnitude && phase && coherence);
    for (size_t i : {size_t(0), size_t(196), size_t(800)}) {  // line 196 is 50 Hz, the resonance
      const Complex h = frf->h[0](static_cast<Eigen::Index>(i), 0);
      QCOMPARE(magnitude->sample(i).x(), frf->frequencyHz[static_cast<Eigen::Index>(i)]);
      QVERIFY(std::abs(magnitude->sample(i).y() - 20.0 * std::log10(std::abs(h))) < 1e-9);
      QVERIFY(std::abs(phase->sample(i).y() - std::arg(h) * 180.0 / M_PI) < 1e-9);
      QCOMPARE(coherence->sample(i).y(), 0.99);
    }
    // At resonance the phase of a receptance is -90 degrees.
    QVERIFY(std::abs(phase->sample(196).y() + 90.0) < 1e-6);
  }

  void selectingAnotherPairRedraws() {
    mozzi::views::FrfPlot plot;
    auto frf = twoResponses();
    plot.setFrfs(frf);
    auto* pairs = plot.findChild<QComboBox*>(QStringLiteral("frfPairs"));
    QCOMPARE(pairs->count(), 2);
    QCOMPARE(pairs->itemText(1), QStringLiteral("2:-Y / 1:+Z"));
    pairs->setCurrentIndex(1);
    QCOMPARE(plot.currentResponse(), 1);
    const Complex h = frf->h[0](500, 1);
    QVERIFY(std::abs(firstCurve(plot.magnitudePlot())->sample(500).y() - 20.0 * std::log10(std::abs(h))) < 1e-9);
    QCOMPARE(firstCurve(plot.coherencePlot())->sample(500).y(), 0.5);
    QVERIFY(!plot.showPair(2, 0));
    QVERIFY(!plot.showPair(0, 1));
    QCOMPARE(plot.currentResponse(), 1);
    plot.setFrfs(nullptr);
    QCOMPARE(plot.pairCount(), 0);
  }
};

QTEST_MAIN(FrfPlotTest)
#include "frf_plot_test.moc"
