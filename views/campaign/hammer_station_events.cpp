// The hammer-station page following the campaign session: the verdict, the
// live and recorded traces, the engine's state, progress and running FRF.

#include "views/campaign/hammer_station_page.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_text.h>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFont>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QSplitter>
#include <QStackedWidget>
#include <QStringList>
#include <QTableWidget>
#include <QTime>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <initializer_list>

#include "core/geometry/mode_shape.h"
#include "devices/campaign/campaign_store.h"
#include "devices/common/driver.h"
#include "views/campaign/campaign_session.h"
#include "views/campaign/campaign_wizard.h"
#include "views/campaign/hammer_station_internal.h"
#include "views/common/dof_text.h"
#include "views/plots/frf_plot.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/plot_export.h"
#include "views/plots/vector_series.h"
#include "views/scene/scene_view.h"

namespace mozzi {
namespace views {

namespace cp = devices::campaign;

namespace {

QString stateName(cp::EngineState state) {
  switch (state) {
    case cp::EngineState::Idle: return HammerStationPage::tr("Idle: press A to arm");
    case cp::EngineState::Armed: return HammerStationPage::tr("Armed: hit the point");
    case cp::EngineState::Recording: return HammerStationPage::tr("Recording the hit");
    case cp::EngineState::VerdictPending: return HammerStationPage::tr("Verdict: Space accepts, Backspace rejects");
    case cp::EngineState::PointDone: return HammerStationPage::tr("Point done");
    case cp::EngineState::WaitingForDevice: return HammerStationPage::tr("Waiting for the device");
    case cp::EngineState::Finished: return HammerStationPage::tr("Campaign finished");
  }
  return QString();
}

std::shared_ptr<const core::Vector> column(const std::vector<std::shared_ptr<const core::Matrix>>& blocks,
                                           Eigen::Index channel) {
  Eigen::Index n = 0;
  for (const auto& b : blocks) n += b->rows();
  auto out = std::make_shared<core::Vector>(n);
  Eigen::Index k = 0;
  for (const auto& b : blocks) {
    if (channel < b->cols())
      out->segment(k, b->rows()) = b->col(channel);
    else
      out->segment(k, b->rows()).setZero();
    k += b->rows();
  }
  return out;
}

}  // namespace

using hammer_station::setAxisText;

void HammerStationPage::setVerdict(const QString& headline, const QString& detail, const QString& colour) {
  verdictHeadline_ = headline;
  verdict_->setText(headline.isEmpty() ? QStringLiteral(" ") : headline);
  verdictDetail_->setText(detail);
  QPalette p = verdict_->palette();
  p.setColor(QPalette::Window, colour.isEmpty() ? palette().color(QPalette::Window) : QColor(colour));
  p.setColor(QPalette::WindowText, colour.isEmpty() ? palette().color(QPalette::WindowText) : QColor(Qt::white));
  verdict_->setPalette(p);
}

void HammerStationPage::refreshTraces() {
  // The trigger lamp follows the engine's state and the live stream.
  const LiveSnapshot live = session_->liveSnapshot();
  const bool triggered =
      state_ && (*state_ == cp::EngineState::Recording || (*state_ == cp::EngineState::Armed && live.triggered));
  const bool armed = state_ && *state_ == cp::EngineState::Armed;
  QPalette p = trigger_->palette();
  p.setColor(QPalette::Window, triggered ? QColor(214, 40, 40) : armed ? QColor(244, 162, 97) : QColor(200, 200, 200));
  p.setColor(QPalette::WindowText, triggered ? Qt::white : Qt::black);
  trigger_->setPalette(p);
  trigger_->setText(triggered ? tr("TRIGGERED") : armed ? tr("ARMED") : tr("TRIGGER"));

  if (showingRecord_ || live.generation == shownGeneration_ || live.blocks.empty() || live.sampleRateHz <= 0.0) return;
  shownGeneration_ = live.generation;
  const auto force = column(live.blocks, forceChannel_);
  const int r = responseChannel_->currentIndex();
  const int responseColumn = r >= 0 && r < static_cast<int>(responseChannels_.size()) ? responseChannels_[r] : -1;
  auto time = std::make_shared<core::Vector>(force->size());
  for (Eigen::Index i = 0; i < time->size(); ++i)
    (*time)[i] = static_cast<double>(live.firstSample + i) / live.sampleRateHz;
  forceCurve_->setData(new VectorSeries(time, force));
  if (responseColumn >= 0) responseCurve_->setData(new VectorSeries(time, column(live.blocks, responseColumn)));
  setAxisText(traces_, QwtPlot::xBottom, tr("Time since arming [s]"));
  traces_->replot();
  ++traceRefreshes_;
}

void HammerStationPage::showRecordTraces(const core::signal::TimeRecord& record) {
  if (record.sampleRateHz <= 0.0 || record.samples.rows() == 0) return;
  showingRecord_ = true;
  const Eigen::Index n = record.samples.rows();
  auto time = std::make_shared<core::Vector>(n);
  for (Eigen::Index i = 0; i < n; ++i) (*time)[i] = static_cast<double>(i) / record.sampleRateHz;
  auto force = std::make_shared<core::Vector>(
      record.samples.col(std::min<Eigen::Index>(forceChannel_, record.samples.cols() - 1)));
  forceCurve_->setData(new VectorSeries(time, force));
  const int r = responseChannel_->currentIndex();
  if (r >= 0 && r < static_cast<int>(responseChannels_.size()) && responseChannels_[r] < record.samples.cols())
    responseCurve_->setData(
        new VectorSeries(time, std::make_shared<core::Vector>(record.samples.col(responseChannels_[r]))));
  setAxisText(traces_, QwtPlot::xBottom, tr("Time in the hit's record [s]"));
  traces_->replot();
  ++traceRefreshes_;
}

void HammerStationPage::onState(cp::EngineState state, const QString& message) {
  const bool newArm = state == cp::EngineState::Armed && state_ != cp::EngineState::Armed;
  state_ = state;
  stateLabel_->setText(stateName(state));
  if (newArm) {
    showingRecord_ = false;
    shownGeneration_ = 0;
    setVerdict(tr("ARMED"), tr("Hit point %1").arg(current_ ? QString::number(*current_ + 1) : QString()),
               QStringLiteral("#b86f00"));
  }
  if (state == cp::EngineState::WaitingForDevice) {
    showBanner(message.isEmpty() ? tr("The device went away; the campaign goes on when it is back.") : message);
    QApplication::beep();
  }
  if (!message.isEmpty() && state != cp::EngineState::WaitingForDevice) log(message);
  updateActions();
}

void HammerStationPage::onVerdict(const cp::HitVerdictEvent& v) {
  if (v.record) showRecordTraces(*v.record);
  QStringList details;
  details << tr("Point %1 (%2), hit attempt %3").arg(v.position + 1).arg(dofText(v.point)).arg(v.attempt + 1);
  for (const auto& note : v.verdict.notes) details << QString::fromStdString(note);
  if (v.verdict.meanCoherence) details << tr("mean coherence %1").arg(*v.verdict.meanCoherence, 0, 'f', 3);
  if (v.verdict.passed) {
    setVerdict(tr("GOOD HIT — Space accepts"), details.join(QStringLiteral("; ")), QStringLiteral("#2a7f3f"));
    QApplication::beep();
  } else {
    // The headline names the faults ("double hit", "overload on acc 5:+Z"),
    // readable across the room, when they are short enough for its two
    // lines; their measures go to the lines below it.
    QStringList faults, reasons;
    for (const auto& reason : v.verdict.reasons) {
      const QString text = QString::fromStdString(reason);
      reasons << text;
      faults << text.section(QStringLiteral(": "), 0, 0).section(QStringLiteral(" ("), 0, 0).trimmed();
    }
    const QString named = faults.join(QStringLiteral(", "));
    constexpr int kHeadlineChars = 30;  // two lines of the headline's font in its column at 1280x800
    setVerdict(named.size() <= kHeadlineChars ? tr("REJECT: %1").arg(named) : tr("REJECT"),
               tr("%1. Backspace rejects, Space keeps it anyway. %2")
                   .arg(reasons.join(QStringLiteral("; ")), details.join(QStringLiteral("; "))),
               QStringLiteral("#b3261e"));
    QApplication::beep();
    QTimer::singleShot(180, this, [] { QApplication::beep(); });  // two beeps: look at the screen
  }
  updateActions();
}

void HammerStationPage::onCommitted(const cp::CommittedHitEvent& hit) {
  const QString reasons = QString::fromStdString(hit.reasons);
  if (hit.accepted) {
    setVerdict(tr("ACCEPTED"),
               tr("Hit %1 stored at point %2 (%3)").arg(hit.hitId).arg(hit.position + 1).arg(dofText(hit.point)),
               QStringLiteral("#2a7f3f"));
    log(tr("Point %1: hit %2 accepted").arg(hit.position + 1).arg(hit.hitId));
  } else {
    setVerdict(tr("REJECTED"), reasons, QStringLiteral("#6d6d6d"));
    log(tr("Point %1: hit %2 rejected (%3)").arg(hit.position + 1).arg(hit.hitId).arg(reasons));
  }
}

void HammerStationPage::onRunningFrf(const cp::RunningFrfEvent& e) {
  if (!e.frf) return;
  const int response = std::max(0, frf_->currentResponse());
  const int reference = std::max(0, frf_->currentReference());
  frf_->setFrfs(e.frf);
  frfStack_->setCurrentWidget(frf_);
  frf_->showPair(response, reference);
  // Short axis titles: the FRF shares the column with the traces.
  setAxisText(frf_->magnitudePlot(), QwtPlot::yLeft, tr("|H| [dB]"));
  setAxisText(frf_->coherencePlot(), QwtPlot::yLeft, tr("Coh."));
  pointTitle_->setText(tr("Point %1 (%2): running FRF of %n accepted hit(s)", nullptr, e.hits)
                           .arg(e.position + 1)
                           .arg(dofText(e.point)));
}

void HammerStationPage::onProgress(const cp::EngineProgress& p) {
  const bool pointChanged = p.current != current_;
  lastProgress_ = p;
  current_ = p.current;
  if (pointChanged) updateHitMarker();
  state_ = p.state;
  stationDevice_ = QString::fromStdString(p.device);
  station_->setText(tr("Station: %1").arg(stationDevice_));
  const auto& s = p.schedule;
  progress_->setValue(static_cast<int>(std::lround(s.fraction() * 1000.0)));
  progress_->setFormat(tr("%1 of %2 points").arg(s.pointsDone + s.pointsSkipped).arg(s.pointCount));
  progressLabel_->setText(tr("%1: %2 done, %3 skipped; %4 hits accepted, %5 rejected")
                              .arg(QString::fromStdString(p.campaignName))
                              .arg(s.pointsDone)
                              .arg(s.pointsSkipped)
                              .arg(s.acceptedHits)
                              .arg(s.rejectedHits));
  if (points_->rowCount() != static_cast<int>(p.points.size())) points_->setRowCount(static_cast<int>(p.points.size()));
  for (const auto& pt : p.points) {
    const int row = pt.position;
    if (row < 0 || row >= points_->rowCount()) continue;
    const bool current = p.current && *p.current == row;
    QString status;
    QColor background;
    if (pt.skipped) {
      status = tr("skipped: %1").arg(QString::fromStdString(pt.skipReason));
      background = QColor(225, 225, 225);
    } else if (pt.done) {
      status = tr("done");
      background = QColor(214, 240, 219);
    } else if (current) {
      status = tr("measuring now");
      background = QColor(255, 221, 87);
    } else {
      status = pt.attempts > 0 ? tr("started") : tr("to do");
    }
    const QStringList cells = {QString::number(row + 1), dofText(pt.dof),
                               tr("%1 / %2").arg(pt.accepted).arg(p.hitsPerPoint), status};
    for (int c = 0; c < cells.size(); ++c) {
      QTableWidgetItem* item = points_->item(row, c);
      if (!item) {
        item = new QTableWidgetItem;
        points_->setItem(row, c, item);
      }
      item->setText(cells[c]);
      item->setBackground(background.isValid() ? QBrush(background) : QBrush());
      QFont f = item->font();
      f.setBold(current);
      item->setFont(f);
      if (c == 3 && pt.attempts > pt.accepted)
        item->setToolTip(tr("%n attempt(s) at this point", nullptr, pt.attempts));
    }
  }
  if (pointChanged && p.current) {
    points_->scrollToItem(points_->item(*p.current, 0), QAbstractItemView::PositionAtCenter);
    if (!showingRecord_) {
      frf_->setFrfs(nullptr);
      frfStack_->setCurrentWidget(frfHint_);
    }
    pointTitle_->setText(tr("Point %1 (%2)").arg(*p.current + 1).arg(dofText(p.points[*p.current].dof)));
  }
  updateActions();
}

void HammerStationPage::onFinished(const cp::FinishedEvent& f) {
  setVerdict(tr("CAMPAIGN COMPLETE"),
             tr("%1 points measured, %2 skipped; FRF set %3 stored with its hits")
                 .arg(f.schedule.pointsDone)
                 .arg(f.schedule.pointsSkipped)
                 .arg(f.frfSetId),
             QStringLiteral("#1d3557"));
  log(tr("Campaign finished: FRF set %1").arg(f.frfSetId));
  QApplication::beep();
  updateActions();
}

void HammerStationPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void HammerStationPage::retranslate() {
  for (auto& e : actions_) {
    const QString key = e.action->shortcut().toString(QKeySequence::NativeText);
    e.action->setText(tr("%1 (%2)").arg(tr(e.text), key));
    e.action->setToolTip(e.action->text());
    // The point's actions beside the mesh: the key under the name (two
    // narrower columns; on one line they made the page wider than the tab
    // area at 1280x800). The action's text keeps one line.
    static const QStringList kPointActions = {QStringLiteral("arm"),    QStringLiteral("disarm"),
                                              QStringLiteral("accept"), QStringLiteral("reject"),
                                              QStringLiteral("redo"),   QStringLiteral("skip")};
    if (kPointActions.contains(e.name)) e.action->setIconText(QStringLiteral("%1\n(%2)").arg(tr(e.text), key));
  }
  if (scene_ && sceneMesh_) updateHitMarker();  // the marker's "Next: ..." in the new language
  autoArm_->setText(tr("Arm again after each decision"));
  autoArm_->setToolTip(tr("Applies when the campaign starts"));
  responseLabel_->setText(tr("Response:"));
  skipReason_->setPlaceholderText(tr("Reason for Skip or Redo"));
  skipReason_->setToolTip(tr("Type the reason, then S skips the current point or R measures the selected point again"));
  points_->setHorizontalHeaderLabels({tr("Point"), tr("DOF"), tr("Hits"), tr("Status")});
  traces_->setTitle(QString());
  forceCurve_->setTitle(tr("Force"));
  responseCurve_->setTitle(responseChannel_->currentText().isEmpty() ? tr("Response")
                                                                     : responseChannel_->currentText());
  {
    const int r = responseChannel_->currentIndex();
    const QString unit = r >= 0 && r < responseUnits_.size() ? responseUnits_[r] : tr("EU");
    // The unit alone: the legend names the response, and "Response [m/s^2]"
    // is longer than the traces are high at 1280x800.
    setAxisText(traces_, QwtPlot::yRight, tr("[%1]", "right axis of the hit traces: the response's unit").arg(unit));
  }
  // Every text from its state, not "if still empty": a text set in one
  // language must change with the next.
  setAxisText(traces_, QwtPlot::yLeft, tr("Force [%1]").arg(forceUnit_));
  setAxisText(traces_, QwtPlot::xBottom,
              showingRecord_ ? tr("Time in the hit's record [s]") : tr("Time since arming [s]"));
  if (!state_) stateLabel_->setText(session_->isRunning() ? QString() : tr("Not started: choose a campaign, press F5"));
  station_->setText(stationDevice_.isEmpty() ? tr("Station: not connected") : tr("Station: %1").arg(stationDevice_));
  frfHint_->setText(tr("The running FRF and coherence of the point appear after its first accepted hit."));
  if (!lastProgress_) pointTitle_->setText(tr("No point yet"));  // no campaign has run here yet
  if (verdictHeadline_.isEmpty()) verdictDetail_->setText(tr("The verdict of each hit appears here."));
}

}  // namespace views
}  // namespace mozzi
