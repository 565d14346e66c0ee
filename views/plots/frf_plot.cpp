#include "views/plots/frf_plot.h"

#include <qwt_legend.h>
#include <qwt_plot_curve.h>
#include <qwt_scale_draw.h>
#include <qwt_scale_widget.h>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSet>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/plot_math.h"
#include "core/modal/shape_tools.h"
#include "views/common/dof_text.h"
#include "views/plots/decimating_curve.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {
namespace {

// Ten distinguishable colours (Tableau 10), cycled over the overlay.
QColor overlayColour(std::size_t i) {
  static const QColor colours[] = {{31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
                                   {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  return colours[i % 10];
}

std::shared_ptr<const core::Vector> share(core::Vector v) {
  return std::make_shared<const core::Vector>(std::move(v));
}

DecimatingCurve* addCurve(QwtPlot* plot, const QString& title, std::shared_ptr<const core::Vector> x,
                          std::shared_ptr<const core::Vector> y, const QColor& colour, double width, bool antialias) {
  auto* curve = new DecimatingCurve(title);
  curve->setPen(colour, width);
  curve->setRenderHint(QwtPlotItem::RenderAntialiased, antialias);
  curve->setVectors(std::move(x), std::move(y));
  curve->attach(plot);
  return curve;
}

// Nyquist: one unit per pixel on both axes, so a mode's circle is a circle;
// the ranges grow about their centres to keep every sample in view.
void equalAspect(QwtPlot* p) {
  const QRect c = p->canvas()->contentsRect();
  if (c.width() < 10 || c.height() < 10) return;
  const QwtInterval x = p->axisInterval(QwtPlot::xBottom), y = p->axisInterval(QwtPlot::yLeft);
  if (!(x.width() > 0.0) || !(y.width() > 0.0)) return;
  const double u = std::max(x.width() / c.width(), y.width() / c.height());
  const double cx = 0.5 * (x.minValue() + x.maxValue()), cy = 0.5 * (y.minValue() + y.maxValue());
  p->setAxisScale(QwtPlot::xBottom, cx - 0.5 * u * c.width(), cx + 0.5 * u * c.width());
  p->setAxisScale(QwtPlot::yLeft, cy - 0.5 * u * c.height(), cy + 0.5 * u * c.height());
  p->replot();
}

}  // namespace

FrfPlot::FrfPlot(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* row1 = new QHBoxLayout;
  auto* row2 = new QHBoxLayout;
  viewLabel_ = new QLabel(this);
  viewBox_ = new QComboBox(this);
  viewBox_->setObjectName(QStringLiteral("frfView"));
  scaleBox_ = new QComboBox(this);
  scaleBox_->setObjectName(QStringLiteral("frfMagnitudeScale"));
  unwrapBox_ = new QCheckBox(this);
  unwrapBox_->setObjectName(QStringLiteral("frfUnwrap"));
  logFrequencyBox_ = new QCheckBox(this);
  logFrequencyBox_->setObjectName(QStringLiteral("frfLogFrequency"));
  sumBox_ = new QCheckBox(this);
  sumBox_->setObjectName(QStringLiteral("frfSum"));
  cmifBox_ = new QCheckBox(this);
  cmifBox_->setObjectName(QStringLiteral("frfCmif"));
  autoscaleButton_ = new QPushButton(this);
  autoscaleButton_->setObjectName(QStringLiteral("frfAutoscale"));
  showLabel_ = new QLabel(this);
  responseBox_ = new QComboBox(this);
  responseBox_->setObjectName(QStringLiteral("frfResponse"));
  referenceBox_ = new QComboBox(this);
  referenceBox_->setObjectName(QStringLiteral("frfReference"));
  pointBox_ = new QComboBox(this);
  pointBox_->setObjectName(QStringLiteral("frfPoint"));
  for (int i = 0; i < 6; ++i) viewBox_->addItem(QString());
  for (int i = 0; i < 3; ++i) scaleBox_->addItem(QString());
  row1->addWidget(viewLabel_);
  row1->addWidget(viewBox_);
  row1->addWidget(scaleBox_);
  row1->addWidget(unwrapBox_);
  row1->addWidget(logFrequencyBox_);
  row1->addStretch(1);
  row1->addWidget(autoscaleButton_);
  row2->addWidget(showLabel_);
  row2->addWidget(responseBox_, 1);
  row2->addWidget(referenceBox_, 1);
  row2->addWidget(pointBox_, 1);
  row2->addWidget(sumBox_);
  row2->addWidget(cmifBox_);
  layout->addLayout(row1);
  layout->addLayout(row2);
  main_ = new InteractivePlot(this);
  main_->setObjectName(QStringLiteral("frfMain"));
  secondary_ = new InteractivePlot(this);
  secondary_->setObjectName(QStringLiteral("frfSecondary"));
  coherence_ = new InteractivePlot(this);
  coherence_->setObjectName(QStringLiteral("frfCoherence"));
  // Small minimum sizes: three stacked plots and the readout fit a 1280x800
  // window (and half that in logical pixels at scale 2).
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) plot->setMinimumSize(200, 90);
  coherence_->setMinimumHeight(110);               // it carries the frequency axis under its canvas
  coherence_->setAxisMaxMajor(QwtPlot::yLeft, 3);  // 0, 0.5, 1: readable in a short plot
  layout->addWidget(main_, 3);
  layout->addWidget(secondary_, 2);
  layout->addWidget(coherence_, 2);
  readout_ = new QLabel(this);
  readout_->setObjectName(QStringLiteral("frfReadout"));
  readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  readout_->setWordWrap(true);
  layout->addWidget(readout_);

  connect(viewBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int i) { setView(static_cast<View>(i)); });
  connect(scaleBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int i) { setMagnitudeScale(static_cast<MagnitudeScale>(i)); });
  connect(unwrapBox_, &QCheckBox::toggled, this, &FrfPlot::setUnwrapPhase);
  connect(logFrequencyBox_, &QCheckBox::toggled, this, &FrfPlot::setLogFrequency);
  connect(sumBox_, &QCheckBox::toggled, this, &FrfPlot::setShowSum);
  connect(cmifBox_, &QCheckBox::toggled, this, &FrfPlot::setShowCmif);
  connect(autoscaleButton_, &QPushButton::clicked, this, &FrfPlot::autoscale);
  for (QComboBox* box : {responseBox_, referenceBox_, pointBox_}) {
    connect(box, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { applyChoices(); });
  }
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) {
    connect(plot, &InteractivePlot::cursorMoved, this, [this](double x) {
      if (syncing_) return;
      setCursorFrequency(x);
    });
    connect(plot, &InteractivePlot::xRangeChanged, this, [this, plot](double lo, double hi) { syncX(plot, lo, hi); });
    connect(plot->axisWidget(QwtPlot::yLeft), &QwtScaleWidget::scaleDivChanged, this, [this] {
      alignLeftAxes({main_, secondary_, coherence_});
    });
  }
  main_->canvas()->installEventFilter(this);
  retranslate();
  redraw(false);
}

FrfPlot::~FrfPlot() = default;

bool FrfPlot::eventFilter(QObject* watched, QEvent* event) {
  if (watched == main_->canvas() && event->type() == QEvent::Resize && view_ == View::Nyquist && !syncing_) {
    syncing_ = true;
    main_->autoscale();
    equalAspect(main_);
    syncing_ = false;
  }
  return QWidget::eventFilter(watched, event);
}

QwtPlot* FrfPlot::magnitudePlot() const {
  return main_;
}

QwtPlot* FrfPlot::phasePlot() const {
  return view_ == View::Phase ? main_ : secondary_;
}

void FrfPlot::setFrfs(std::shared_ptr<const core::FrfMatrix> frfs) {
  frfs_ = std::move(frfs);
  frequency_ = frfs_ ? share(frfs_->frequencyHz) : nullptr;
  filter_ = {};
  cursorHz_.reset();
  rebuildChoices();
  // The strongest FRF alone, as a start (a DOF no mode moves gives a zero
  // FRF, nothing to look at): choose "all" in the boxes for the overlay.
  picks_.clear();
  if (frfs_ && frfs_->responseCount() > 0 && frfs_->referenceCount() > 0) {
    core::FrfPick best{0, 0};
    double bestNorm = -1.0;
    for (std::size_t i = 0; i < frfs_->h.size(); ++i) {
      for (Eigen::Index o = 0; o < frfs_->responseCount(); ++o) {
        const double n = frfs_->h[i].col(o).squaredNorm();
        if (n > bestNorm) {
          bestNorm = n;
          best = core::FrfPick{o, static_cast<Eigen::Index>(i)};
        }
      }
    }
    picks_.push_back(best);
    const QSignalBlocker b1(responseBox_), b2(referenceBox_);
    responseBox_->setCurrentIndex(1 + static_cast<int>(best.response));
    referenceBox_->setCurrentIndex(1 + static_cast<int>(best.reference));
    filter_.response = frfs_->responses[static_cast<std::size_t>(best.response)];
    filter_.reference = frfs_->references[static_cast<std::size_t>(best.reference)];
  }
  redraw(false);
}

void FrfPlot::setModeFrequencies(std::vector<double> frequenciesHz) {
  modesHz_ = std::move(frequenciesHz);
  updateReadout();
}

void FrfPlot::setView(View view) {
  view_ = view;
  if (viewBox_->currentIndex() != static_cast<int>(view)) {
    const QSignalBlocker block(viewBox_);
    viewBox_->setCurrentIndex(static_cast<int>(view));
  }
  retranslate();
  redraw(view != View::Nyquist);
}

void FrfPlot::setMagnitudeScale(MagnitudeScale scale) {
  magnitudeScale_ = scale;
  if (scaleBox_->currentIndex() != static_cast<int>(scale)) {
    const QSignalBlocker block(scaleBox_);
    scaleBox_->setCurrentIndex(static_cast<int>(scale));
  }
  retranslate();
  redraw(true);
}

void FrfPlot::setUnwrapPhase(bool on) {
  unwrap_ = on;
  if (unwrapBox_->isChecked() != on) {
    const QSignalBlocker block(unwrapBox_);
    unwrapBox_->setChecked(on);
  }
  redraw(true);
}

void FrfPlot::setLogFrequency(bool on) {
  logFrequency_ = on;
  if (logFrequencyBox_->isChecked() != on) {
    const QSignalBlocker block(logFrequencyBox_);
    logFrequencyBox_->setChecked(on);
  }
  redraw(false);
}

void FrfPlot::setShowSum(bool on) {
  showSum_ = on;
  if (sumBox_->isChecked() != on) {
    const QSignalBlocker block(sumBox_);
    sumBox_->setChecked(on);
  }
  redraw(true);
}

void FrfPlot::setShowCmif(bool on) {
  showCmif_ = on;
  if (cmifBox_->isChecked() != on) {
    const QSignalBlocker block(cmifBox_);
    cmifBox_->setChecked(on);
  }
  redraw(true);
}

void FrfPlot::setFilter(const core::FrfFilter& filter) {
  filter_ = filter;
  if (frfs_) {
    const QSignalBlocker b1(responseBox_), b2(referenceBox_), b3(pointBox_);
    auto indexOf = [](const std::vector<core::Dof>& dofs, const std::optional<core::Dof>& d) {
      if (!d) return 0;
      for (std::size_t i = 0; i < dofs.size(); ++i) {
        if (dofs[i] == *d) return static_cast<int>(i) + 1;
      }
      return 0;
    };
    responseBox_->setCurrentIndex(indexOf(frfs_->responses, filter.response));
    referenceBox_->setCurrentIndex(indexOf(frfs_->references, filter.reference));
    pointBox_->setCurrentIndex(filter.node ? std::max(0, pointBox_->findData(*filter.node)) : 0);
    picks_ = core::pickFrfs(*frfs_, filter_);
  }
  redraw(true);
}

bool FrfPlot::showPair(int response, int reference) {
  if (!frfs_ || response < 0 || reference < 0 || response >= frfs_->responseCount() ||
      reference >= frfs_->referenceCount()) {
    return false;
  }
  core::FrfFilter f;
  f.response = frfs_->responses[static_cast<std::size_t>(response)];
  f.reference = frfs_->references[static_cast<std::size_t>(reference)];
  setFilter(f);
  // Two responses can share a DOF only in a malformed set; keep exactly this pair.
  picks_ = {core::FrfPick{response, reference}};
  redraw(true);
  return true;
}

int FrfPlot::pairCount() const {
  return frfs_ ? static_cast<int>(frfs_->responseCount() * frfs_->referenceCount()) : 0;
}

int FrfPlot::currentResponse() const {
  return picks_.empty() ? -1 : static_cast<int>(picks_.front().response);
}

int FrfPlot::currentReference() const {
  return picks_.empty() ? -1 : static_cast<int>(picks_.front().reference);
}

size_t FrfPlot::shownSamples() const {
  for (const QwtPlotItem* item : main_->itemList(QwtPlotItem::Rtti_PlotCurve))
    return static_cast<const QwtPlotCurve*>(item)->dataSize();
  return 0;
}

void FrfPlot::rebuildChoices() {
  const QSignalBlocker b1(responseBox_), b2(referenceBox_), b3(pointBox_);
  responseBox_->clear();
  referenceBox_->clear();
  pointBox_->clear();
  responseBox_->addItem(tr("All responses"));
  referenceBox_->addItem(tr("All references"));
  pointBox_->addItem(tr("All points"));
  if (!frfs_) return;
  QList<int> nodes;
  for (const auto& d : frfs_->responses) {
    responseBox_->addItem(tr("Response %1").arg(dofText(d)));
    if (!nodes.contains(d.node)) nodes.push_back(d.node);
  }
  for (const auto& d : frfs_->references) {
    referenceBox_->addItem(tr("Reference %1").arg(dofText(d)));
    if (!nodes.contains(d.node)) nodes.push_back(d.node);
  }
  std::sort(nodes.begin(), nodes.end());
  for (int n : nodes) pointBox_->addItem(tr("Point %1").arg(n), n);
}

void FrfPlot::applyChoices() {
  if (!frfs_) return;
  core::FrfFilter f;
  if (responseBox_->currentIndex() > 0)
    f.response = frfs_->responses[static_cast<std::size_t>(responseBox_->currentIndex() - 1)];
  if (referenceBox_->currentIndex() > 0)
    f.reference = frfs_->references[static_cast<std::size_t>(referenceBox_->currentIndex() - 1)];
  if (pointBox_->currentIndex() > 0) f.node = pointBox_->currentData().toInt();
  filter_ = f;
  picks_ = core::pickFrfs(*frfs_, filter_);
  redraw(true);
}

QString FrfPlot::curveTitle(const core::FrfPick& p) const {
  return QStringLiteral("H %1 / %2")
      .arg(dofText(frfs_->responses[static_cast<std::size_t>(p.response)]),
           dofText(frfs_->references[static_cast<std::size_t>(p.reference)]));
}

void FrfPlot::redraw(bool keepX) {
  const QwtInterval oldX = main_->axisInterval(QwtPlot::xBottom);
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) plot->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  const bool hasCoherence = frfs_ && !frfs_->coherence.empty();
  secondary_->setVisible(view_ == View::Bode || view_ == View::RealImaginary);
  // Magnitude and coherence together: what a technician judges a point by.
  const bool coherenceBelow = stacksCoherence();
  coherence_->setVisible(coherenceBelow && hasCoherence);
  scaleBox_->setEnabled(stacksCoherence());
  unwrapBox_->setEnabled(view_ == View::Bode || view_ == View::Phase);
  cmifBox_->setEnabled(stacksCoherence());
  const bool magnitudeView = stacksCoherence();
  const core::FrfView magnitude = magnitudeScale_ == MagnitudeScale::Decibel  ? core::FrfView::MagnitudeDb
                                  : magnitudeScale_ == MagnitudeScale::Linear ? core::FrfView::MagnitudeLinear
                                                                              : core::FrfView::MagnitudeLog;
  const core::FrfView phase = unwrap_ ? core::FrfView::PhaseUnwrapped : core::FrfView::PhaseWrapped;
  core::FrfView mainView = magnitude;
  switch (view_) {
    case View::Bode:
    case View::Magnitude: mainView = magnitude; break;
    case View::Phase: mainView = phase; break;
    case View::RealImaginary: mainView = core::FrfView::Real; break;
    case View::Nyquist: mainView = core::FrfView::Nyquist; break;
    case View::Coherence: mainView = core::FrfView::Coherence; break;
  }
  main_->setLogY(magnitudeView && magnitudeScale_ == MagnitudeScale::Logarithmic);
  main_->setYFloor(magnitudeView && magnitudeScale_ == MagnitudeScale::Decibel
                       ? core::kMagnitudeFloorDb
                       : -std::numeric_limits<double>::infinity());
  const bool logX = logFrequency_ && view_ != View::Nyquist;
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) plot->setLogX(logX);

  if (frfs_) {
    const bool antialias = picks_.size() <= 8;
    const double width = picks_.size() <= 8 ? 1.5 : 1.0;
    auto drawOne = [&](const QString& title, const core::ComplexVector& h, const core::Vector* gamma,
                       const QColor& colour, double w) {
      if (view_ == View::Nyquist) {
        addCurve(main_, title, share(h.real()), share(h.imag()), colour, w, antialias);
      } else if (view_ == View::Coherence) {
        if (gamma) addCurve(main_, title, frequency_, share(*gamma), colour, w, antialias);
      } else {
        addCurve(main_, title, frequency_, share(core::frfViewValues(h, mainView)), colour, w, antialias);
      }
      if (view_ == View::Bode)
        addCurve(secondary_, title, frequency_, share(core::frfViewValues(h, phase)), colour, w, antialias);
      if (view_ == View::RealImaginary)
        addCurve(secondary_, title, frequency_, share(core::frfViewValues(h, core::FrfView::Imaginary)), colour, w,
                 antialias);
      if (coherenceBelow && gamma) addCurve(coherence_, title, frequency_, share(*gamma), colour, w, antialias);
    };
    for (std::size_t c = 0; c < picks_.size(); ++c) {
      const auto& p = picks_[c];
      const core::ComplexVector h = frfs_->h[static_cast<std::size_t>(p.reference)].col(p.response);
      core::Vector gamma;
      if (hasCoherence) gamma = frfs_->coherence[static_cast<std::size_t>(p.reference)].col(p.response);
      drawOne(curveTitle(p), h, hasCoherence ? &gamma : nullptr, overlayColour(c), width);
    }
    if (showSum_ && view_ != View::Coherence && !picks_.empty()) {
      auto sum = core::frfSum(*frfs_, picks_);
      if (sum) drawOne(tr("sum"), *sum, nullptr, Qt::black, 2.0);
    }
    if (showCmif_ && magnitudeView && !picks_.empty()) {
      auto subset = core::frfSubset(*frfs_, picks_);
      auto sv = subset ? core::modal::cmif(*subset) : core::Result<core::Matrix>(subset.error());
      if (sv) {
        for (Eigen::Index j = 0; j < sv->cols(); ++j) {
          const core::ComplexVector s = sv->col(j).cast<core::Complex>();
          addCurve(main_, tr("CMIF %1").arg(j + 1), frequency_, share(core::frfViewValues(s, magnitude)),
                   j == 0 ? QColor(20, 20, 20) : QColor(110, 110, 110), 2.0, true);
        }
      }
    }
  }
  if (keepX && oldX.width() > 0 && view_ != View::Nyquist && frfs_ &&
      main_->axisInterval(QwtPlot::xBottom).width() > 0) {
    syncing_ = true;
    for (InteractivePlot* plot : {main_, secondary_, coherence_}) {
      plot->setAxisScale(QwtPlot::xBottom, oldX.minValue(), oldX.maxValue());
      plot->autoscaleY();
    }
    syncing_ = false;
  } else {
    syncing_ = true;
    for (InteractivePlot* plot : {main_, secondary_, coherence_}) plot->autoscale();
    syncing_ = false;
  }
  if (view_ == View::Coherence || (coherenceBelow && hasCoherence)) {
    InteractivePlot* c = view_ == View::Coherence ? main_ : coherence_;
    c->setAxisScale(QwtPlot::yLeft, 0.0, 1.05);
    c->replot();
  }
  if (view_ == View::Nyquist) {
    syncing_ = true;
    equalAspect(main_);
    syncing_ = false;
  }
  // A legend names the curves of a small overlay (up to 8), above the plot so the
  // stacked canvases keep one width; more would hide the plot.
  const std::size_t curveCount = main_->itemList(QwtPlotItem::Rtti_PlotCurve).size();
  if (curveCount > 1 && curveCount <= 8) {
    if (!main_->legend()) main_->insertLegend(new QwtLegend(main_), QwtPlot::TopLegend);
  } else if (main_->legend()) {
    main_->insertLegend(nullptr);
  }
  retranslate();
  alignLeftAxes({main_, secondary_, coherence_});
  updateReadout();
}

void FrfPlot::autoscale() {
  syncing_ = true;
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) plot->autoscale();
  if (view_ == View::Nyquist) equalAspect(main_);
  syncing_ = false;
  if (view_ == View::Coherence || stacksCoherence()) {
    InteractivePlot* c = view_ == View::Coherence ? main_ : coherence_;
    c->setAxisScale(QwtPlot::yLeft, 0.0, 1.05);
    c->replot();
  }
}

void FrfPlot::setFrequencyRange(double lowHz, double highHz) {
  if (view_ == View::Nyquist || !(highHz > lowHz)) return;
  syncing_ = true;
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) {
    plot->setAxisScale(QwtPlot::xBottom, lowHz, highHz);
    plot->autoscaleY();
  }
  syncing_ = false;
  if (view_ == View::Coherence || (stacksCoherence() && !coherence_->isHidden())) {
    InteractivePlot* c = view_ == View::Coherence ? main_ : coherence_;
    c->setAxisScale(QwtPlot::yLeft, 0.0, 1.05);
    c->replot();
  }
}

void FrfPlot::syncX(InteractivePlot* from, double lower, double upper) {
  if (syncing_ || view_ == View::Nyquist) return;
  syncing_ = true;
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) {
    if (plot == from || plot->isHidden()) continue;
    const QwtInterval x = plot->axisInterval(QwtPlot::xBottom);
    if (x.minValue() == lower && x.maxValue() == upper) continue;
    plot->setAxisScale(QwtPlot::xBottom, lower, upper);
    plot->replot();
  }
  syncing_ = false;
}

void FrfPlot::setCursorFrequency(double frequencyHz) {
  cursorHz_ = frequencyHz;
  syncing_ = true;
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) {
    if (view_ == View::Nyquist) {
      plot->setCursor(std::nullopt);
    } else {
      plot->setCursor(frequencyHz);
    }
  }
  syncing_ = false;
  updateReadout();
}

void FrfPlot::updateReadout() {
  if (!frfs_ || picks_.empty()) {
    readout_->setText(frfs_ ? tr("No FRF matches the choice.") : tr("No FRF set."));
    return;
  }
  if (!cursorHz_) {
    readout_->setText(tr("%n FRF(s) shown (%1). Click a plot for a cursor; arrows step it, Shift+arrows pan, "
                         "Ctrl+arrows or the wheel zoom, Home autoscales.",
                         nullptr, static_cast<int>(picks_.size()))
                          .arg(typeText()));
    return;
  }
  const Eigen::Index k = core::nearestSample(frfs_->frequencyHz, *cursorHz_);
  QStringList parts;
  parts << tr("f = %1 Hz").arg(frfs_->frequencyHz[k], 0, 'f', 4);
  const std::size_t shown = std::min<std::size_t>(picks_.size(), 3);
  for (std::size_t c = 0; c < shown; ++c) {
    const auto& p = picks_[c];
    const core::Complex h = frfs_->h[static_cast<std::size_t>(p.reference)](k, p.response);
    const double db = 20.0 * std::log10(std::max(std::abs(h), 1e-300));
    parts << tr("%1: |H| %2 (%3 dB), phase %4 deg, Re %5, Im %6")
                 .arg(curveTitle(p))
                 .arg(std::abs(h), 0, 'g', 6)
                 .arg(db, 0, 'f', 2)
                 .arg(std::arg(h) * 180.0 / M_PI, 0, 'f', 1)
                 .arg(h.real(), 0, 'g', 5)
                 .arg(h.imag(), 0, 'g', 5);
  }
  if (picks_.size() > shown) parts << tr("and %n more", nullptr, static_cast<int>(picks_.size() - shown));
  const int mode = core::nearestMode(modesHz_, frfs_->frequencyHz[k]);
  if (mode >= 0) {
    parts << tr("nearest mode %1: %2 Hz (%3 Hz away)")
                 .arg(mode + 1)
                 .arg(modesHz_[static_cast<std::size_t>(mode)], 0, 'f', 3)
                 .arg(frfs_->frequencyHz[k] - modesHz_[static_cast<std::size_t>(mode)], 0, 'f', 3);
  } else {
    parts << tr("no identified mode");
  }
  readout_->setText(parts.join(QStringLiteral("  |  ")));
}

QString FrfPlot::readoutText() const {
  return readout_->text();
}

void FrfPlot::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    const int r = responseBox_->currentIndex(), f = referenceBox_->currentIndex(), p = pointBox_->currentIndex();
    rebuildChoices();
    const QSignalBlocker b1(responseBox_), b2(referenceBox_), b3(pointBox_);
    responseBox_->setCurrentIndex(r);
    referenceBox_->setCurrentIndex(f);
    pointBox_->setCurrentIndex(p);
  }
  QWidget::changeEvent(event);
}

QString FrfPlot::unitText() const {
  if (!frfs_) return QString();
  switch (frfs_->type) {
    case core::FrfType::Receptance: return tr("m/N");
    case core::FrfType::Mobility: return tr("(m/s)/N");
    case core::FrfType::Accelerance: return tr("(m/s²)/N");
  }
  return QString();
}

QString FrfPlot::typeText() const {
  if (!frfs_) return QString();
  switch (frfs_->type) {
    case core::FrfType::Receptance: return tr("receptance");
    case core::FrfType::Mobility: return tr("mobility");
    case core::FrfType::Accelerance: return tr("accelerance");
  }
  return QString();
}

// Short enough for one line along the axis of a 1280x800 window's Bode plot
// ("dB re 1 (m/s^2)/N" wrapped there): "dB re" the FRF's unit, its 1 implied.
QString FrfPlot::magnitudeTitle() const {
  const QString unit = unitText();
  if (magnitudeScale_ == MagnitudeScale::Decibel)
    return unit.isEmpty() ? tr("|H| [dB]") : tr("|H| [dB re %1]").arg(unit);
  return unit.isEmpty() ? tr("|H|") : tr("|H| [%1]").arg(unit);
}

QString FrfPlot::partTitle(const QString& part) const {
  const QString unit = unitText();
  return unit.isEmpty() ? part : tr("%1 [%2]").arg(part, unit);
}

void FrfPlot::retranslate() {
  viewLabel_->setText(tr("View"));
  showLabel_->setText(tr("Show"));
  const QStringList views = {tr("Bode"),    tr("Magnitude"), tr("Phase"), tr("Real and imaginary"),
                             tr("Nyquist"), tr("Coherence")};
  for (int i = 0; i < views.size(); ++i) viewBox_->setItemText(i, views[i]);
  const QStringList scales = {tr("dB"), tr("Linear"), tr("Logarithmic")};
  for (int i = 0; i < scales.size(); ++i) scaleBox_->setItemText(i, scales[i]);
  scaleBox_->setToolTip(tr("Magnitude axis"));
  unwrapBox_->setText(tr("Unwrap phase"));
  logFrequencyBox_->setText(tr("Log frequency"));
  sumBox_->setText(tr("Sum"));
  sumBox_->setToolTip(tr("Complex sum of the FRFs shown"));
  cmifBox_->setText(tr("CMIF"));
  cmifBox_->setToolTip(tr("Complex mode indicator function of the FRFs shown (singular values per line)"));
  autoscaleButton_->setText(tr("Autoscale"));
  autoscaleButton_->setToolTip(tr("Fit the axes to the curves (Home)"));
  responseBox_->setToolTip(tr("Response DOF"));
  referenceBox_->setToolTip(tr("Reference DOF"));
  pointBox_->setToolTip(tr("Mesh point: FRFs whose response or reference is at this node"));
  const QString freq = tr("Frequency [Hz]");
  const QString phaseTitle = unwrap_ ? tr("Phase, unwrapped [deg]") : tr("Phase [deg]");
  for (InteractivePlot* plot : {main_, secondary_, coherence_}) plot->setAxisTitle(QwtPlot::xBottom, freq);
  switch (view_) {
    case View::Bode:
    case View::Magnitude: main_->setAxisTitle(QwtPlot::yLeft, magnitudeTitle()); break;
    case View::Phase: main_->setAxisTitle(QwtPlot::yLeft, phaseTitle); break;
    case View::RealImaginary: main_->setAxisTitle(QwtPlot::yLeft, partTitle(tr("Re H"))); break;
    case View::Nyquist:
      main_->setAxisTitle(QwtPlot::yLeft, partTitle(tr("Im H")));
      main_->setAxisTitle(QwtPlot::xBottom, partTitle(tr("Re H")));
      break;
    case View::Coherence: main_->setAxisTitle(QwtPlot::yLeft, tr("Coherence")); break;
  }
  secondary_->setAxisTitle(QwtPlot::yLeft, view_ == View::RealImaginary ? partTitle(tr("Im H")) : phaseTitle);
  // The stacked coherence plot is short (its axis about 80 pixels at
  // 1280x800): its title is the symbol, which fits, and the word a tooltip.
  coherence_->setAxisTitle(QwtPlot::yLeft, tr("γ²"));
  coherence_->axisWidget(QwtPlot::yLeft)->setToolTip(tr("Coherence γ² (0 to 1)"));
  // Stacked plots share one frequency axis, drawn under the lowest: the
  // height goes to the curves (three plots in a 1280x800 window).
  const bool coherenceBelow = stacksCoherence() && !coherence_->isHidden();
  const bool secondaryBelow = (view_ == View::Bode || view_ == View::RealImaginary) && !secondary_->isHidden();
  main_->enableAxis(QwtPlot::xBottom, !secondaryBelow && !coherenceBelow);
  secondary_->enableAxis(QwtPlot::xBottom, !coherenceBelow);
}

}  // namespace views
}  // namespace mozzi
