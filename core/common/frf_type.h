#pragma once
// FRF H(omega) = response / reference with its type kept beside the data.
// Receptance [m/N], mobility [m/s/N], accelerance [m/s^2/N]; from receptance the
// others follow by multiplying by (i omega)^n, n = 1, 2 (thesis eq. 7 is the
// accelerance-to-receptance case, division by (i omega)^2 = -omega^2).

#include <complex>

namespace mozzi::core {

enum class FrfType { Receptance = 0, Mobility = 1, Accelerance = 2 };

const char* frfTypeName(FrfType type);  // "receptance", "mobility", "accelerance"

// Power of (i omega) that takes receptance to this type.
inline int frfTypeOrder(FrfType type) {
  return static_cast<int>(type);
}

// Factor that converts a value of type `from` into type `to` at angular
// frequency omega [rad/s]: (i omega)^(order(to) - order(from)). At omega = 0 a
// division is undefined; callers must skip the DC line (the factor is then inf).
std::complex<double> frfConversionFactor(FrfType from, FrfType to, double omega);

}  // namespace mozzi::core
