#pragma once
// The report's stability and wheelchair figures (issues 22, 23), drawn by the
// pages' own plots: "stability-real" and "stability-imaginary" (the Stability
// page's real and imaginary parts of a stored "stability" analysis, critical
// speeds marked) and "wheelchair-trajectory" (the Wheelchair page's trajectory
// plot of a stored "wheelchair" analysis). Figure::recordId is the analysis id.

#include <QString>
#include <memory>
#include <string>

#include "core/io/project_store.h"
#include "core/report/report.h"

class QWidget;
class QwtPlot;

namespace mozzi {
namespace views {

bool isStabilityFigure(const std::string& view);

// The plot to render; `owner` keeps its page alive. nullptr and *error when
// the analysis cannot be read.
QwtPlot* stabilityFigurePlot(const core::report::Figure& figure, const core::io::ProjectStore& store,
                             std::unique_ptr<QWidget>& owner, QString* error);

}  // namespace views
}  // namespace mozzi
