#pragma once
// The plot every FRF-like figure uses: grid, a cursor (left click, or the
// arrow keys once the plot has focus), zoom (wheel, +/- keys, Ctrl+arrows),
// pan (middle or Shift+left drag, Shift+arrows), autoscale (Home or the A key,
// or autoscale()), linear or logarithmic axes, and the export action of
// plot_export. Ranges come from core (core::dataRange, core::roundedRange).

#include <qwt_plot.h>

#include <vector>

#include <QPoint>
#include <QPointF>
#include <limits>
#include <optional>

class QwtPlotMarker;
class QwtPlotMagnifier;
class QwtPlotPanner;
class QwtPlotPicker;

namespace mozzi {
namespace views {

class InteractivePlot : public QwtPlot {
  Q_OBJECT
 public:
  explicit InteractivePlot(QWidget* parent = nullptr);

  void setLogX(bool on);
  void setLogY(bool on);
  // Values at or below `floor` are left out of the y autoscale (a dB axis
  // passes core::kMagnitudeFloorDb, the value of a zero magnitude).
  void setYFloor(double floor) { yFloor_ = floor; }
  bool logX() const { return logX_; }
  bool logY() const { return logY_; }

  // Fits both axes to the visible curves (x: every sample; y: the samples in
  // the x range, on a log axis only positive ones) and replots.
  void autoscale();
  // Fits y to the visible curves within the current x range.
  void autoscaleY();
  // Keeps the x range when the data is replaced (a new selection): y is refit.
  void setKeepX(bool keep) { keepX_ = keep; }
  // Equal aspect (a drawing of a plane, both axes in the same unit): autoscale
  // grows the shorter range so a unit is as long across as up on the canvas,
  // and refits when the canvas is resized. Curves whose AutoScale attribute is
  // off (lines clipped to the view) never widen the autoscale.
  void setEqualAspect(bool on);
  bool equalAspect() const { return equalAspect_; }
  // Whether a left click places the cursor (default) or only emits clicked().
  void setCursorOnClick(bool on) { cursorOnClick_ = on; }

  // Cursor at frequency x (nullopt hides it); emits cursorMoved.
  void setCursor(std::optional<double> x);
  std::optional<double> cursor() const { return cursor_; }
  // Steps the cursor to the next/previous x of the first visible curve.
  void stepCursor(int lines);

  // Zoom by a factor about the centre of the x range (and y unless xOnly); pan
  // by a fraction of the x span.
  void zoomX(double factor);
  void panX(double fraction);

 signals:
  void cursorMoved(double x);
  // A left click on the canvas: plot coordinates and the canvas pixel.
  void clicked(QPointF plotPoint, QPoint pixel);
  void xRangeChanged(double lower, double upper);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void emitRange();

  bool logX_ = false, logY_ = false, keepX_ = false, cursorOnClick_ = true, equalAspect_ = false;
  double yFloor_ = -std::numeric_limits<double>::infinity();
  std::optional<double> cursor_;
  QwtPlotMarker* cursorMarker_ = nullptr;
  QwtPlotMagnifier* magnifier_ = nullptr;
  QwtPlotPanner* panner_ = nullptr;
  QwtPlotPicker* picker_ = nullptr;
};

// Stacked plots sharing a frequency or speed axis: their left axes take the
// widest one's width so the canvases line up (hidden plots do not count).
void alignLeftAxes(const std::vector<QwtPlot*>& plots);

}  // namespace views
}  // namespace mozzi
