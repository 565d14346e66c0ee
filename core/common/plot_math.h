#pragma once
// The numbers behind FRF plots, kept out of the widgets (STYLE 6) so they are
// tested without a display: magnitude in dB, phase in degrees (wrapped or
// unwrapped) and axis ranges that end on round numbers.

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

}  // namespace mozzi::core
