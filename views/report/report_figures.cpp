#include "views/report/report_figures.h"

#include <QWidget>

#include "views/report/stability_figures.h"

namespace mozzi {
namespace views {
namespace {

// The stability and wheelchair figures (stability_figures.h) as rows of the table.
bool renderStabilityFigure(const FigureRequest& r, FigureDrawing& out, QString* error) {
  std::unique_ptr<QWidget> owner;
  QwtPlot* plot = stabilityFigurePlot(r.figure, r.store, owner, error);
  if (!plot) return false;
  out.plot = plot;
  out.keep.push_back(std::move(owner));
  return true;
}

}  // namespace

const std::map<std::string, FigureRenderer>& figureRenderers() {
  static const std::map<std::string, FigureRenderer> table = {
      {"frf-overlay", renderFrfOverlay},
      {"frf-coherence", renderFrfCoherence},
      {"gap-overlay", renderGapOverlay},
      {"tyre-steady-state", renderTyreSteadyState},
      {"stabilization", renderStabilization},
      {"twist-axes", renderTwistAxes},
      {"tyre-relaxation", renderTyreRelaxation},
      {"mesh", renderMesh},
      {"mode-shape", renderModeShape},
      {"stability-real", renderStabilityFigure},
      {"stability-imaginary", renderStabilityFigure},
      {"wheelchair-trajectory", renderStabilityFigure},
  };
  return table;
}

}  // namespace views
}  // namespace mozzi
