#include "views/plots/hit_time_view.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/common/dof.h"
#include "core/signal/window.h"
#include "devices/campaign/campaign_store.h"
#include "views/common/dof_text.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

namespace cp = devices::campaign;

namespace {

QwtPlotCurve* makeCurve(QwtPlot* plot, const QColor& colour, double width, Qt::PenStyle style, int yAxis) {
  auto* c = new QwtPlotCurve;
  c->setPen(QPen(colour, width, style));
  c->setYAxis(yAxis);
  c->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  c->attach(plot);
  return c;
}

}  // namespace

HitTimeView::HitTimeView(QWidget* parent) : QWidget(parent) {
  hitLabel_ = new QLabel(this);
  hitBox_ = new QComboBox(this);
  hitBox_->setObjectName(QStringLiteral("hitTimeHit"));
  hitBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  responseLabel_ = new QLabel(this);
  responseBox_ = new QComboBox(this);
  responseBox_->setObjectName(QStringLiteral("hitTimeResponse"));
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("hitTimeStatus"));
  status_->setWordWrap(true);
  plot_ = new InteractivePlot(this);  // the workbench's plot: grid, cursor, zoom, pan, export
  plot_->setObjectName(QStringLiteral("hitTimePlot"));
  plot_->enableAxis(QwtPlot::yRight, true);
  force_ = makeCurve(plot_, QColor(29, 53, 87), 1.2, Qt::SolidLine, QwtPlot::yLeft);
  response_ = makeCurve(plot_, QColor(230, 57, 70), 1.0, Qt::SolidLine, QwtPlot::yRight);
  forceWindow_ = makeCurve(plot_, QColor(29, 53, 87), 1.5, Qt::DashLine, QwtPlot::yLeft);
  responseWindow_ = makeCurve(plot_, QColor(230, 57, 70), 1.5, Qt::DashLine, QwtPlot::yRight);
  plot_->insertLegend(new QwtLegend, QwtPlot::TopLegend);
  // A small least size: beside the FRFs in one tab, the page fits 1280x800 (at scale 2 too).
  plot_->setMinimumSize(200, 160);

  auto* bar = new QHBoxLayout;
  bar->addWidget(hitLabel_);
  bar->addWidget(hitBox_, 1);
  bar->addWidget(responseLabel_);
  bar->addWidget(responseBox_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(status_);
  layout->addWidget(plot_, 1);

  connect(hitBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int i) { showHit(i, std::max(0, responseBox_->currentIndex())); });
  connect(responseBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int) { redraw(); });
  retranslate();
}

core::Result<void> HitTimeView::setFrfSet(const core::io::ProjectStore& store, std::int64_t frfSetId) {
  const std::string where = "FRF set " + std::to_string(frfSetId);
  auto ids = store.frfSetHits(frfSetId);
  if (!ids) return ids.error();
  if (ids->empty()) return core::makeError(core::ErrorCode::NotFound, "the FRF set has no stored hits", where);
  auto sets = store.frfSets();
  if (!sets) return sets.error();
  const auto set = std::find_if(sets->begin(), sets->end(), [&](const auto& s) { return s.id == frfSetId; });
  if (set == sets->end() || !set->campaignId)
    return core::makeError(core::ErrorCode::NotFound, "the FRF set belongs to no campaign", where);
  auto campaign = cp::loadCampaign(store, *set->campaignId);
  if (!campaign) return campaign.error();
  store_ = &store;
  hitIds_ = std::move(ids).value();
  definition_ = campaign->definition;
  std::unordered_map<std::int64_t, const core::io::HitInfo*> info;
  for (const auto& h : campaign->hits) info[h.id] = &h;
  const QSignalBlocker block(hitBox_);
  hitBox_->clear();
  for (const std::int64_t id : hitIds_) {
    const auto it = info.find(id);
    hitBox_->addItem(it == info.end() ? tr("hit %1").arg(id)
                                      : tr("hit %1 at %2").arg(it->second->sequence).arg(dofText(it->second->point)),
                     QVariant::fromValue<qlonglong>(id));
  }
  showHit(0);
  return {};
}

bool HitTimeView::showHit(int index, int response) {
  if (!store_ || index < 0 || index >= hitCount()) return false;
  auto hit = store_->hit(hitIds_[static_cast<std::size_t>(index)]);
  if (!hit) {
    status_->setText(tr("Cannot read the hit: %1").arg(QString::fromStdString(hit.error().describe())));
    haveHit_ = false;
    redraw();
    return false;
  }
  hit_ = std::move(hit).value();
  haveHit_ = true;
  {
    const QSignalBlocker block(hitBox_);
    hitBox_->setCurrentIndex(index);
  }
  const QSignalBlocker block(responseBox_);
  responseBox_->clear();
  const int force = definition_.forceChannel();
  for (std::size_t c = 0; c < definition_.channels.size() && static_cast<Eigen::Index>(c) < hit_.channelCount(); ++c) {
    if (static_cast<int>(c) == force) continue;
    responseBox_->addItem(dofText(definition_.channelDof(c, hit_.point)), static_cast<int>(c));
  }
  responseBox_->setCurrentIndex(std::clamp(response, 0, std::max(0, responseBox_->count() - 1)));
  redraw();
  return true;
}

QString HitTimeView::hitText() const {
  return status_->text();
}

void HitTimeView::redraw() {
  for (QwtPlotCurve* c : {force_, response_, forceWindow_, responseWindow_}) c->setSamples(QVector<QPointF>());
  if (!haveHit_) {
    plot_->replot();
    return;
  }
  const int force = definition_.forceChannel();
  const int response = responseBox_->currentData().isValid() ? responseBox_->currentData().toInt() : -1;
  const Eigen::Index n = hit_.sampleCount();
  const double fs = hit_.sampleRateHz;
  // The windows the FRFs were computed with, their origin at the trigger.
  const core::signal::FrfOptions options = definition_.frfOptions();
  const auto origin = static_cast<Eigen::Index>(definition_.preTriggerScans());
  auto referenceWindow = core::signal::makeWindow(options.referenceWindow, n, fs, origin);
  auto responseWindow = core::signal::makeWindow(options.responseWindow, n, fs, origin);
  auto draw = [&](QwtPlotCurve* curve, int channel, const core::Result<core::Vector>* window,
                  QwtPlotCurve* windowCurve) {
    if (channel < 0 || channel >= hit_.channelCount()) return;
    QVector<QPointF> samples(static_cast<int>(n));
    double peak = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double v = hit_.samples(k, channel);
      samples[static_cast<int>(k)] = QPointF(static_cast<double>(k) / fs, v);
      peak = std::max(peak, std::abs(v));
    }
    curve->setSamples(samples);
    if (window && *window && (*window)->size() == n) {
      QVector<QPointF> w(static_cast<int>(n));
      for (Eigen::Index k = 0; k < n; ++k)
        w[static_cast<int>(k)] = QPointF(static_cast<double>(k) / fs, peak * (**window)[k]);
      windowCurve->setSamples(w);
    }
  };
  // A rectangular window is all ones: nothing to draw over the signal.
  using core::signal::WindowKind;
  draw(force_, force, options.referenceWindow.kind == WindowKind::Rectangular ? nullptr : &referenceWindow,
       forceWindow_);
  draw(response_, response, options.responseWindow.kind == WindowKind::Rectangular ? nullptr : &responseWindow,
       responseWindow_);
  QString unit = QStringLiteral("m/s^2");
  if (response >= 0 && static_cast<std::size_t>(response) < hit_.channels.size() &&
      !hit_.channels[static_cast<std::size_t>(response)].unit.empty())
    unit = QString::fromStdString(hit_.channels[static_cast<std::size_t>(response)].unit);
  plot_->setAxisTitle(QwtPlot::yRight, tr("Response [%1]").arg(unit));
  const QString verdict =
      hit_.accepted ? tr("accepted") : tr("rejected: %1").arg(QString::fromStdString(hit_.qualityReasons));
  QString windows;
  const auto& w = definition_.windows;
  if (w.forceWidthS > 0.0)
    windows +=
        tr("force window %1 ms (taper %2 ms)").arg(w.forceWidthS * 1e3, 0, 'g', 4).arg(w.forceTaperS * 1e3, 0, 'g', 4);
  if (w.exponentialTauS > 0.0)
    windows += (windows.isEmpty() ? QString() : QStringLiteral(", ")) +
               tr("exponential window tau %1 s").arg(w.exponentialTauS, 0, 'g', 4);
  if (windows.isEmpty()) windows = tr("rectangular windows");
  status_->setText(tr("Hit %1 at %2, %3 samples at %4 Hz, %5; %6")
                       .arg(hit_.sequence)
                       .arg(dofText(hit_.point))
                       .arg(n)
                       .arg(fs, 0, 'g', 6)
                       .arg(verdict, windows));
  plot_->setAxisAutoScale(QwtPlot::yRight);
  static_cast<InteractivePlot*>(plot_)->autoscale();  // x and the force axis; the response axis by Qwt
}

void HitTimeView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    redraw();
  }
  QWidget::changeEvent(event);
}

void HitTimeView::retranslate() {
  hitLabel_->setText(tr("Hit:"));
  responseLabel_->setText(tr("Response:"));
  plot_->setAxisTitle(QwtPlot::xBottom, tr("Time in the hit's record [s]"));
  plot_->setAxisTitle(QwtPlot::yLeft, tr("Force [N]"));
  force_->setTitle(tr("force"));
  response_->setTitle(tr("response"));
  forceWindow_->setTitle(tr("force window (x peak force)"));
  responseWindow_->setTitle(tr("response window (x peak response)"));
}

}  // namespace views
}  // namespace mozzi
