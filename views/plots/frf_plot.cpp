#include "views/plots/frf_plot.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include "core/common/plot_math.h"
#include "views/plots/plot_export.h"
#include "views/plots/vector_series.h"

namespace mozzi {
namespace views {
namespace {

QwtPlot* makePlot(QWidget* parent, const QString& name, QwtPlotCurve** curve, const QColor& colour) {
  auto* plot = new QwtPlot(parent);
  plot->setObjectName(name);
  plot->setCanvasBackground(Qt::white);
  auto* grid = new QwtPlotGrid;
  grid->setMajorPen(QColor(0, 0, 0, 40), 0.0, Qt::DotLine);
  grid->attach(plot);
  *curve = new QwtPlotCurve;
  (*curve)->setPen(colour, 1.5);
  (*curve)->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  (*curve)->attach(plot);
  return plot;
}

}  // namespace

FrfPlot::FrfPlot(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  pairs_ = new QComboBox(this);
  pairs_->setObjectName(QStringLiteral("frfPairs"));
  unwrap_ = new QCheckBox(this);
  unwrap_->setObjectName(QStringLiteral("frfUnwrap"));
  bar->addWidget(pairs_, 1);
  bar->addWidget(unwrap_);
  layout->addLayout(bar);
  magnitude_ = makePlot(this, QStringLiteral("frfMagnitude"), &magnitudeCurve_, QColor(29, 53, 87));
  phase_ = makePlot(this, QStringLiteral("frfPhase"), &phaseCurve_, QColor(230, 57, 70));
  coherence_ = makePlot(this, QStringLiteral("frfCoherence"), &coherenceCurve_, QColor(42, 157, 143));
  coherence_->setAxisScale(QwtPlot::yLeft, 0.0, 1.05);
  for (QwtPlot* plot : {magnitude_, phase_, coherence_}) installPlotExportAction(plot);
  layout->addWidget(magnitude_, 3);
  layout->addWidget(phase_, 2);
  layout->addWidget(coherence_, 1);

  connect(pairs_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    if (!frfs_ || index < 0) return;
    const int no = static_cast<int>(frfs_->responseCount());
    showPair(index % no, index / no);
  });
  connect(unwrap_, &QCheckBox::toggled, this, [this] { showPair(response_, reference_); });
  retranslate();
}

FrfPlot::~FrfPlot() = default;

void FrfPlot::setFrfs(std::shared_ptr<const core::FrfMatrix> frfs) {
  frfs_ = std::move(frfs);
  frequency_ = frfs_ ? std::make_shared<const core::Vector>(frfs_->frequencyHz) : nullptr;
  response_ = reference_ = -1;
  rebuildPairList();
  if (pairCount() > 0) showPair(0, 0);
}

int FrfPlot::pairCount() const {
  return frfs_ ? static_cast<int>(frfs_->responseCount() * frfs_->referenceCount()) : 0;
}

size_t FrfPlot::shownSamples() const {
  return magnitudeCurve_->dataSize();
}

bool FrfPlot::showPair(int response, int reference) {
  if (!frfs_ || response < 0 || reference < 0 || response >= frfs_->responseCount() ||
      reference >= frfs_->referenceCount()) {
    return false;
  }
  response_ = response;
  reference_ = reference;
  const core::ComplexVector h = frfs_->h[static_cast<size_t>(reference)].col(response);
  auto db = std::make_shared<const core::Vector>(core::magnitudeDb(h));
  auto phase = std::make_shared<const core::Vector>(core::phaseDegrees(h, unwrap_->isChecked()));
  magnitudeCurve_->setData(new VectorSeries(frequency_, db));
  phaseCurve_->setData(new VectorSeries(frequency_, phase));
  if (!frfs_->coherence.empty()) {
    auto gamma = std::make_shared<const core::Vector>(frfs_->coherence[static_cast<size_t>(reference)].col(response));
    coherenceCurve_->setData(new VectorSeries(frequency_, gamma));
  } else {
    coherenceCurve_->setSamples(QVector<QPointF>());
  }
  const core::AxisRange f = core::roundedRange(frequency_->minCoeff(), frequency_->maxCoeff(), false);
  for (QwtPlot* plot : {magnitude_, phase_, coherence_}) plot->setAxisScale(QwtPlot::xBottom, f.lower, f.upper);
  const core::AxisRange m = core::roundedRange(db->minCoeff(), db->maxCoeff(), false);
  magnitude_->setAxisScale(QwtPlot::yLeft, m.lower, m.upper);
  const core::AxisRange p = core::roundedRange(phase->minCoeff(), phase->maxCoeff(), false);
  phase_->setAxisScale(QwtPlot::yLeft, p.lower, p.upper);
  const int index = reference * static_cast<int>(frfs_->responseCount()) + response;
  if (pairs_->currentIndex() != index) pairs_->setCurrentIndex(index);
  retranslate();
  for (QwtPlot* plot : {magnitude_, phase_, coherence_}) plot->replot();
  return true;
}

void FrfPlot::rebuildPairList() {
  const QSignalBlocker block(pairs_);
  pairs_->clear();
  if (!frfs_) return;
  for (const auto& ref : frfs_->references) {
    for (const auto& res : frfs_->responses) {
      pairs_->addItem(QStringLiteral("%1 / %2").arg(QString::fromStdString(core::formatDof(res)),
                                                    QString::fromStdString(core::formatDof(ref))));
    }
  }
}

void FrfPlot::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void FrfPlot::retranslate() {
  unwrap_->setText(tr("Unwrap phase"));
  pairs_->setToolTip(tr("Response / reference"));
  QString type;
  if (frfs_) {
    switch (frfs_->type) {
      case core::FrfType::Receptance: type = tr("receptance"); break;
      case core::FrfType::Mobility: type = tr("mobility"); break;
      case core::FrfType::Accelerance: type = tr("accelerance"); break;
    }
  }
  magnitude_->setAxisTitle(QwtPlot::yLeft, type.isEmpty() ? tr("Magnitude [dB]") : tr("|H| %1 [dB]").arg(type));
  phase_->setAxisTitle(QwtPlot::yLeft, tr("Phase [deg]"));
  // Curve titles name the columns of an exported CSV.
  magnitudeCurve_->setTitle(tr("magnitude"));
  phaseCurve_->setTitle(tr("phase"));
  coherenceCurve_->setTitle(tr("coherence"));
  coherence_->setAxisTitle(QwtPlot::yLeft, tr("Coherence"));
  coherence_->setAxisTitle(QwtPlot::xBottom, tr("Frequency [Hz]"));
}

}  // namespace views
}  // namespace mozzi
