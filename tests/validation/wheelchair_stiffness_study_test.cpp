// Thesis §7.3 and §7.4: effect of the rear-tyre cornering stiffness C_alpha and
// aligning-torque stiffness C_M on the wheelchair's steady turn and slalom.
//
// The thesis's study (§7.2-§7.4): forward speed u held ("the forward speed u
// is constant"), the user's propulsive torques are the input (§7.2, first
// assumption), the radius is an output ("the radius increases", §7.4), and one
// stiffness is changed at a time with the other held. In this model the steady
// balance has a closed form (both rear wheels share v - b r):
//   lateral  -C_alpha (v - b r) S = m u r,   S = 1/(u + r w) + 1/(u - r w)
//   yaw      w dT/R_w = b m u r + C_M m u r/C_alpha
// so r = w dT/(R_w m u (b + k)), k = C_M/C_alpha, and
// alpha_R,L = -m u r/(C_alpha S (u +- r w)). Halving C_alpha with C_M held
// therefore multiplies the slip by 2 (b + k)/(b + 2 k) (times wheel-speed
// factors of order (r w/u)^2), not by 2: the yaw rate falls because the
// aligning torque's share of the yaw balance doubles. The 2% criterion of
// issue 7 holds exactly at a matched path (u, r fixed) and for a whole tyre
// scaled with its pneumatic trail k held; in the thesis's study it holds when
// k <= 0.021 b. docs/validation/tire.md gives the reasoning.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/stability/wheelchair_model.h"

namespace mozzi::core::stability {
namespace {

constexpr double kU = 4.0 / 3.6;     // §7.1 disc speed 4 km/h
constexpr double kTurnTorque = 6.0;  // N m differential: radius 3.4 m, slip about 0.3 deg
// Newton converges to rounding (steps < 1e-14); 1e-9 relative leaves room for
// the conditioning of the 2x2 balance and still catches any modelling slip.
constexpr double kExact = 1e-9;

// The closed form above, written independently of the Newton solver.
struct ClosedForm {
  double r, slipRight, slipLeft, radius;
};
ClosedForm closedForm(const WheelchairParameters& p, double u, double dT) {
  const double m = p.mass, b = p.rearAxleBehindCoM, w = p.rearHalfTrack, Ca = p.rearCorneringStiffness;
  const double r = w * dT / (p.rearWheelRadius * m * u * (b + p.rearAligningStiffness / Ca));
  const double S = 1.0 / (u + r * w) + 1.0 / (u - r * w);
  const double lateral = -m * u * r / (Ca * S);  // v - b r
  return {r, lateral / (u + r * w), lateral / (u - r * w), std::hypot(u, b * r + lateral) / r};
}

void expectClosedForm(const WheelchairParameters& p, const SteadyTurn& s) {
  const ClosedForm c = closedForm(p, s.u, kTurnTorque);
  EXPECT_NEAR(s.r, c.r, kExact * c.r);
  EXPECT_NEAR(s.slipRight, c.slipRight, kExact * std::abs(c.slipRight));
  EXPECT_NEAR(s.slipLeft, c.slipLeft, kExact * std::abs(c.slipLeft));
  EXPECT_NEAR(s.radius, c.radius, kExact * c.radius);
}

WheelchairParameters scaled(WheelchairParameters p, double cornering, double aligning) {
  p.rearCorneringStiffness *= cornering;
  p.rearAligningStiffness *= aligning;
  return p;
}

SteadyTurn turn(const WheelchairParameters& p) {
  auto s = steadyTurn(p, kU, kTurnTorque);
  EXPECT_TRUE(s) << s.error().describe();
  return s ? *s : SteadyTurn{};
}

TEST(WheelchairStiffnessStudy, CorneringStiffnessAloneAtTheUsersTorqueSection73) {
  const WheelchairParameters p;
  auto cases =
      stiffnessSensitivity(p, WheelchairStiffness::Cornering, {0.5, 1.0, 2.0}, kU, kTurnTorque, 3.0, 0.5, 12.0);
  ASSERT_TRUE(cases) << cases.error().describe();
  const auto& half = (*cases)[0].steady;
  const auto& nom = (*cases)[1].steady;
  const auto& dbl = (*cases)[2].steady;
  expectClosedForm(scaled(p, 0.5, 1.0), half);
  expectClosedForm(p, nom);
  expectClosedForm(scaled(p, 2.0, 1.0), dbl);

  // "the radius of the trajectory slightly decreases if the cornering
  // stiffness increases": through r = w dT/(R_w m u (b + C_M/C_alpha)).
  EXPECT_GT(half.radius, nom.radius);
  EXPECT_GT(nom.radius, dbl.radius);
  EXPECT_LT((half.radius - dbl.radius) / nom.radius, 0.2);  // "slightly": under 20% over a factor 4

  // "If the stiffness increases, the slip angles reached at the steady-state decrease."
  EXPECT_GT(std::abs(half.slipRight), std::abs(nom.slipRight));
  EXPECT_GT(std::abs(nom.slipRight), std::abs(dbl.slipRight));

  // "for a value of cornering stiffness equal to the half of the measured
  // value a double slip angle is obtained": here 2 (b + k)/(b + 2 k), the
  // wheel speeds u -+ r w splitting the two wheels by about r w/u = 0.08
  // times the 5% change of r, 0.4% (1% allowed).
  const double k = p.rearAligningStiffness / p.rearCorneringStiffness, b = p.rearAxleBehindCoM;
  const double linear = 2.0 * (b + k) / (b + 2.0 * k);
  const double ratioRight = half.slipRight / nom.slipRight, ratioLeft = half.slipLeft / nom.slipLeft;
  EXPECT_NEAR(ratioRight, linear, 0.01 * linear);
  EXPECT_NEAR(ratioLeft, linear, 0.01 * linear);
  // The shortfall from 2 is exactly the §7.4 effect of doubling C_M: halving
  // C_alpha alone = halving the whole tyre (exactly 2x, next test) and then
  // doubling C_M at that tyre. Both cases have C_M/C_alpha = 2 k, hence the
  // same r and the same wheel speeds, so the identity holds to rounding.
  const SteadyTurn doubleAligning = turn(scaled(p, 1.0, 2.0));
  EXPECT_NEAR(half.slipRight, 2.0 * doubleAligning.slipRight, kExact * std::abs(half.slipRight));
  EXPECT_NEAR(half.slipLeft, 2.0 * doubleAligning.slipLeft, kExact * std::abs(half.slipLeft));
  // With the assumed chair (b = 0.13 m, 7.5 mm pneumatic trail) the shortfall
  // exceeds 2%: the criterion does not hold in the thesis's study
  // for this chair, and the test says so rather than hiding it.
  EXPECT_GT(2.0 - ratioRight, 0.02 * 2.0);
  std::printf(
      "C_alpha halved, C_M held: slip ratio right %.4f left %.4f, 2(b+k)/(b+2k) = %.4f; radius %.4f / %.4f "
      "/ %.4f m\n",
      ratioRight, ratioLeft, linear, half.radius, nom.radius, dbl.radius);

  // The criterion holds in the thesis's study when k/(b + 2 k) <= 1%, i.e.
  // k <= 0.0208 b: a tyre with 1.5% of b as pneumatic trail (2 mm here).
  WheelchairParameters lowTrail = p;
  lowTrail.rearAligningStiffness = 0.015 * b * p.rearCorneringStiffness;
  const double lowRatio = turn(scaled(lowTrail, 0.5, 1.0)).slipRight / turn(lowTrail).slipRight;
  EXPECT_NEAR(lowRatio, 2.0, 0.02 * 2.0);
  EXPECT_LT(lowRatio, 2.0);  // still below 2: the aligning torque always takes a share

  // Slalom (§7.3): "an increase in the stiffness causes a small increase in
  // the amplitude of the trajectory"; "the amplitudes [of slip] decrease".
  EXPECT_LT((*cases)[0].slalom.lateralAmplitude, (*cases)[1].slalom.lateralAmplitude);
  EXPECT_LT((*cases)[1].slalom.lateralAmplitude, (*cases)[2].slalom.lateralAmplitude);
  EXPECT_GT((*cases)[0].slalom.slipAmplitudeRight, (*cases)[1].slalom.slipAmplitudeRight);
  EXPECT_GT((*cases)[1].slalom.slipAmplitudeRight, (*cases)[2].slalom.slipAmplitudeRight);
  // "the right wheel shows a positive mean value, the left wheel shows a
  // negative mean value": alpha_i = (v - b r)/(u -+ r w) divides the same
  // numerator by the faster outer-wheel speed in each half-cycle.
  for (const auto& c : *cases) {
    EXPECT_GT(c.slalom.slipMeanRight, 0.0);
    EXPECT_LT(c.slalom.slipMeanLeft, 0.0);
  }
}

TEST(WheelchairStiffnessStudy, WholeTyreScaledWithItsTrailHalvesSlipExactly) {
  // C_alpha and C_M halved together (pneumatic trail k held): r does not
  // depend on C_alpha, so the wheel speeds are unchanged and alpha = 1/C_alpha
  // exactly. Tolerance kExact: far inside the 2%.
  const WheelchairParameters p;
  auto cases = stiffnessSensitivity(p, WheelchairStiffness::Tyre, {0.5, 1.0, 2.0}, kU, kTurnTorque, 3.0, 0.5, 12.0);
  ASSERT_TRUE(cases) << cases.error().describe();
  const auto& half = (*cases)[0].steady;
  const auto& nom = (*cases)[1].steady;
  const auto& dbl = (*cases)[2].steady;
  expectClosedForm(scaled(p, 0.5, 0.5), half);
  EXPECT_NEAR(half.slipRight / nom.slipRight, 2.0, 2.0 * kExact);
  EXPECT_NEAR(half.slipLeft / nom.slipLeft, 2.0, 2.0 * kExact);
  EXPECT_NEAR(dbl.slipRight / nom.slipRight, 0.5, 0.5 * kExact);
  EXPECT_NEAR(half.r, nom.r, kExact * nom.r);
  // This is not the thesis's §7.3 study: with the yaw rate fixed, the radius
  // of G's path sqrt(u^2 + v^2)/r can only change through v = b r + (v - b r),
  // and it rises (by < 0.1%) as the tyre stiffens, against §7.3's "the radius
  // slightly decreases if the cornering stiffness increases".
  EXPECT_GT(dbl.radius, half.radius);
  EXPECT_LT(dbl.radius / half.radius - 1.0, 1e-3);
  // Nor does its slalom: the lateral amplitude shrinks as the whole tyre
  // stiffens, where §7.3 reports "a small increase in the amplitude".
  EXPECT_GT((*cases)[0].slalom.lateralAmplitude, (*cases)[1].slalom.lateralAmplitude);
  EXPECT_GT((*cases)[1].slalom.lateralAmplitude, (*cases)[2].slalom.lateralAmplitude);
  std::printf("whole tyre halved: slip ratio right %.10f left %.10f; radius %.5f / %.5f / %.5f m\n",
              half.slipRight / nom.slipRight, half.slipLeft / nom.slipLeft, half.radius, nom.radius, dbl.radius);
}

TEST(WheelchairStiffnessStudy, MatchedPathSlipIsLateralForceOverCorneringStiffness) {
  // Same forward speed and yaw rate: the lateral force sum m u r is fixed and
  // the slip angles are F_y/C_alpha, whatever C_M. The torque the user needs
  // for that path changes instead, by (b + 2 k)/(b + k).
  const WheelchairParameters p;
  const double r = closedForm(p, kU, kTurnTorque).r;
  for (const double aligningFactor : {0.0, 1.0, 2.0}) {
    const WheelchairParameters q = scaled(p, 1.0, aligningFactor);
    auto nom = steadyTurnAtYawRate(q, kU, r);
    auto half = steadyTurnAtYawRate(scaled(q, 0.5, 1.0), kU, r);
    ASSERT_TRUE(nom && half);
    EXPECT_NEAR(half->slipRight / nom->slipRight, 2.0, 2.0 * kExact);
    EXPECT_NEAR(half->slipLeft / nom->slipLeft, 2.0, 2.0 * kExact);
    // The lateral forces themselves balance m u r.
    const double fy = -q.rearCorneringStiffness * (nom->slipRight + nom->slipLeft);
    EXPECT_NEAR(fy, q.mass * kU * r, kExact * q.mass * kU * r);
    const double k = q.rearAligningStiffness / q.rearCorneringStiffness, b = q.rearAxleBehindCoM;
    EXPECT_NEAR(half->differentialTorque / nom->differentialTorque, (b + 2.0 * k) / (b + k), kExact);
    // Round trip through the independent Newton solver at the returned torque.
    auto back = steadyTurn(scaled(q, 0.5, 1.0), kU, half->differentialTorque);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->r, r, kExact * r);
    EXPECT_NEAR(back->slipRight, half->slipRight, kExact * std::abs(half->slipRight));
  }
  // And through the time simulation (RK4; after 15 s the slowest mode,
  // time constant about I_z/(m u (b + k)) = 0.5 s, has decayed to e^-29).
  auto onPath = steadyTurnAtYawRate(p, kU, r);
  ASSERT_TRUE(onPath);
  auto h = simulate(p, steadyTurningManoeuvre(kU, onPath->differentialTorque, 0.5, 15.0));
  ASSERT_TRUE(h) << h.error().describe();
  EXPECT_NEAR(h->back().r, r, 1e-6 * r);
  EXPECT_NEAR(h->back().slipLeft, onPath->slipLeft, 1e-6 * std::abs(onPath->slipLeft));
}

TEST(WheelchairStiffnessStudy, AligningStiffnessAloneAtTheUsersTorqueSection74) {
  const WheelchairParameters p;
  auto cases = stiffnessSensitivity(p, WheelchairStiffness::Aligning, {0.5, 1.0, 2.0}, kU, kTurnTorque, 3.0, 0.5, 12.0);
  ASSERT_TRUE(cases) << cases.error().describe();
  expectClosedForm(scaled(p, 1.0, 0.5), (*cases)[0].steady);
  expectClosedForm(scaled(p, 1.0, 2.0), (*cases)[2].steady);
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
  // Weaker than C_alpha on the slip angles: (b + k)/(b + 2 k) per doubling of
  // C_M against about 2 per halving of C_alpha. On r the two are equal (both
  // set C_M/C_alpha = 2 k), so the radius moves alike in both studies.
  const double slipChange = (*cases)[2].steady.slipRight / (*cases)[1].steady.slipRight;
  std::printf("C_M doubled: slip ratio %.4f, radius %.4f -> %.4f m\n", slipChange, (*cases)[1].steady.radius,
              (*cases)[2].steady.radius);
}

}  // namespace
}  // namespace mozzi::core::stability
