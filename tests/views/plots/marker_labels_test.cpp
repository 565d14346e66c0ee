// Marker labels kept apart: the rectangle markerLabelRect gives is where Qwt
// paints the label (the label's background read back from a grab of the
// canvas, to a pixel), and the greedy choice takes each label's first clear
// spot, avoids obstacles and the outside, and takes the least overlap when
// nothing is clear.
#include "views/plots/marker_labels.h"

#include <qwt_plot.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_marker.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QImage>
#include <QtTest>

using mozzi::views::chooseLabelSpots;
using mozzi::views::markerLabelRect;

namespace {

// The box of the pixels of `colour` in `image`.
QRect boxOf(const QImage& image, QRgb colour) {
  QRect box;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if ((image.pixel(x, y) & 0xffffff) == (colour & 0xffffff)) box |= QRect(x, y, 1, 1);
  return box;
}

}  // namespace

class MarkerLabelsTest : public QObject {
  Q_OBJECT

 private slots:
  void theRectangleIsWhereQwtPaintsTheLabel() {
    QwtPlot plot;
    plot.resize(600, 400);
    plot.setAxisScale(QwtPlot::xBottom, 0.0, 10.0);
    plot.setAxisScale(QwtPlot::yLeft, 0.0, 10.0);
    plot.setCanvasBackground(Qt::white);
    static_cast<QwtPlotCanvas*>(plot.canvas())->setFrameStyle(QFrame::NoFrame);
    auto* marker = new QwtPlotMarker;
    marker->setValue(5.0, 5.0);
    marker->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(Qt::black), QPen(Qt::black), QSize(12, 12)));
    QwtText text(QStringLiteral("load point (swing-arm pivot)"));
    const QColor green(0, 200, 0);
    text.setBackgroundBrush(green);
    text.setColor(green);  // the whole rectangle one colour
    marker->setLabel(text);
    marker->attach(&plot);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    for (Qt::Alignment align : {Qt::AlignRight | Qt::AlignBottom, Qt::AlignLeft | Qt::AlignTop,
                                Qt::AlignHCenter | Qt::AlignBottom, Qt::AlignLeft | Qt::AlignVCenter}) {
      marker->setLabelAlignment(align);
      plot.replot();
      const QImage image = plot.canvas()->grab().toImage();
      const QRect painted = boxOf(image.convertToFormat(QImage::Format_RGB32), green.rgb());
      const QRectF computed = markerLabelRect(&plot, marker);
      QVERIFY(!painted.isEmpty());
      const double dpr = image.devicePixelRatio();
      const QRectF logical(painted.x() / dpr, painted.y() / dpr, painted.width() / dpr, painted.height() / dpr);
      for (auto [a, b] : {std::pair{logical.left(), computed.left()}, std::pair{logical.top(), computed.top()},
                          std::pair{logical.right(), computed.right()}, std::pair{logical.bottom(), computed.bottom()}})
        QVERIFY2(std::abs(a - b) <= 1.5,
                 qPrintable(QStringLiteral("align %1: painted (%2,%3 %4x%5), computed (%6,%7 %8x%9)")
                                .arg(int(align))
                                .arg(logical.x())
                                .arg(logical.y())
                                .arg(logical.width())
                                .arg(logical.height())
                                .arg(computed.x())
                                .arg(computed.y())
                                .arg(computed.width())
                                .arg(computed.height())));
    }
  }

  void eachLabelTakesItsFirstClearSpot() {
    const QRectF bounds(0, 0, 100, 100);
    // Label 0 takes its first spot; label 1's first spot is under it, its second is clear.
    const std::vector<std::vector<QRectF>> c = {{QRectF(10, 10, 30, 10)},
                                                {QRectF(20, 15, 30, 10), QRectF(20, 30, 30, 10)}};
    QCOMPARE(chooseLabelSpots(c, bounds, {}), (std::vector<int>{0, 1}));
    // An obstacle on label 0's first spot sends it to its second.
    const std::vector<std::vector<QRectF>> d = {{QRectF(10, 10, 30, 10), QRectF(10, 50, 30, 10)}};
    QCOMPARE(chooseLabelSpots(d, bounds, {QRectF(12, 12, 4, 4)}), (std::vector<int>{1}));
    // A spot partly outside counts its outside as overlap.
    const std::vector<std::vector<QRectF>> e = {{QRectF(90, 10, 30, 10), QRectF(60, 10, 30, 10)}};
    QCOMPARE(chooseLabelSpots(e, bounds, {}), (std::vector<int>{1}));
    // Nothing clear: the least overlap (the second spot covers 2 x 10 px of label 0, the first 20 x 10).
    const std::vector<std::vector<QRectF>> f = {{QRectF(10, 10, 30, 10)},
                                                {QRectF(20, 10, 30, 10), QRectF(38, 10, 30, 10)}};
    QCOMPARE(chooseLabelSpots(f, bounds, {}), (std::vector<int>{0, 1}));
    // No candidates: -1.
    QCOMPARE(chooseLabelSpots({{}}, bounds, {}), (std::vector<int>{-1}));
  }
};

QTEST_MAIN(MarkerLabelsTest)
#include "marker_labels_test.moc"
