#include "views/plots/interactive_plot.h"

#include <qwt_picker_machine.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_magnifier.h>
#include <qwt_plot_marker.h>
#include <qwt_plot_panner.h>
#include <qwt_plot_picker.h>
#include <qwt_scale_engine.h>
#include <qwt_scale_widget.h>
#include <QKeyEvent>
#include <QPointer>
#include <QResizeEvent>
#include <QTimer>
#include <cmath>
#include <limits>

#include "core/common/plot_math.h"
#include "views/plots/plot_export.h"

namespace mozzi {
namespace views {

namespace {

std::vector<const QwtPlotCurve*> visibleCurves(const QwtPlot* plot, bool autoscaledOnly = false) {
  std::vector<const QwtPlotCurve*> out;
  for (const QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
    if (autoscaledOnly && !item->testItemAttribute(QwtPlotItem::AutoScale)) continue;
    if (item->isVisible() && static_cast<const QwtPlotCurve*>(item)->dataSize() > 0)
      out.push_back(static_cast<const QwtPlotCurve*>(item));
  }
  return out;
}

}  // namespace

InteractivePlot::InteractivePlot(QWidget* parent) : QwtPlot(parent) {
  setCanvasBackground(Qt::white);
  auto* grid = new QwtPlotGrid;
  grid->setMajorPen(QColor(0, 0, 0, 40), 0.0, Qt::DotLine);
  grid->attach(this);
  cursorMarker_ = new QwtPlotMarker;
  cursorMarker_->setLineStyle(QwtPlotMarker::VLine);
  cursorMarker_->setLinePen(QColor(200, 30, 30), 1.0, Qt::DashLine);
  cursorMarker_->setZ(100);
  cursorMarker_->setItemAttribute(QwtPlotItem::AutoScale, false);
  cursorMarker_->hide();
  cursorMarker_->attach(this);

  magnifier_ = new QwtPlotMagnifier(canvas());
  magnifier_->setMouseButton(Qt::NoButton);  // wheel and keys only
  // Qwt divides by the factor on a forward turn: 1.25 makes forward zoom in.
  magnifier_->setWheelFactor(1.25);
  panner_ = new QwtPlotPanner(canvas());
  panner_->setMouseButton(Qt::MiddleButton);
  // Shift + left drag pans too (touchpads have no middle button).
  auto* shiftPanner = new QwtPlotPanner(canvas());
  shiftPanner->setMouseButton(Qt::LeftButton, Qt::ShiftModifier);
  picker_ =
      new QwtPlotPicker(QwtPlot::xBottom, QwtPlot::yLeft, QwtPicker::NoRubberBand, QwtPicker::AlwaysOff, canvas());
  picker_->setStateMachine(new QwtPickerClickPointMachine);
  connect(picker_, QOverload<const QPointF&>::of(&QwtPlotPicker::selected), this, [this](const QPointF& p) {
    const QPoint pixel(static_cast<int>(std::lround(transform(QwtPlot::xBottom, p.x()))),
                       static_cast<int>(std::lround(transform(QwtPlot::yLeft, p.y()))));
    emit clicked(p, pixel);
    if (cursorOnClick_) setCursor(p.x());
  });
  canvas()->setFocusPolicy(Qt::StrongFocus);
  canvas()->installEventFilter(this);
  connect(axisWidget(QwtPlot::xBottom), &QwtScaleWidget::scaleDivChanged, this, &InteractivePlot::emitRange);
  installPlotExportAction(this);
}

void InteractivePlot::setLogX(bool on) {
  if (on == logX_) return;
  logX_ = on;
  if (on) {
    setAxisScaleEngine(QwtPlot::xBottom, new QwtLogScaleEngine);
  } else {
    setAxisScaleEngine(QwtPlot::xBottom, new QwtLinearScaleEngine);
  }
  autoscale();
}

void InteractivePlot::setLogY(bool on) {
  if (on == logY_) return;
  logY_ = on;
  if (on) {
    setAxisScaleEngine(QwtPlot::yLeft, new QwtLogScaleEngine);
  } else {
    setAxisScaleEngine(QwtPlot::yLeft, new QwtLinearScaleEngine);
  }
  autoscaleY();
}

void InteractivePlot::setEqualAspect(bool on) {
  if (on == equalAspect_) return;
  equalAspect_ = on;
  autoscale();
}

void InteractivePlot::autoscale() {
  if (equalAspect_) {
    // Both axes from every sample, padded 5%, then the shorter one grown.
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const QwtPlotCurve* c : visibleCurves(this, true)) {
      const QRectF r = c->boundingRect();  // top() is the lower y
      if (r.width() < 0 || r.height() < 0) continue;
      x0 = std::min(x0, r.left());
      x1 = std::max(x1, r.right());
      y0 = std::min(y0, r.top());
      y1 = std::max(y1, r.bottom());
    }
    if (!(x0 <= x1 && y0 <= y1)) {
      replot();
      return;
    }
    const double pad = 0.05 * std::max(x1 - x0, y1 - y0);
    core::AxisRange x{x0 - pad, x1 + pad}, y{y0 - pad, y1 + pad};
    core::equalAspectRanges(x, y, std::max(1, canvas()->width()), std::max(1, canvas()->height()));
    setAxisScale(QwtPlot::xBottom, x.lower, x.upper);
    setAxisScale(QwtPlot::yLeft, y.lower, y.upper);
    replot();
    return;
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const QwtPlotCurve* c : visibleCurves(this, true)) {
    const QRectF r = c->boundingRect();
    if (r.width() < 0) continue;
    double l = r.left();
    if (logX_ && !(l > 0.0)) {
      // First positive x (a 0 Hz line cannot sit on a log axis).
      for (size_t i = 0; i < c->dataSize(); ++i) {
        if (c->sample(i).x() > 0.0) {
          l = c->sample(i).x();
          break;
        }
      }
    }
    lo = std::min(lo, l);
    hi = std::max(hi, r.right());
  }
  if (lo < hi) {
    if (logX_ && lo > 0.0) {
      setAxisScale(QwtPlot::xBottom, lo, hi);
    } else {
      setAxisScale(QwtPlot::xBottom, lo, hi);
    }
  }
  autoscaleY();
}

void InteractivePlot::autoscaleY() {
  // setAxisScale stores the range and Qwt applies it at the next replot; the
  // interval read here must be the one just set (autoscale, zoom, callers), not
  // the one shown before it.
  updateAxes();
  const QwtInterval x = axisInterval(QwtPlot::xBottom);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const QwtPlotCurve* c : visibleCurves(this, true)) {
    if (c->yAxis() != QwtPlot::yLeft) continue;
    core::Vector xs(static_cast<Eigen::Index>(c->dataSize())), ys(xs.size());
    for (size_t i = 0; i < c->dataSize(); ++i) {
      const QPointF p = c->sample(i);
      xs[static_cast<Eigen::Index>(i)] = p.x();
      ys[static_cast<Eigen::Index>(i)] = p.y();
    }
    // Nyquist-like curves (x not a frequency axis) use all their points.
    const core::AxisRange r = core::dataRange(xs, ys, x.minValue(), x.maxValue(), logY_, 0.0, yFloor_);
    if (r.upper < r.lower) continue;
    if ((logY_ && r.lower == 1.0 && r.upper == 10.0) || (!logY_ && r.lower == 0.0 && r.upper == 1.0)) {
      // dataRange's empty-selection answer: count only if the curve has points there.
      bool any = false;
      for (Eigen::Index k = 0; k < xs.size() && !any; ++k) any = xs[k] >= x.minValue() && xs[k] <= x.maxValue();
      if (!any) continue;
    }
    lo = std::min(lo, r.lower);
    hi = std::max(hi, r.upper);
  }
  if (lo <= hi) {
    const core::AxisRange padded =
        logY_ ? core::AxisRange{lo / 1.5, hi * 1.5}
              : core::AxisRange{lo - 0.05 * std::max(hi - lo, 1e-300), hi + 0.05 * std::max(hi - lo, 1e-300)};
    setAxisScale(QwtPlot::yLeft, padded.lower, padded.upper);
  } else {
    setAxisAutoScale(QwtPlot::yLeft, true);
  }
  replot();
}

void InteractivePlot::setCursor(std::optional<double> x) {
  cursor_ = x;
  if (x) {
    cursorMarker_->setXValue(*x);
    cursorMarker_->show();
  } else {
    cursorMarker_->hide();
  }
  replot();
  if (x) emit cursorMoved(*x);
}

void InteractivePlot::stepCursor(int lines) {
  const auto curves = visibleCurves(this);
  if (curves.empty()) return;
  const QwtPlotCurve* c = curves.front();
  const QwtInterval xr = axisInterval(QwtPlot::xBottom);
  const double at = cursor_ ? *cursor_ : 0.5 * (xr.minValue() + xr.maxValue());
  // Nearest sample, then `lines` further (the curve's x is its frequency axis).
  size_t best = 0;
  for (size_t i = 0; i < c->dataSize(); ++i) {
    if (std::abs(c->sample(i).x() - at) < std::abs(c->sample(best).x() - at)) best = i;
  }
  const long target = std::clamp<long>(static_cast<long>(best) + lines, 0, static_cast<long>(c->dataSize()) - 1);
  setCursor(c->sample(static_cast<size_t>(target)).x());
}

void InteractivePlot::zoomX(double factor) {
  const QwtInterval x = axisInterval(QwtPlot::xBottom);
  if (logX_ && x.minValue() > 0.0) {
    const double a = std::log10(x.minValue()), b = std::log10(x.maxValue()), m = 0.5 * (a + b),
                 h = 0.5 * (b - a) * factor;
    setAxisScale(QwtPlot::xBottom, std::pow(10.0, m - h), std::pow(10.0, m + h));
  } else {
    const double m = 0.5 * (x.minValue() + x.maxValue()), h = 0.5 * x.width() * factor;
    setAxisScale(QwtPlot::xBottom, m - h, m + h);
  }
  replot();
}

void InteractivePlot::panX(double fraction) {
  const QwtInterval x = axisInterval(QwtPlot::xBottom);
  if (logX_ && x.minValue() > 0.0) {
    const double d = fraction * (std::log10(x.maxValue()) - std::log10(x.minValue()));
    setAxisScale(QwtPlot::xBottom, x.minValue() * std::pow(10.0, d), x.maxValue() * std::pow(10.0, d));
  } else {
    const double d = fraction * x.width();
    setAxisScale(QwtPlot::xBottom, x.minValue() + d, x.maxValue() + d);
  }
  replot();
}

bool InteractivePlot::eventFilter(QObject* watched, QEvent* event) {
  if (watched == canvas() && event->type() == QEvent::Resize && equalAspect_) autoscale();
  if (watched == canvas() && event->type() == QEvent::KeyPress) {
    auto* key = static_cast<QKeyEvent*>(event);
    const bool shift = key->modifiers() & Qt::ShiftModifier, ctrl = key->modifiers() & Qt::ControlModifier;
    switch (key->key()) {
      case Qt::Key_Left:
      case Qt::Key_Right: {
        const int dir = key->key() == Qt::Key_Left ? -1 : 1;
        if (ctrl) {
          zoomX(dir < 0 ? 1.25 : 0.8);
        } else if (shift) {
          panX(0.1 * dir);
        } else {
          stepCursor(dir);
        }
        return true;
      }
      case Qt::Key_Home:
      case Qt::Key_A: autoscale(); return true;
      default: break;
    }
  }
  return QwtPlot::eventFilter(watched, event);
}

void InteractivePlot::emitRange() {
  const QwtInterval x = axisInterval(QwtPlot::xBottom);
  emit xRangeChanged(x.minValue(), x.maxValue());
}

namespace {

// Aligns again when an axis changes length: its title wraps by the length, and
// a title on one line more widens that axis by a line. Once per burst of
// resizes, after the layout that sent them has finished (aligning inside it
// would re-enter QwtPlot::updateLayout half-way); plots destroyed in the
// meantime are left out.
class LeftAxesAligner : public QObject {
 public:
  LeftAxesAligner(const std::vector<QwtPlot*>& plots, QObject* parent) : QObject(parent) {
    setObjectName(QStringLiteral("leftAxesAligner"));
    for (QwtPlot* p : plots) {
      plots_.push_back(p);
      p->axisWidget(QwtPlot::yLeft)->installEventFilter(this);
    }
  }
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Resize && !queued_) {
      const auto* resize = static_cast<QResizeEvent*>(event);
      if (resize->size().height() != resize->oldSize().height()) {
        queued_ = true;
        QTimer::singleShot(0, this, [this] {
          queued_ = false;
          std::vector<QwtPlot*> alive;
          for (const QPointer<QwtPlot>& p : plots_)
            if (p) alive.push_back(p);
          alignLeftAxes(alive);
        });
      }
    }
    return QObject::eventFilter(watched, event);
  }

 private:
  std::vector<QPointer<QwtPlot>> plots_;
  bool queued_ = false;
};

}  // namespace

void alignLeftAxes(const std::vector<QwtPlot*>& plots) {
  if (plots.empty()) return;
  // The whole axis takes the same width - labels, spacing and title, whose
  // wrapping depends on the axis length - not only the labels: a title wrapped
  // to two lines on the shorter plot shifted its canvas, and the curve against
  // the shared frequency axis below it, by a line's height (17 Hz on the demo's
  // FRF page).
  std::vector<double> own(plots.size(), 0.0);
  std::vector<int> dims(plots.size(), 0);
  int widest = 0;
  for (std::size_t k = 0; k < plots.size(); ++k) {
    QwtScaleWidget* w = plots[k]->axisWidget(QwtPlot::yLeft);
    w->scaleDraw()->setMinimumExtent(0.0);
    if (plots[k]->isHidden()) continue;
    own[k] = w->scaleDraw()->extent(w->font());
    const int length = w->height() > 0 ? w->height() : w->sizeHint().height();
    dims[k] = w->dimForLength(length, w->font());
    widest = std::max(widest, dims[k]);
  }
  for (std::size_t k = 0; k < plots.size(); ++k) {
    QwtScaleWidget* w = plots[k]->axisWidget(QwtPlot::yLeft);
    const double extent = plots[k]->isHidden() ? 0.0 : own[k] + (widest - dims[k]);
    if (w->scaleDraw()->minimumExtent() == extent) continue;
    w->scaleDraw()->setMinimumExtent(extent);
    w->updateGeometry();
    plots[k]->updateLayout();
  }
  // QwtPlotLayout wraps a title to a length a few pixels off the axis's own:
  // a title at the edge of a line break (the FRF page's magnitude at 1000x480)
  // took one line in the layout where dimForLength above gave two. The widths
  // the layout gave are the truth: widen the narrower axes to the widest.
  for (int pass = 0; pass < 2; ++pass) {
    int widestNow = 0;
    for (QwtPlot* p : plots)
      if (!p->isHidden()) widestNow = std::max(widestNow, p->axisWidget(QwtPlot::yLeft)->width());
    bool changed = false;
    for (QwtPlot* p : plots) {
      QwtScaleWidget* w = p->axisWidget(QwtPlot::yLeft);
      if (p->isHidden() || w->width() >= widestNow) continue;
      w->scaleDraw()->setMinimumExtent(w->scaleDraw()->minimumExtent() + (widestNow - w->width()));
      w->updateGeometry();
      p->updateLayout();
      changed = true;
    }
    if (!changed) break;
  }
  if (!plots.front()->findChild<LeftAxesAligner*>(QStringLiteral("leftAxesAligner"), Qt::FindDirectChildrenOnly))
    new LeftAxesAligner(plots, plots.front());
}

}  // namespace views
}  // namespace mozzi
