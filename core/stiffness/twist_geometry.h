#pragma once
// Geometry of twist axes in the plane of the component, for drawing them over
// its silhouette (thesis §1.2, §1.3; Figures 15 to 18, 20, 21 and 29): a
// stored axis back into PlateAxis form, the segment of an axis inside the
// drawn region, where two axes cross, where an axis crosses an outline, the
// path the dynamic twist axis traces as the excitation frequency changes, and
// the equal-aspect region a plot of the plane shows.
//
// Plate coordinates and the PlateAxis convention as in plate_motion.h:
// (u, v) in the plate plane [m], beta the angle from the v axis towards u,
// direction (sin beta, cos beta).

#include <cstddef>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/stiffness/plate_motion.h"

namespace mozzi::core::stiffness {

// The axis through `point` inclined by `beta` from the v axis towards u [rad]
// (the stored "axis_point_u", "axis_point_v", "axis_inclination" of a rig test).
PlateAxis plateAxisAt(const Vector2& point, double beta);

// Foot of the perpendicular from p on the axis (the point of the axis nearest p).
Vector2 footOf(const PlateAxis& axis, const Vector2& p);

// An axis-aligned region of the plate plane [m].
struct PlaneBox {
  Vector2 lower = Vector2(1.0, 1.0);  // empty until a point is included
  Vector2 upper = Vector2(-1.0, -1.0);
  bool empty() const { return !(lower(0) <= upper(0) && lower(1) <= upper(1)); }
  void include(const Vector2& p);
  void include(const PlaneBox& b);
  double width() const { return empty() ? 0.0 : upper(0) - lower(0); }
  double height() const { return empty() ? 0.0 : upper(1) - lower(1); }
  // Grown on every side by `fraction` of the larger side, at least `minimum` [m].
  PlaneBox padded(double fraction, double minimum) const;
};

// The part of the axis inside the box, `from` on the -direction side, `to` on
// the +direction side (Liang-Barsky clipping). Errors: an empty box, a line
// that misses the box or only touches a corner.
struct AxisSegment {
  Vector2 from = Vector2::Zero();
  Vector2 to = Vector2::Zero();
};
Result<AxisSegment> clipAxis(const PlateAxis& axis, const PlaneBox& box);

// Where two axes cross. Error when they are parallel (|sin| of the angle
// between them below 1e-9): no crossing, or the same line.
Result<Vector2> axisIntersection(const PlateAxis& a, const PlateAxis& b);

// The points where the axis line crosses the edges of a closed polygon
// (vertices in order, the last joined to the first), ordered along the
// axis direction. Empty when the line misses the polygon.
std::vector<Vector2> axisCrossings(const PlateAxis& axis, const std::vector<Vector2>& polygon);

// The dynamic twist axis against frequency (thesis §1.3, Fig. 29): the axes at
// the excitation frequencies, sorted by frequency, each with the foot of the
// perpendicular from `reference` (the load point): the trace the axis leaves
// as it moves. The twist arm at each frequency is |reference - foot|.
struct AxisPathPoint {
  double frequencyHz = 0.0;
  PlateAxis axis;
  Vector2 foot = Vector2::Zero();
  double arm = 0.0;  // |reference - foot| [m]
};
struct AxisPath {
  Vector2 reference = Vector2::Zero();
  std::vector<AxisPathPoint> points;  // ascending frequency
  // Index of the point whose frequency is nearest `frequencyHz` (0 when empty).
  std::size_t nearest(double frequencyHz) const;
};
struct AxisAtFrequency {
  double frequencyHz = 0.0;
  PlateAxis axis;
};
// Errors: no axes, a non-finite frequency, point or direction, a zero
// direction, two axes at the same frequency.
Result<AxisPath> dynamicAxisPath(const std::vector<AxisAtFrequency>& axes, const Vector2& reference);

}  // namespace mozzi::core::stiffness
