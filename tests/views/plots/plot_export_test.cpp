// The plot export helper writes each of its four formats: the CSV holds every
// visible curve's samples exactly (17 significant digits read back to the same
// doubles), padded where a curve is shorter, with the curve and axis titles in
// the header; the PNG has the requested size; the SVG and PDF are non-empty and
// parse as such; bad names and folders give a clear message.
#include "views/plots/plot_export.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <QAction>
#include <QApplication>
#include <QFile>
#include <QImage>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>

#include "views/plots/vector_series.h"

namespace {

QStringList readLines(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
  QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'));
  if (!lines.isEmpty() && lines.last().isEmpty()) lines.removeLast();
  return lines;
}

}  // namespace

class PlotExportTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    QVERIFY(dir_.isValid());
    plot_ = std::make_unique<QwtPlot>();
    plot_->setObjectName(QStringLiteral("frfMagnitude"));
    plot_->resize(640, 400);
    plot_->setAxisTitle(QwtPlot::xBottom, QStringLiteral("Frequency [Hz]"));
    plot_->setAxisTitle(QwtPlot::yLeft, QStringLiteral("|H| [dB]"));
    // A curve through the no-copy adapter over core vectors, as FrfPlot draws.
    auto f = std::make_shared<const mozzi::core::Vector>(mozzi::core::Vector::LinSpaced(101, 0.0, 100.0));
    auto db = std::make_shared<mozzi::core::Vector>(101);
    for (int i = 0; i < 101; ++i)
      (*db)[i] = 20.0 * std::log10(1.0 / std::abs(1.0 - std::pow((*f)[i] / 42.0, 2) + 0.02));
    measured_ = new QwtPlotCurve(QStringLiteral("measured, H1"));
    measured_->setData(new mozzi::views::VectorSeries(f, db));
    measured_->attach(plot_.get());
    // A shorter curve of plain samples.
    model_ = new QwtPlotCurve(QStringLiteral("model"));
    model_->setSamples(QVector<QPointF>{{1.0 / 3.0, -1.0e-12}, {2.5, M_PI}, {7.0, 1.0e300}});
    model_->attach(plot_.get());
    // A hidden curve is not exported.
    auto* hidden = new QwtPlotCurve(QStringLiteral("hidden"));
    hidden->setSamples(QVector<QPointF>{{0.0, 0.0}});
    hidden->setVisible(false);
    hidden->attach(plot_.get());
    plot_->replot();
  }
  void cleanup() { plot_.reset(); }

  void csvHoldsTheSamplesExactly() {
    const QString path = file(QStringLiteral("plot.csv"));
    QCOMPARE(mozzi::views::exportPlot(plot_.get(), path), QString());
    const QStringList lines = readLines(path);
    QCOMPARE(lines.size(), 1 + 101);
    QCOMPARE(lines[0], QStringLiteral("\"measured, H1: Frequency [Hz]\",\"measured, H1: |H| [dB]\","
                                      "model: Frequency [Hz],model: |H| [dB]"));
    for (int r = 0; r < 101; ++r) {
      const QStringList cells = lines[r + 1].split(QLatin1Char(','));
      QCOMPARE(cells.size(), 4);
      const QPointF p = measured_->sample(static_cast<size_t>(r));
      QCOMPARE(cells[0].toDouble(), p.x());  // exact: 17 digits round-trip a double
      QCOMPARE(cells[1].toDouble(), p.y());
      if (r < 3) {
        const QPointF q = model_->sample(static_cast<size_t>(r));
        QCOMPARE(cells[2].toDouble(), q.x());
        QCOMPARE(cells[3].toDouble(), q.y());
      } else {
        QVERIFY(cells[2].isEmpty() && cells[3].isEmpty());
      }
    }
  }

  void pngHasTheRequestedSize() {
    const QString path = file(QStringLiteral("plot.png"));
    mozzi::views::PlotExportOptions options;
    options.sizeMm = QSizeF(160.0, 100.0);
    options.pngDpi = 100;
    QCOMPARE(mozzi::views::exportPlot(plot_.get(), path, options), QString());
    QImage image(path);
    QVERIFY(!image.isNull());
    // 160 mm at 100 dpi = 629.9 px (QwtPlotRenderer rounds to whole pixels).
    QVERIFY2(std::abs(image.width() - 630) <= 1, qPrintable(QString::number(image.width())));
    QVERIFY2(std::abs(image.height() - 394) <= 1, qPrintable(QString::number(image.height())));
    // Something is drawn: not a blank page.
    int dark = 0;
    for (int y = 0; y < image.height(); y += 4) {
      for (int x = 0; x < image.width(); x += 4) dark += qGray(image.pixel(x, y)) < 128 ? 1 : 0;
    }
    QVERIFY2(dark > 50, qPrintable(QString::number(dark)));
  }

  void svgAndPdfAreVectorDocuments() {
    const QString svg = file(QStringLiteral("plot.svg"));
    QCOMPARE(mozzi::views::exportPlot(plot_.get(), svg), QString());
    QVERIFY(QFileInfo(svg).size() > 1000);
    QSvgRenderer renderer(svg);
    QVERIFY(renderer.isValid());
    QVERIFY(renderer.defaultSize().width() > 0);
    QFile svgFile(svg);
    QVERIFY(svgFile.open(QIODevice::ReadOnly));
    const QByteArray svgText = svgFile.readAll();
    QVERIFY(svgText.contains("<svg"));
    QVERIFY(svgText.contains("<path") || svgText.contains("<polyline"));  // curves as vector paths

    const QString pdf = file(QStringLiteral("plot.PDF"));  // extension case does not matter
    QCOMPARE(mozzi::views::exportPlot(plot_.get(), pdf), QString());
    QFile pdfFile(pdf);
    QVERIFY(pdfFile.open(QIODevice::ReadOnly));
    const QByteArray bytes = pdfFile.readAll();
    QVERIFY(bytes.size() > 1000);
    QVERIFY(bytes.startsWith("%PDF-1."));
    QVERIFY(bytes.trimmed().endsWith("%%EOF"));
    QVERIFY(bytes.contains("/Type /Page") || bytes.contains("/Type/Page"));
  }

  void badNamesGiveAMessage() {
    QString error = mozzi::views::exportPlot(plot_.get(), file(QStringLiteral("plot.xlsx")));
    QVERIFY2(error.contains(QStringLiteral(".png, .svg, .pdf or .csv")), qPrintable(error));
    error = mozzi::views::exportPlot(plot_.get(), file(QStringLiteral("no/such/folder/plot.pdf")));
    QVERIFY2(error.contains(QStringLiteral("folder")), qPrintable(error));
    error = mozzi::views::exportPlot(plot_.get(), file(QStringLiteral("no/such/folder/plot.csv")));
    QVERIFY2(error.contains(QStringLiteral("Cannot write")), qPrintable(error));
    // An untitled axis still names its columns.
    QwtPlot bare;
    auto* curve = new QwtPlotCurve;
    curve->setSamples(QVector<QPointF>{{1.0, 2.0}});
    curve->attach(&bare);
    QCOMPARE(mozzi::views::plotCsv(&bare), QStringLiteral("curve 1: x,curve 1: y\n1,2\n"));
    QwtPlot empty;
    error = mozzi::views::exportPlot(&empty, file(QStringLiteral("empty.csv")));
    QVERIFY2(error.contains(QStringLiteral("no curve")), qPrintable(error));
  }

  void actionIsOnThePlotsContextMenu() {
    QAction* action = mozzi::views::installPlotExportAction(plot_.get());
    QVERIFY(action);
    QVERIFY(plot_->actions().contains(action));
    QCOMPARE(plot_->contextMenuPolicy(), Qt::ActionsContextMenu);
    QCOMPARE(action->text(), QStringLiteral("Export Plot..."));
  }

 private:
  QString file(const QString& name) const { return QDir(dir_.path()).filePath(name); }
  QTemporaryDir dir_;
  std::unique_ptr<QwtPlot> plot_;
  QwtPlotCurve* measured_ = nullptr;
  QwtPlotCurve* model_ = nullptr;
};

QTEST_MAIN(PlotExportTest)
#include "plot_export_test.moc"
