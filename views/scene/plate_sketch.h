#pragma once
// The specimen and the stiffness rig's plate drawn in the plate's plane
// (thesis §1.2, Figures 15 to 18, 20, 21, 28 to 30): the specimen's
// approximate silhouette (resources/silhouettes), its constrained end, the
// reference plate, the laser spots L1..L4, the load point and the centre of
// gravity where the silhouette has one, each labelled. One drawing for every
// page that shows a plate or a specimen: the Twist Axes page draws its axes
// over it, the Stiffness Rig page's set-up view draws the set-up being edited.
// The sketch places nothing itself: the silhouette is placed by
// core/stiffness/silhouettes.h, the points come from the rig set-up.

#include <QString>
#include <QStringList>
#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/stiffness/silhouettes.h"

class QwtPlot;
class QwtPlotCurve;
class QwtPlotMarker;

namespace mozzi {
namespace views {

// The shipped silhouettes (resources/silhouettes/silhouettes.json), parsed once.
const core::Result<core::stiffness::SilhouetteCatalogue>& silhouetteCatalogue();
// A silhouette's named point ("steering head") in the user's language.
QString silhouettePointName(const std::string& name);

struct PlateSketchInput {
  const core::stiffness::PlacedSilhouette* silhouette = nullptr;  // none: no outline
  std::vector<core::Vector2> laserPoints;                         // [m], plate coordinates
  std::optional<core::Vector2> loadPoint;
  std::vector<core::Vector2> plateOutline;      // the plate's corners (closed when drawn); empty: none
  std::optional<core::Vector2> constrainedEnd;  // instead of the silhouette's
};

class PlateSketch {
 public:
  explicit PlateSketch(QwtPlot* plot);
  ~PlateSketch();
  PlateSketch(const PlateSketch&) = delete;
  PlateSketch& operator=(const PlateSketch&) = delete;

  // Replaces what the sketch drew (the plot is not replotted).
  void draw(const PlateSketchInput& input);
  void clear();

  // The labelled point markers and their labels' vertical alignment, for a
  // page that puts labels on the side towards the view's centre.
  const std::vector<QwtPlotMarker*>& markers() const { return markers_; }
  const std::vector<Qt::Alignment>& markerAlignments() const { return markerAlign_; }
  // Points the view must hold that no autoscaled curve draws.
  const std::vector<core::Vector2>& extent() const { return extent_; }
  QwtPlotCurve* laserCurve() const { return lasers_; }
  QwtPlotCurve* plateCurve() const { return plate_; }
  // Every polygon of the silhouette drawn.
  const std::vector<QwtPlotCurve*>& silhouetteCurves() const { return silhouette_; }

 private:
  QwtPlot* plot_;
  QwtPlotCurve* lasers_ = nullptr;
  QwtPlotCurve* plate_ = nullptr;
  std::vector<QwtPlotCurve*> silhouette_;
  std::vector<QwtPlotMarker*> markers_;
  std::vector<Qt::Alignment> markerAlign_;
  std::vector<core::Vector2> extent_;
};

}  // namespace views
}  // namespace mozzi
