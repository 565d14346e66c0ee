// Wheelchair model of thesis §7.2 and the stiffness studies of §7.3/§7.4.
#include "core/stability/wheelchair_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace mozzi::core::stability {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kU = 4.0 / 3.6;     // §7.1 disc speed 4 km/h
constexpr double kTurnTorque = 6.0;  // N m differential: radius 3.4 m

TEST(WheelchairSteadyTurn, SimulationSettlesOnTheAlgebraicSteadyState) {
  const WheelchairParameters p;
  auto st = steadyTurn(p, kU, kTurnTorque);
  ASSERT_TRUE(st) << st.error().describe();
  auto h = simulate(p, steadyTurningManoeuvre(kU, kTurnTorque, 0.5, 15.0));
  ASSERT_TRUE(h) << h.error().describe();
  const auto& e = h->back();
  // Two independent routes (Newton on the algebraic balance, RK4 in time);
  // after 15 s the slowest mode (yaw-sideslip, time constant about
  // I_z/(m u (b + k)) = 0.5 s; caster e/u = 0.05 s) has decayed to e^-29.
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

// The closed form of the steady balance and the §7.3/§7.4 stiffness studies:
// tests/validation/wheelchair_stiffness_study_test.cpp.

TEST(WheelchairSteadyTurn, PrescribedYawRateNeedsTheTorqueThatProducesIt) {
  // steadyTurnAtYawRate (closed form) against steadyTurn (Newton on the
  // residuals) at the torque it returns: two routes to the same balance.
  const WheelchairParameters p;
  auto path = steadyTurnAtYawRate(p, kU, 1.0);
  ASSERT_TRUE(path) << path.error().describe();
  auto back = steadyTurn(p, kU, path->differentialTorque);
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->r, 1.0, 1e-9);  // Newton stops at steps below 1e-14
  EXPECT_NEAR(back->v, path->v, 1e-9);
  EXPECT_NEAR(back->radius, path->radius, 1e-9);
  EXPECT_FALSE(steadyTurnAtYawRate(p, kU, kU / p.rearHalfTrack));  // inner wheel stopped
  EXPECT_FALSE(steadyTurnAtYawRate(p, 0.0, 1.0));
  EXPECT_FALSE(steadyTurnAtYawRate(p, kU, NAN));
}

TEST(WheelchairSlalom, SummaryRemovesDriftWithoutTakingAShareOfTheWeave) {
  // y = c0 + c1 t + A sin(wt + 0.4) over two cycles: a straight line fitted
  // alone would absorb about A of the sine's correlation with t; fitted
  // together with the fundamental it leaves A. Sampling every 10 ms at
  // 0.5 Hz misses the peak by at most A (1 - cos(pi f dt)) = 1.2e-4 A.
  const double A = 0.2, f = 0.5, w = 2 * kPi * f;
  std::vector<WheelchairState> h;
  for (int i = 0; i <= 1000; ++i) {
    WheelchairState x;
    x.t = i * 0.01;
    x.y = 0.3 + 0.05 * x.t + A * std::sin(w * x.t + 0.4);
    x.slipRight = 0.01 + 0.002 * std::cos(w * x.t);
    h.push_back(x);
  }
  auto s = summariseSlalom(h, 4.0, f);  // 3 whole cycles, 4 s to 10 s
  ASSERT_TRUE(s) << s.error().describe();
  EXPECT_NEAR(s->lateralAmplitude, A, 2e-4 * A);
  EXPECT_NEAR(s->slipMeanRight, 0.01, 1e-12);  // whole cycles: the cosine averages out
  EXPECT_NEAR(s->slipAmplitudeRight, 0.002, 1e-9);
  EXPECT_FALSE(summariseSlalom(h, 9.5, f));  // less than one cycle left
  EXPECT_FALSE(summariseSlalom(h, 4.0, 0.0));
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
