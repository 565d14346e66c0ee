#include "core/common/frf_type.h"

#include <limits>

#include "core/common/enum_names.h"

namespace mozzi::core {

namespace {
constexpr auto kFrfTypeNames = enumTable<FrfType>(
    {{FrfType::Receptance, "receptance"}, {FrfType::Mobility, "mobility"}, {FrfType::Accelerance, "accelerance"}}, "?");
}  // namespace

const char* frfTypeName(FrfType type) {
  return kFrfTypeNames.of(type);
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
