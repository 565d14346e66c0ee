#include "core/geometry/animation.h"

#include <cmath>
#include <cstdio>

namespace mozzi::core::geometry {

double animationPhase(double elapsedSeconds, double cyclesPerSecond) {
  constexpr double kTwoPi = 2.0 * M_PI;
  // Wrap the cycle count first so long sessions keep full precision in theta.
  const double cycles = elapsedSeconds * cyclesPerSecond;
  double theta = kTwoPi * (cycles - std::floor(cycles));
  if (!std::isfinite(theta) || theta >= kTwoPi) theta = 0.0;
  return theta;
}

WarpScales warpScales(double amplitude, double theta) {
  return {amplitude * std::sin(theta), amplitude * std::cos(theta)};
}

void deformPoints(const double* base, const double* re, const double* im, Eigen::Index n, WarpScales s, double* out,
                  double* magnitudes) {
  const double a = s.re, b = s.im;
  if (magnitudes) {
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index k = 3 * i;
      const double dx = a * re[k] + b * im[k];
      const double dy = a * re[k + 1] + b * im[k + 1];
      const double dz = a * re[k + 2] + b * im[k + 2];
      out[k] = base[k] + dx;
      out[k + 1] = base[k + 1] + dy;
      out[k + 2] = base[k + 2] + dz;
      magnitudes[i] = std::sqrt(dx * dx + dy * dy + dz * dz);
    }
  } else {
    for (Eigen::Index k = 0; k < 3 * n; ++k) out[k] = base[k] + a * re[k] + b * im[k];
  }
}

void deformPoints(const NodePoints& base, const NodePoints& re, const NodePoints& im, WarpScales s, NodePoints& out,
                  Vector* magnitudes) {
  const Eigen::Index n = base.rows();
  if (out.rows() != n) out.resize(n, 3);
  if (magnitudes && magnitudes->size() != n) magnitudes->resize(n);
  deformPoints(base.data(), re.data(), im.data(), n, s, out.data(), magnitudes ? magnitudes->data() : nullptr);
}

NodePoints realPart(const NodeDisplacements& u) {
  return u.real();
}
NodePoints imagPart(const NodeDisplacements& u) {
  return u.imag();
}

Result<double> autoAmplitude(const NodePoints& base, const NodeDisplacements& u, double fraction) {
  if (!(fraction > 0.0) || !std::isfinite(fraction)) {
    return makeError(ErrorCode::InvalidArgument, "the fraction of the mesh size must be positive", "amplitude");
  }
  if (base.rows() == 0 || base.rows() != u.rows()) {
    return makeError(ErrorCode::InvalidArgument, "the shape and the mesh have different node counts", "amplitude");
  }
  const double diag = (base.colwise().maxCoeff() - base.colwise().minCoeff()).norm();
  if (!(diag > 0.0)) return makeError(ErrorCode::InvalidArgument, "the mesh has no extent", "amplitude");
  const double peak = peakMagnitudes(u).maxCoeff();
  if (!(peak > 0.0) || !std::isfinite(peak)) {
    return makeError(ErrorCode::InvalidArgument, "the shape is zero at every node", "amplitude");
  }
  return fraction * diag / peak;
}

ColourRange colourRange(const NodeDisplacements& u, double amplitude) {
  ColourRange range;
  range.min = 0.0;
  const double peak = u.rows() > 0 ? peakMagnitudes(u).maxCoeff() : 0.0;
  range.max = std::abs(amplitude) * peak;
  if (!(range.max > 0.0) || !std::isfinite(range.max)) range.max = 1.0;  // a still shape: any non-empty range
  return range;
}

Vector colourValues(const NodeDisplacements& u, double amplitude) {
  return std::abs(amplitude) * peakMagnitudes(u);
}

Vector framePhases(int frames) {
  if (frames <= 0) return Vector();
  Vector phases(frames);
  for (int k = 0; k < frames; ++k) phases[k] = 2.0 * M_PI * k / frames;
  return phases;
}

std::string frameFileName(const std::string& stem, int framesPerSecond, int index) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "_%dfps_%04d.png", framesPerSecond, index);
  return stem + buffer;
}

}  // namespace mozzi::core::geometry
