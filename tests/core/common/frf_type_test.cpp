#include "core/common/frf_type.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core {
namespace {

// Analytic check: for x(t) = X e^{i w t}, velocity = i w X and acceleration =
// -w^2 X, so accelerance = -w^2 receptance (thesis eq. 7 read backwards).
TEST(FrfType, ConversionFactorsArePowersOfIOmega) {
  const double w = 2.0 * M_PI * 37.5;
  const auto a2r = frfConversionFactor(FrfType::Accelerance, FrfType::Receptance, w);
  EXPECT_NEAR(a2r.real(), -1.0 / (w * w), 1e-15 / (w * w));
  EXPECT_NEAR(a2r.imag(), 0.0, 1e-15 / (w * w));
  const auto r2m = frfConversionFactor(FrfType::Receptance, FrfType::Mobility, w);
  EXPECT_DOUBLE_EQ(r2m.real(), 0.0);
  EXPECT_DOUBLE_EQ(r2m.imag(), w);
  const auto m2a = frfConversionFactor(FrfType::Mobility, FrfType::Accelerance, w);
  EXPECT_DOUBLE_EQ(m2a.imag(), w);
  // Round trip through every pair is identity.
  for (auto from : {FrfType::Receptance, FrfType::Mobility, FrfType::Accelerance}) {
    for (auto to : {FrfType::Receptance, FrfType::Mobility, FrfType::Accelerance}) {
      const auto roundTrip = frfConversionFactor(from, to, w) * frfConversionFactor(to, from, w);
      EXPECT_NEAR(roundTrip.real(), 1.0, 1e-14);
      EXPECT_NEAR(roundTrip.imag(), 0.0, 1e-14);
    }
  }
}

TEST(FrfType, DivisionAtDcIsFlaggedAsInfinite) {
  EXPECT_TRUE(std::isinf(frfConversionFactor(FrfType::Accelerance, FrfType::Receptance, 0.0).real()));
  EXPECT_EQ(frfConversionFactor(FrfType::Receptance, FrfType::Accelerance, 0.0), std::complex<double>(0.0, 0.0));
}

}  // namespace
}  // namespace mozzi::core
