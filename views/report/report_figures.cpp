#include "views/report/report_figures.h"

namespace mozzi {
namespace views {

const std::map<std::string, FigureRenderer>& figureRenderers() {
  static const std::map<std::string, FigureRenderer> table = {
      {"frf-overlay", renderFrfOverlay},         {"frf-coherence", renderFrfCoherence},
      {"gap-overlay", renderGapOverlay},         {"tyre-steady-state", renderTyreSteadyState},
      {"stabilization", renderStabilization},    {"twist-axes", renderTwistAxes},
      {"tyre-relaxation", renderTyreRelaxation}, {"mesh", renderMesh},
      {"mode-shape", renderModeShape},
  };
  return table;
}

}  // namespace views
}  // namespace mozzi
