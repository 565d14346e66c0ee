// Lumped fork models and bicycle-fork stiffness/damping: analytic identities
// (1-DOF relations, series springs, curve intersection) and bad input.
#include "core/stiffness/fork_models.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::stiffness {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

TEST(ForkLumpedModels, OneDofRelationsHold) {
  ForkLumpedInput in{30e3, 0.6, 0.8, 0.3, 10.0, 0.25, 20.0, 0.03};
  const auto m = forkLumpedModels(in);
  ASSERT_TRUE(m.ok()) << m.error().describe();
  // J1 = Jw + M (L1 - hc)^2, f1 = sqrt(k/J1)/2pi.
  EXPECT_NEAR(m->model1.inertia, 0.25 + 10.0 * 0.09, 1e-12);
  EXPECT_NEAR(m->model1.frequencyHz, std::sqrt(30e3 / 1.15) / kTwoPi, 1e-9);
  // Models 2 and 3 reproduce the measured frequency by construction.
  EXPECT_NEAR(m->model2.frequencyHz, 20.0, 1e-9);
  EXPECT_NEAR(m->model3.frequencyHz, 20.0, 1e-9);
  EXPECT_NEAR(m->model2.inertia, 0.25 + 10.0 * 0.25, 1e-12);
  EXPECT_NEAR(m->model3.pureMoment, m->model3.inertia - m->model1.inertia, 1e-15);
  // c = 2 zeta sqrt(k J) equals zeta * critical damping; c / (2 J omega_n) = zeta.
  for (const auto* mm : {&m->model1, &m->model2, &m->model3}) {
    EXPECT_NEAR(mm->damping / (2 * mm->inertia * kTwoPi * mm->frequencyHz), 0.03, 1e-12);
  }
  in.measuredFrequencyHz = 0.0;
  EXPECT_FALSE(forkLumpedModels(in).ok());
  in.measuredFrequencyHz = 20.0;
  in.staticBendStiffness = -1.0;
  EXPECT_FALSE(forkLumpedModels(in).ok());
}

BicycleForkParameters params() {
  return {0.4, 1.3, 0.35, 0.1, 0.005, 0.2, 0.05, 0.46};
}

TEST(BicycleFork, TorsionSeriesAndDamping) {
  const auto p = params();
  const auto t = bicycleForkTorsion(p, 20.0, 0.1, 190.0, 220.0);
  ASSERT_TRUE(t.ok()) << t.error().describe();
  const double iw = 2 * (0.4 / 6) * 0.0025 + 0.5 * 1.3 * 0.1225;
  EXPECT_NEAR(t->inertiaWithWheel, iw, 1e-15);
  EXPECT_NEAR(t->stiffnessWithWheel, std::pow(kTwoPi * 20.0, 2) * iw, 1e-9);
  EXPECT_NEAR(1 / t->stiffnessAlone, 1 / t->stiffnessAloneMode1 + 1 / t->stiffnessAloneMode2, 1e-15);
  // eta = 0.1 -> zeta = 0.05; c / c_c = zeta
  EXPECT_NEAR(t->damping / (2 * std::sqrt(t->stiffnessWithWheel * iw)), 0.05, 1e-12);
  EXPECT_FALSE(seriesStiffness(0.0, 1.0).ok());
  EXPECT_FALSE(bicycleForkTorsion(p, -1.0, 0.1, 190.0).ok());
  auto q = p;
  q.hubLength = 0.0;
  EXPECT_FALSE(bicycleForkTorsion(q, 20.0, 0.1, 190.0).ok());
}

// The bending arm is where the two stiffness curves meet; check against a
// brute-force scan of the curves (independent of the closed form).
TEST(BicycleFork, BendingArmIsTheCurveIntersection) {
  const auto p = params();
  const double fw = 21.0, fa = 64.0;
  const auto b = bicycleForkBending(p, fw, 0.05, fa);
  ASSERT_TRUE(b.ok()) << b.error().describe();
  double best = 1e9, hbest = -1;
  for (int i = 0; i <= 460000; ++i) {
    const double h = i * 1e-6;
    const double diff =
        std::abs(modalStiffness(fw, bendInertiaWithWheel(p, h)) - modalStiffness(fa, bendInertiaForkAlone(p, h)));
    if (diff < best) {
      best = diff;
      hbest = h;
    }
  }
  EXPECT_NEAR(b->bendArm, hbest, 2e-6);  // scan step 1 um
  EXPECT_NEAR(b->stiffness, modalStiffness(fa, bendInertiaForkAlone(p, b->bendArm)), 1e-9 * b->stiffness);
  // Curves that never meet inside [0, 0.46 m]: an error, not an extrapolated arm.
  EXPECT_FALSE(bicycleForkBending(p, 21.0, 0.05, 30.0).ok());
}

// Issue 17: inputs at the edge of the double range (1e308 on any mass,
// length or frequency) overflowed the inertias to inf and dereferenced the
// failed series-stiffness / damping results (bad_variant_access). Now an
// error naming the quantity, or a finite result; never a crash.
TEST(BicycleFork, HugeInputsGiveAnErrorNotACrash) {
  const auto p = params();
  for (double huge : {1e308, 1e200, 1e-300}) {
    for (int field = 0; field < 5; ++field) {
      auto q = p;
      double* targets[] = {&q.forkMass, &q.wheelMass, &q.wheelRadius, &q.tipDistance, &q.hubLength};
      *targets[field] = huge;
      const auto t = bicycleForkTorsion(q, 20.0, 0.1, 190.0, 220.0);
      if (t.ok()) {
        EXPECT_TRUE(std::isfinite(t->stiffnessAlone) && std::isfinite(t->damping)) << field << " " << huge;
      }
      const auto b = bicycleForkBending(q, 30.0, 0.1, 120.0);
      if (b.ok()) {
        EXPECT_TRUE(std::isfinite(b->stiffness) && std::isfinite(b->damping)) << field << " " << huge;
      }
    }
    const auto f = bicycleForkTorsion(p, huge, 0.1, 190.0, 220.0);
    if (f.ok()) {
      EXPECT_TRUE(std::isfinite(f->damping));
    }
    const auto g = bicycleForkTorsion(p, 20.0, 0.1, 190.0, huge);
    if (g.ok()) {
      EXPECT_TRUE(std::isfinite(g->stiffnessAlone));
    }
  }
  const auto lumped = forkLumpedModels({1e308, 0.6, 0.8, 0.3, 1e308, 0.25, 1e308, 0.03});
  if (lumped.ok()) {
    EXPECT_TRUE(std::isfinite(lumped->model3.pureMoment));
  }
}

}  // namespace
}  // namespace mozzi::core::stiffness
