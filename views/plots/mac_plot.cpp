#include "views/plots/mac_plot.h"

#include <qwt_plot_curve.h>
#include <qwt_plot_item.h>
#include <qwt_scale_div.h>
#include <qwt_scale_draw.h>
#include <qwt_scale_map.h>
#include <QPainter>
#include <cmath>

#include "core/common/plot_math.h"
#include "views/plots/plot_export.h"

namespace mozzi {
namespace views {

class MacGridItem : public QwtPlotItem {
 public:
  MacGridItem() { setZ(1); }
  int rtti() const override { return QwtPlotItem::Rtti_PlotUserItem + 18; }
  void draw(QPainter* painter, const QwtScaleMap& xMap, const QwtScaleMap& yMap, const QRectF&) const override {
    const QFont font = painter->font();
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
      for (Eigen::Index c = 0; c < values.cols(); ++c) {
        // Cell (c, r) spans [c + 0.5, c + 1.5] x [r + 0.5, r + 1.5] (1-based labels).
        const QRectF cell(QPointF(xMap.transform(c + 0.5), yMap.transform(r + 0.5)),
                          QPointF(xMap.transform(c + 1.5), yMap.transform(r + 1.5)));
        const double v = values(r, c);
        const core::Rgb rgb = core::heatColour(v);
        painter->fillRect(cell.normalized(), QColor(rgb.r, rgb.g, rgb.b));
        painter->setPen(QColor(0, 0, 0, 60));
        painter->drawRect(cell.normalized());
        painter->setPen(core::heatColourIsDark(v) ? Qt::white : Qt::black);
        QFont f = font;
        f.setPointSizeF(std::max(6.0, std::min(font.pointSizeF(), std::abs(cell.height()) / 3.0)));
        painter->setFont(f);
        painter->drawText(cell.normalized(), Qt::AlignCenter, QString::number(v, 'f', 2));
      }
    }
    painter->setFont(font);
  }
  core::Matrix values;
};

namespace {

// Integer ticks named by the labels.
class LabelScaleDraw : public QwtScaleDraw {
 public:
  explicit LabelScaleDraw(QStringList labels) : labels_(std::move(labels)) {}
  QwtText label(double v) const override {
    const int i = static_cast<int>(std::lround(v)) - 1;
    if (std::abs(v - std::lround(v)) > 1e-9 || i < 0 || i >= labels_.size()) return QwtText();
    return QwtText(labels_[i]);
  }

 private:
  QStringList labels_;
};

}  // namespace

MacPlot::MacPlot(QWidget* parent) : QwtPlot(parent) {
  setCanvasBackground(Qt::white);
  grid_ = new MacGridItem;
  grid_->attach(this);
  installPlotExportAction(this);
}

void MacPlot::setMatrix(const core::Matrix& values, const QStringList& rowLabels, const QStringList& columnLabels) {
  values_ = values;
  grid_->values = values;
  detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  for (Eigen::Index r = 0; r < values.rows(); ++r) {
    auto* row = new QwtPlotCurve(r < rowLabels.size() ? rowLabels[static_cast<int>(r)] : QString::number(r + 1));
    row->setStyle(QwtPlotCurve::NoCurve);  // data for the CSV, nothing drawn
    QVector<QPointF> pts;
    for (Eigen::Index c = 0; c < values.cols(); ++c) pts.push_back(QPointF(c + 1, values(r, c)));
    row->setSamples(pts);
    row->setItemAttribute(QwtPlotItem::AutoScale, false);
    row->attach(this);
  }
  const int nc = static_cast<int>(values.cols()), nr = static_cast<int>(values.rows());
  QList<double> xt, yt;
  for (int c = 1; c <= nc; ++c) xt << c;
  for (int r = 1; r <= nr; ++r) yt << r;
  setAxisScaleDiv(QwtPlot::xBottom, QwtScaleDiv(0.5, nc + 0.5, QList<double>(), QList<double>(), xt));
  setAxisScaleDiv(QwtPlot::yLeft, QwtScaleDiv(nr + 0.5, 0.5, QList<double>(), QList<double>(), yt));
  setAxisScaleDraw(QwtPlot::xBottom, new LabelScaleDraw(columnLabels));
  setAxisScaleDraw(QwtPlot::yLeft, new LabelScaleDraw(rowLabels));
  replot();
}

}  // namespace views
}  // namespace mozzi
