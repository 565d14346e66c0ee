#pragma once
// A curve over core vectors (VectorSeries: no copies) that draws, per pixel
// column of the visible range, only the samples holding the column's minimum
// and maximum (core::decimateMinMax): 100 FRFs of 20,000 lines stay fluid
// while panning and zooming. Its data stays complete: samples, CSV export and
// tests see every line. Curves whose x is not ascending (Nyquist) are drawn
// in full.

#include <qwt_plot_curve.h>

#include <memory>

#include "core/common/eigen_types.h"

namespace mozzi {
namespace views {

class DecimatingCurve : public QwtPlotCurve {
 public:
  explicit DecimatingCurve(const QString& title = QString());

  // x and y share their length; x ascending enables decimation.
  void setVectors(std::shared_ptr<const core::Vector> x, std::shared_ptr<const core::Vector> y);
  bool decimates() const { return ascending_; }
  // Points drawn by the last paint (for tests and benchmarks).
  int lastDrawnPoints() const { return lastDrawn_; }

 protected:
  void drawSeries(QPainter* painter, const QwtScaleMap& xMap, const QwtScaleMap& yMap, const QRectF& canvasRect,
                  int from, int to) const override;

 private:
  std::shared_ptr<const core::Vector> x_, y_;
  bool ascending_ = false;
  mutable int lastDrawn_ = 0;
};

}  // namespace views
}  // namespace mozzi
