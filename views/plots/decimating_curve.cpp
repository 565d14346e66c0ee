#include "views/plots/decimating_curve.h"

#include <qwt_painter.h>
#include <qwt_scale_map.h>
#include <QPaintDevice>
#include <QPainter>
#include <QPolygon>
#include <QPolygonF>
#include <cmath>
#include <vector>

#include "core/common/plot_math.h"
#include "views/plots/vector_series.h"

namespace mozzi {
namespace views {

DecimatingCurve::DecimatingCurve(const QString& title) : QwtPlotCurve(title) {
  setPaintAttribute(QwtPlotCurve::ClipPolygons, true);
}

void DecimatingCurve::setVectors(std::shared_ptr<const core::Vector> x, std::shared_ptr<const core::Vector> y) {
  x_ = std::move(x);
  y_ = std::move(y);
  ascending_ = true;
  for (Eigen::Index k = 1; k < x_->size() && ascending_; ++k) ascending_ = (*x_)[k] >= (*x_)[k - 1];
  setData(new VectorSeries(x_, y_));
}

void DecimatingCurve::drawSeries(QPainter* painter, const QwtScaleMap& xMap, const QwtScaleMap& yMap,
                                 const QRectF& canvasRect, int from, int to) const {
  if (!x_ || !y_ || !ascending_ || style() != QwtPlotCurve::Lines) {
    lastDrawn_ = static_cast<int>(dataSize());
    QwtPlotCurve::drawSeries(painter, xMap, yMap, canvasRect, from, to);
    return;
  }
  // Device pixels across the canvas (twice the logical ones at scale 2).
  const double ratio = painter->device() ? painter->device()->devicePixelRatioF() : 1.0;
  const int columns = std::max(1, static_cast<int>(std::ceil(std::abs(xMap.p2() - xMap.p1()) * ratio)));
  const bool logX = xMap.transformation() && xMap.s1() > 0.0 && xMap.transformation()->transform(10.0) != 10.0;
  const double lo = std::min(xMap.s1(), xMap.s2()), hi = std::max(xMap.s1(), xMap.s2());
  // The pixel columns depend only on the x vector and the view: curves of one
  // set share them (one per frame instead of one per curve).
  struct ColumnCache {
    std::weak_ptr<const core::Vector> x;  // alive: its address cannot be another vector's
    double lo = 0, hi = 0;
    int columns = 0;
    bool logX = false;
    std::vector<Eigen::Index> starts;
  };
  static thread_local ColumnCache cache;
  if (cache.x.lock() != x_ || cache.lo != lo || cache.hi != hi || cache.columns != columns || cache.logX != logX) {
    cache.starts = core::pixelColumnStarts(*x_, lo, hi, columns, logX);
    cache.x = x_;
    cache.lo = lo;
    cache.hi = hi;
    cache.columns = columns;
    cache.logX = logX;
  }
  const core::DecimatedCurve d = core::decimateMinMax(*x_, *y_, cache.starts);
  lastDrawn_ = static_cast<int>(d.x.size());
  if (d.x.size() < 2) return;
  painter->save();
  const bool antialias = testRenderHint(QwtPlotItem::RenderAntialiased);
  painter->setRenderHint(QPainter::Antialiasing, antialias);
  QPen p = pen();
  if (!antialias && p.widthF() <= 1.0) {
    // Thin lines without antialiasing: a cosmetic pen on integer pixels takes
    // the raster engine's fastest path (the picture is the same).
    p.setWidth(0);
    p.setCosmetic(true);
    painter->setPen(p);
    QPolygon polygon(static_cast<int>(d.x.size()));
    for (Eigen::Index q = 0; q < d.x.size(); ++q) {
      polygon[static_cast<int>(q)] = QPoint(static_cast<int>(std::lround(xMap.transform(d.x[q]))),
                                            static_cast<int>(std::lround(yMap.transform(d.y[q]))));
    }
    painter->drawPolyline(polygon);
  } else {
    painter->setPen(p);
    QPolygonF polygon(static_cast<int>(d.x.size()));
    for (Eigen::Index q = 0; q < d.x.size(); ++q) {
      polygon[static_cast<int>(q)] = QPointF(xMap.transform(d.x[q]), yMap.transform(d.y[q]));
    }
    QwtPainter::drawPolyline(painter, polygon);
  }
  painter->restore();
}

}  // namespace views
}  // namespace mozzi
