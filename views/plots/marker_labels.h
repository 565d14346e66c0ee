#pragma once
// Labels of point markers (QwtPlotMarker without lines) that stay apart: the
// rectangle a marker's label takes on the canvas, as Qwt places it, and a
// greedy placement that gives each label the first of its candidate spots
// that is on the canvas and clear of the labels placed before it and of the
// marked points. The choice itself works on rectangles alone
// (chooseLabelSpots) and is tested without a plot.

#include <QPointF>
#include <QRectF>
#include <utility>
#include <vector>

class QwtPlot;
class QwtPlotMarker;

namespace mozzi {
namespace views {

// Where `marker` draws its label on the canvas [canvas pixels] when placed at
// plot coordinates `value` with `align` (Qwt's rule for markers without
// lines: beside the symbol, `spacing` away). Empty for an empty label.
QRectF markerLabelRect(const QwtPlot* plot, const QwtPlotMarker* marker, QPointF value, Qt::Alignment align);
// The same where the marker is now.
QRectF markerLabelRect(const QwtPlot* plot, const QwtPlotMarker* marker);
// Visible markers of `plot` with a label whose rectangles intersect.
std::vector<std::pair<const QwtPlotMarker*, const QwtPlotMarker*>> overlappingMarkerLabels(const QwtPlot* plot);

// For each label (in order, the first placed first) the index of its chosen
// candidate: the first inside `bounds` that intersects no rectangle placed
// before and no obstacle; when none is clear, the one overlapping least
// (area, counting what lies outside `bounds`). A label without candidates gets -1.
std::vector<int> chooseLabelSpots(const std::vector<std::vector<QRectF>>& candidates, const QRectF& bounds,
                                  const std::vector<QRectF>& obstacles);

struct LabelSpot {
  QPointF value;  // plot coordinates of the marker
  Qt::Alignment align;
};
struct LabelChoice {
  QwtPlotMarker* marker = nullptr;
  std::vector<LabelSpot> spots;  // in order of preference
};
// Places each marker at its chosen spot (chooseLabelSpots over the canvas;
// the obstacles in canvas pixels). The plot is not replotted.
void placeMarkerLabels(QwtPlot* plot, const std::vector<LabelChoice>& labels, const std::vector<QRectF>& obstacles);

}  // namespace views
}  // namespace mozzi
