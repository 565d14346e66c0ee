// One physical mode, one pole (mode_merging.h): the same-mode rules on
// constructed pairs, and the automatic selection on a three-FRF
// roving-hammer-like set at 1 Hz resolution with a resonance at 958 Hz
// narrower than a line (the real case of issue 18, rebuilt from known modes).
#include "core/modal/mode_merging.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/modal/plscf.h"

namespace mozzi::core::modal {
namespace {

ComplexVector shape3(double a, double b, double c) {
  ComplexVector v(3);
  v << a, b, c;
  return v;
}

TEST(ModeMerging, ResolutionIsTheMedianLineSpacing) {
  Vector f = Vector::LinSpaced(2001, 0.0, 2000.0);  // 1 Hz
  EXPECT_DOUBLE_EQ(frequencyResolutionHz(f, 300.0, 1600.0), 1.0);
  f[700] = 700.4;  // one uneven line does not move the median
  EXPECT_DOUBLE_EQ(frequencyResolutionHz(f, 300.0, 1600.0), 1.0);
  EXPECT_EQ(frequencyResolutionHz(f, 5000.0, 6000.0), 0.0);
}

TEST(ModeMerging, PairsCloserThanTheResolutionOrWithTheSameShapeAreOneMode) {
  SameModeCriteria c;
  c.resolutionHz = 1.0;  // 1 Hz lines
  c.macThreshold = 0.98;
  c.frequencyTolerance = 0.01;
  // The real case: 958.42 and 958.58 Hz, 0.16 Hz apart at 1 Hz resolution;
  // shapes deliberately different, the resolution alone decides.
  const ModeCandidate a{958.42, shape3(1, 0.5, -0.2)}, b{958.58, shape3(0.1, 1, 0.7)};
  const SameModePair ab = compareModes(a, b, c);
  EXPECT_EQ(ab.reason, SameModeReason::WithinResolution);
  EXPECT_NEAR(ab.separationHz, 0.16, 1e-9);
  // 3 Hz apart (beyond the resolution, within 1% of 958 Hz) with the same shape.
  const ModeCandidate d{961.42, shape3(1.01, 0.49, -0.2)};
  const SameModePair ad = compareModes(a, d, c);
  EXPECT_EQ(ad.reason, SameModeReason::SameShape);
  EXPECT_GT(ad.mac, 0.99);
  // The same shape 20 Hz away (2%): a different mode seen through 3 DOFs.
  EXPECT_EQ(compareModes(a, ModeCandidate{978.0, a.shape}, c).reason, SameModeReason::Distinct);
  // 3 Hz apart with orthogonal shapes: two close modes, both kept.
  EXPECT_EQ(compareModes(a, ModeCandidate{961.42, shape3(0.2, 0.0, 1.0)}, c).reason, SameModeReason::Distinct);
  const std::string why = describeSameMode(SameModePair{0, 1, ab.separationHz, ab.mac, ab.reason}, {a, b}, c);
  EXPECT_NE(why.find("958.42 Hz and 958.58 Hz"), std::string::npos) << why;
  EXPECT_NE(why.find("resolution (1 Hz)"), std::string::npos) << why;
  // Two poles equal to six digits are told apart with more.
  const ModeCandidate e{958.4201, a.shape}, f{958.4203, a.shape};
  const SameModePair ef = compareModes(e, f, c);
  const std::string close = describeSameMode(SameModePair{0, 1, ef.separationHz, ef.mac, ef.reason}, {e, f}, c);
  EXPECT_NE(close.find("958.4201 Hz and 958.4203 Hz"), std::string::npos) << close;
}

TEST(ModeMerging, KeepsTheBestSupportedPoleOfEachGroup) {
  SameModeCriteria c;
  c.resolutionHz = 1.0;
  // 958.42 / 958.58 / 959.3 chain (pairwise within 1 Hz through the middle one) and 420 Hz alone.
  const std::vector<ModeCandidate> cand = {{420.0, {}}, {958.42, {}}, {958.58, {}}, {959.3, {}}};
  const auto kept = keepOnePerMode(cand, {30, 12, 25, 8}, c);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0], 0u);
  EXPECT_EQ(kept[1], 2u);  // 25 orders, the most of its group

  std::vector<SelectedPole> sel(3);
  sel[0].pole = poleFromFrequencyDamping(420.0, 0.005);
  sel[0].clusterSize = 40;
  sel[1].pole = poleFromFrequencyDamping(958.42, 2e-4);
  sel[1].clusterSize = 20;
  sel[2].pole = poleFromFrequencyDamping(958.58, 2e-4);
  sel[2].clusterSize = 31;
  PlscfOptions opt;
  mergeSameModes(sel, opt, 1.0);
  ASSERT_EQ(sel.size(), 2u);
  EXPECT_NEAR(poleFrequencyHz(sel[1].pole), 958.58, 1e-9);
}

// The real case, rebuilt as a diagram: besides a mode at 420 Hz, two pole
// tracks 0.16 Hz apart at 958.42 and 958.58 Hz, stable from order 10 to 60,
// with shapes too different (MAC 0.5) for the clustering to join them. The
// clustering alone keeps both (the behaviour before); with the resolution rule
// at 1 Hz lines, one, the better supported.
TEST(ModeMerging, SelectPolesMergesTwoTracksWithinOneLine) {
  StabilizationDiagram d;
  d.bandLowHz = 300.0;
  d.bandHighHz = 1600.0;
  d.resolutionHz = 1.0;
  for (int m = 2; m <= 60; ++m) d.orders.push_back(m);
  auto add = [&](int order, double f, double zeta, const ComplexVector& shape) {
    StabilizationPole p;
    p.order = order;
    p.pole = poleFromFrequencyDamping(f, zeta);
    p.frequencyHz = f;
    p.zeta = zeta;
    p.status = PoleStatus::Stable;
    p.shape = shape;
    p.participation = ComplexVector::Ones(1);
    d.poles.push_back(p);
  };
  for (int m = 10; m <= 60; ++m) {
    const double jitter = 1e-4 * ((m * 7) % 5 - 2);  // Hz, a stable track
    add(m, 420.0 + jitter, 0.005, shape3(1, 0.7, 0.2));
    add(m, 958.42 + jitter, 2e-4, shape3(1, 0, 0));
    if (m >= 14) add(m, 958.58 + jitter, 2e-4, shape3(1, 1, 0));  // MAC 0.5 with the other track
  }
  PlscfOptions opt;
  StabilizationDiagram before = d;
  before.resolutionHz = 0.0;
  auto raw = selectPoles(before, opt);
  ASSERT_TRUE(raw.ok()) << raw.error().describe();
  EXPECT_EQ(raw->size(), 3u);  // two modes at 958 Hz without the rule
  auto sel = selectPoles(d, opt);
  ASSERT_TRUE(sel.ok()) << sel.error().describe();
  ASSERT_EQ(sel->size(), 2u);
  EXPECT_NEAR(poleFrequencyHz((*sel)[0].pole), 420.0, 1e-3);
  EXPECT_NEAR(poleFrequencyHz((*sel)[1].pole), 958.42, 1e-3);  // 51 orders against 47
  EXPECT_EQ((*sel)[1].clusterSize, 51);
}

// Three accelerances (roving hammer over 3 points, one accelerometer) at 1 Hz
// resolution: 420 Hz (zeta 0.5%), 958 Hz (zeta 0.02%, half-power width 0.38 Hz,
// under half a line) and 1350 Hz (zeta 0.3%), 0.5% complex noise per line.
FrfMatrix threeFrfSet() {
  const double fn[3] = {420.0, 958.0, 1350.0}, zeta[3] = {0.005, 0.0002, 0.003};
  const double phi[3][3] = {{1.0, 0.6, -0.4}, {0.7, -1.0, 0.3}, {0.2, 0.9, 1.0}};  // [point][mode]
  const double phiRef[3] = {0.8, 0.5, -0.6};                                       // accelerometer
  FrfMatrix f;
  f.frequencyHz = Vector::LinSpaced(2001, 0.0, 2000.0);
  f.type = FrfType::Accelerance;
  for (int p = 0; p < 3; ++p) f.responses.push_back(Dof{p + 1, Direction::Z});
  f.references = {Dof{10, Direction::Z}};
  std::mt19937 rng(958);
  std::normal_distribution<double> nd(0.0, 1.0);
  ComplexMatrix h(2001, 3);
  for (int k = 0; k < 2001; ++k) {
    const double w = 2 * M_PI * f.frequencyHz[k];
    for (int p = 0; p < 3; ++p) {
      Complex s(0.0, 0.0);
      for (int r = 0; r < 3; ++r) {
        const double wr = 2 * M_PI * fn[r];
        s += -w * w * phi[p][r] * phiRef[r] / Complex(wr * wr - w * w, 2 * zeta[r] * wr * w);
      }
      h(k, p) = s * (1.0 + 0.005 * Complex(nd(rng), nd(rng)));
    }
  }
  f.h = {h};
  return f;
}

TEST(ModeMerging, AutomaticSelectionGivesOneModeAtASharp958HzResonance) {
  const FrfMatrix frf = threeFrfSet();
  PlscfOptions opt;
  opt.bandLowHz = 300.0;
  opt.bandHighHz = 1600.0;
  opt.maxOrder = 60;  // the CLI's default
  auto res = identifyPlscf(frf, opt);
  ASSERT_TRUE(res.ok()) << res.error().describe();
  EXPECT_DOUBLE_EQ(res->diagram.resolutionHz, 1.0);
  // What the selection gives without the resolution rule (the old behaviour).
  StabilizationDiagram unmerged = res->diagram;
  unmerged.resolutionHz = 0.0;
  auto raw = selectPoles(unmerged, opt);
  ASSERT_TRUE(raw.ok());
  for (const auto& s : *raw)
    std::printf("without the rule: %.3f Hz (%d orders)\n", poleFrequencyHz(s.pole), s.clusterSize);
  int near958 = 0;
  for (const auto& m : res->model.modes) {
    std::printf("selected %.3f Hz zeta %.6f\n", m.frequencyHz(), m.zeta());
    if (std::abs(m.frequencyHz() - 958.0) < 5.0) ++near958;
  }
  EXPECT_EQ(near958, 1);
  ASSERT_EQ(res->model.modes.size(), 3u);  // no mode missing either
  // Frequencies to a tenth of a line (0.1 Hz).
  EXPECT_NEAR(res->model.modes[0].frequencyHz(), 420.0, 0.1);
  EXPECT_NEAR(res->model.modes[1].frequencyHz(), 958.0, 0.1);
  EXPECT_NEAR(res->model.modes[2].frequencyHz(), 1350.0, 0.1);
}

}  // namespace
}  // namespace mozzi::core::modal
