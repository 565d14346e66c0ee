#pragma once
// Renders a core::report::Report (issue 23): figures drawn by the views' own
// widgets offscreen, HTML as a folder (index.html, each figure as SVG and PNG)
// and PDF through QTextDocument and QPdfWriter at print resolution. The
// content is core's; this file only draws it. Needs a QApplication (the
// offscreen platform is enough). docs/cli/report.md.
//
// Figures rendered today: "frf-overlay" (views/plots FrfPlot, every FRF of the
// set, magnitude); "stability-real", "stability-imaginary", "wheelchair-trajectory"
// (stability_figures.h). Others ("gap-overlay" outside the Model vs Test page) are
// left as a placeholder naming the view.

#include <QImage>
#include <QString>
#include <string>
#include <vector>

#include "core/io/project_store.h"
#include "core/report/report.h"

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
