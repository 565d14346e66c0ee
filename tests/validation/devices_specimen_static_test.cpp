// Validation of the virtual specimen catalogue on the simulated Motostiffmeter
// (thesis §1.1): for every specimen with a static test in the thesis, a ramp
// through the driver (load cell noise, lasers quantised to 4 um, 16-bit DAQ)
// processed by core/stiffness's static twist test gives back the printed
// lateral stiffness, twist arm and twist stiffness (Tables 3, 5, 7, 9, 10, 13);
// for the forks also the inclination of the twist axis and, through the fork
// decomposition (eq. 35, 36), the bending and torsion stiffness; for frames
// A, B and the swing-arms the recovered k_tw balances eq. 24 with the printed
// bending and torsion arms and stiffnesses (Tables 4, 7, 9). The expected
// numbers are written out from the tables, not read from the catalogue.
#include <cstdio>

#include <Eigen/LU>

#include "core/stiffness/decomposition.h"
#include "devices_campaign.h"

namespace mozzi::devices {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct StaticExpected {
  const char* key;
  const char* table;
  double kLat;                            // [N/m]
  double arm;                             // [m]; 0 = not printed (Table 5)
  double kTw;                             // [Nm/rad] as printed
  double bendArm, kBend, torsArm, kTors;  // 0 = not printed
  double inclinationDeg;                  // 0 = not printed
};

const StaticExpected kStatics[] = {
    {"frame-a-front-constrained", "Tables 3, 4", 167e3, 0.551, 50.8e3, 0.556, 52.1e3, 0.032, 22.0e3, 0},
    {"frame-b-front-constrained", "Tables 3, 4", 272e3, 0.689, 129e3, 0.553, 138.3e3, 0.298, 60.4e3, 0},
    {"frame-a-rear-constrained", "Tables 3, 4", 253e3, 0.475, 57.0e3, 0.458, 53.5e3, 0.026, 19.6e3, 0},
    {"frame-b-rear-constrained", "Tables 3, 4", 238e3, 0.498, 59.1e3, 0.510, 64.3e3, 0.097, 60.2e3, 0},
    {"frame-c-without-engine", "Table 5", 361e3, 0, 260.2e3, 0, 0, 0, 0, 0},
    {"frame-c-with-engine", "Table 5", 539e3, 0, 414.6e3, 0, 0, 0, 0, 0},
    {"swing-arm-a", "Table 7", 623e3, 0.375, 87.6e3, 0.388, 94.2e3, 0.025, 98.8e3, 0},
    {"swing-arm-b", "Table 9", 1083e3, 0.477, 246.4e3, 0.451, 222.4e3, 0.026, 77.4e3, 0},
    {"fork-a-with-wheel", "Table 10", 56.1e3, 0.517, 15e3, 0.67, 28e3, 0.066, 3e3, 45.5},
    {"fork-b-with-wheel", "Table 13", 109.3e3, 0.452, 22e3, 0.528, 35e3, 0.083, 6e3, 41.2},
};

class SpecimenStatic : public ::testing::TestWithParam<std::size_t> {};

TEST_P(SpecimenStatic, RampGivesBackTheTable) {
  const StaticExpected& t = kStatics[GetParam()];
  auto res = testing::runStaticRamp(testing::StaticRamp{t.key});
  ASSERT_TRUE(res.has_value());
  std::printf("%-26s %-11s k_lat %9.0f N/m (%+.2f%%), a_tw %.4f m, k_tw %8.0f Nm/rad (%+.2f%%), beta %.2f deg\n", t.key,
              t.table, res->lateralStiffness, 100 * (res->lateralStiffness / t.kLat - 1), res->twistArm,
              res->twistStiffness, 100 * (res->twistStiffness / t.kTw - 1), res->axis.axis.beta * 180 / kPi);
  // 1%: the tolerance for frame A; the ramp regression averages the
  // 4 um laser quantisation and the 0.5 N load-cell noise well below it.
  EXPECT_NEAR(res->lateralStiffness / t.kLat, 1.0, 0.01) << t.table;
  if (t.arm > 0) {
    EXPECT_NEAR(res->twistArm / t.arm, 1.0, 0.01) << t.table;
  }
  // k_tw = k_lat a_tw^2 (eq. 30, 32) against the printed value: 1% plus the
  // rounding of the printed inputs (Table 10/13 print k_tw with two digits,
  // 15 and 22 kNm/rad: +/-0.5 kNm/rad = 3.3% and 2.3%).
  const double printedRounding = t.kTw < 30e3 ? 0.5e3 / t.kTw : 0.005;
  EXPECT_NEAR(res->twistStiffness / t.kTw, 1.0, 0.01 + printedRounding) << t.table;

  if (t.inclinationDeg > 0) {
    // Inclination of the twist axis to the fork (Tables 10, 13): 0.5 degrees,
    // the printed precision is 0.1 degrees and the plane fit's beta sigma is
    // a few hundredths of a degree with four lasers.
    const double beta = std::abs(res->axis.axis.beta) * 180 / kPi;
    const double incl = beta > 90 ? 180 - beta : beta;
    EXPECT_NEAR(incl, t.inclinationDeg, 0.5) << t.table;
    core::stiffness::ForkDecompositionInput in;
    in.twistStiffness = res->twistStiffness;
    in.twistArm = res->twistArm;
    in.bendArm = t.bendArm;
    in.torsArm = t.torsArm;
    in.alpha = incl * kPi / 180;
    auto d = core::stiffness::decomposeForkStiffness(in);
    ASSERT_TRUE(d.ok()) << d.error().describe();
    std::printf("  eq. 35-36: k_bend %.1f kNm/rad (printed %.0f), k_tors %.2f kNm/rad (printed %.0f)\n",
                d->bendStiffness / 1e3, t.kBend / 1e3, d->torsStiffness / 1e3, t.kTors / 1e3);
    // The tables print these with one or two digits: k_bend 28 and 35 within
    // 5%, k_tors 3 and 6 kNm/rad (one digit, +/-0.5 = 17% and 8%) within 20%.
    EXPECT_NEAR(d->bendStiffness / t.kBend, 1.0, 0.05) << t.table;
    EXPECT_NEAR(d->torsStiffness / t.kTors, 1.0, 0.20) << t.table;
  } else if (t.bendArm > 0) {
    // Eq. 24: a_tw^2 / k_tw = a_bend^2 / k_bend + a_tors^2 / k_tors with the
    // printed Table 4/7/9 decomposition and the recovered twist; 2% covers
    // the 1% of the recovery and the three-digit printing of six numbers.
    const double lhs = res->twistArm * res->twistArm / res->twistStiffness;
    const double rhs = t.bendArm * t.bendArm / t.kBend + t.torsArm * t.torsArm / t.kTors;
    std::printf("  eq. 24: a_tw^2/k_tw = %.4e, a_b^2/k_b + a_t^2/k_t = %.4e (%+.2f%%)\n", lhs, rhs,
                100 * (lhs / rhs - 1));
    EXPECT_NEAR(lhs / rhs, 1.0, 0.02) << t.table;
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, SpecimenStatic, ::testing::Range<std::size_t>(0, 10),
                         [](const ::testing::TestParamInfo<std::size_t>& i) {
                           std::string n = kStatics[i.param].key;
                           for (auto& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

// Mutual consistency of the modal and static models: the spatial modal
// model's static compliance at the driving point (the static load point),
// sum_r phi_er^2 / w_r^2, is 1/k_lat of the static table, so a static test on
// the modal model gives the same stiffness; the driven square system of the
// hammer station has the same flexibility there (K_y^-1 (0, 0)).
TEST(SpecimenStatic, ModalModelsHaveTheTabulatedStaticCompliance) {
  for (const auto& t : kStatics) {
    auto m = sim::modalSpecimen(t.key);
    ASSERT_TRUE(m.ok());
    const Eigen::Index e = m->excitedDof;
    EXPECT_NEAR(1.0 / m->staticCompliance(e, e) / t.kLat, 1.0, 1e-9) << t.key;
    const auto driven = m->drivenSystem(e);
    const core::Matrix flex = driven.system.stiffness.inverse();
    EXPECT_NEAR(1.0 / flex(0, 0) / t.kLat, 1.0, 1e-9) << t.key;
  }
}

}  // namespace
}  // namespace mozzi::devices
