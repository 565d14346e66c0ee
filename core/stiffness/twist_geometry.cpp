#include "core/stiffness/twist_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mozzi::core::stiffness {

namespace {

double cross2(const Vector2& a, const Vector2& b) {
  return a(0) * b(1) - a(1) * b(0);
}

}  // namespace

PlateAxis plateAxisAt(const Vector2& point, double beta) {
  PlateAxis a;
  a.point = point;
  a.direction = Vector2(std::sin(beta), std::cos(beta));
  a.beta = beta;
  return a;
}

Vector2 footOf(const PlateAxis& axis, const Vector2& p) {
  const double n = axis.direction.squaredNorm();
  if (!(n > 0.0)) return axis.point;
  return axis.point + axis.direction * ((p - axis.point).dot(axis.direction) / n);
}

void PlaneBox::include(const Vector2& p) {
  if (!p.allFinite()) return;
  if (empty()) {
    lower = upper = p;
    return;
  }
  lower = lower.cwiseMin(p);
  upper = upper.cwiseMax(p);
}

void PlaneBox::include(const PlaneBox& b) {
  if (b.empty()) return;
  include(b.lower);
  include(b.upper);
}

PlaneBox PlaneBox::padded(double fraction, double minimum) const {
  if (empty()) return *this;
  const double pad = std::max(fraction * std::max(width(), height()), minimum);
  PlaneBox out = *this;
  out.lower -= Vector2(pad, pad);
  out.upper += Vector2(pad, pad);
  return out;
}

Result<AxisSegment> clipAxis(const PlateAxis& axis, const PlaneBox& box) {
  if (box.empty()) return makeError(ErrorCode::InvalidArgument, "the region to draw in is empty", "clipAxis");
  if (!axis.point.allFinite() || !axis.direction.allFinite() || !(axis.direction.norm() > 0.0))
    return makeError(ErrorCode::InvalidArgument, "the axis has no finite point or direction", "clipAxis");
  // Liang-Barsky: p(t) = point + t d inside lower <= p <= upper.
  const Vector2 d = axis.direction.normalized();
  double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (d(k) == 0.0) {
      if (axis.point(k) < box.lower(k) || axis.point(k) > box.upper(k))
        return makeError(ErrorCode::NotFound, "the axis runs outside the region drawn", "clipAxis");
      continue;
    }
    double a = (box.lower(k) - axis.point(k)) / d(k), b = (box.upper(k) - axis.point(k)) / d(k);
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  const double scale = std::max(box.width(), box.height());
  if (!(t1 - t0 > 1e-12 * scale))
    return makeError(ErrorCode::NotFound, "the axis runs outside the region drawn", "clipAxis");
  return AxisSegment{axis.point + t0 * d, axis.point + t1 * d};
}

Result<Vector2> axisIntersection(const PlateAxis& a, const PlateAxis& b) {
  const Vector2 da = a.direction.normalized(), db = b.direction.normalized();
  const double s = cross2(da, db);  // sin of the angle between them
  if (!std::isfinite(s) || std::abs(s) < 1e-9)
    return makeError(ErrorCode::NumericalFailure, "the two axes are parallel: they do not cross", "axisIntersection");
  // a.point + t da = b.point + r db  =>  t = cross2(b.point - a.point, db) / cross2(da, db)
  const double t = cross2(b.point - a.point, db) / s;
  return Vector2(a.point + t * da);
}

std::vector<Vector2> axisCrossings(const PlateAxis& axis, const std::vector<Vector2>& polygon) {
  std::vector<std::pair<double, Vector2>> hits;
  const std::size_t n = polygon.size();
  if (n < 2 || !(axis.direction.norm() > 0.0)) return {};
  const Vector2 d = axis.direction.normalized();
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2& p = polygon[i];
    const Vector2& q = polygon[(i + 1) % n];
    // Signed distances of the edge's ends from the line; a crossing where
    // they differ in sign (an end on the line counts for the edge it starts).
    const double sp = cross2(p - axis.point, d), sq = cross2(q - axis.point, d);
    if ((sp > 0.0 && sq > 0.0) || (sp < 0.0 && sq < 0.0) || (sp == 0.0 && sq == 0.0)) continue;
    if (sq == 0.0) continue;  // counted by the next edge, which starts there
    const Vector2 x = p + (q - p) * (sp / (sp - sq));
    hits.emplace_back((x - axis.point).dot(d), x);
  }
  std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vector2> out;
  for (const auto& h : hits) out.push_back(h.second);
  return out;
}

std::size_t AxisPath::nearest(double frequencyHz) const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (std::abs(points[i].frequencyHz - frequencyHz) < std::abs(points[best].frequencyHz - frequencyHz)) best = i;
  return best;
}

Result<AxisPath> dynamicAxisPath(const std::vector<AxisAtFrequency>& axes, const Vector2& reference) {
  if (axes.empty()) return makeError(ErrorCode::InvalidArgument, "no dynamic twist axis to trace", "dynamicAxisPath");
  if (!reference.allFinite())
    return makeError(ErrorCode::InvalidArgument, "the reference point is not finite", "dynamicAxisPath");
  AxisPath path;
  path.reference = reference;
  for (const auto& a : axes) {
    const std::string where = "dynamicAxisPath: axis at " + std::to_string(a.frequencyHz) + " Hz";
    if (!std::isfinite(a.frequencyHz)) return makeError(ErrorCode::InvalidArgument, "non-finite frequency", where);
    if (!a.axis.point.allFinite() || !a.axis.direction.allFinite() || !(a.axis.direction.norm() > 0.0))
      return makeError(ErrorCode::InvalidArgument, "the axis has no finite point or direction", where);
    AxisPathPoint p;
    p.frequencyHz = a.frequencyHz;
    p.axis = a.axis;
    p.foot = footOf(a.axis, reference);
    p.arm = (reference - p.foot).norm();
    path.points.push_back(p);
  }
  std::sort(path.points.begin(), path.points.end(),
            [](const AxisPathPoint& a, const AxisPathPoint& b) { return a.frequencyHz < b.frequencyHz; });
  for (std::size_t i = 1; i < path.points.size(); ++i)
    if (path.points[i].frequencyHz == path.points[i - 1].frequencyHz)
      return makeError(ErrorCode::InvalidArgument, "two axes at the same frequency",
                       "dynamicAxisPath: " + std::to_string(path.points[i].frequencyHz) + " Hz");
  return path;
}

}  // namespace mozzi::core::stiffness
