#include "core/common/frf_type.h"

#include <limits>

namespace mozzi::core {

const char* frfTypeName(FrfType type) {
  switch (type) {
    case FrfType::Receptance: return "receptance";
    case FrfType::Mobility: return "mobility";
    case FrfType::Accelerance: return "accelerance";
  }
  return "?";
}

std::complex<double> frfConversionFactor(FrfType from, FrfType to, double omega) {
  const int n = frfTypeOrder(to) - frfTypeOrder(from);
  if (n == 0) return {1.0, 0.0};
  if (omega == 0.0) {
    if (n > 0) return {0.0, 0.0};
    return {std::numeric_limits<double>::infinity(), 0.0};
  }
  const std::complex<double> iw(0.0, omega);
  std::complex<double> factor(1.0, 0.0);
  for (int k = 0; k < (n > 0 ? n : -n); ++k) factor *= iw;
  return n > 0 ? factor : 1.0 / factor;
}

}  // namespace mozzi::core
