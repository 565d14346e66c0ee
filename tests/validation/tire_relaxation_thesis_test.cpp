// Thesis §5.3-§5.4: Table 16 modal stiffnesses with Table 17 contact patches
// give relaxation lengths (eq. 48-50) with the structure of Fig. 43.
// The thesis prints neither the cornering stiffnesses, nor the tyre masses,
// nor the numbers behind Fig. 43; the assumptions (core/tire/thesis_tyres.h)
// and the range used below are documented in docs/validation/tire.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/tire/relaxation_prediction.h"
#include "core/tire/ring_model.h"
#include "core/tire/thesis_tyres.h"

namespace mozzi::core::tire {
namespace {

constexpr double kPi = 3.14159265358979323846;

RingModel table16Ring(const ThesisTyre& t) {
  auto r = ringModelFromStiffness({{0, t.lateralStiffness, kAssumedDampingRatio},
                                   {1, t.camberStiffness, kAssumedDampingRatio},
                                   {2, t.cShapedStiffness, kAssumedDampingRatio},
                                   {3, t.sShapedStiffness, kAssumedDampingRatio}},
                                  {t.tyreMass, 0.8, t.outerRadius});
  EXPECT_TRUE(r) << r.error().describe();
  return *r;
}

ContactPatchInputs contact(const ThesisTyre& t, double a) {
  return {a, kAssumedNormalisedCorneringStiffness * t.testLoad, t.testLoad, kAssumedFriction, 1.5 * kPi / 180};
}

TEST(ThesisFig43, TwoBarPredictionsLieInTheFigureRange) {
  // Fig. 43 plots predicted and measured sigma of the order of 0.1-0.3 m;
  // range accepted here 0.08-0.35 m (the figure's numbers are not printed).
  for (const auto& t : thesisTyres()) {
    auto p = predictRelaxationLength(table16Ring(t), contact(t, t.halfLength[4]));  // 2 bar
    ASSERT_TRUE(p) << t.size;
    std::printf("%-11s sigma %.4f m = a m %.4f + camber %.4f + lateral %.4f + C %.4f + S %.4f\n", t.size.c_str(),
                p->total(), p->contactPatch, p->camber, p->lateral, p->cShaped, p->sShaped);
    EXPECT_GT(p->total(), 0.08) << t.size;
    EXPECT_LT(p->total(), 0.35) << t.size;
  }
}

TEST(ThesisFig43, TermOrderingStatedInSection54) {
  for (const auto& t : thesisTyres()) {
    auto p = predictRelaxationLength(table16Ring(t), contact(t, t.halfLength[4]));
    ASSERT_TRUE(p);
    // "The most important term related to modal stiffness is the one of the
    // rigid ring camber mode"; "the term due to the lateral mode is much
    // smaller": read as at least 1.9x; Table 16's smallest ratio is
    // 709/360 = 1.97 (130/70-12), so "much" is a factor of about 2 there.
    EXPECT_GT(p->camber, p->lateral) << t.size;
    EXPECT_GT(p->camber, p->cShaped) << t.size;
    EXPECT_GT(p->camber, 1.9 * p->lateral) << t.size;
    // "The contribution of S-shaped mode is very small in all the tested tires."
    EXPECT_LT(p->sShaped, p->lateral) << t.size;
    EXPECT_LT(p->sShaped, p->cShaped) << t.size;
    // "In motorcycle tires the contribution of the C-shaped mode is comparable
    // with the one of the lateral mode, whereas in scooter tires it is a
    // fraction": comparable read as within a factor 2, fraction as < 0.7.
    const double ratio = p->cShaped / p->lateral;
    if (t.radial) {
      EXPECT_GT(ratio, 0.5) << t.size;
      EXPECT_LT(ratio, 2.0) << t.size;
    } else {
      EXPECT_LT(ratio, 0.7) << t.size;
    }
    // "The contribution due to the contact patch is always important": at
    // least a quarter of the total.
    EXPECT_GT(p->contactPatch, 0.25 * p->total()) << t.size;
  }
}

TEST(ThesisFig43, SigmaDecreasesWithPressure) {
  // Table 17's a falls with pressure; with the nominal-pressure modal
  // stiffnesses (the thesis gives no others) sigma falls with it. One entry
  // breaks the trend: 120/70-12 has a = 0.062 m at 0.5 bar and 0.074 m at
  // 0.75 bar, against every other tyre and against §5.4's "a increases by
  // about 50% if inflation pressure decreases from 2 to 0.5 bar" (0.047 ->
  // 0.062 is +32%). That step is asserted as the thesis prints it.
  for (const auto& t : thesisTyres()) {
    const RingModel ring = table16Ring(t);
    std::vector<PressureCase> cases;
    for (std::size_t i = 0; i < kThesisPressures.size(); ++i)
      cases.push_back({kThesisPressures[i], contact(t, t.halfLength[i]), ring});
    auto r = predictOverPressures(cases);
    ASSERT_TRUE(r) << r.error().describe();
    for (std::size_t i = 1; i < r->size(); ++i) {
      const double lo = (*r)[i - 1].prediction.total(), hi = (*r)[i].prediction.total();
      if (t.size == "120/70-12" && i == 1)
        EXPECT_GT(hi, lo) << "thesis Table 17 anomaly no longer reproduced";
      else
        EXPECT_LT(hi, lo) << t.size << " between " << (*r)[i - 1].pressure << " and " << (*r)[i].pressure << " Pa";
    }
    // Contact patch share grows as pressure falls ("small but steady increase").
    EXPECT_GT(r->front().prediction.contactPatch, r->back().prediction.contactPatch) << t.size;
  }
}

TEST(ThesisAppendix1, FirstOrderEqualsTheFrfPhaseAndFullModelDifferenceIsReported) {
  // For each tyre at 2 bar: the sigma implied by the first-order FRF phase
  // equals eq. 48 to 1e-9 m at 0.84-1.68 Hz; with the assumed 3% damping the
  // no-trail model differs by less than 1% (damping enters as
  // zeta w/w_k ~ 1e-3); the full model with a 15 mm trail feeds the aligning
  // torque back through the yaw stiffness C_zz = C_1 r^2 (t_0 C/C_zz ~ 1e-2
  // relative) and stays within 5% (measured -0.9% to -2.4%). Printed for the docs.
  Vector w(3);
  w << 2 * kPi * 0.84, 2 * kPi * 1.26, 2 * kPi * 1.68;
  for (const auto& t : thesisTyres()) {
    const RingModel ring = table16Ring(t);
    const ContactPatchInputs cp = contact(t, t.halfLength[4]);
    auto p = predictRelaxationLength(ring, cp);
    ASSERT_TRUE(p);
    RingFrfInputs in{5.0 / 3.6, cp.halfLength, p->contactPatch, cp.corneringStiffness, 0.015};
    auto first = impliedRelaxationLength(ring, in, w, RingFrfVariant::FirstOrder);
    auto noTrail = impliedRelaxationLength(ring, in, w, RingFrfVariant::NoTrail);
    auto full = impliedRelaxationLength(ring, in, w, RingFrfVariant::Full);
    ASSERT_TRUE(first && noTrail && full);
    for (Eigen::Index i = 0; i < w.size(); ++i) {
      EXPECT_NEAR(first->sigma[i], p->total(), 1e-9) << t.size;
      ASSERT_TRUE(noTrail->valid[static_cast<std::size_t>(i)] && full->valid[static_cast<std::size_t>(i)]);
      EXPECT_LT(std::abs(noTrail->sigma[i] / p->total() - 1), 0.01) << t.size;
      EXPECT_LT(std::abs(full->sigma[i] / p->total() - 1), 0.05) << t.size;
    }
    std::printf("%-11s first-order %.4f m, no trail %+.2f%%, full (t0 15 mm) %+.2f%% at 1.26 Hz\n", t.size.c_str(),
                p->total(), 100 * (noTrail->sigma[1] / p->total() - 1), 100 * (full->sigma[1] / p->total() - 1));
  }
}

TEST(ThesisTable17, HalfLengthChangesQuotedInSection54) {
  // "a increases by about 50% if inflation pressure decreases from 2 to 0.5
  // bar. If inflation pressure doubles, a decreases by about 15-20%."
  // Checked over the table: +32%..+77% (0.5 bar) and -7%..-24% (4 bar) are the
  // printed extremes; the stated "about" values hold on average.
  double up = 0, down = 0;
  for (const auto& t : thesisTyres()) {
    up += (t.halfLength[0] / t.halfLength[4] - 1) / 6;
    down += (1 - t.halfLength[6] / t.halfLength[4]) / 6;
  }
  EXPECT_NEAR(up, 0.50, 0.10);
  EXPECT_NEAR(down, 0.175, 0.06);
}

TEST(ThesisTable16, AssumedMassesGiveTheFrequenciesOfSection52) {
  // §5.2 (110/70-16): lateral mode ("second peak") about 100 Hz, C-shaped
  // ("third peak") about 170 Hz. With the assumed 3.5 kg tyre and 80% belt,
  // eq. 45-46 inverted give 103 Hz and 183 Hz: within 10% of the quoted values.
  const ThesisTyre& t = thesisTyres()[2];
  const RingModel ring = table16Ring(t);
  EXPECT_NEAR(ring.mode(0)->naturalFrequencyHz, 100.0, 10.0);
  EXPECT_NEAR(ring.mode(2)->naturalFrequencyHz, 170.0, 17.0);
}

}  // namespace
}  // namespace mozzi::core::tire
