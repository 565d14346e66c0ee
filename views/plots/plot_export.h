#pragma once
// One export helper for every plot (WORKBENCH.md "Plots through one adapter"):
// the figure as PNG, or as vector SVG or PDF through QwtPlotRenderer, or the
// plotted data as CSV, chosen by the file's extension. Pages call
// installPlotExportAction() on each QwtPlot they show.

#include <QSizeF>
#include <QString>

class QAction;
class QwtPlot;

namespace mozzi {
namespace views {

struct PlotExportOptions {
  // Size of the figure. Default: the plot's size on screen at 96 dpi.
  QSizeF sizeMm;
  int pngDpi = 192;  // raster resolution (twice a 96-dpi screen)
};

// Writes `plot` to `path`: .png, .svg, .pdf or .csv (case-insensitive).
// CSV: every visible curve's samples as plotted, one x/y column pair per
// curve, a header naming the curve and each axis' title with its unit, shorter
// curves padded with empty cells, numbers with 17 significant digits.
// Returns an empty string on success, else a translated message saying what
// failed (unknown extension, nothing to write, file not writable).
QString exportPlot(QwtPlot* plot, const QString& path, const PlotExportOptions& options = {});

// The CSV text exportPlot writes for `plot`.
QString plotCsv(const QwtPlot* plot);

// One CSV field: quoted (with doubled quotes) when it holds a comma, a quote
// or a line break; as it is otherwise. For pages that export a table.
QString csvField(const QString& text);

// Adds an "Export Plot..." action to the plot's context menu (right click on
// the plot) that asks for a file and calls exportPlot(); returns the action so
// a page can put it on a tool bar too.
QAction* installPlotExportAction(QwtPlot* plot);

}  // namespace views
}  // namespace mozzi
