// The Stiffness page (issue 22) on the demo project (its static and dynamic
// rig tests of fork A with wheel and frame A front-constrained, run by the
// stiffness-rig sequences on the simulated rig). Checked against:
//  - the results the project stores for each test, read here straight from
//    the store: every measured cell's value and uncertainty equal to the bit,
//    its text the stored value in the display unit;
//  - the thesis as printed (Table 10 for fork A with wheel, simple method;
//    Tables 3 and 4 for frame A front-constrained), typed here from
//    reference/thesis.md, independent of the catalogue the page reads: within
//    1 %, except fork A's bending arm and stiffness (see below);
//  - the CSV: the same numbers, the header naming each test;
//  - the thesis toggle, the columns per test.
// Screenshot: stiffness_tables (and @2x under QT_SCALE_FACTOR=2).
#include "views/stiffness/stiffness_table_page.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QHeaderView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <map>

#include "core/io/project_store.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/stiffness/page_fixture.h"

using mozzi::views::JobRunner;
using mozzi::views::PageContext;
using mozzi::views::ProjectModel;
using mozzi::views::RecordKind;
using mozzi::views::StiffnessTablePage;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Row order of the page (thesis Tables 7, 9, 10, 13).
const char* const kKeys[] = {"k_lat", "a_tw", "k_tw", "a_bend", "k_bend", "a_tors", "k_tors", "axis_inclination"};

struct Stored {
  double value = std::nan("");
  double uncertainty = 0.0;
};
std::map<std::string, Stored> wholeTestResults(const mozzi::core::io::StoredRigTest& t) {
  std::map<std::string, Stored> out;
  for (const auto& r : t.results)
    if (!r.step) out[r.quantity] = {r.value, r.uncertainty};
  return out;
}

// The thesis as printed, SI. Table 10 (enduro fork with wheel, simple method):
// 56.1 kN/m, 0.517 m, 15 kNm/rad, 0.67 m, 28 kNm/rad, 0.066 m, 3 kNm/rad,
// 45.5 deg. Tables 3 and 4 (frame A, front-constrained): 167 kN/m, 0.551 m,
// 50.8 kNm/rad, 0.556 m, 52.1 kNm/rad, 0.032 m, 22.0 kNm/rad.
const std::map<std::string, double> kTable10{
    {"k_lat", 56.1e3}, {"a_tw", 0.517},   {"k_tw", 15e3},  {"a_bend", 0.67},
    {"k_bend", 28e3},  {"a_tors", 0.066}, {"k_tors", 3e3}, {"axis_inclination", 45.5 * kPi / 180}};
const std::map<std::string, double> kTables3And4{{"k_lat", 167e3},  {"a_tw", 0.551},    {"k_tw", 50.8e3},
                                                 {"a_bend", 0.556}, {"k_bend", 52.1e3}, {"a_tors", 0.032},
                                                 {"k_tors", 22.0e3}};

}  // namespace

class StiffnessTablePageTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    const QString problem = stiffness_pages::openDemo(model_, dir_);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void showsTheStoredResultsBesideTheThesis() {
    PageContext ctx{&model_, &jobs_, {RecordKind::None, 0, 0}, nullptr, {}};
    StiffnessTablePage page(ctx);
    QVERIFY(stiffness_pages::showAt1280x800(page));
    auto* table = page.table();
    QCOMPARE(table->rowCount(), 8);

    // One measured column per static test of the project.
    auto tests = model_.store()->rigTests();
    QVERIFY(tests.ok());
    std::vector<qint64> statics;
    for (const auto& t : *tests)
      if (t.kind == "static") statics.push_back(t.id);
    QCOMPARE(statics.size(), std::size_t{2});  // the demo's fork A and frame A
    std::map<qint64, int> columnOf;
    for (int c = 0; c < table->columnCount(); ++c)
      if (page.testOfColumn(c) > 0) columnOf[page.testOfColumn(c)] = c;
    QCOMPARE(columnOf.size(), statics.size());
    // With the thesis shown: measured, thesis and difference for both.
    QCOMPARE(table->columnCount(), 6);

    for (qint64 id : statics) {
      auto test = model_.store()->rigTest(id);
      QVERIFY(test.ok());
      const auto stored = wholeTestResults(*test);
      const int col = columnOf.at(id);
      for (int r = 0; r < 8; ++r) {
        const auto it = stored.find(kKeys[r]);
        QVERIFY2(it != stored.end(), kKeys[r]);
        const auto* item = table->item(r, col);
        QVERIFY(item);
        // Equal to the bit: the page shows the stored number.
        QCOMPARE(item->data(Qt::UserRole).toDouble(), it->second.value);
        QCOMPARE(item->data(Qt::UserRole + 1).toDouble(), it->second.uncertainty);
        // Its text: the value in kN/m, m, kNm/rad or degrees.
        const double scale = r == 7 ? 180 / kPi : (r == 1 || r == 3 || r == 5) ? 1.0 : 1e-3;
        const int decimals = (r == 1 || r == 3 || r == 5) ? 4 : 2;
        QVERIFY2(item->text().startsWith(QString::number(it->second.value * scale, 'f', decimals)),
                 qPrintable(item->text()));
      }
    }

    // Against the thesis as printed. Fork A with wheel (simulated): Table 10.
    const std::string forkName = "Fork A (enduro) with wheel";
    const std::string frameName = "Frame A";
    for (const auto& t : *tests) {
      if (t.kind != "static") continue;
      const auto stored = wholeTestResults(*model_.store()->rigTest(t.id));
      const auto& thesis = t.specimenName == forkName ? kTable10 : kTables3And4;
      QVERIFY(t.specimenName == forkName || t.specimenName == frameName);
      for (const auto& [key, expected] : thesis) {
        const double measured = stored.at(key).value;
        const double rel = std::abs(measured - expected) / expected;
        qInfo("%s %s: measured %.6g, thesis %.6g, %.2f %%", t.specimenName.c_str(), key.c_str(), measured, expected,
              100 * rel);
        // Table 10's simple-method row does not balance eq. 35 by itself:
        // a_tw^2/k_tw = 1.782e-5 against a_bend^2/k_bend + a_tors^2/k_tors =
        // 1.748e-5 (1.9 %). The simulated rig keeps k_lat, a_tw, k_tw, the
        // torsion axis and the inclination and places the bending axis where
        // eq. 35 balances (0.684 m), so a_bend and k_bend come out 2.1 % above
        // the printed 0.67 m and 28 kNm/rad; they are checked against the
        // balance instead (below), and within 2.5 % of the print.
        const bool unbalancedInPrint = t.specimenName == forkName && (key == "a_bend" || key == "k_bend");
        QVERIFY2(rel < (unbalancedInPrint ? 0.025 : 0.01), key.c_str());
      }
      if (t.specimenName == forkName) {
        const auto v = [&](const char* k) { return stored.at(k).value; };
        const double lhs = v("a_tw") * v("a_tw") / v("k_tw");
        const double rhs = v("a_bend") * v("a_bend") / v("k_bend") + v("a_tors") * v("a_tors") / v("k_tors");
        QVERIFY2(std::abs(lhs - rhs) / lhs < 0.005, qPrintable(QString::number(lhs / rhs - 1)));
      }
      // The page's difference column says the same as these numbers.
      const int col = columnOf.at(t.id);
      QVERIFY(table->horizontalHeaderItem(col + 1)->text().contains(QStringLiteral("thesis")));
      for (int r = 0; r < 7; ++r) {
        const double measured = table->item(r, col)->data(Qt::UserRole).toDouble();
        const double printedThesis = table->item(r, col + 1)->data(Qt::UserRole).toDouble();
        const double deviation = table->item(r, col + 2)->data(Qt::UserRole).toDouble();
        QVERIFY(std::abs(deviation - (measured - printedThesis) / printedThesis) < 1e-12);
        QVERIFY(std::abs(printedThesis - thesis.at(kKeys[r])) <= 1e-9 * thesis.at(kKeys[r]));
      }
    }
    stiffness_pages::saveShot(page, QStringLiteral("stiffness_tables"));

    // Opened on a rig test: its measured column selected; a sweep has none.
    QVERIFY(page.showRigTest(statics[1]));
    QCOMPARE(table->selectionModel()->selectedColumns().size(), 1);
    QCOMPARE(page.testOfColumn(table->selectionModel()->selectedColumns().first().column()), statics[1]);
    for (const auto& t : *tests)
      if (t.kind == "dynamic") QVERIFY(!page.showRigTest(t.id));

    // CSV: a header naming each test, one line per quantity with the same numbers.
    const QStringList lines = page.csv().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 9);
    QVERIFY(lines[0].contains(QStringLiteral("Fork A (enduro) with wheel")));
    QVERIFY(lines[0].contains(QStringLiteral("Frame A, front-constrained / static test: measured")));
    const QStringList klat = lines[1].split(QLatin1Char(','));
    QCOMPARE(klat[1], QStringLiteral("kN/m"));
    // Columns: quantity, unit, then per test measured, standard deviation, thesis.
    for (std::size_t i = 0; i < statics.size(); ++i) {
      const double fromCsv = klat[2 + 3 * static_cast<int>(i)].toDouble();
      const qint64 id = page.testOfColumn(3 * static_cast<int>(i));
      const double stored = wholeTestResults(*model_.store()->rigTest(id)).at("k_lat").value;
      QVERIFY2(std::abs(fromCsv * 1e3 - stored) <= 1e-10 * stored, qPrintable(klat.join(QLatin1Char(' '))));
    }
    QTemporaryDir out;
    const QString path = out.filePath(QStringLiteral("stiffness.csv"));
    QCOMPARE(page.exportCsv(path), QString());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(f.readAll()), page.csv());

    // Without the thesis: one column per test.
    page.setThesisShown(false);
    QCOMPARE(table->columnCount(), 2);
    const QString header = page.csv().split(QLatin1Char('\n')).first();
    QCOMPARE(header.count(QStringLiteral(": measured")), 2);
    QCOMPARE(header.count(QStringLiteral(": thesis")), 0);
  }

 private:
  QTemporaryDir dir_;
  ProjectModel model_;
  JobRunner jobs_;
};

QTEST_MAIN(StiffnessTablePageTest)
#include "stiffness_table_page_test.moc"
