// ProjectOverview shows exactly what core's ProjectSummary holds, and follows
// language changes.
#include "views/panels/project_overview.h"

#include <QApplication>
#include <QLabel>
#include <QTableWidget>
#include <QtTest>

using mozzi::core::io::ProjectSummary;
using mozzi::views::ProjectOverview;

class ProjectOverviewTest : public QObject {
  Q_OBJECT
 private slots:
  void showsSummaryRowsAndDetails() {
    ProjectOverview view;
    ProjectSummary summary;
    summary.schemaVersion = 7;
    summary.createdUtc = "2026-11-21T05:00:00Z";
    summary.mozziVersion = "0.1.0";
    summary.specimens = {{1, "Frame A", "frame", "thesis Table 3"}, {2, "Fork A", "fork", "thesis Table 11"}};
    view.showSummary(QStringLiteral("/data/lab/campaign-12.mozzi"), summary, true,
                     QStringLiteral("another Mozzi instance has this project open"));
    QCOMPARE(view.specimenRows(), 2);
    auto* table = view.findChild<QTableWidget*>(QStringLiteral("overviewSpecimens"));
    QVERIFY(table);
    QCOMPARE(table->item(1, 0)->text(), QStringLiteral("Fork A"));
    QCOMPARE(table->item(1, 1)->text(), QStringLiteral("fork"));
    QCOMPARE(table->item(0, table->columnCount() - 1)->text(), QStringLiteral("thesis Table 3"));
    auto* title = view.findChild<QLabel*>(QStringLiteral("overviewTitle"));
    QCOMPARE(title->text(), QStringLiteral("campaign-12"));
    const QString details = view.findChild<QLabel*>(QStringLiteral("overviewDetails"))->text();
    QVERIFY2(details.contains(QStringLiteral("Schema version 7")), qPrintable(details));
    QVERIFY2(details.contains(QStringLiteral("read-only: another Mozzi instance")), qPrintable(details));

    view.clear();
    QCOMPARE(view.specimenRows(), 0);
    QCOMPARE(title->text(), QStringLiteral("No project open"));
  }
};

QTEST_MAIN(ProjectOverviewTest)
#include "project_overview_test.moc"
