// Distribution functions and Holm's correction against published tables and
// the procedure's definition.
#include "core/gap/engine/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::gap {
namespace {

TEST(EngineStatistics, ChiSquareQuantilesMatchTables) {
  // Abramowitz and Stegun, Table 26.8 (percentage points of the chi-square
  // distribution), printed to 4-5 significant digits: tolerance 1e-3.
  struct Row {
    double p, dof, x;
  };
  const Row rows[] = {{0.95, 1, 3.8415},  {0.95, 2, 5.9915},   {0.95, 5, 11.0705}, {0.95, 10, 18.3070},
                      {0.99, 1, 6.6349},  {0.99, 10, 23.2093}, {0.05, 10, 3.9403}, {0.5, 3, 2.3660},
                      {0.999, 1, 10.828}, {0.95, 100, 124.342}};
  for (const auto& r : rows) {
    EXPECT_NEAR(chiSquareQuantile(r.p, r.dof), r.x, 1e-3) << "p " << r.p << " dof " << r.dof;
    EXPECT_NEAR(chiSquareSurvival(r.x, r.dof), 1.0 - r.p, 2e-5) << "p " << r.p << " dof " << r.dof;
  }
  // Closed forms: dof 2 is exponential, P(X > x) = exp(-x / 2).
  EXPECT_NEAR(chiSquareSurvival(3.0, 2.0), std::exp(-1.5), 1e-14);
  EXPECT_NEAR(normalQuantile(0.975), 1.959963985, 1e-8);
  EXPECT_NEAR(normalQuantile(0.025), -1.959963985, 1e-8);
  EXPECT_NEAR(normalTwoSidedP(1.959963985), 0.05, 1e-9);
}

TEST(EngineStatistics, HolmStepsDownAndStopsAtTheFirstAcceptance) {
  // Sorted: 0.005 <= 0.05/4 reject; 0.01 <= 0.05/3 reject; 0.03 > 0.05/2 stop,
  // so 0.04 is kept although 0.04 <= 0.05 / 1.
  const auto r = holmReject({0.01, 0.04, 0.03, 0.005}, 0.05);
  EXPECT_EQ(r, (std::vector<bool>{true, false, false, true}));
  EXPECT_EQ(holmReject({0.001, 0.002}, 0.05), (std::vector<bool>{true, true}));
  EXPECT_TRUE(holmReject({}, 0.05).empty());
}

TEST(EngineStatistics, HolmFlagsEachKindSeparately) {
  GapMetrics m;
  // Bands: z = 3 (p = 0.0027 <= 0.05 / 2) rejected, then z = 2.2 (p = 0.028
  // <= 0.05 / 1) rejected too.
  m.entries = {{"band", "a", 1, 3.0, false, false, {}},
               {"band", "b", 1, 2.2, false, false, {}},
               {"mode", "1", 1, 2.2, false, false, {}},
               {"mode", "2", 1, 0.1, false, false, {}},
               {"dof", "1+Z", 1, 0.0, true, false, {}},
               // One-sided (a chi-square excess): z = -3 is better than
               // noise, no gap (p = 0.9987); z = 3 alone: p = 0.00135 <= 0.05.
               {"condition", "lo", 1, -3.0, false, true, {}},
               {"overall", "hi", 1, 3.0, false, true, {}}};
  applyHolmFlags(m, 0.05);
  EXPECT_TRUE(m.entries[0].flagged);
  EXPECT_TRUE(m.entries[1].flagged);
  // Modes: smallest p = 0.028 > 0.05 / 2: nothing rejected.
  EXPECT_FALSE(m.entries[2].flagged);
  EXPECT_FALSE(m.entries[3].flagged);
  // No z-score: the problem's own flag stands.
  EXPECT_TRUE(m.entries[4].flagged);
  EXPECT_FALSE(m.entries[5].flagged);
  EXPECT_TRUE(m.entries[6].flagged);
}

TEST(EngineStatistics, EmpiricalQuantileInterpolates) {
  EXPECT_DOUBLE_EQ(empiricalQuantile({4, 1, 3, 2, 5}, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(empiricalQuantile({1, 2, 3, 4, 5}, 0.9), 4.6);  // h = 3.6
  EXPECT_TRUE(std::isnan(empiricalQuantile({}, 0.5)));
}

}  // namespace
}  // namespace mozzi::core::gap
