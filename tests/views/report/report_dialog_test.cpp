// The Report dialog (issue 23): it opens on the project's report template
// (defaults without one), the check boxes, specimen and language make the
// template it saves into the project, and OK needs a section and an output.
// Screenshots: report_dialog(.png, @2x.png under QT_SCALE_FACTOR=2).
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

#include "core/report/report_template.h"
#include "tests/views/screenshot.h"
#include "views/common/project_model.h"
#include "views/report/report_dialog.h"

using namespace mozzi;

class ReportDialogTest : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    path_ = dir_.filePath(QStringLiteral("p%1.mozzi").arg(++n_));
    auto store = core::io::ProjectStore::create(path_.toStdString(), "test");
    QVERIFY(store.ok());
    QVERIFY(store->addSpecimen("Frame X", "frame", "").ok());
    QVERIFY(store->addSpecimen("Fork Y", "fork", "").ok());
  }

  void defaultsWithoutTemplate() {
    views::ProjectModel model;
    QVERIFY(model.open(path_).ok());
    views::ReportDialog dialog(&model);
    for (const auto& key : core::report::reportSectionKeys()) {
      QVERIFY(dialog.sectionBox(key));
      QVERIFY(dialog.sectionBox(key)->isChecked());
    }
    QCOMPARE(dialog.specimenBox()->count(), 3);  // every specimen, then the two
    QCOMPARE(dialog.specimenBox()->currentIndex(), 0);
    const auto t = dialog.reportTemplate();
    QVERIFY(t.sections.empty());  // every section
    QVERIFY(t.specimen.empty());
    QCOMPARE(t.language, core::report::Language::English);
    QVERIFY(t.pdf);
  }

  void choicesAreSavedIntoTheProject() {
    views::ProjectModel model;
    QVERIFY(model.open(path_).ok());
    {
      views::ReportDialog dialog(&model);
      dialog.sectionBox("frf")->setChecked(false);
      dialog.sectionBox("gap")->setChecked(false);
      dialog.specimenBox()->setCurrentIndex(dialog.specimenBox()->findText(QStringLiteral("Fork Y")));
      dialog.languageBox()->setCurrentIndex(1);
      dialog.setPdfPath(dir_.filePath(QStringLiteral("r.pdf")));
      dialog.accept();
    }
    auto loaded = core::report::loadReportTemplate(*model.store());
    QVERIFY(loaded.ok());
    QVERIFY(loaded->has_value());
    // Every section but the two unticked, in report order.
    std::vector<std::string> expected;
    for (const auto& key : core::report::reportSectionKeys())
      if (key != "frf" && key != "gap") expected.push_back(key);
    QCOMPARE((*loaded)->sections, expected);
    QCOMPARE((*loaded)->specimen, std::string("Fork Y"));
    QCOMPARE((*loaded)->language, core::report::Language::Italian);
    // A new dialog opens on what was saved.
    views::ReportDialog again(&model);
    QVERIFY(!again.sectionBox("frf")->isChecked());
    QVERIFY(again.sectionBox("modal")->isChecked());
    QCOMPARE(again.specimenBox()->currentText(), QStringLiteral("Fork Y"));
    QCOMPARE(again.languageBox()->currentIndex(), 1);
  }

  void okNeedsASectionAndAnOutput() {
    views::ProjectModel model;
    QVERIFY(model.open(path_).ok());
    views::ReportDialog dialog(&model);
    auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    dialog.setPdfPath(dir_.filePath(QStringLiteral("r.pdf")));
    QVERIFY(ok->isEnabled());
    for (const auto& key : core::report::reportSectionKeys()) dialog.sectionBox(key)->setChecked(false);
    QVERIFY(!ok->isEnabled());
    dialog.sectionBox("title")->setChecked(true);
    QVERIFY(ok->isEnabled());
    dialog.setPdfPath(QString());
    QVERIFY(!ok->isEnabled());  // PDF ticked without a file
  }

  void screenshot() {
    views::ProjectModel model;
    QVERIFY(model.open(path_).ok());
    views::ReportDialog dialog(&model);
    dialog.setPdfPath(QStringLiteral("/home/lab/fork-a-report.pdf"));
    dialog.setHtmlDir(QStringLiteral("/home/lab/fork-a-report"));
    dialog.sectionBox("gap")->setChecked(false);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QVERIFY(views::test::saveShot(dialog, QStringLiteral("report_dialog")));
  }

 private:
  QTemporaryDir dir_;
  QString path_;
  int n_ = 0;
};

QTEST_MAIN(ReportDialogTest)
#include "report_dialog_test.moc"
