// The rig test page running a sequence: start and stop, and the hand-over
// buffer drained on the GUI timer into the live plots and readouts.

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

using rig_page::kPi;
using rig_page::kPlotRateHz;
using rig_page::number;
using rig_page::qs;
using rig_page::runOnSimulatedRig;
using rig_page::SequenceRun;
using rig_page::shown;
using rig_page::trimFront;

void RigTestPage::start() {
  if (isRunning()) return;
  core::io::ProjectStore* store = model_->store();
  if (!store) {
    setStatus([] { return tr("Open or create a project first: the test is stored in it."); }, true);
    return;
  }
  if (model_->isReadOnly()) {
    setStatus(
        [this] {
          return tr("The project is open read-only (%1): the test could not be stored.").arg(model_->readOnlyReason());
        },
        true);
    return;
  }
  if (testForm_->hasProblems() || rigForm_->hasProblems()) {
    setStatus([] { return tr("Correct the settings marked in the form first."); }, true);
    return;
  }
  const std::string key = specimenKey().toStdString();
  const auto rigValues = rigForm_->values();
  const auto seed = static_cast<std::uint64_t>(devices::parameterInteger(rigValues, "sim.seed", 1));
  const bool realtime = devices::parameterBool(rigValues, "sim.realtime", true);
  const QString id = testId();
  auto refuse = [this](const core::Error& e) {
    const QString why = qs(e.describe());
    setStatus([why] { return tr("Not started: %1").arg(why); }, true);
    if (log_) log_(tr("Rig test not started: %1").arg(qs(e.describe())));
  };

  auto handOver = std::make_shared<RigHandOver>();
  auto storeHandle = model_->storeHandle();
  const bool tyre = rig_ == Rig::Tyre;
  SequenceRun run;
  roles_.clear();
  if (!tyre) {
    auto setup = rt::simulatedStiffnessSetup(key, seed, realtime);
    if (!setup) return refuse(setup.error());
    std::shared_ptr<devices::Device> actuator;
    if (!setupForm_->specs().empty()) {
      setup = rt::stiffnessSetupFrom(*setup, geometryValues());
      if (!setup) return refuse(setup.error());
      auto device = rt::actuatorFor(
          devices::parameterText(setupForm_->values(), "setup.actuator", rt::kActuatorRigDrive), *setup);
      if (!device) return refuse(device.error());
      actuator = std::shared_ptr<devices::Device>(std::move(device).value());
      if (auto ok = rt::checkPlateGeometry(*setup); !ok) {
        drawSetup();  // marks the field
        plotTabs_->setCurrentIndex(1);
        setStatus([this] { return tr("Not started: %1").arg(geometry_->text()); }, true);
        if (log_) log_(tr("Rig test not started: %1").arg(geometry_->text()));
        return;
      }
    }
    laserPoints_.clear();
    for (const auto& p : setup->laserPoints) laserPoints_.emplace_back(p.x(), p.y());
    loadPoint_ = {setup->loadPoint.x(), setup->loadPoint.y()};
    if (id == QLatin1String("static")) {
      auto st = rt::staticSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkStaticSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st, actuator](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                                 const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runStaticStiffnessTest(d, actuator.get(), setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    } else {
      auto st = rt::dynamicSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkDynamicSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st, actuator](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                                 const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runDynamicStiffnessTest(d, actuator.get(), setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    }
  } else {
    const double pressure = devices::parameterReal(rigValues, "tyre.pressure_bar", 2.0);
    auto setup = rt::simulatedTyreSetup(key, pressure, seed, realtime);
    if (!setup) return refuse(setup.error());
    roles_ = {setup->lateralForce.name, setup->aligningMoment.name, setup->yawAngle.name, setup->camberAngle.name};
    if (id == QLatin1String("relaxation")) {
      auto st = rt::relaxationSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkRelaxationSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                       const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runRelaxationTest(d, setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    } else {
      auto st = rt::steadyStateSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkSteadyStateSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                       const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runSteadyStateTest(d, setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    }
  }

  handOver_ = handOver;
  runningTest_ = test_->currentText();
  lastTestId_.reset();
  redraws_ = 0;
  firstRedrawMs_ = lastRedrawMs_ = -1;
  clock_.start();
  resetPlots();
  plotTabs_->setCurrentIndex(0);
  results_->setRowCount(0);
  headline_->clear();
  logView_->show();
  progress_->setValue(0);
  setRunning(true);
  setStatus([this] { return tr("Running: %1 on %2").arg(test_->currentText(), specimen_->currentText()); });
  if (log_) log_(tr("Rig test started: %1 on %2").arg(runningTest_, specimen_->currentText()));
  jobId_ = jobs_->run<rt::Outcome>(
      this, tr("%1 on %2").arg(runningTest_, specimen_->currentText()),
      [handOver, storeHandle, key, tyre, run](JobProgress& p) {
        return runOnSimulatedRig(p, *handOver, storeHandle, key, tyre, run);
      },
      [this](const core::Result<rt::Outcome>& result) { onJobFinished(result); },
      [this](double fraction, const QString&) { progress_->setValue(static_cast<int>(fraction * 1000)); });
  timer_->start();
}

// The job's end, on the GUI thread: what the sequence stored (also when it
// failed after storing steps), the project told, the status line set.
void RigTestPage::onJobFinished(const core::Result<rt::Outcome>& result) {
  jobId_ = 0;
  timer_->stop();
  drain();
  std::optional<rt::Outcome> outcome;
  QString error;
  if (result) {
    outcome = *result;
  } else {
    error = qs(result.error().describe());
    std::lock_guard<std::mutex> lock(handOver_->mutex);
    outcome = handOver_->outcome;
  }
  bool added = false;
  {
    std::lock_guard<std::mutex> lock(handOver_->mutex);
    added = handOver_->specimenAdded;
  }
  if (added) model_->notifyChanged(RecordKind::Specimen);
  bool ok = false;
  std::function<QString()> message;
  if (outcome) {
    ok = outcome->status == core::io::TestStatus::Complete;
    if (outcome->testId) {
      lastTestId_ = *outcome->testId;
      model_->notifyChanged(rig_ == Rig::Stiffness ? RecordKind::RigTest : RecordKind::TyreTest, *outcome->testId);
      showStoredTest(*outcome->testId);
    }
    const QString name = qs(outcome->testName), note = qs(outcome->note);
    switch (outcome->status) {
      case core::io::TestStatus::Complete:
        message = [name] { return tr("Complete: stored as '%1'.").arg(name); };
        break;
      case core::io::TestStatus::Interrupted:
        message = [name, note] {
          return tr("Interrupted: stored as '%1' with the finished steps (%2).").arg(name, note);
        };
        break;
      default: message = [note] { return tr("Failed: %1").arg(note); }; break;
    }
  } else {
    message = [error] { return tr("Failed: %1").arg(error); };
  }
  onDone(ok, message);
}

void RigTestPage::stop() {
  if (!isRunning() || !handOver_) return;
  handOver_->cancel.cancel();
  setStatus([] { return tr("Stopping: the sequence keeps the finished steps..."); });
}

void RigTestPage::onDone(bool ok, const std::function<QString()>& message) {
  setRunning(false);
  if (ok) progress_->setValue(1000);
  setStatus(message, !ok);
  if (log_) log_(tr("Rig test: %1").arg(message()));
  emit finished(ok);
}

void RigTestPage::drain() {
  if (!handOver_) return;
  std::vector<rt::LiveReadout> live;
  std::vector<std::variant<rt::StepReport, std::string>> events;
  {
    std::lock_guard<std::mutex> lock(handOver_->mutex);
    live.swap(handOver_->live);
    events.swap(handOver_->events);
  }
  for (const auto& r : live) onLive(r);
  bool stepped = false;
  for (const auto& e : events) {
    if (const auto* step = std::get_if<rt::StepReport>(&e)) {
      onStep(*step);
      stepped = true;
    } else {
      logView_->appendPlainText(qs(std::get<std::string>(e)));
    }
  }
  if (stepped)  // the running test's committed steps are in the project now
    model_->notifyChanged(rig_ == Rig::Stiffness ? RecordKind::RigTest : RecordKind::TyreTest);
  if (!live.empty() || stepped || dirty_) replot();
}

void RigTestPage::onLive(const rt::LiveReadout& r) {
  const Eigen::Index rows = r.block.rows();
  if (rows == 0 || r.sampleRateHz <= 0) return;
  const bool stiff = rig_ == Rig::Stiffness;
  if (r.step != liveStep_) {
    // A new step: a sine or a yaw frequency starts its own loop; the static
    // ramp is one step; a steady-state set-point keeps the traces running.
    if (liveStep_ >= 0 && testId() != QLatin1String("steady-state")) {
      timeLeftData_.clear();
      timeRightData_.clear();
      xyData_.clear();
      if (sineFit_) sineFit_->setSamples(QVector<QPointF>());  // the fit of the frequency before
    }
    liveStep_ = r.step;
  }
  auto column = [&](const std::string& name) {
    for (std::size_t c = 0; c < r.channels.size(); ++c)
      if (r.channels[c] == name) return static_cast<Eigen::Index>(c);
    return Eigen::Index{-1};
  };
  const int stride = std::max(1, static_cast<int>(std::lround(r.sampleRateHz / kPlotRateHz)));
  const double dt = 1.0 / r.sampleRateHz;
  // Time of the steady-state traces runs on over the set-points.
  const double offset = (!stiff && testId() == QLatin1String("steady-state") && !timeLeftData_.isEmpty() &&
                         r.time - (rows - 1) * dt < timeLeftData_.last().x() - 1e-9)
                            ? timeLeftData_.last().x() + dt - (r.time - (rows - 1) * dt)
                            : 0.0;
  Eigen::Index left = 0, right = -1, xCol = -1;
  if (stiff) {
    left = 0;  // the load cell
  } else if (roles_.size() == 4) {
    left = column(roles_[0]);
    right = column(roles_[1]);
    xCol = column(roles_[2]);
  }
  for (Eigen::Index i = 0; i < rows; i += stride) {
    const double t = r.time - static_cast<double>(rows - 1 - i) * dt + offset;
    if (left >= 0) timeLeftData_.append(QPointF(t, r.block(i, left)));
    if (stiff && r.derived.size() == rows) {
      const double x = r.derived(i) * 1e3;
      timeRightData_.append(QPointF(t, x));
      xyData_.append(QPointF(x, r.block(i, 0)));
    } else if (!stiff) {
      if (right >= 0) timeRightData_.append(QPointF(t, r.block(i, right)));
      if (xCol >= 0 && left >= 0 && testId() == QLatin1String("relaxation"))
        xyData_.append(QPointF(r.block(i, xCol) * 180.0 / kPi, r.block(i, left)));
    }
  }
  if (timeWindowS_ > 0 && !timeLeftData_.isEmpty()) {
    const double from = timeLeftData_.last().x() - timeWindowS_;
    trimFront(timeLeftData_, from);
    trimFront(timeRightData_, from);
    if (stiff) {
      // The force-displacement loop of the last window only (a settled sine).
      while (xyData_.size() > timeLeftData_.size()) xyData_.remove(0);
    }
  }
  // Readouts: the block's last scan, every channel.
  QStringList parts;
  parts << tr("%1 at %2 s").arg(qs(r.stepLabel)).arg(r.time, 0, 'f', 2);
  for (std::size_t c = 0; c < r.channels.size() && c < static_cast<std::size_t>(r.block.cols()); ++c) {
    const auto s = shown(r.block(rows - 1, static_cast<Eigen::Index>(c)), 0.0, c < r.units.size() ? r.units[c] : "");
    parts << QStringLiteral("%1 %2 %3").arg(qs(r.channels[c]), QString::number(s.value, 'f', 3), s.unit);
  }
  if (stiff && r.derived.size() == rows)
    parts << tr("load point %1 mm").arg(QString::number(r.derived(rows - 1) * 1e3, 'f', 4));
  readout_->setText(parts.join(QStringLiteral("   |   ")));
  dirty_ = true;
}

void RigTestPage::onStep(const rt::StepReport& s) {
  logView_->appendPlainText(
      s.ok ? tr("Step %1 (%2) committed.").arg(s.step).arg(qs(s.label))
           : tr("Step %1 (%2) kept without a result: %3").arg(s.step).arg(qs(s.label), qs(s.note)));
  if (rig_ == Rig::Stiffness && testId() == QLatin1String("dynamic") && s.ok) addAxisPoint(s.results);
  if (rig_ != Rig::Tyre || testId() != QLatin1String("steady-state")) return;
  const auto* slip = rt::findQuantity(s.results, "slip");
  const auto* camber = rt::findQuantity(s.results, "camber");
  const auto* fy = rt::findQuantity(s.results, "lateral_force");
  if (!slip || !camber || !fy) return;
  // The slip sweep runs at zero camber, the camber sweep at zero side-slip.
  const bool slipSweep = QString::fromStdString(s.label).startsWith(QLatin1String("slip"));
  if (slipSweep)
    xyData_.append(QPointF(slip->value * 180.0 / kPi, fy->value));
  else
    xySecondData_.append(QPointF(camber->value * 180.0 / kPi, fy->value));
  dirty_ = true;
}

}  // namespace views
}  // namespace mozzi
