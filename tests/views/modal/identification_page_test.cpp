// The identification page on real data (the ModeLAB beam of shared/data):
// run off the GUI thread, the automatic selection gives the four published
// modes with the CLI's numbers; a click on a pole changes the modal table and
// the synthesis at once and a second pole of one mode raises the same-mode
// warning; the saved modal result equals `mozzi-cli identify --store` on the
// same set. A synthetic set of 100 FRFs x 20,000 lines checks the time
// budgets: diagram drawn within 0.5 s of the result; a pole click in 50 ms
// (issue 18: the median of ten clicks, in GUI-thread CPU time).
// Screenshots at the window size (1280x800) for the user guide.
#include "views/modal/identification_page.h"

#include <qwt_plot_canvas.h>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "core/io/modelab_ascii.h"
#include "core/io/project_store.h"
#include "core/modal/modal_model.h"
#include "devices/sim/specimen_models.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/plots/decimating_curve.h"
#include "views/plots/frf_plot.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/mac_plot.h"
#include "views/plots/stabilization_plot.h"

using namespace mozzi;

namespace {

const std::string kBeam = std::string(MOZZI_SHARED_DATA_DIR) + "/modelab-beam/SignalCalc/";
constexpr double kPublished[4] = {111.99, 306.86, 596.37, 974.14};  // modelab-beam/README.md

core::FrfMatrix loadBeam() {
  std::vector<std::string> files;
  std::vector<core::Dof> hammers;
  for (int i = 1; i <= 9; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "ASCII%05d/Hxysv%05d.txt", i, i);
    files.push_back(kBeam + name);
    hammers.push_back(core::Dof{i, core::Direction::X, false});
  }
  auto frf = core::io::readSignalCalcRovingHammer(files, hammers, core::Dof{4, core::Direction::X, true},
                                                  core::FrfType::Accelerance);
  return std::move(frf).value();
}

QString shotName(const QString& base) {
  return qApp->devicePixelRatio() > 1.0 ? base + QStringLiteral("@2x.png") : base + QStringLiteral(".png");
}

void screenshot(QWidget* w, const QString& base) {
  const QString dir = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR");
  if (dir.isEmpty()) return;
  QDir().mkpath(dir);
  // Layout requests (a plot shown or hidden) are handled before the grab.
  QApplication::processEvents();
  QTest::qWait(50);
  QVERIFY(w->grab().save(QDir(dir).filePath(shotName(base))));
}

nlohmann::json runCli(const QStringList& args) {
  QProcess cli;
  cli.start(QStringLiteral(MOZZI_CLI_PATH), args);
  if (!cli.waitForFinished(600000)) return {};
  const QByteArray out = cli.readAllStandardOutput();
  if (cli.exitCode() != 0) {
    qWarning("mozzi-cli: %s", cli.readAllStandardError().constData());
    return {};
  }
  return nlohmann::json::parse(out.toStdString());
}

bool waitFinished(QSignalSpy& spy, int seconds) {
  return spy.count() > 0 || spy.wait(seconds * 1000);
}

// The demo project's finished campaign, without the hours of simulated hits:
// the accelerances of the virtual "Fork A (enduro) with wheel" (thesis Table 11
// right: 22.3, 23.5, 67.2 Hz; zeta 0.024, 0.014, 0.059, plus three completion
// modes near 170..200 Hz) from its modal model, on the campaign's grid (0 to
// 800 Hz at 0.5 Hz: 2048 Hz, 2 s records), hammer roving over every DOF of
// its mesh, three fixed accelerometers where modes 1, 2, 3 move most (as
// devices/campaign/virtual_campaign.cpp places them). Stored by reciprocity
// (H_ij = H_ji) as 54 responses x 3 references: pLSCF's cost grows with the
// references, and with the campaign's 54 it runs for many minutes (report of
// issue 18: the estimator should transpose such sets itself).
struct ForkSet {
  devices::sim::ModalSpecimen spec;
  core::FrfMatrix frf;
};

ForkSet forkSet() {
  ForkSet out;
  out.spec = devices::sim::modalSpecimen("fork-a-with-wheel").value();
  const auto& spec = out.spec;
  std::vector<Eigen::Index> rows;
  for (Eigen::Index r = 0; r < 3; ++r) {
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < spec.shapes.rows(); ++i) {
      if (std::find(rows.begin(), rows.end(), i) != rows.end()) continue;
      if (best < 0 || std::abs(spec.shapes(i, r)) > std::abs(spec.shapes(best, r))) best = i;
    }
    rows.push_back(best);
  }
  core::FrfMatrix& frf = out.frf;
  frf.frequencyHz = core::Vector::LinSpaced(1601, 0.0, 800.0);
  frf.type = core::FrfType::Accelerance;
  for (Eigen::Index i : rows) frf.references.push_back(spec.dofs[static_cast<std::size_t>(i)]);
  frf.responses = spec.dofs;
  // 0.1% complex Gaussian noise per line (seeded): noise-free FRFs of 54
  // references and 3 responses hold only six independent columns (six modes),
  // which no measured set does and which leaves pLSCF's normal equations singular.
  std::mt19937 rng(18);
  std::normal_distribution<double> noise(0.0, 1e-3 / std::sqrt(2.0));
  const auto no = static_cast<Eigen::Index>(spec.dofs.size());
  for (Eigen::Index i : rows) {
    core::ComplexMatrix h(frf.lineCount(), no);
    for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
      const double w = 2.0 * M_PI * frf.frequencyHz[k];
      for (Eigen::Index o = 0; o < no; ++o)
        h(k, o) = -w * w * spec.receptance(o, i, w) * core::Complex(1.0 + noise(rng), noise(rng));
    }
    frf.h.push_back(std::move(h));
  }
  return out;
}

void clickPole(views::StabilizationPlot* plot, int index) {
  QTest::mouseClick(plot->canvas(), Qt::LeftButton, Qt::NoModifier, plot->polePixel(index));
}

}  // namespace

class IdentificationPageTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    path_ = dir_.filePath(QStringLiteral("beam.mozzi"));
    QVERIFY(model_.create(path_).ok());
    auto sp = model_.addSpecimen(QStringLiteral("ModeLAB beam"), QStringLiteral("beam"));
    QVERIFY(sp.ok());
    specimen_ = *sp;
    core::io::FrfSetInfo info;
    info.specimenId = specimen_;
    info.name = "roving hammer";
    auto set = model_.addFrfSet(info, loadBeam());
    QVERIFY(set.ok());
    set_ = *set;
    // The CLI's copy of the project: the workbench holds its project locked
    // for writing (a second writer is refused), so `identify --store` runs on
    // a project made the same way, with the same set.
    cliPath_ = dir_.filePath(QStringLiteral("beam-cli.mozzi"));
    auto cliStore = core::io::ProjectStore::create(cliPath_.toStdString(), "test");
    QVERIFY(cliStore.ok());
    auto cliSp = cliStore->addSpecimen("ModeLAB beam", "beam", "");
    QVERIFY(cliSp.ok());
    info.specimenId = *cliSp;
    auto cliSet = cliStore->addFrfSet(info, loadBeam());
    QVERIFY(cliSet.ok());
    cliSet_ = *cliSet;
  }

  void beamRunClickSaveEqualsCli() {
    views::PageContext ctx;
    ctx.model = &model_;
    ctx.jobs = &jobs_;
    ctx.item = views::ProjectItem{views::RecordKind::FrfSet, set_, specimen_};
    views::IdentificationPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    QCOMPARE(page.frfSetId(), set_);
    page.setBand(65.0, 1000.0);  // setup.csv fMin, fMax
    page.setMaxOrder(60);
    QSignalSpy finished(&page, &views::IdentificationPage::finished);
    QTest::mouseClick(page.findChild<QPushButton*>(QStringLiteral("identificationRun")), Qt::LeftButton);
    QVERIFY(page.isRunning());  // off the GUI thread
    QVERIFY(waitFinished(finished, 600));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(page.statusText()));
    // The band's 47,873 lines are refined on those carrying the modes, and the status says so (as the CLI).
    QVERIFY2(page.statusText().contains(QStringLiteral("of 47,873 band lines: those carrying the modes")),
             qPrintable(page.statusText()));

    // The automatic selection: the four published modes (0.05%, README), no warning.
    const auto rows = page.tableRows();
    QCOMPARE(rows.size(), size_t(4));
    QCOMPARE(page.modalTable()->rowCount(), 4);
    for (int r = 0; r < 4; ++r) {
      QVERIFY2(std::abs(rows[r].frequencyHz - kPublished[r]) < 5e-4 * kPublished[r],
               qPrintable(QString::number(rows[r].frequencyHz)));
      QVERIFY(rows[r].frequencyStdHz.has_value());
      QCOMPARE(rows[r].eta, 2.0 * rows[r].zeta);
      QVERIFY(rows[r].mpc > 0.9);  // a beam's modes are real
    }
    QVERIFY(page.warningText().isEmpty());
    QVERIFY(page.residualTable()->rowCount() == 9);
    // The MAC tab is brought up to date when it is shown.
    auto* tabs = page.findChild<QTabWidget*>();
    tabs->setCurrentIndex(1);
    QVERIFY(page.autoMacPlot()->matrix().rows() == 4);
    for (int r = 0; r < 4; ++r) QCOMPARE(page.autoMacPlot()->matrix()(r, r), 1.0);
    tabs->setCurrentIndex(0);

    // The same numbers as the CLI on the same set (same calls, so equal to
    // the printed digits: JSON carries 17 significant digits).
    // One CLI run: the JSON numbers, and with --store the table it keeps.
    const QStringList cliArgs = {QStringLiteral("identify"),  cliPath_,
                                 QStringLiteral("--frf-set"), QString::number(cliSet_),
                                 QStringLiteral("--band"),    QStringLiteral("65:1000"),
                                 QStringLiteral("--json"),    QStringLiteral("--store")};
    const nlohmann::json cli = runCli(cliArgs);
    QVERIFY(cli.contains("modes"));
    QCOMPARE(cli["modes"].size(), size_t(4));
    for (int r = 0; r < 4; ++r) {
      const auto& m = cli["modes"][static_cast<std::size_t>(r)];
      QVERIFY(std::abs(m["frequency_hz"].get<double>() - rows[r].frequencyHz) <= 1e-12 * rows[r].frequencyHz);
      QVERIFY(std::abs(m["zeta"].get<double>() - rows[r].zeta) <= 1e-12 * rows[r].zeta);
      QVERIFY(std::abs(m["frequency_std"].get<double>() - *rows[r].frequencyStdHz) <= 1e-9 * *rows[r].frequencyStdHz);
      QVERIFY(std::abs(m["mpc"].get<double>() - rows[r].mpc) <= 1e-12);
    }
    screenshot(&page, QStringLiteral("identification_beam"));

    // A click on a pole of mode 1 at another order adds it: the table grows,
    // and the two are one mode - a warning names them.
    auto* diagram = page.diagramPlot();
    const auto& poles = page.outcome()->diagram->poles;
    const int chosen1 = diagram->selection()[0];
    QVERIFY(chosen1 >= 0);
    int twin = -1;
    for (int i = 0; i < static_cast<int>(poles.size()); ++i) {
      if (i != chosen1 && poles[i].status == core::modal::PoleStatus::Stable &&
          std::abs(poles[i].frequencyHz - poles[chosen1].frequencyHz) < 0.01 &&
          poles[i].order < poles[chosen1].order - 4)
        twin = i;
    }
    QVERIFY(twin >= 0);
    QSignalSpy changed(&page, &views::IdentificationPage::selectionChanged);
    // Zoom the diagram on mode 1 so the two poles are apart on screen.
    diagram->setAxisScale(QwtPlot::xBottom, poles[chosen1].frequencyHz - 0.05, poles[chosen1].frequencyHz + 0.05);
    diagram->replot();
    clickPole(diagram, twin);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(page.tableRows().size(), size_t(5));
    QVERIFY2(!page.warningText().isEmpty(), "no same-mode warning");
    QVERIFY2(page.warningText().contains(QStringLiteral("one mode")), qPrintable(page.warningText()));
    qInfo("pole click -> table and synthesis: %.1f ms CPU, %.1f ms wall", page.lastSelectionUpdateCpuMs(),
          page.lastSelectionUpdateMs());
    QVERIFY(page.lastSelectionUpdateCpuMs() <= 100.0);  // issue 18: 50 ms, see timeBudgetsOn100x20000
    page.findChild<QTabWidget*>()->setCurrentIndex(1);
    screenshot(&page, QStringLiteral("identification_beam_warning"));
    // Clicking it again removes it; clicking mode 4's pole removes mode 4.
    clickPole(diagram, twin);
    QCOMPARE(page.tableRows().size(), size_t(4));
    QVERIFY(page.warningText().isEmpty());
    diagram->setAxisScale(QwtPlot::xBottom, 65.0, 1000.0);
    diagram->replot();
    const int chosen4 = diagram->selection()[3];
    clickPole(diagram, chosen4);
    QCOMPARE(page.tableRows().size(), size_t(3));
    QVERIFY(page.tableRows()[2].frequencyHz < 700.0);
    QVERIFY(!page.tableRows()[0].frequencyStdHz.has_value());  // hand-made: no standard errors until saved
    page.findChild<QTabWidget*>()->setCurrentIndex(0);
    QTest::mouseClick(page.findChild<QPushButton*>(QStringLiteral("identificationAutomatic")), Qt::LeftButton);
    QCOMPARE(page.tableRows().size(), size_t(4));

    // Save, and the CLI's --store on the same set: equal stored tables.
    QSignalSpy saved(&page, &views::IdentificationPage::saved);
    QTest::mouseClick(page.findChild<QPushButton*>(QStringLiteral("identificationSave")), Qt::LeftButton);
    QVERIFY(saved.count() == 1 || saved.wait(600000));
    const qint64 guiId = saved.at(0).at(0).toLongLong();
    QVERIFY(cli.contains("modal_result_id"));
    const qint64 cliId = cli["modal_result_id"].get<qint64>();
    auto cliStore = core::io::ProjectStore::open(cliPath_.toStdString(), core::io::ProjectStore::OpenMode::ReadOnly);
    QVERIFY(cliStore.ok());
    auto gui = model_.store()->modalResult(guiId);
    auto cliTable = cliStore->modalResult(cliId);
    QVERIFY(gui.ok() && cliTable.ok());
    QCOMPARE(gui->modes.size(), size_t(4));
    QCOMPARE(cliTable->modes.size(), size_t(4));
    QVERIFY(gui->dofs == cliTable->dofs);
    for (std::size_t r = 0; r < 4; ++r) {
      QCOMPARE(gui->modes[r].frequencyHz, cliTable->modes[r].frequencyHz);
      QCOMPARE(gui->modes[r].dampingRatio, cliTable->modes[r].dampingRatio);
      QVERIFY((gui->modes[r].shape - cliTable->modes[r].shape).norm() <= 1e-12 * cliTable->modes[r].shape.norm());
    }
    auto infos = model_.store()->modalResults();
    auto cliInfos = cliStore->modalResults();
    QVERIFY(infos.ok() && cliInfos.ok());
    QCOMPARE(infos->size(), size_t(1));
    QCOMPARE(cliInfos->size(), size_t(1));
    for (const auto& i : {infos->front(), cliInfos->front()}) {
      QCOMPARE(QString::fromStdString(i.method), QStringLiteral("PolyMAX"));
      QCOMPARE(QString::fromStdString(i.name), QStringLiteral("PolyMAX 65 .. 1000 Hz"));
      QVERIFY(i.frfSetId.has_value());
    }
    QCOMPARE(infos->front().id, guiId);
    QCOMPARE(*infos->front().frfSetId, set_);
    QCOMPARE(cliInfos->front().id, cliId);
    QCOMPARE(*cliInfos->front().frfSetId, cliSet_);
  }

  // The pages on the demo project's FRF set (forkSet above): the automatic
  // selection gives the specimen's three modes, frequencies within 0.1% and
  // damping within 5% (0.1% noise: the error is the estimator's, the close
  // pair 22.3 / 23.5 Hz is two modes 2 lines apart); the FRF page shows
  // them at the cursor. With MOZZI_DEMO_PROJECT naming a demo project made by
  // `mozzi-cli project demo`, the FRF page opens its first set too (screenshot
  // frf_page_demo).
  void pagesOnTheDemoForkSet() {
    const ForkSet fork = forkSet();
    core::io::FrfSetInfo info;
    info.specimenId = specimen_;
    info.name = "fork-a-with-wheel hammer 1 FRFs";
    auto set = model_.addFrfSet(info, fork.frf);
    QVERIFY(set.ok());
    views::PageContext ctx;
    ctx.model = &model_;
    ctx.jobs = &jobs_;
    ctx.item = views::ProjectItem{views::RecordKind::FrfSet, *set, specimen_};
    views::IdentificationPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    page.setBand(15.0, 80.0);
    page.setMaxOrder(40);
    // 162 FRFs: the refinement (all residues with the poles, minutes here) is
    // the beam test's; the LSFD fit of the automatic selection is checked.
    page.setRefine(false);
    QSignalSpy finished(&page, &views::IdentificationPage::finished);
    page.run();
    QVERIFY(waitFinished(finished, 900));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(page.statusText()));
    const auto rows = page.tableRows();
    QCOMPARE(rows.size(), size_t(3));
    for (std::size_t r = 0; r < 3; ++r) {
      qInfo("fork mode %zu: %.4f Hz (model %.1f), zeta %.5f (model %.3f)", r + 1, rows[r].frequencyHz,
            fork.spec.frequencyHz[r], rows[r].zeta, fork.spec.zeta[r]);
      QVERIFY(std::abs(rows[r].frequencyHz - fork.spec.frequencyHz[r]) < 1e-3 * fork.spec.frequencyHz[r]);
      QVERIFY(std::abs(rows[r].zeta - fork.spec.zeta[r]) < 0.05 * fork.spec.zeta[r]);
    }
    // The diagram draws the band and one selected pole per mode.
    auto* diagram = page.diagramPlot();
    QCOMPARE(diagram->selection().size(), size_t(3));
    QVERIFY(diagram->drawnPoleCount() > 0);
    screenshot(&page, QStringLiteral("identification_fork"));

    views::FrfPlot plot;
    plot.resize(1280, 800);
    plot.setFrfs(std::make_shared<const core::FrfMatrix>(fork.frf));
    std::vector<double> modes;
    for (const auto& r : rows) modes.push_back(r.frequencyHz);
    plot.setModeFrequencies(modes);
    plot.setView(views::FrfPlot::View::Bode);
    plot.setShowSum(true);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.setFrequencyRange(0.0, 120.0);
    plot.setCursorFrequency(67.0);
    QVERIFY2(plot.readoutText().contains(QStringLiteral("nearest mode 3")), qPrintable(plot.readoutText()));
    screenshot(&plot, QStringLiteral("frf_page_fork"));

    const QString demo = qEnvironmentVariable("MOZZI_DEMO_PROJECT");
    if (demo.isEmpty()) return;
    views::ProjectModel demoModel;
    QVERIFY(demoModel.open(demo).ok());
    auto sets = demoModel.store()->frfSets();
    QVERIFY(sets.ok() && !sets->empty());
    views::FrfPlot dplot;
    dplot.resize(1280, 800);
    dplot.setFrfs(std::make_shared<const core::FrfMatrix>(demoModel.store()->frfSet(sets->front().id).value()));
    dplot.setModeFrequencies(modes);  // the model's modes, identified above
    dplot.setShowSum(true);
    dplot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dplot));
    dplot.setFrequencyRange(0.0, 120.0);
    dplot.setCursorFrequency(modes.front());
    screenshot(&dplot, QStringLiteral("frf_page_demo"));
  }

  void cancelStopsTheRun() {
    views::PageContext ctx;
    ctx.model = &model_;
    ctx.jobs = &jobs_;
    ctx.item = views::ProjectItem{views::RecordKind::FrfSet, set_, specimen_};
    views::IdentificationPage page(ctx);
    page.setBand(65.0, 1000.0);
    page.setMaxOrder(60);
    QSignalSpy finished(&page, &views::IdentificationPage::finished);
    page.run();
    QVERIFY(page.isRunning());
    page.cancel();
    QVERIFY(waitFinished(finished, 600));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QVERIFY2(page.statusText().contains(QStringLiteral("cancelled")), qPrintable(page.statusText()));
    // A band with no line is refused with the reason.
    page.setBand(2000.0, 3000.0);
    page.run();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
    QCOMPARE(finished.at(1).at(0).toBool(), false);
    QVERIFY(page.statusText().contains(QStringLiteral("failed")));
  }

  // 100 FRFs x 20,000 lines: the diagram is drawn within 0.5 s of the
  // result, and a pole click updates table and synthesis in 50 ms or less.
  void timeBudgetsOn100x20000() {
    core::FrfMatrix frf;
    const int n = 20000, no = 100;
    frf.frequencyHz = core::Vector::LinSpaced(n, 0.05, 1000.0);
    frf.references = {core::Dof{1, core::Direction::Z}};
    frf.type = core::FrfType::Accelerance;
    frf.h.emplace_back(n, no);
    const double fn[5] = {120.0, 260.0, 410.0, 640.0, 870.0};
    for (int o = 0; o < no; ++o) {
      frf.responses.push_back(core::Dof{o + 2, core::Direction::Z});
      for (int k = 0; k < n; ++k) {
        const double w = 2 * M_PI * frf.frequencyHz[k];
        core::Complex h(0.0, 0.0);
        for (int r = 0; r < 5; ++r) {
          const double wr = 2 * M_PI * fn[r];
          h += -w * w * std::sin(0.37 * (r + 1) * (o + 1)) / core::Complex(wr * wr - w * w, 2 * 0.01 * wr * w);
        }
        frf.h[0](k, o) = h;
      }
    }
    core::io::FrfSetInfo info;
    info.specimenId = specimen_;
    info.name = "100 x 20000";
    auto set = model_.addFrfSet(info, frf);
    QVERIFY(set.ok());
    views::PageContext ctx;
    ctx.model = &model_;
    ctx.jobs = &jobs_;
    ctx.item = views::ProjectItem{views::RecordKind::FrfSet, *set, specimen_};
    views::IdentificationPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    page.setBand(50.0, 950.0);
    page.setMaxOrder(30);
    page.setRefine(false);  // the budgets are about drawing and clicking, not the refinement's minutes
    QSignalSpy finished(&page, &views::IdentificationPage::finished);
    QElapsedTimer run;
    run.start();
    page.run();
    QVERIFY(waitFinished(finished, 900));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(page.statusText()));
    // Budgets on the GUI thread's CPU time (the suite's machine is shared;
    // wall time printed too).
    qInfo("100 x 20000: identification %.1f s; diagram (%d poles) drawn %.1f ms CPU (%.1f ms wall) after the result",
          run.elapsed() / 1000.0, page.diagramPlot()->drawnPoleCount(), page.lastDiagramDrawCpuMs(),
          page.lastDiagramDrawMs());
    QCOMPARE(page.tableRows().size(), size_t(5));
    QVERIFY(page.lastDiagramDrawCpuMs() <= 500.0);
    // Remove and re-add a mode by clicking its pole, five times each.
    auto* diagram = page.diagramPlot();
    const int p = diagram->selection()[2];
    std::vector<double> removeCpu, addCpu, wall;
    for (int k = 0; k < 5; ++k) {
      clickPole(diagram, p);
      QCOMPARE(page.tableRows().size(), size_t(4));
      removeCpu.push_back(page.lastSelectionUpdateCpuMs());
      wall.push_back(page.lastSelectionUpdateMs());
      clickPole(diagram, p);
      QCOMPARE(page.tableRows().size(), size_t(5));
      addCpu.push_back(page.lastSelectionUpdateCpuMs());
      wall.push_back(page.lastSelectionUpdateMs());
    }
    std::vector<double> all = removeCpu;
    all.insert(all.end(), addCpu.begin(), addCpu.end());
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
    };
    auto max = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    qInfo(
        "100 x 20000: pole click -> table and synthesis, ms CPU median (max): removing %.1f (%.1f), adding %.1f "
        "(%.1f), all ten %.1f (%.1f); wall median %.1f (max %.1f)",
        median(removeCpu), max(removeCpu), median(addCpu), max(addCpu), median(all), max(all), median(wall), max(wall));
    QString each;
    for (std::size_t k = 0; k < removeCpu.size(); ++k)
      each += QStringLiteral(" -%1 +%2").arg(removeCpu[k], 0, 'f', 1).arg(addCpu[k], 0, 'f', 1);
    qInfo("100 x 20000: each click, ms CPU:%s", qPrintable(each));
    // Issue 18: 50 ms, asserted on the median of the ten clicks. With the
    // page's SelectionFitter (fit once per band, residual per FRF in blocks,
    // only the FRF shown synthesised, the hidden tab left for later) this
    // machine measures medians of 25 to 33 ms and single clicks up to 39 ms
    // in GUI-thread CPU with another build running
    // (docs/performance/workbench-plots.md): half to two thirds of the
    // budget, so the median holds on a shared 2-core machine; before, 41 to
    // 77 ms. A single click may be slowed by what else the machine runs: it
    // is held to twice the budget.
    QVERIFY2(median(all) <= 50.0, qPrintable(QStringLiteral("median %1 ms").arg(median(all))));
    QVERIFY2(max(all) <= 100.0, qPrintable(QStringLiteral("%1 ms").arg(max(all))));
  }

  // A kept LSCE result: the page opened on its set shows it over an LSCE
  // diagram of its band (the method box follows the kept result, so a
  // selection saved from it is LSCE), each mode ringed on a pole; the Over box
  // redraws the curve under it and keeps the selection. A kept peak-picking
  // result has no diagram behind it.
  void keptResultShownOverItsOwnMethodsDiagram() {
    const ForkSet fork = forkSet();
    const auto keep = [&](const std::string& name, const std::string& method) -> qint64 {
      core::io::FrfSetInfo info;
      info.specimenId = specimen_;
      info.name = name;
      auto set = model_.addFrfSet(info, fork.frf);
      if (!set.ok()) return 0;
      core::io::ModalResultInfo kept;
      kept.specimenId = specimen_;
      kept.frfSetId = *set;
      kept.name = name + " modes";
      kept.method = method;
      kept.bandLowHz = 15.0;
      kept.bandHighHz = 80.0;
      core::io::ModalTable table;
      for (std::size_t r = 0; r < 3; ++r) {
        table.modes.push_back({fork.spec.frequencyHz[r], fork.spec.zeta[r], {}});
        table.modes[r].frequencyStdHz = 0.001 * static_cast<double>(r + 1);  // as a refinement keeps them
        table.modes[r].dampingRatioStd = 1e-4 * static_cast<double>(r + 1);
      }
      return model_.addModalResult(kept, table).ok() ? *set : 0;
    };
    const qint64 lsceSet = keep("fork kept LSCE", "LSCE");
    QVERIFY(lsceSet > 0);
    views::PageContext ctx;
    ctx.model = &model_;
    ctx.jobs = &jobs_;
    ctx.item = views::ProjectItem{views::RecordKind::FrfSet, lsceSet, specimen_};
    views::IdentificationPage page(ctx);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    QVERIFY(page.keptResult());
    QTRY_VERIFY_WITH_TIMEOUT(page.diagramPlot()->drawnPoleCount() > 0, 300000);
    QVERIFY(page.outcome());
    QCOMPARE(page.outcome()->options.method, views::identification::Method::Lsce);
    QCOMPARE(page.findChild<QComboBox*>(QStringLiteral("identificationMethod"))->currentIndex(),
             static_cast<int>(views::identification::Method::Lsce));
    const auto ringed = page.diagramPlot()->selection();
    QCOMPARE(ringed.size(), size_t(3));
    for (int index : ringed) QVERIFY(index >= 0);
    const std::size_t sumLines = page.diagramPlot()->backdropCurve()->dataSize();
    const double sumFirst = page.diagramPlot()->backdropCurve()->sample(0).y();
    page.setBackdrop(views::identification::Backdrop::Cmif);
    QCOMPARE(page.outcome()->options.backdrop, views::identification::Backdrop::Cmif);
    QCOMPARE(page.diagramPlot()->backdropCurve()->dataSize(), sumLines);      // the same band
    QVERIFY(page.diagramPlot()->backdropCurve()->sample(0).y() != sumFirst);  // another curve
    QCOMPARE(page.diagramPlot()->selection(), ringed);
    QCOMPARE(page.tableRows().size(), size_t(3));
    // The kept modes with the standard errors they were kept with, in the rows and the table's cells.
    auto* modeTable = page.findChild<QTableWidget*>(QStringLiteral("identificationModalTable"));
    QVERIFY(modeTable);
    for (std::size_t r = 0; r < 3; ++r) {
      const auto& row = page.tableRows()[r];
      QVERIFY(row.frequencyStdHz && row.zetaStd && row.etaStd);
      QCOMPARE(*row.frequencyStdHz, 0.001 * static_cast<double>(r + 1));
      QCOMPARE(*row.zetaStd, 1e-4 * static_cast<double>(r + 1));
      QCOMPARE(*row.etaStd, 2e-4 * static_cast<double>(r + 1));
      QCOMPARE(modeTable->item(static_cast<int>(r), 2)->text(), QString::number(0.001 * static_cast<double>(r + 1)));
    }
    // The kept modes are in the project already: Save waits for another
    // selection (it stored a re-refined copy of them).
    auto* save = page.findChild<QPushButton*>(QStringLiteral("identificationSave"));
    QVERIFY(save && !save->isEnabled());
    clickPole(page.diagramPlot(), ringed[0]);
    QCOMPARE(page.tableRows().size(), size_t(2));
    QVERIFY(save->isEnabled());
    // Another selection is an LSFD fit of its own: no standard errors until refined.
    for (const auto& row : page.tableRows()) QVERIFY(!row.frequencyStdHz && !row.zetaStd);

    const qint64 peakSet = keep("fork kept peak", "peak picking");
    QVERIFY(peakSet > 0);
    QVERIFY(page.setFrfSet(peakSet));
    QVERIFY(page.keptResult());
    QTRY_VERIFY_WITH_TIMEOUT(!jobs_.isRunning(), 300000);
    QTest::qWait(50);  // a result posted by a finished job is delivered
    QCOMPARE(page.diagramPlot()->drawnPoleCount(), 0);
    QVERIFY(!page.outcome());
    QCOMPARE(page.tableRows().size(), size_t(3));
    // Without a diagram the Over box redraws the whole set's curve (it was
    // left on CMIF above): 20 log10 of the sum of |H| over the FRFs on every
    // line above 0 Hz (1e-9 dB: the same sum, another order of adding).
    page.setBackdrop(views::identification::Backdrop::Sum);
    const auto* curve = page.diagramPlot()->backdropCurve();
    Eigen::Index first = 0;
    while (!(fork.frf.frequencyHz[first] > 0.0)) ++first;
    QCOMPARE(static_cast<Eigen::Index>(curve->dataSize()), fork.frf.lineCount() - first);
    for (Eigen::Index k = first; k < fork.frf.lineCount(); k += 97) {
      double sum = 0.0;
      for (const auto& h : fork.frf.h) sum += h.row(k).cwiseAbs().sum();
      QVERIFY(std::abs(curve->sample(static_cast<std::size_t>(k - first)).y() - 20.0 * std::log10(sum)) < 1e-9);
    }
  }

 private:
  QTemporaryDir dir_;
  QString path_, cliPath_;
  views::ProjectModel model_;
  views::JobRunner jobs_;
  qint64 specimen_ = 0, set_ = 0, cliSet_ = 0;
};

QTEST_MAIN(IdentificationPageTest)
#include "identification_page_test.moc"
