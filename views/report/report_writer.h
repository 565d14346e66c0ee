#pragma once
// Renders a core::report::Report (issue 23): figures drawn by the views' own
// widgets offscreen, HTML as a folder (index.html, each figure as SVG and PNG)
// and PDF through QTextDocument and QPdfWriter at print resolution. The
// content is core's; this file only draws it. Needs a QApplication (the
// offscreen platform is enough). docs/cli/report.md.
//
// Figures: the table of renderers keyed by view name (report_figures.h). A
// figure its view cannot draw here (a 3-D scene without OpenGL) is left as a
// placeholder naming the view. Plots are vector in the HTML report (SVG beside
// the PNG) and raster at `dpi` in the PDF.

#include <QImage>
#include <QRectF>
#include <QString>
#include <string>
#include <vector>

#include "core/io/project_store.h"
#include "core/report/report.h"

class QPainter;
class QwtPlot;

namespace mozzi {
namespace views {

struct ReportRenderOptions {
  int dpi = 300;               // raster figures and the PDF
  double figureWidthMm = 170;  // A4 with 20 mm margins
  double figureHeightMm = 95;
};

// The figure as an image at `options.dpi`; a null image when the figure's view
// cannot render here (then *error says why when given).
QImage renderReportFigure(const core::report::Figure& figure, const core::io::ProjectStore& store,
                          const ReportRenderOptions& options = {}, QString* error = nullptr);

// Draws `plot` into `rect` of `painter` (QwtPlotRenderer, background kept).
void renderPlot(QwtPlot* plot, QPainter& painter, const QRectF& rect);

// Writes `dir`/index.html and the figures (<id>.svg, <id>.png); creates `dir`.
// index.html is never written over one of `inputs` (the project). Returns an
// empty string on success, else what failed.
QString writeHtmlReport(const core::report::Report& report, const core::io::ProjectStore& store, const QString& dir,
                        const std::vector<std::string>& inputs, const ReportRenderOptions& options = {});

// Writes the PDF to `path` (atomically, core::io::writeOutputFile); refused
// when `path` is the same file as one of `inputs` (the project). Returns an
// empty string on success, else what failed. *pages receives the page count.
QString writePdfReport(const core::report::Report& report, const core::io::ProjectStore& store, const QString& path,
                       const std::vector<std::string>& inputs, const ReportRenderOptions& options = {},
                       int* pages = nullptr);

}  // namespace views
}  // namespace mozzi
