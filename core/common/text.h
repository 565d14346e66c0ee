#pragma once
// Numbers in error messages and reports: short, with enough significant digits
// to recognise the value ("0.0412", "1.67e+05").

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace mozzi::core {

inline std::string formatNumber(double value, int significantDigits = 4) {
  std::ostringstream s;
  s.precision(significantDigits);
  s << value;
  return s.str();
}

// A measured value and its standard uncertainty as a reader takes them in:
// the uncertainty to two significant digits and the value to the same decimal
// place (GUM, JCGM 100:2008 7.2.6): 55996.04 +- 6.1756 -> "55996.0", "6.2";
// 121337 +- 3421 -> "121300", "3400". Where that place is beyond 1e-9 or
// 1e9, or the value beyond 1e15, both in 5 and 2 significant digits
// ("3e-17", "1e-18") rather than a row of zeros or a cut string. Without a
// positive, finite uncertainty: the value alone to 5 significant digits and an
// empty uncertainty.
struct MeasuredText {
  std::string value, uncertainty;
};
inline MeasuredText formatMeasured(double value, double uncertainty) {
  if (!(uncertainty > 0.0) || !std::isfinite(uncertainty) || !std::isfinite(value)) return {formatNumber(value, 5), {}};
  // Decimal places of the uncertainty's second significant digit (negative:
  // tens, hundreds ...), taken after rounding (9.96 rounds to 10, not 9.96).
  int places = 1 - static_cast<int>(std::floor(std::log10(uncertainty)));
  const double rounded = std::round(uncertainty * std::pow(10.0, places)) / std::pow(10.0, places);
  places = 1 - static_cast<int>(std::floor(std::log10(rounded)));
  if (places > 9 || places < -9 || std::abs(value) >= 1e15) return {formatNumber(value, 5), formatNumber(rounded, 2)};
  const double unit = std::pow(10.0, -places);
  double shown = std::round(value / unit) * unit;
  if (shown == 0.0) shown = 0.0;  // no "-0.0"
  char v[64], u[64];
  std::snprintf(v, sizeof v, "%.*f", std::max(places, 0), shown);
  std::snprintf(u, sizeof u, "%.*f", std::max(places, 0), rounded);
  return {v, u};
}

}  // namespace mozzi::core
