// FRF representations against closed forms of a viscous SDOF receptance
// H = 1 / (k - m w^2 + i c w), and the FRF picks, sums (complex and of
// magnitudes) and sub-sets of a set.
#include "core/common/frf_display.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core {
namespace {

FrfMatrix twoByTwo() {
  FrfMatrix f;
  f.frequencyHz = Vector::LinSpaced(5, 1.0, 5.0);
  f.responses = {Dof{1, Direction::Z}, Dof{2, Direction::Z}};
  f.references = {Dof{1, Direction::Z}, Dof{3, Direction::Y}};
  f.type = FrfType::Receptance;
  for (int i = 0; i < 2; ++i) {
    ComplexMatrix h(5, 2);
    for (int k = 0; k < 5; ++k)
      for (int o = 0; o < 2; ++o) h(k, o) = Complex(k + 1, 10 * o + 100 * i);
    f.h.push_back(h);
  }
  return f;
}

TEST(FrfDisplay, RepresentationsOfAnSdofReceptance) {
  const double m = 2.0, k = 8.0e4, c = 12.0;  // fn = 31.8 Hz, zeta = 0.015
  const int n = 400;
  ComplexVector h(n);
  Vector w(n);
  for (int q = 0; q < n; ++q) {
    w[q] = 2 * M_PI * (1.0 + 0.25 * q);
    h[q] = 1.0 / Complex(k - m * w[q] * w[q], c * w[q]);
  }
  const Vector mag = frfViewValues(h, FrfView::MagnitudeLinear);
  const Vector db = frfViewValues(h, FrfView::MagnitudeDb);
  const Vector ph = frfViewValues(h, FrfView::PhaseWrapped);
  const Vector un = frfViewValues(h, FrfView::PhaseUnwrapped);
  const Vector re = frfViewValues(h, FrfView::Real);
  const Vector im = frfViewValues(h, FrfView::Imaginary);
  for (int q = 0; q < n; ++q) {
    const double d = (k - m * w[q] * w[q]) * (k - m * w[q] * w[q]) + c * c * w[q] * w[q];
    EXPECT_NEAR(mag[q], 1.0 / std::sqrt(d), 1e-15);
    EXPECT_NEAR(db[q], -10.0 * std::log10(d), 1e-9);
    EXPECT_NEAR(re[q], (k - m * w[q] * w[q]) / d, 1e-15);
    EXPECT_NEAR(im[q], -c * w[q] / d, 1e-15);
    // Phase of a receptance: atan2(-c w, k - m w^2), from 0 to -180 deg.
    const double phase = std::atan2(-c * w[q], k - m * w[q] * w[q]) * 180.0 / M_PI;
    EXPECT_NEAR(ph[q], phase, 1e-9);
    EXPECT_NEAR(un[q], phase, 1e-9);
  }
  EXPECT_TRUE(frfViewIsLogarithmic(FrfView::MagnitudeLog));
  EXPECT_FALSE(frfViewIsLogarithmic(FrfView::MagnitudeDb));
  EXPECT_TRUE(std::isnan(frfViewValues(h, FrfView::Coherence)[0]));
}

TEST(FrfDisplay, PicksByResponseReferenceAndNode) {
  const FrfMatrix f = twoByTwo();
  EXPECT_EQ(pickFrfs(f, {}).size(), 4u);
  FrfFilter byRef;
  byRef.reference = Dof{3, Direction::Y};
  const auto r = pickFrfs(f, byRef);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].reference, 1);
  FrfFilter byNode;
  byNode.node = 1;  // response 1 (both references) and reference 1 (both responses)
  EXPECT_EQ(pickFrfs(f, byNode).size(), 3u);
  FrfFilter both;
  both.response = Dof{2, Direction::Z};
  both.reference = Dof{1, Direction::Z};
  const auto b = pickFrfs(f, both);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].response, 1);
  EXPECT_EQ(b[0].reference, 0);
}

TEST(FrfDisplay, SumAndSubset) {
  const FrfMatrix f = twoByTwo();
  auto s = frfSum(f, {{0, 0}, {1, 1}});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ((*s)[2], Complex(3, 0) + Complex(3, 110));
  auto sub = frfSubset(f, {{1, 1}});
  ASSERT_TRUE(sub.ok());
  ASSERT_EQ(sub->responseCount(), 1);
  ASSERT_EQ(sub->referenceCount(), 1);
  EXPECT_EQ(sub->responses[0], f.responses[1]);
  EXPECT_EQ(sub->h[0](4, 0), Complex(5, 110));
  auto bad = frfSum(f, {{2, 0}});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("not in the set"), std::string::npos);
  EXPECT_FALSE(frfSum(f, {}).ok());
}

// Two points mirrored about a plane of symmetry, driven on the plane: mode 1
// (10 Hz) moves them alike, mode 2 (25 Hz) in opposition, so their receptances
//   H_o = sum_r phi_o,r / (w_r^2 - w^2 + 2 i zeta w_r w)
// have residues +1, +1 for mode 1 and +1, -1 for mode 2. Mode 2 drops out of
// the complex sum; the sum of magnitudes peaks at both modes.
TEST(FrfDisplay, NoModeCancelsInTheMagnitudeSum) {
  FrfMatrix f;
  const int n = 301;
  f.frequencyHz = Vector::LinSpaced(n, 0.0, 30.0);  // 0.1 Hz lines
  f.responses = {Dof{1, Direction::Y}, Dof{2, Direction::Y}};
  f.references = {Dof{3, Direction::Z}};
  f.type = FrfType::Receptance;
  const double w1 = 2 * M_PI * 10.0, w2 = 2 * M_PI * 25.0, zeta = 0.01;
  ComplexMatrix h(n, 2);
  for (int k = 0; k < n; ++k) {
    const double w = 2 * M_PI * f.frequencyHz[k];
    const Complex m1 = 1.0 / Complex(w1 * w1 - w * w, 2 * zeta * w1 * w);
    const Complex m2 = 1.0 / Complex(w2 * w2 - w * w, 2 * zeta * w2 * w);
    h(k, 0) = m1 + m2;
    h(k, 1) = m1 - m2;
  }
  f.h = {h};
  auto magnitudes = frfMagnitudeSum(f, pickFrfs(f, {}));
  auto complexSum = frfSum(f, pickFrfs(f, {}));
  ASSERT_TRUE(magnitudes.ok() && complexSum.ok());
  for (int k = 0; k < n; ++k) {
    EXPECT_DOUBLE_EQ((*magnitudes)[k], std::abs(h(k, 0)) + std::abs(h(k, 1))) << "line " << k;
  }
  // Lines of the local maxima of each curve above 5 Hz (line k is k / 10 Hz).
  const auto peaksOf = [&](const Vector& y) {
    std::vector<int> at;
    for (int k = 51; k < n - 1; ++k) {
      if (y[k] > y[k - 1] && y[k] >= y[k + 1]) at.push_back(k);
    }
    return at;
  };
  EXPECT_EQ(peaksOf(*magnitudes), (std::vector<int>{100, 250}));
  EXPECT_EQ(peaksOf(complexSum->cwiseAbs()), (std::vector<int>{100}));  // mode 2 is gone
  // At 25 Hz the complex sum is 2 |m1| = 2 / (w2^2 - w1^2), the magnitude sum
  // about 2 |m2| = 1 / (zeta w2^2): (w2^2 - w1^2) / (2 zeta w2^2) = 42 times more.
  EXPECT_NEAR((*magnitudes)[250] / std::abs((*complexSum)[250]), 42.0, 0.5);
  EXPECT_FALSE(frfMagnitudeSum(f, {}).ok());
}

TEST(FrfDisplay, NearestMode) {
  EXPECT_EQ(nearestMode({112.0, 306.9, 596.4}, 300.0), 1);
  EXPECT_EQ(nearestMode({112.0, 306.9, 596.4}, 0.0), 0);
  EXPECT_EQ(nearestMode({}, 10.0), -1);
}

}  // namespace
}  // namespace mozzi::core
