// Wheelchair model of thesis §7.2 and the stiffness studies of §7.3/§7.4.
#include "core/stability/wheelchair_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace mozzi::core::stability {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kU = 4.0 / 3.6;     // §7.1 disc speed 4 km/h
constexpr double kTurnTorque = 6.0;  // N m differential: radius about 1 m

TEST(WheelchairSteadyTurn, SimulationSettlesOnTheAlgebraicSteadyState) {
  const WheelchairParameters p;
  auto st = steadyTurn(p, kU, kTurnTorque);
  ASSERT_TRUE(st) << st.error().describe();
  auto h = simulate(p, steadyTurningManoeuvre(kU, kTurnTorque, 0.5, 15.0));
  ASSERT_TRUE(h) << h.error().describe();
  const auto& e = h->back();
  // Two independent routes (Newton on the algebraic balance, RK4 in time);
  // after 15 s the slowest mode (caster, e/u ~ 0.05 s; yaw ~ 0.1 s) has
  // decayed far below 1e-6.
  EXPECT_NEAR(e.r, st->r, 1e-6 * std::abs(st->r));
  EXPECT_NEAR(e.v, st->v, 1e-6 * std::abs(st->r));
  EXPECT_NEAR(e.slipRight, st->slipRight, 1e-6 * std::abs(st->slipRight));
  EXPECT_NEAR(e.deltaRight, st->deltaRight, 1e-6);
  EXPECT_NEAR(e.deltaLeft, st->deltaLeft, 1e-6);
  EXPECT_NEAR(e.u, kU, 1e-12);  // speed hold
  std::printf("radius %.3f m, slip R %.3f deg L %.3f deg, casters %.2f / %.2f deg\n", st->radius,
              st->slipRight * 180 / kPi, st->slipLeft * 180 / kPi, st->deltaRight * 180 / kPi,
              st->deltaLeft * 180 / kPi);
  // §7.3: "the values of the slip angles are lesser than 1 deg in most cases".
  EXPECT_LT(std::abs(st->slipRight), 1.0 * kPi / 180);
}

TEST(WheelchairSteadyTurn, MatchesTheLinearClosedFormForGentleTurns) {
  // Small dT: rear-wheel speeds u -+ r w -> u, so
  // r = w dT/R_w / (m u (b + C_M/C_alpha)) (wheelchair_model.h) to O((r w/u)^2).
  const WheelchairParameters p;
  const double dT = 0.05;
  auto st = steadyTurn(p, kU, dT);
  ASSERT_TRUE(st);
  const double r = p.rearHalfTrack * dT / p.rearWheelRadius /
                   (p.mass * kU * (p.rearAxleBehindCoM + p.rearAligningStiffness / p.rearCorneringStiffness));
  EXPECT_NEAR(st->r, r, 1e-4 * r);
}

TEST(WheelchairSteadyTurn, CorneringStiffnessStudyOfSection73) {
  const WheelchairParameters p;
  auto cases =
      stiffnessSensitivity(p, WheelchairStiffness::Cornering, {0.5, 1.0, 2.0}, kU, kTurnTorque, 3.0, 0.5, 12.0);
  ASSERT_TRUE(cases) << cases.error().describe();
  const auto& half = (*cases)[0].steady;
  const auto& nom = (*cases)[1].steady;
  const auto& dbl = (*cases)[2].steady;
  // "the radius of the trajectory slightly decreases if the cornering stiffness increases"
  EXPECT_GT(half.radius, nom.radius);
  EXPECT_GT(nom.radius, dbl.radius);
  EXPECT_LT((half.radius - dbl.radius) / nom.radius, 0.2);  // "slightly"
  // "for a value of cornering stiffness equal to the half of the measured
  // value a double slip angle is obtained". In this model alpha = -m u r/(2 C_alpha)
  // and r falls with C_alpha through the aligning term:
  // ratio = 2 (b + C_M/C_alpha)/(b + 2 C_M/C_alpha) = 1.90 with the assumed
  // b = 0.13 m and C_M/C_alpha = 7.5 mm. Asserted: the ratio follows that
  // closed form within 1% (measured 1.905 right, 1.889 left: the wheel-speed
  // denominators u -+ r w split the wheels) and lies in [1.85, 2.0]. Issue 7
  // asks for 2% of 2, which this model reaches only when C_M/C_alpha < 0.02 b
  // (docs/validation/tire.md).
  const double k = p.rearAligningStiffness / p.rearCorneringStiffness, b = p.rearAxleBehindCoM;
  const double predicted = 2.0 * (b + k) / (b + 2.0 * k);
  for (const double ratio : {half.slipRight / nom.slipRight, half.slipLeft / nom.slipLeft}) {
    EXPECT_NEAR(ratio, predicted, 0.01 * predicted);
    EXPECT_GT(ratio, 1.85);
    EXPECT_LT(ratio, 2.0);
  }
  std::printf("slip ratio (half/nominal) %.4f, closed form %.4f\n", half.slipRight / nom.slipRight, predicted);
  // Without an aligning torque the inverse proportionality is exact to the
  // small-angle order (r w/u)^2 of the wheel-speed denominators: 2%.
  WheelchairParameters noMz = p;
  noMz.rearAligningStiffness = 0.0;
  auto a = steadyTurn(noMz, kU, kTurnTorque);
  noMz.rearCorneringStiffness *= 0.5;
  auto c = steadyTurn(noMz, kU, kTurnTorque);
  ASSERT_TRUE(a && c);
  EXPECT_NEAR(c->slipRight / a->slipRight, 2.0, 0.02 * 2.0);
  // "If the stiffness increases, the slip angles reached at the steady-state decrease."
  EXPECT_GT(std::abs(nom.slipRight), std::abs(dbl.slipRight));
  // Slalom: "an increase in the stiffness causes a small increase in the
  // amplitude of the trajectory"; "if the stiffness increases, the [slip]
  // amplitudes decrease".
  EXPECT_LT((*cases)[0].slalom.lateralAmplitude, (*cases)[1].slalom.lateralAmplitude);
  EXPECT_LT((*cases)[1].slalom.lateralAmplitude, (*cases)[2].slalom.lateralAmplitude);
  EXPECT_GT((*cases)[0].slalom.slipAmplitudeRight, (*cases)[1].slalom.slipAmplitudeRight);
  EXPECT_GT((*cases)[1].slalom.slipAmplitudeRight, (*cases)[2].slalom.slipAmplitudeRight);
  // "the right wheel shows a positive mean value, the left wheel shows a
  // negative mean value": alpha_i = (v - b r)/(u -+ r w) divides the same
  // numerator by the faster wheel speed on the outside of each half-cycle.
  for (const auto& c : *cases) {
    EXPECT_GT(c.slalom.slipMeanRight, 0.0);
    EXPECT_LT(c.slalom.slipMeanLeft, 0.0);
  }
}

TEST(WheelchairSteadyTurn, AligningStiffnessStudyOfSection74) {
  const WheelchairParameters p;
  auto cases = stiffnessSensitivity(p, WheelchairStiffness::Aligning, {0.5, 1.0, 2.0}, kU, kTurnTorque, 3.0, 0.5, 12.0);
  ASSERT_TRUE(cases) << cases.error().describe();
  for (int i = 1; i < 3; ++i) {
    const auto& lo = (*cases)[i - 1];
    const auto& hi = (*cases)[i];
    // "If the value of C_mr increases, the slip angles slightly decrease";
    // "if the self-aligning torque stiffness increases, also the radius of the
    // trajectory increases".
    EXPECT_LT(std::abs(hi.steady.slipRight), std::abs(lo.steady.slipRight));
    EXPECT_GT(hi.steady.radius, lo.steady.radius);
    // "a weaker influence" than the cornering stiffness: under 10% per doubling.
    EXPECT_LT(hi.steady.radius / lo.steady.radius - 1.0, 0.10);
    // Slalom: "the trajectory tends to become slightly tighter".
    EXPECT_LT(hi.slalom.lateralAmplitude, lo.slalom.lateralAmplitude);
  }
}

TEST(WheelchairSimulation, StraightRunningStaysStraight) {
  const WheelchairParameters p;
  Manoeuvre m = steadyTurningManoeuvre(kU, 0.0, 0.0, 3.0);
  auto h = simulate(p, m);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->back().x, 3.0 * kU, 1e-9);
  EXPECT_EQ(h->back().y, 0.0);
  EXPECT_EQ(h->back().r, 0.0);
}

TEST(WheelchairSimulation, BadInputGivesClearErrors) {
  WheelchairParameters p;
  auto still = steadyTurn(p, 0.0, 2.0);
  ASSERT_FALSE(still);
  EXPECT_NE(still.error().message.find("speed"), std::string::npos);
  EXPECT_FALSE(simulate(p, slalomManoeuvre(0.0, 2.0, 0.5, 5.0)));
  WheelchairParameters q = p;
  q.mass = -1;
  auto neg = steadyTurn(q, kU, 2.0);
  ASSERT_FALSE(neg);
  EXPECT_NE(neg.error().message.find("mass"), std::string::npos);
  q = p;
  q.casterAligningStiffness = q.casterTrail * q.casterCorneringStiffness;
  EXPECT_FALSE(validate(q));
  // A turn so tight the inner wheel stops.
  EXPECT_FALSE(steadyTurn(p, kU, 500.0));
}

}  // namespace
}  // namespace mozzi::core::stability
