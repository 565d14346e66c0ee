// The rig test page's plots and results: the curves each test shows, the
// sine sweep's axis plot, and a stored test read back from the project.

#include "views/rigs/rig_test_page.h"

#include <qwt_interval_symbol.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_symbol.h>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScopeGuard>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>
#include <variant>

#include "core/common/text.h"
#include "core/io/project_store.h"
#include "core/tire/magic_formula.h"
#include "devices/rigtests/rig_sequence.h"
#include "devices/rigtests/sequence_parameters.h"
#include "devices/rigtests/stiffness_results.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/tyre_tests.h"
#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"
#include "views/common/job_runner.h"
#include "views/panels/parameter_form.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/plot_export.h"
#include "views/scene/plate_sketch.h"

#include "views/rigs/rig_test_page_internal.h"

namespace mozzi {
namespace views {

using rig_page::addCurve;
using rig_page::kPi;
using rig_page::kSineTimeWindowS;
using rig_page::kTyreTimeWindowS;
using rig_page::qs;
using rig_page::resultLabel;
using rig_page::setAxisText;
using rig_page::shown;

void RigTestPage::resetPlots(bool clearData) {
  const bool stiff = rig_ == Rig::Stiffness;
  const QString id = testId();
  if (clearData) {
    timeLeftData_.clear();
    timeRightData_.clear();
    xyData_.clear();
    xySecondData_.clear();
    liveStep_ = -1;
  }
  if (!timeLeft_) {  // the curves are made once; a reset empties and re-titles them
    timeLeft_ = addCurve(livePlot_, QColor(31, 119, 180));
    timeRight_ = addCurve(livePlot_, QColor(214, 39, 40), QwtPlot::yRight);
    xyLive_ = addCurve(resultPlot_, QColor(31, 119, 180));
    xySecond_ = addCurve(resultPlot_, QColor(44, 160, 44));
    fitLine_ = addCurve(resultPlot_, QColor(0, 0, 0));
    fitLine2_ = addCurve(resultPlot_, QColor(120, 120, 120));
    fitLine_->setPen(QPen(Qt::black, 1.5, Qt::DashLine));
    fitLine2_->setPen(QPen(QColor(120, 120, 120), 1.5, Qt::DashLine));
    mfSlip_ = addCurve(resultPlot_, QColor(148, 103, 189));
    mfCamber_ = addCurve(resultPlot_, QColor(140, 86, 75));
    mfSlip_->setPen(QPen(QColor(148, 103, 189), 2.0));
    mfCamber_->setPen(QPen(QColor(140, 86, 75), 2.0));
    timeLeft_->setPen(QPen(QColor(31, 119, 180), 3.0));  // wide: an in-phase trace on the right axis covers it
    sineFit_ = addCurve(resultPlot_, Qt::black);
    sineFit_->setPen(QPen(Qt::black, 1.5, Qt::DashLine));
    const QColor incColour(31, 119, 180), armColour(214, 39, 40);
    inclination_ = addCurve(axisPlot_, incColour);
    inclination_->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(incColour), QPen(incColour), QSize(7, 7)));
    arm_ = addCurve(axisPlot_, armColour, QwtPlot::yRight);
    arm_->setSymbol(new QwtSymbol(QwtSymbol::Rect, QBrush(armColour), QPen(armColour), QSize(7, 7)));
    auto bars = [this](const QColor& colour, int yAxis) {
      auto* c = new QwtPlotIntervalCurve();
      c->setStyle(QwtPlotIntervalCurve::NoCurve);
      auto* symbol = new QwtIntervalSymbol(QwtIntervalSymbol::Bar);
      symbol->setWidth(8);
      symbol->setPen(QPen(colour, 1.2));
      c->setSymbol(symbol);
      c->setYAxis(yAxis);
      c->setItemAttribute(QwtPlotItem::Legend, false);
      c->attach(axisPlot_);
      return c;
    };
    inclinationBars_ = bars(incColour, QwtPlot::yLeft);
    armBars_ = bars(armColour, QwtPlot::yRight);
  }
  const bool sine = stiff && id == QLatin1String("dynamic");
  axisPlot_->setVisible(sine);
  if (clearData) {
    livePlot_->setVisible(true);
    clearAxisPlot();
    sineFit_->setSamples(QVector<QPointF>());
  }
  sineFit_->setVisible(sine);
  sineFit_->setItemAttribute(QwtPlotItem::Legend, sine);
  const bool steady = id == QLatin1String("steady-state");
  for (QwtPlotCurve* c : {xyLive_, xySecond_}) {
    // Steady state: one point per set-point; otherwise a line through the scans.
    c->setStyle(steady ? QwtPlotCurve::NoCurve : QwtPlotCurve::Lines);
    const QColor colour = c->pen().color();
    c->setSymbol(steady ? new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(7, 7)) : nullptr);
  }
  if (clearData)
    for (QwtPlotCurve* c : {timeLeft_, timeRight_, xyLive_, xySecond_, fitLine_, fitLine2_, mfSlip_, mfCamber_})
      c->setSamples(QVector<QPointF>());
  // Which curves this test draws (and lists in the legend).
  const bool second = !stiff && steady;
  const bool fit = stiff ? id == QLatin1String("static") : steady;
  const std::pair<QwtPlotCurve*, bool> used[] = {
      {xySecond_, second}, {fitLine_, fit}, {fitLine2_, second}, {mfSlip_, second}, {mfCamber_, second}};
  for (const auto& [c, on] : used) {
    c->setVisible(on);
    c->setItemAttribute(QwtPlotItem::Legend, on);
  }
  // A measured line under a stored fit is drawn wide and light, so both show where they agree.
  const bool under = (fit && !steady) || sine;  // a stored line or a sine-fit loop drawn over it
  xyLive_->setPen(QPen(under ? QColor(120, 170, 220) : QColor(31, 119, 180), under ? 5.0 : 1.5));
  setAxisText(livePlot_, QwtPlot::xBottom, tr("Time [s]"));
  if (stiff) {
    timeWindowS_ = id == QLatin1String("dynamic") ? kSineTimeWindowS : 0.0;
    livePlot_->setTitle(tr("Load cell and load-point displacement"));
    setAxisText(livePlot_, QwtPlot::yLeft, tr("Force [N]"));
    setAxisText(livePlot_, QwtPlot::yRight, tr("Displacement [mm]"));
    timeLeft_->setTitle(tr("load cell [N]"));
    timeRight_->setTitle(tr("load-point displacement [mm]"));
    resultPlot_->setTitle(tr("Force vs load-point displacement"));
    setAxisText(resultPlot_, QwtPlot::xBottom, tr("Load-point displacement [mm]"));
    setAxisText(resultPlot_, QwtPlot::yLeft, tr("Force [N]"));
    xyLive_->setTitle(id == QLatin1String("dynamic") ? tr("current frequency") : tr("measured"));
    fitLine_->setTitle(tr("F = k_lat x (stored k_lat)"));
    sineFit_->setTitle(tr("sine fit, last frequency"));
    axisPlot_->setTitle(tr("Dynamic twist axis against frequency"));
    setAxisText(axisPlot_, QwtPlot::xBottom, tr("Frequency [Hz]"));
    setAxisText(axisPlot_, QwtPlot::yLeft, tr("Inclination [deg]"));
    setAxisText(axisPlot_, QwtPlot::yRight, tr("Twist arm a_tw [mm]"));
    inclination_->setTitle(tr("inclination ± 1σ"));
    arm_->setTitle(tr("a_tw ± 1σ"));
  } else {
    timeWindowS_ = kTyreTimeWindowS;
    livePlot_->setTitle(tr("Lateral force and aligning moment"));
    setAxisText(livePlot_, QwtPlot::yLeft, tr("F_y [N]"));
    setAxisText(livePlot_, QwtPlot::yRight, tr("M_z [N m]"));
    timeLeft_->setTitle(tr("F_y [N]"));
    timeRight_->setTitle(tr("M_z [N m]"));
    setAxisText(resultPlot_, QwtPlot::yLeft, tr("F_y [N]"));
    if (steady) {
      resultPlot_->setTitle(tr("Steady-state characteristic"));
      setAxisText(resultPlot_, QwtPlot::xBottom, tr("Side-slip, camber [deg]"));
      xyLive_->setTitle(tr("F_y vs side-slip"));
      xySecond_->setTitle(tr("F_y vs camber"));
      fitLine_->setTitle(tr("cornering stiffness (stored)"));
      fitLine2_->setTitle(tr("camber stiffness (stored)"));
      mfSlip_->setTitle(tr("Magic Formula vs side-slip"));
      mfCamber_->setTitle(tr("Magic Formula vs camber"));
    } else {
      resultPlot_->setTitle(tr("Lateral force vs yaw angle"));
      setAxisText(resultPlot_, QwtPlot::xBottom, tr("Yaw angle [deg]"));
      xyLive_->setTitle(tr("current frequency"));
    }
  }
  livePlot_->setAxisAutoScale(QwtPlot::xBottom);
  livePlot_->setAxisAutoScale(QwtPlot::yLeft);
  livePlot_->setAxisAutoScale(QwtPlot::yRight);
  resultPlot_->setAxisAutoScale(QwtPlot::xBottom);
  resultPlot_->setAxisAutoScale(QwtPlot::yLeft);
  livePlot_->updateLegend();
  resultPlot_->updateLegend();
  livePlot_->replot();
  resultPlot_->replot();
}

void RigTestPage::clearAxisPlot() {
  inclinationData_.clear();
  armData_.clear();
  inclinationSigma_.clear();
  armSigma_.clear();
  if (!inclination_) return;
  inclination_->setSamples(QVector<QPointF>());
  arm_->setSamples(QVector<QPointF>());
  inclinationBars_->setSamples(QVector<QwtIntervalSample>());
  armBars_->setSamples(QVector<QwtIntervalSample>());
}

void RigTestPage::addAxisPoint(const std::vector<rt::Quantity>& results) {
  const auto* f = rt::findQuantity(results, "frequency");
  const auto* beta = rt::findQuantity(results, "axis_inclination");
  const auto* arm = rt::findQuantity(results, "a_tw");
  if (!f) return;
  // As stored (rad, m), shown in degrees and millimetres.
  if (beta) {
    inclinationData_.append(QPointF(f->value, beta->value * 180.0 / kPi));
    inclinationSigma_.append(QPointF(f->value, beta->uncertainty * 180.0 / kPi));
  }
  if (arm) {
    armData_.append(QPointF(f->value, arm->value * 1e3));
    armSigma_.append(QPointF(f->value, arm->uncertainty * 1e3));
  }
  auto bars = [](const QVector<QPointF>& data, const QVector<QPointF>& sigma) {
    QVector<QwtIntervalSample> out;
    for (int i = 0; i < data.size() && i < sigma.size(); ++i)
      out.append(QwtIntervalSample(data[i].x(), data[i].y() - sigma[i].y(), data[i].y() + sigma[i].y()));
    return out;
  };
  inclination_->setSamples(inclinationData_);
  arm_->setSamples(armData_);
  inclinationBars_->setSamples(bars(inclinationData_, inclinationSigma_));
  armBars_->setSamples(bars(armData_, armSigma_));
  // The loop the sine fits of this frequency describe, over the measured one.
  const auto* force = rt::findQuantity(results, "force_amplitude");
  const auto phasors = rt::laserPhasorsOf(results, laserPoints_.size());
  if (force && phasors) {
    std::vector<core::Vector2> lasers;
    for (const auto& [u, v] : laserPoints_) lasers.emplace_back(u, v);
    auto loop = rt::fittedSineLoop(lasers, core::Vector2(loadPoint_.first, loadPoint_.second), force->value, *phasors);
    QVector<QPointF> samples;
    if (loop)
      for (const auto& p : *loop) samples.append(QPointF(p.x() * 1e3, p.y()));
    sineFit_->setSamples(samples);
  }
  dirty_ = true;
}

void RigTestPage::replot() {
  timeLeft_->setSamples(timeLeftData_);
  timeRight_->setSamples(timeRightData_);
  xyLive_->setSamples(xyData_);
  xySecond_->setSamples(xySecondData_);
  livePlot_->replot();
  resultPlot_->replot();
  axisPlot_->replot();
  dirty_ = false;
  if (isRunning()) {
    ++redraws_;
    const qint64 now = clock_.elapsed();
    if (firstRedrawMs_ < 0) firstRedrawMs_ = now;
    lastRedrawMs_ = now;
  }
}

double RigTestPage::redrawRateHz() const {
  if (redraws_ < 2 || lastRedrawMs_ <= firstRedrawMs_) return 0.0;
  return (redraws_ - 1) * 1000.0 / static_cast<double>(lastRedrawMs_ - firstRedrawMs_);
}

std::optional<qint64> RigTestPage::latestStoredTest(bool anyKind) const {
  core::io::ProjectStore* store = model_->store();
  if (!store) return std::nullopt;
  auto tests = rig_ == Rig::Stiffness ? store->rigTests() : store->tyreTests();
  if (!tests) return std::nullopt;
  const std::string key = specimenKey().toStdString(), kind = testId().toStdString();
  std::optional<qint64> latest;
  for (const auto& t : *tests) {
    const auto* entry = rt::catalogueEntryForName(t.specimenName);
    if (!entry || entry->key != key || (!anyKind && t.kind != kind)) continue;
    if (!latest || t.id > *latest) latest = t.id;  // ids grow with each test stored
  }
  return latest;
}

void RigTestPage::showLatestStored(bool anyKind) {
  if (isRunning() || showingStored_) return;
  if (const auto id = latestStoredTest(anyKind)) {
    showStoredTest(*id);
    return;
  }
  // Nothing stored for this choice: no other specimen's or test's result stays.
  results_->setRowCount(0);
  headline_->clear();
  headline_->setToolTip(QString());
  lastTestId_.reset();
}

void RigTestPage::showStoredTest(qint64 id) {
  core::io::ProjectStore* store = model_->store();
  if (!store) return;
  showingStored_ = true;
  const auto done = qScopeGuard([this] { showingStored_ = false; });
  using Row = StoredRow;
  std::vector<Row> rows;
  std::vector<core::io::StoredTyreTest::Point> storedPoints;
  double tyreLoadN = 0.0, tyrePressurePa = 0.0;
  std::string parametersJson, name, note;
  core::io::TestStatus status = core::io::TestStatus::Complete;
  if (rig_ == Rig::Stiffness) {
    auto t = store->rigTest(id);
    if (!t) {
      const QString why = qs(t.error().describe());
      setStatus([why] { return tr("Cannot read the rig test: %1").arg(why); }, true);
      return;
    }
    for (const auto& r : t->results) rows.push_back({r.step, r.quantity, r.value, r.uncertainty, r.unit});
    parametersJson = t->parametersJson;
    name = t->name;
    status = t->status;
    note = t->statusNote;
  } else {
    auto t = store->tyreTest(id);
    if (!t) {
      const QString why = qs(t.error().describe());
      setStatus([why] { return tr("Cannot read the tyre test: %1").arg(why); }, true);
      return;
    }
    for (const auto& r : t->parameters) rows.push_back({r.step, r.name, r.value, r.uncertainty, r.unit});
    storedPoints = t->points;
    tyreLoadN = t->verticalLoadN;
    tyrePressurePa = t->inflationPressurePa;
    parametersJson = t->parametersJson;
    name = t->name;
    status = t->status;
    note = t->statusNote;
  }
  // Step labels from the plan the sequence stored ("steps": [{"label": ...}]).
  std::vector<QString> labels;
  const auto plan = nlohmann::json::parse(parametersJson, nullptr, false);
  // A test opened from the project tree: its kind's plots, its stored points.
  if (!isRunning() && plan.is_object() && plan.contains("test") && plan["test"].is_string()) {
    const QString kind = qs(plan["test"].get<std::string>());
    if (kind != testId()) selectTest(kind);
  }
  if (!isRunning() && rig_ == Rig::Tyre && testId() == QLatin1String("steady-state") && xyData_.isEmpty() &&
      xySecondData_.isEmpty()) {
    // Each point to its sweep by the plan's step of the same set-point (the
    // point at zero slip and zero camber is in both sweeps, once each); a
    // plan without steps: the slip sweep runs at zero camber.
    struct PlanStep {
      double slip, camber;
      bool slipSweep, used;
    };
    std::vector<PlanStep> planSteps;
    if (plan.is_object() && plan.contains("steps") && plan["steps"].is_array())
      for (const auto& st : plan["steps"])
        if (st.is_object() && st.value("slip_rad", nlohmann::json()).is_number() &&
            st.value("camber_rad", nlohmann::json()).is_number() && st.value("label", nlohmann::json()).is_string())
          planSteps.push_back({st["slip_rad"].get<double>(), st["camber_rad"].get<double>(),
                               st["label"].get<std::string>().rfind("slip", 0) == 0, false});
    for (const auto& p : storedPoints) {
      bool slipSweep = p.camberRad == 0.0;
      for (auto& st : planSteps)
        if (!st.used && std::abs(st.slip - p.slipAngleRad) <= 1e-12 && std::abs(st.camber - p.camberRad) <= 1e-12) {
          st.used = true;
          slipSweep = st.slipSweep;
          break;
        }
      if (slipSweep)
        xyData_.append(QPointF(p.slipAngleRad * 180.0 / kPi, p.lateralForceN));
      else
        xySecondData_.append(QPointF(p.camberRad * 180.0 / kPi, p.lateralForceN));
    }
  }
  if (plan.is_object() && plan.contains("steps") && plan["steps"].is_array())
    for (const auto& st : plan["steps"])
      labels.push_back(st.is_object() && st.contains("label") && st["label"].is_string()
                           ? qs(st["label"].get<std::string>())
                           : QString());
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.step.value_or(-1) < b.step.value_or(-1); });
  results_->setRowCount(static_cast<int>(rows.size()));
  const std::string headlineKeys[] = {
      "k_lat", "k_tw", "axis_inclination", "relaxation_length_m", "cornering_stiffness", "camber_stiffness"};
  QStringList headline, stepHeadline;
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const Row& r = rows[static_cast<std::size_t>(i)];
    const auto s = shown(r.value, r.uncertainty, r.unit);
    // Value and uncertainty to the uncertainty's second digit (not 55996 ±
    // 6.1756 N/m); the value alone to 5 digits without one.
    const core::MeasuredText m = core::formatMeasured(s.value, s.uncertainty);
    const QString value = qs(m.value), uncertainty = m.uncertainty.empty() ? QStringLiteral("-") : qs(m.uncertainty);
    const QString withUncertainty = m.uncertainty.empty() ? value : QStringLiteral("%1 ± %2").arg(value, uncertainty);
    QString step = tr("whole test");
    if (r.step) {
      const auto k = static_cast<std::size_t>(*r.step);
      step = k < labels.size() && !labels[k].isEmpty() ? QStringLiteral("%1: %2").arg(*r.step).arg(labels[k])
                                                       : QString::number(*r.step);
    }
    const QString items[] = {step, resultLabel(r.key), value, uncertainty, s.unit};
    for (int c = 0; c < 5; ++c) {
      auto* item = new QTableWidgetItem(items[c]);
      if (c == 2 || c == 3) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setData(Qt::UserRole, qs(r.key));
      item->setToolTip(items[c]);  // a long quantity's name is elided in its column
      results_->setItem(i, c, item);
    }
    if (!r.step)
      for (const auto& k : headlineKeys)
        if (r.key == k) headline << QStringLiteral("%1 = %2 %3").arg(resultLabel(r.key), withUncertainty, s.unit);
    if (r.step && r.key == "k_lat")  // a sine sweep: the dynamic stiffness per frequency
      stepHeadline << QStringLiteral("%1: %2 = %3 %4").arg(step, resultLabel(r.key), withUncertainty, s.unit);
  }
  results_->resizeColumnsToContents();
  results_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
  QString word;
  switch (status) {
    case core::io::TestStatus::Running: word = tr("running"); break;
    case core::io::TestStatus::Complete: word = tr("complete"); break;
    case core::io::TestStatus::Interrupted: word = tr("interrupted"); break;
    case core::io::TestStatus::Failed: word = tr("failed"); break;
  }
  QString head = tr("'%1' (%2)").arg(qs(name), word);
  headline_->setToolTip(qs(note));  // the status line shows it too
  // A sweep of more frequencies than four lines hold: the first two, the
  // last, and how many more the table lists (the trend, not the first four).
  if (headline.isEmpty() && stepHeadline.size() > 4) {
    headline = stepHeadline.mid(0, 2);
    headline << tr("… %n more in the table", nullptr, static_cast<int>(stepHeadline.size() - 3));
    headline << stepHeadline.back();
  } else if (headline.isEmpty()) {
    headline = stepHeadline;
  }
  if (!headline.isEmpty()) head += QStringLiteral("\n") + headline.join(QStringLiteral("\n"));
  headline_->setText(head);

  drawStoredFits(id, rows, tyreLoadN, tyrePressurePa);
  lastTestId_ = id;
  // A stored test opened without its run has no live traces: their plot
  // gives its room to the stored results until a run starts.
  livePlot_->setVisible(isRunning() || !timeLeftData_.isEmpty());
  replot();
}

// The stored results over what was measured: the fitted lines, the dynamic
// twist axes, the Magic Formula curves (plots show what the numbers say).
void RigTestPage::drawStoredFits(qint64 id, const std::vector<StoredRow>& rows, double tyreLoadN,
                                 double tyrePressurePa) {
  using Row = StoredRow;
  core::io::ProjectStore* store = model_->store();
  auto find = [&](const char* key) -> const Row* {
    for (const auto& r : rows)
      if (!r.step && r.key == key) return &r;
    return nullptr;
  };
  fitLine_->setSamples(QVector<QPointF>());
  fitLine2_->setSamples(QVector<QPointF>());
  if (rig_ == Rig::Stiffness && testId() == QLatin1String("dynamic")) {
    // The dynamic twist axis of every stored frequency, and the sine-fit
    // loop of the last one, from what the project holds.
    clearAxisPlot();
    sineFit_->setSamples(QVector<QPointF>());
    auto view = rt::readStiffnessTest(*store, id);
    if (view) {
      laserPoints_.clear();
      for (const auto& p : view->laserPoints) laserPoints_.emplace_back(p.x(), p.y());
      loadPoint_ = {view->loadPoint.x(), view->loadPoint.y()};
      for (const auto& st : view->steps) {
        std::vector<rt::Quantity> results;
        for (const auto& [key, q] : st.results)
          results.push_back(rt::Quantity{key, "", q.value, q.unit, q.uncertainty});
        addAxisPoint(results);
      }
    } else {
      const QString why = qs(view.error().describe());
      setStatus([why] { return tr("Cannot read the rig test's twist axes: %1").arg(why); }, true);
    }
  }
  if (rig_ == Rig::Stiffness) {
    const Row* k = find("k_lat");
    const Row* peak = find("peak_force");
    if (k && testId() == QLatin1String("static") && (!xyData_.isEmpty() || (peak && k->value > 0.0))) {
      // Over the measured ramp, or (a stored test without its live data)
      // over the displacement the stored peak force gives: +-F_peak / k_lat.
      double lo = 0.0, hi = 0.0;
      if (!xyData_.isEmpty()) {
        lo = hi = xyData_.first().x();
        for (const auto& p : xyData_) {
          lo = std::min(lo, p.x());
          hi = std::max(hi, p.x());
        }
      } else {
        hi = std::abs(peak->value) / k->value * 1e3;
        lo = -hi;
      }
      fitLine_->setSamples(QVector<QPointF>{{lo, k->value * lo * 1e-3}, {hi, k->value * hi * 1e-3}});
    }
  } else if (testId() == QLatin1String("steady-state")) {
    // Over the window the sequence fits the slope in (SteadyStateSettings).
    auto line = [](QwtPlotCurve* c, const QVector<QPointF>& data, double slopePerRad, double windowDeg) {
      if (data.isEmpty()) return;
      double lo = 0, hi = 0;
      for (const auto& p : data) {
        lo = std::min(lo, std::max(p.x(), -windowDeg));
        hi = std::max(hi, std::min(p.x(), windowDeg));
      }
      c->setSamples(QVector<QPointF>{{lo, slopePerRad * lo * kPi / 180.0}, {hi, slopePerRad * hi * kPi / 180.0}});
    };
    const rt::SteadyStateSettings defaults;
    if (const Row* c = find("cornering_stiffness")) line(fitLine_, xyData_, c->value, defaults.slipWindowDeg);
    if (const Row* c = find("camber_stiffness")) line(fitLine2_, xySecondData_, c->value, defaults.camberWindowDeg);
    // The stored Magic Formula over each sweep: the fitted coefficients, the
    // held ones at the values the fit started from (its defaults), at the
    // test's load and pressure (core/tire/magic_formula.h).
    mfSlip_->setSamples(QVector<QPointF>());
    mfCamber_->setSamples(QVector<QPointF>());
    core::tire::MfLateralCoefficients mf = core::tire::mfLateralDefaults();
    bool fitted = false;
    const auto& names = core::tire::mfLateralNames();
    for (std::size_t i = 0; i < names.size(); ++i)
      if (const Row* r = find(("mf_" + names[i]).c_str())) {
        mf[i] = r->value;
        fitted = true;
      }
    if (fitted && tyreLoadN > 0.0 && tyrePressurePa > 0.0) {
      const core::tire::MfConstants constants{tyreLoadN, tyrePressurePa, 0.3};  // R0 enters M_z only
      auto curve = [&](QwtPlotCurve* c, const QVector<QPointF>& data, bool slip) {
        if (data.size() < 2) return;
        double lo = data.first().x(), hi = lo;
        for (const auto& p : data) {
          lo = std::min(lo, p.x());
          hi = std::max(hi, p.x());
        }
        QVector<QPointF> samples;
        constexpr int kSamples = 200;
        for (int k = 0; k <= kSamples; ++k) {
          const double deg = lo + (hi - lo) * k / kSamples, rad = deg * kPi / 180.0;
          samples.append(QPointF(deg, core::tire::mfLateralForce(mf, constants, slip ? rad : 0.0, slip ? 0.0 : rad,
                                                                 tyreLoadN, tyrePressurePa)));
        }
        c->setSamples(samples);
      };
      curve(mfSlip_, xyData_, true);
      curve(mfCamber_, xySecondData_, false);
    }
  }
}

}  // namespace views
}  // namespace mozzi
