#pragma once
// Numbers in error messages and reports: short, with enough significant digits
// to recognise the value ("0.0412", "1.67e+05").

#include <sstream>
#include <string>

namespace mozzi::core {

inline std::string formatNumber(double value, int significantDigits = 4) {
  std::ostringstream s;
  s.precision(significantDigits);
  s << value;
  return s.str();
}

}  // namespace mozzi::core
