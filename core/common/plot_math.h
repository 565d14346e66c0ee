#pragma once
// The numbers behind FRF plots, kept out of the widgets (STYLE 6) so they are
// tested without a display: magnitude in dB, phase in degrees (wrapped or
// unwrapped) and axis ranges that end on round numbers.

#include <vector>

#include <limits>

#include "core/common/eigen_types.h"

namespace mozzi::core {

// 20 log10(|h| / reference) [dB]. Zero magnitude maps to kMagnitudeFloorDb so a
// plot never receives -inf.
inline constexpr double kMagnitudeFloorDb = -400.0;
Vector magnitudeDb(const ComplexVectorRef& h, double reference = 1.0);

// arg(h) in degrees within (-180, 180]; unwrapped, successive lines differ by
// less than 180 degrees (multiples of 360 removed from the second line on).
Vector phaseDegrees(const ComplexVectorRef& h, bool unwrap);

struct AxisRange {
  double lower = 0.0;
  double upper = 1.0;
};

// Range covering [lo, hi] ending on round values: multiples of 1, 2 or 5 times a
// power of ten on a linear axis, decades on a logarithmic one (lo, hi > 0 there).
// A degenerate or non-finite input gives a unit-wide range around the value.
AxisRange roundedRange(double lo, double hi, bool logarithmic);

// Equal aspect (a drawing of a plane: one metre as long across as up): the
// smallest ranges containing x and y, centred on them, whose spans are in the
// ratio widthPx : heightPx of the drawing area. False (ranges untouched) when
// a range is empty or reversed, or a size is not positive.
bool equalAspectRanges(AxisRange& x, AxisRange& y, double widthPx, double heightPx);

// --- Display decimation ---------------------------------------------------------
// A curve of 20,000 lines drawn into 1,000 pixel columns puts 20 samples in
// each column; only the lowest and highest of them are visible. The decimated
// curve keeps, per pixel column of [xLo, xHi] (equal widths in x, or in log10 x
// on a logarithmic axis), the samples holding that column's minimum and
// maximum y, in their original order, plus the last sample left of xLo and the
// first right of xHi so the line runs to the plot's edges. Drawn, it lights the
// same pixel columns over the same y spans as the full curve, with at most
// 2 columns + 2 points. Non-finite y are skipped; x must be ascending.

// First sample of each pixel column (x >= its left edge), and one past the
// last sample <= xHi: columns + 1 entries. Shared by all curves on one x axis.
std::vector<Eigen::Index> pixelColumnStarts(const VectorRef& x, double xLo, double xHi, int columns,
                                            bool logarithmicX = false);

struct DecimatedCurve {
  Vector x, y;
  std::vector<Eigen::Index> index;  // source sample of each point, ascending
};
DecimatedCurve decimateMinMax(const VectorRef& x, const VectorRef& y, const std::vector<Eigen::Index>& columnStarts);
DecimatedCurve decimateMinMax(const VectorRef& x, const VectorRef& y, double xLo, double xHi, int columns,
                              bool logarithmicX = false);

// Colour of a value in [0, 1] on a sequential map for MAC grids: white at 0,
// through yellow and orange, to dark red at 1 (values outside are clamped).
struct Rgb {
  int r = 0, g = 0, b = 0;
};
Rgb heatColour(double value);
// Whether text on that colour should be white (dark background).
bool heatColourIsDark(double value);

// Index of the sample of ascending x nearest to `value` (-1 when x is empty).
Eigen::Index nearestSample(const VectorRef& x, double value);

// Range of the finite y whose x lies in [xLo, xHi] (on a logarithmic axis only
// y > 0 count), padded by `margin` of the span on either side (a factor on a
// logarithmic axis); what autoscale shows. y at `floor` or below does not
// count either: a magnitude in dB passes kMagnitudeFloorDb, the value of a
// zero magnitude, which would stretch the axis down to -400 (a 0 Hz line).
// Empty selection: {0, 1}, or {1, 10}.
AxisRange dataRange(const VectorRef& x, const VectorRef& y, double xLo, double xHi, bool logarithmicY,
                    double margin = 0.05, double floor = -std::numeric_limits<double>::infinity());

}  // namespace mozzi::core
