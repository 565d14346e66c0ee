#include "views/plots/stabilization_plot.h"

#include <qwt_legend.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_scale_engine.h>
#include <qwt_symbol.h>
#include <QEvent>
#include <cmath>

#include "core/modal/pole_selection.h"
#include "views/plots/decimating_curve.h"

namespace mozzi {
namespace views {

namespace {

QwtSymbol* statusSymbol(core::modal::PoleStatus status) {
  using S = core::modal::PoleStatus;
  switch (status) {
    case S::Stable: return new QwtSymbol(QwtSymbol::Ellipse, QColor(0, 140, 60), QPen(QColor(0, 90, 40)), QSize(7, 7));
    case S::FrequencyDamping:
      return new QwtSymbol(QwtSymbol::Triangle, QColor(40, 110, 220), QPen(QColor(20, 60, 150)), QSize(7, 7));
    case S::FrequencyVector:
      return new QwtSymbol(QwtSymbol::Diamond, QColor(240, 150, 20), QPen(QColor(160, 90, 0)), QSize(7, 7));
    case S::Frequency: return new QwtSymbol(QwtSymbol::XCross, QBrush(), QPen(QColor(200, 40, 40), 1.2), QSize(7, 7));
    case S::New: return new QwtSymbol(QwtSymbol::Ellipse, QBrush(), QPen(QColor(150, 150, 150)), QSize(4, 4));
  }
  return new QwtSymbol;
}

}  // namespace

StabilizationPlot::StabilizationPlot(QWidget* parent) : InteractivePlot(parent) {
  setCursorOnClick(false);
  enableAxis(QwtPlot::yRight, true);
  backdrop_ = new DecimatingCurve;
  backdrop_->setPen(QColor(90, 90, 90), 1.0);
  backdrop_->setYAxis(QwtPlot::yRight);
  backdrop_->setZ(5);
  backdrop_->setItemAttribute(QwtPlotItem::Legend, false);  // the right axis's title names it
  backdrop_->attach(this);
  // Order of the status curves: New (drawn first, at the back) .. Stable.
  for (int s = 0; s <= static_cast<int>(core::modal::PoleStatus::Stable); ++s) {
    auto* c = new QwtPlotCurve;
    c->setStyle(QwtPlotCurve::NoCurve);
    c->setSymbol(statusSymbol(static_cast<core::modal::PoleStatus>(s)));
    c->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);  // the legend shows the diagram's symbols
    c->setZ(10 + s);
    c->attach(this);
    statusCurves_.push_back(c);
  }
  selectedCurve_ = new QwtPlotCurve;
  selectedCurve_->setStyle(QwtPlotCurve::NoCurve);
  selectedCurve_->setSymbol(new QwtSymbol(QwtSymbol::Rect, QBrush(), QPen(QColor(220, 0, 0), 2.0), QSize(13, 13)));
  selectedCurve_->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
  selectedCurve_->setZ(30);
  selectedCurve_->attach(this);
  connect(this, &InteractivePlot::clicked, this, &StabilizationPlot::onClicked);
  // Short names (retranslate) in one or two rows: the long ones took four rows,
  // a third of the panel, at 1280 x 800.
  insertLegend(new QwtLegend, QwtPlot::BottomLegend);
  retranslate();
}

void StabilizationPlot::setDiagram(std::shared_ptr<const core::modal::StabilizationDiagram> diagram,
                                   std::shared_ptr<const core::Vector> frequencyHz,
                                   std::shared_ptr<const core::Vector> backdropDb, const QString& backdropTitle) {
  diagram_ = std::move(diagram);
  backdropTitle_ = backdropTitle;
  selected_.clear();
  std::vector<QVector<QPointF>> points(statusCurves_.size());
  if (diagram_) {
    for (const auto& p : diagram_->poles) {
      points[static_cast<std::size_t>(p.status)].push_back(QPointF(p.frequencyHz, p.order));
    }
  }
  for (std::size_t s = 0; s < statusCurves_.size(); ++s) statusCurves_[s]->setSamples(points[s]);
  selectedCurve_->setSamples(QVector<QPointF>());
  if (frequencyHz && backdropDb) {
    // Only the band's lines (the diagram's frequency range).
    const double lo = diagram_ ? diagram_->bandLowHz : frequencyHz->minCoeff();
    const double hi = diagram_ ? diagram_->bandHighHz : frequencyHz->maxCoeff();
    Eigen::Index a = 0, b = frequencyHz->size();
    while (a < b && (*frequencyHz)[a] < lo) ++a;
    while (b > a && (*frequencyHz)[b - 1] > hi) --b;
    backdrop_->setVectors(std::make_shared<const core::Vector>(frequencyHz->segment(a, b - a)),
                          std::make_shared<const core::Vector>(backdropDb->segment(a, b - a)));
    backdrop_->show();
  } else {
    backdrop_->setSamples(QVector<QPointF>());
  }
  for (auto* m : modeLines_) {
    m->detach();
    delete m;
  }
  modeLines_.clear();
  retranslate();
  if (diagram_) {
    setAxisScale(QwtPlot::xBottom, diagram_->bandLowHz, diagram_->bandHighHz);
    const int top = diagram_->orders.empty() ? 1 : diagram_->orders.back();
    setAxisScale(QwtPlot::yLeft, 0.0, top + 2.0);
  } else if (backdrop_->dataSize() > 1) {
    const QRectF r = backdrop_->boundingRect();
    setAxisScale(QwtPlot::xBottom, r.left(), r.right());
  }
  if (backdrop_->dataSize() > 0) {
    const QRectF r = backdrop_->boundingRect();
    const double span = std::max(1.0, r.height());
    setAxisScale(QwtPlot::yRight, r.top() - 0.05 * span, r.bottom() + 0.05 * span);
  }
  replot();
}

void StabilizationPlot::setSelection(const std::vector<int>& poleIndices, const std::vector<double>& modeHz) {
  selected_ = poleIndices;
  QVector<QPointF> pts;
  if (diagram_) {
    for (int i : poleIndices) {
      if (i < 0 || i >= static_cast<int>(diagram_->poles.size())) continue;
      const auto& p = diagram_->poles[static_cast<std::size_t>(i)];
      pts.push_back(QPointF(p.frequencyHz, p.order));
    }
  }
  selectedCurve_->setSamples(pts);
  for (auto* m : modeLines_) {
    m->detach();
    delete m;
  }
  modeLines_.clear();
  for (double f : modeHz) {
    auto* m = new QwtPlotMarker;
    m->setLineStyle(QwtPlotMarker::VLine);
    m->setLinePen(QColor(220, 0, 0, 140), 1.0, Qt::DashLine);
    m->setXValue(f);
    m->setZ(4);
    m->setItemAttribute(QwtPlotItem::AutoScale, false);
    m->attach(this);
    modeLines_.push_back(m);
  }
  replot();
}

QPoint StabilizationPlot::polePixel(int index) const {
  if (!diagram_ || index < 0 || index >= static_cast<int>(diagram_->poles.size())) return {};
  const auto& p = diagram_->poles[static_cast<std::size_t>(index)];
  return QPoint(static_cast<int>(std::lround(transform(QwtPlot::xBottom, p.frequencyHz))),
                static_cast<int>(std::lround(transform(QwtPlot::yLeft, p.order))));
}

int StabilizationPlot::drawnPoleCount() const {
  int n = 0;
  for (auto* c : statusCurves_) n += static_cast<int>(c->dataSize());
  return n;
}

std::vector<double> StabilizationPlot::modeLineFrequencies() const {
  std::vector<double> out;
  for (const auto* m : modeLines_) out.push_back(m->xValue());
  return out;
}

void StabilizationPlot::onClicked(QPointF plotPoint, QPoint) {
  if (!diagram_) return;
  // Size of one pixel in Hz and in orders: "nearest" as the user sees it.
  const double hzPerPixel = std::abs(invTransform(QwtPlot::xBottom, 1) - invTransform(QwtPlot::xBottom, 0));
  const double orderPerPixel = std::abs(invTransform(QwtPlot::yLeft, 1) - invTransform(QwtPlot::yLeft, 0));
  const int i =
      core::modal::nearestDiagramPole(*diagram_, plotPoint.x(), plotPoint.y(), hzPerPixel, orderPerPixel, 8.0);
  if (i >= 0) emit poleClicked(i);
}

void StabilizationPlot::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  InteractivePlot::changeEvent(event);
}

void StabilizationPlot::retranslate() {
  setAxisTitle(QwtPlot::xBottom, tr("Frequency [Hz]"));
  setAxisTitle(QwtPlot::yLeft, tr("Model order"));
  setAxisTitle(QwtPlot::yRight, backdropTitle_.isEmpty() ? tr("[dB]") : backdropTitle_);
  // The abbreviations of modal software's diagrams: f frequency, d damping,
  // v vector (shape) stable with the previous order.
  const QString names[] = {tr("new"), tr("f stable"), tr("f, d stable"), tr("f, v stable"), tr("stable")};
  for (std::size_t s = 0; s < statusCurves_.size(); ++s) statusCurves_[s]->setTitle(names[s]);
  selectedCurve_->setTitle(tr("selected"));
  backdrop_->setTitle(backdropTitle_.isEmpty() ? tr("backdrop") : backdropTitle_);
}

}  // namespace views
}  // namespace mozzi
