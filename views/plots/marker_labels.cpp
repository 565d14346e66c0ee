#include "views/plots/marker_labels.h"

#include <qwt_plot.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_marker.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <algorithm>
#include <limits>

namespace mozzi {
namespace views {

QRectF markerLabelRect(const QwtPlot* plot, const QwtPlotMarker* marker, QPointF value, Qt::Alignment align) {
  const QwtText label = marker->label();
  if (label.isEmpty()) return {};
  const QPointF at(plot->transform(marker->xAxis(), value.x()), plot->transform(marker->yAxis(), value.y()));
  QSizeF symbolHalf(0.0, 0.0);
  if (marker->lineStyle() == QwtPlotMarker::NoLine && marker->symbol() &&
      marker->symbol()->style() != QwtSymbol::NoSymbol)
    symbolHalf = (marker->symbol()->size() + QSizeF(1.0, 1.0)) / 2.0;
  const double pen = marker->linePen().widthF() > 0.0 ? marker->linePen().widthF() / 2.0 : 0.5;
  const double xOff = std::max(pen, symbolHalf.width()), yOff = std::max(pen, symbolHalf.height());
  const QSizeF size = label.textSize(plot->canvas()->font());
  const int spacing = marker->spacing();
  QPointF corner = at;
  if (align & Qt::AlignLeft)
    corner.rx() -= xOff + spacing + size.width();
  else if (align & Qt::AlignRight)
    corner.rx() += xOff + spacing;
  else
    corner.rx() -= size.width() / 2.0;
  if (align & Qt::AlignTop)
    corner.ry() -= yOff + spacing + size.height();
  else if (align & Qt::AlignBottom)
    corner.ry() += yOff + spacing;
  else
    corner.ry() -= size.height() / 2.0;
  return QRectF(corner, size);
}

QRectF markerLabelRect(const QwtPlot* plot, const QwtPlotMarker* marker) {
  return markerLabelRect(plot, marker, marker->value(), marker->labelAlignment());
}

std::vector<std::pair<const QwtPlotMarker*, const QwtPlotMarker*>> overlappingMarkerLabels(const QwtPlot* plot) {
  std::vector<std::pair<const QwtPlotMarker*, QRectF>> shown;
  for (const QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotMarker)) {
    const auto* m = static_cast<const QwtPlotMarker*>(item);
    if (!m->isVisible() || m->label().isEmpty() || m->lineStyle() != QwtPlotMarker::NoLine) continue;
    shown.emplace_back(m, markerLabelRect(plot, m));
  }
  std::vector<std::pair<const QwtPlotMarker*, const QwtPlotMarker*>> out;
  for (std::size_t i = 0; i < shown.size(); ++i)
    for (std::size_t j = i + 1; j < shown.size(); ++j)
      if (shown[i].second.intersects(shown[j].second)) out.emplace_back(shown[i].first, shown[j].first);
  return out;
}

namespace {
double area(const QRectF& r) {
  return r.isEmpty() ? 0.0 : r.width() * r.height();
}
}  // namespace

std::vector<int> chooseLabelSpots(const std::vector<std::vector<QRectF>>& candidates, const QRectF& bounds,
                                  const std::vector<QRectF>& obstacles) {
  std::vector<int> chosen;
  std::vector<QRectF> placed;
  for (const auto& spots : candidates) {
    int best = -1;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int k = 0; k < static_cast<int>(spots.size()); ++k) {
      const QRectF& r = spots[static_cast<std::size_t>(k)];
      double cost = area(r) - area(r.intersected(bounds));  // what lies outside
      for (const QRectF& p : placed) cost += area(r.intersected(p));
      for (const QRectF& o : obstacles) cost += area(r.intersected(o));
      if (cost < bestCost) {
        bestCost = cost;
        best = k;
      }
      if (cost <= 0.0) break;  // the first clear spot
    }
    chosen.push_back(best);
    if (best >= 0) placed.push_back(spots[static_cast<std::size_t>(best)]);
  }
  return chosen;
}

void placeMarkerLabels(QwtPlot* plot, const std::vector<LabelChoice>& labels, const std::vector<QRectF>& obstacles) {
  std::vector<std::vector<QRectF>> rects;
  for (const auto& l : labels) {
    std::vector<QRectF> r;
    for (const auto& s : l.spots) r.push_back(markerLabelRect(plot, l.marker, s.value, s.align));
    rects.push_back(std::move(r));
  }
  const QRectF canvas = plot->canvas()->contentsRect();
  const std::vector<int> chosen = chooseLabelSpots(rects, canvas, obstacles);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (chosen[i] < 0) continue;
    const LabelSpot& s = labels[i].spots[static_cast<std::size_t>(chosen[i])];
    labels[i].marker->setValue(s.value);
    labels[i].marker->setLabelAlignment(s.align);
  }
}

}  // namespace views
}  // namespace mozzi
