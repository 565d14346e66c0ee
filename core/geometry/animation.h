#pragma once
// Mode-shape animation numerics (STYLE 12, WORKBENCH "What is drawn is
// testable"): the phase from elapsed time, the two warp scales of a phase, the
// deformed points, the amplitude that makes a shape visible, the colour range
// and the names of exported frames. The 3-D view builds its geometry and the
// shape arrays once and calls these per tick.
//
// A node with complex displacement u moves as
//   x(theta) = x0 + A Im(u e^{i theta}) = x0 + A (Re(u) sin(theta) + Im(u) cos(theta)),
// so a real mode goes as A u sin(theta) and each component of a complex mode
// lags by its own phase arg(u).

#include <string>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/geometry/mode_shape.h"

namespace mozzi::core::geometry {

// theta = 2 pi f t, wrapped to [0, 2 pi); f [cycles/s] is the animation speed
// (not the mode's frequency), t [s] the elapsed time.
double animationPhase(double elapsedSeconds, double cyclesPerSecond);

// (sin-scale on Re u, cos-scale on Im u) = (A sin theta, A cos theta).
struct WarpScales {
  double re = 0.0;
  double im = 0.0;
};
WarpScales warpScales(double amplitude, double theta);

// out = base + s.re Re(u) + s.im Im(u), and |out - base| per node into
// `magnitudes` when not null. `re`, `im` are the parts of u split once
// (n x 3, row major, same layout as NodePoints). `out` must have n rows.
void deformPoints(const NodePoints& base, const NodePoints& re, const NodePoints& im, WarpScales s, NodePoints& out,
                  Vector* magnitudes = nullptr);
// Raw-buffer form for views that own their point arrays (n points, 3 doubles each).
void deformPoints(const double* base, const double* re, const double* im, Eigen::Index n, WarpScales s, double* out,
                  double* magnitudes = nullptr);

// Re and Im parts of a field as NodePoints.
NodePoints realPart(const NodeDisplacements& u);
NodePoints imagPart(const NodeDisplacements& u);

// The amplitude A that makes the largest peak displacement `fraction` of the
// mesh's bounding-box diagonal (a visible but not absurd deformation). A
// shape that is zero everywhere, or a mesh with no extent, is an error.
Result<double> autoAmplitude(const NodePoints& base, const NodeDisplacements& u, double fraction = 0.1);

// Colour range of the displacement magnitude at amplitude A: [0, A max peak].
struct ColourRange {
  double min = 0.0;
  double max = 1.0;
};
ColourRange colourRange(const NodeDisplacements& u, double amplitude);

// The value each node is coloured by: its peak displacement over a cycle at
// amplitude A, |A| max_theta |Re(u) sin(theta) + Im(u) cos(theta)| [m]
// (peakMagnitudes in mode_shape.h), spanning colourRange(). It does not change
// with the phase, so a view computes it (and its colours) once per shape and
// amplitude, and a tick only moves the points.
Vector colourValues(const NodeDisplacements& u, double amplitude);

// Phases of an exported cycle: theta_k = 2 pi k / frames, k = 0..frames-1.
Vector framePhases(int frames);
// "<stem>_<fps>fps_<index, zero-padded to 4>.png", e.g. "mode-2_25fps_0007.png".
std::string frameFileName(const std::string& stem, int framesPerSecond, int index);

}  // namespace mozzi::core::geometry
