#pragma once
// The figures of a report (issue 23): one renderer per view name, in one
// table. A renderer builds the view's own widget offscreen for the Figure's
// record and hands back what draws it: a QwtPlot (vector through
// QwtPlotRenderer: SVG in the HTML report) or a raster image (the 3-D scene,
// read from VTK's render buffer). Add a figure kind by adding a row to
// figureRenderers() (report_figures.cpp).

#include <QImage>
#include <QString>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/io/project_store.h"
#include "core/report/report.h"

class QObject;
class QwtPlot;

namespace mozzi {
namespace views {

struct ReportRenderOptions;

// What draws one figure. `keep` owns the widgets until the figure is drawn.
struct FigureDrawing {
  std::vector<std::unique_ptr<QObject>> keep;
  QwtPlot* plot = nullptr;  // vector figure
  QImage image;             // raster figure (when plot is null)
  bool ok() const { return plot != nullptr || !image.isNull(); }
};

struct FigureRequest {
  const core::report::Figure& figure;
  const core::io::ProjectStore& store;
  const ReportRenderOptions& options;
};

// Fills `out` and returns true, or returns false with *error saying why.
using FigureRenderer = std::function<bool(const FigureRequest&, FigureDrawing& out, QString* error)>;

// View name -> renderer.
const std::map<std::string, FigureRenderer>& figureRenderers();

// The renderers, by file: report_figures_plots.cpp (plots) and report_figures_pages.cpp (pages, 3-D scene).
bool renderFrfOverlay(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderFrfCoherence(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderGapOverlay(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderTyreSteadyState(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderStabilization(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderTwistAxes(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderTyreRelaxation(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderMesh(const FigureRequest& request, FigureDrawing& out, QString* error);
bool renderModeShape(const FigureRequest& request, FigureDrawing& out, QString* error);

}  // namespace views
}  // namespace mozzi
