#include "views/report/report_writer.h"

#include <qwt_plot.h>
#include <qwt_plot_renderer.h>
#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextDocument>
#include <QUrl>
#include <map>
#include <memory>

#include "core/io/output_file.h"
#include "core/report/report_html.h"
#include "views/plots/frf_plot.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/plot_export.h"
#include "views/report/report_figures.h"

namespace mozzi {
namespace views {
namespace {

constexpr double kMmPerInch = 25.4;

// What draws `figure` (false and *error when its view cannot draw it here).
bool drawFigure(const core::report::Figure& figure, const core::io::ProjectStore& store,
                const ReportRenderOptions& options, FigureDrawing& out, QString* error) {
  const auto& renderers = figureRenderers();
  const auto it = renderers.find(figure.view);
  if (it == renderers.end()) {
    if (error)
      *error = QCoreApplication::translate("ReportWriter", "the %1 view does not render in a project report")
                   .arg(QString::fromStdString(figure.view));
    return false;
  }
  return it->second(FigureRequest{figure, store, options}, out, error) && out.ok();
}

}  // namespace

QImage renderReportFigure(const core::report::Figure& figure, const core::io::ProjectStore& store,
                          const ReportRenderOptions& options, QString* error) {
  FigureDrawing drawing;
  if (!drawFigure(figure, store, options, drawing, error)) return {};
  if (!drawing.plot) return drawing.image;  // raster already (the 3-D scene)
  // As QwtPlotRenderer::renderDocument does for a raster file: the image's
  // resolution set, so fonts and pens scale to print size.
  const QSizeF sizeMm(options.figureWidthMm, options.figureHeightMm);
  const QSize pixels = (sizeMm / kMmPerInch * options.dpi).toSize();
  QImage image(pixels, QImage::Format_ARGB32);
  const int dotsPerMetre = qRound(options.dpi * 1000.0 / kMmPerInch);
  image.setDotsPerMeterX(dotsPerMetre);
  image.setDotsPerMeterY(dotsPerMetre);
  image.fill(Qt::white);
  QPainter painter(&image);
  renderPlot(drawing.plot, painter, QRectF(QPointF(0, 0), QSizeF(pixels)));
  painter.end();
  return image;
}

void renderPlot(QwtPlot* plot, QPainter& painter, const QRectF& rect) {
  QwtPlotRenderer renderer;
  renderer.setDiscardFlag(QwtPlotRenderer::DiscardBackground, false);
  renderer.render(plot, &painter, rect);
}

QString writeHtmlReport(const core::report::Report& report, const core::io::ProjectStore& store, const QString& dir,
                        const std::vector<std::string>& inputs, const ReportRenderOptions& options) {
  if (!QDir().mkpath(dir)) return QCoreApplication::translate("ReportWriter", "Cannot create the folder %1").arg(dir);
  QString failure;
  const auto figureSource = [&](const core::report::Figure& f) -> std::string {
    FigureDrawing drawing;
    if (!drawFigure(f, store, options, drawing, nullptr)) return {};
    const QString stem = QDir(dir).filePath(QString::fromStdString(f.id));
    if (!drawing.plot) {  // raster: PNG only
      if (!drawing.image.save(stem + QStringLiteral(".png")) && failure.isEmpty())
        failure = QCoreApplication::translate("ReportWriter", "Cannot write %1").arg(stem + QStringLiteral(".png"));
      return f.id + ".png";
    }
    QwtPlot* plot = drawing.plot;
    PlotExportOptions exportOptions;
    exportOptions.sizeMm = QSizeF(options.figureWidthMm, options.figureHeightMm);
    exportOptions.pngDpi = options.dpi;
    for (const char* suffix : {".svg", ".png"}) {
      const QString written = exportPlot(plot, stem + QLatin1String(suffix), exportOptions);
      if (!written.isEmpty() && failure.isEmpty()) failure = written;
    }
    return f.id + ".svg";  // vector in the page; the PNG beside it
  };
  const std::string html = core::report::toHtml(report, figureSource);
  if (!failure.isEmpty()) return failure;
  auto written =
      core::io::writeOutputFile(QDir(dir).filePath(QStringLiteral("index.html")).toStdString(), html, inputs);
  if (!written) return QString::fromStdString(written.error().describe());
  return {};
}

QString writePdfReport(const core::report::Report& report, const core::io::ProjectStore& store, const QString& path,
                       const std::vector<std::string>& inputs, const ReportRenderOptions& options, int* pages) {
  // Refuse before any rendering: the project is never the output.
  if (auto refused = core::io::refuseInputAsOutput(path.toStdString(), inputs); !refused)
    return QString::fromStdString(refused.error().describe());
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  QPdfWriter pdf(&buffer);
  pdf.setResolution(options.dpi);
  pdf.setPageLayout(
      QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(20, 15, 20, 15), QPageLayout::Millimeter));
  pdf.setTitle(QString::fromStdString(report.title));
  pdf.setCreator(QStringLiteral("Mozzi"));

  QTextDocument document;
  // Laid out at the page's width in points (72 per inch), so the text prints at
  // its point size; figures are as wide as the text.
  const QSizeF pagePoints = pdf.pageLayout().paintRect(QPageLayout::Point).size();
  document.setPageSize(pagePoints);
  QFont font = document.defaultFont();
  font.setPointSizeF(9);
  document.setDefaultFont(font);
  std::map<std::string, QImage> images;
  const auto figureSource = [&](const core::report::Figure& f) -> std::string {
    QImage image = renderReportFigure(f, store, options);
    if (image.isNull()) return {};
    const std::string name = "figure:" + f.id;
    document.addResource(QTextDocument::ImageResource, QUrl(QString::fromStdString(name)), image);
    images[name] = std::move(image);
    return name;
  };
  const int width = static_cast<int>(pagePoints.width() * 0.98);
  document.setHtml(QString::fromStdString(core::report::toHtml(report, figureSource, width)));
  document.print(&pdf);
  if (pages) *pages = document.pageCount();
  buffer.close();
  auto written =
      core::io::writeOutputFile(path.toStdString(), std::string_view(bytes.constData(), bytes.size()), inputs);
  if (!written) return QString::fromStdString(written.error().describe());
  return {};
}

}  // namespace views
}  // namespace mozzi
