#pragma once
// The Identification page's residual list on the demo frame's kept
// identification (demo_pages_test.cpp): worst misfit first, misfit = level +
// 20 log10 residual (0.2 dB: the cells' rounding), so the hammer points by
// the constrained front, whose residuals near 100 % are their noise 60-70 dB
// down, come last and a strong FRF first.
#include <QTableWidget>
#include <QTest>
#include <cmath>

inline void checkResidualList(QWidget* page, int frfCount) {
  auto* residuals = page->findChild<QTableWidget*>(QStringLiteral("identificationResiduals"));
  QVERIFY(residuals && residuals->rowCount() == frfCount);
  double previousMisfit = 1e9;
  for (int r = 0; r < residuals->rowCount(); ++r) {
    const double residual = residuals->item(r, 1)->text().toDouble() / 100.0;
    const double level = residuals->item(r, 2)->text().toDouble();
    const double misfit = residuals->item(r, 3)->text().toDouble();
    QVERIFY2(std::abs(misfit - (level + 20.0 * std::log10(residual))) < 0.2 && misfit <= previousMisfit,
             qPrintable(QStringLiteral("row %1: residual %2, level %3 dB, misfit %4 dB after %5 dB")
                            .arg(r)
                            .arg(residual)
                            .arg(level)
                            .arg(misfit)
                            .arg(previousMisfit)));
    previousMisfit = misfit;
  }
  QVERIFY2(residuals->item(0, 2)->text().toDouble() > -20.0, qPrintable(residuals->item(0, 0)->text()));
  QVERIFY(residuals->item(residuals->rowCount() - 1, 2)->text().toDouble() < -40.0);
}
