// Stability-mode frequency gap problem (core/gap/stability): the baseline is
// the rigid-fork model of core/stability; the fork and tyre effects move the
// weave and wobble frequencies; folds are speed ranges; the file parsers.
#include "core/gap/stability/stability_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/gap/diagnosis.h"
#include "core/stability/mode_tracking.h"

namespace mozzi::core::gap {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;
const std::string kSharp = std::string(MOZZI_SHARED_DATA_DIR) + "/motorcycle/sharp1971-parameters.csv";

StabilityGapModel motorcycleModel() {
  auto m = parseStabilityGapModel(
      R"({"schema": "mozzi-stability-gap/1", "vehicle": "motorcycle", "parameters": ")" + kSharp + "\"}", "test", "");
  EXPECT_TRUE(m) << m.error().describe();
  return *m;
}

StabilityGapModel bicycleModel() {
  auto m = parseStabilityGapModel(R"({"schema": "mozzi-stability-gap/1", "vehicle": "bicycle"})", "test", "");
  EXPECT_TRUE(m) << m.error().describe();
  return *m;
}

// Sharp (1971) published weave and wobble frequencies (shared/data/motorcycle/README.md).
std::vector<ModeFrequency> sharpPublished() {
  const double u[] = {9.144, 15.24, 21.336, 30.48, 39.624, 48.768};
  const double weave[] = {4.56, 11.4, 16.8, 19.2, 20.4, 21.2};
  const double wobble[] = {55.5, 54.6, 54.0, 54.3, 55.6, 57.5};
  std::vector<ModeFrequency> out;
  for (int i = 0; i < 6; ++i) {
    // 3 printed figures: half a unit in the last digit, as a standard uncertainty.
    out.push_back({"weave", u[i], weave[i] / kTwoPi, 0.05 / kTwoPi});
    out.push_back({"wobble", u[i], wobble[i] / kTwoPi, 0.05 / kTwoPi});
  }
  return out;
}

int indexOf(const GapProblem& p, const std::string& effect) {
  const auto c = p.candidates();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].effect == effect) return static_cast<int>(i);
  return -1;
}

TEST(StabilityGapProblem, MotorcycleBaselineIsTheRigidForkSweep) {
  auto p = StabilityGapProblem::create(motorcycleModel(), sharpPublished());
  ASSERT_TRUE(p) << p.error().describe();
  const double theta = 1.0;
  const auto pred = (*p)->predict({&theta, -1, nullptr});
  // Independent path: the model built and swept directly, named by mode tracking.
  auto built = stability::MotorcycleModel::build(motorcycleModel().motorcycle, std::nullopt);
  ASSERT_TRUE(built);
  const auto& meas = (*p)->measured();
  for (std::size_t j = 0; j < meas.size(); ++j) {
    auto sweep = stability::sweepSpeeds(built->system(), {meas[j].speed - 0.2, meas[j].speed});
    ASSERT_TRUE(sweep);
    double f = NAN;
    for (const auto& r : sweep->points.back().roots)
      if (r.name == meas[j].mode) f = r.lambda.imag() / kTwoPi;
    // Same model, different tracking grid: the named root is the same one.
    EXPECT_NEAR(pred[j], f, 1e-9) << meas[j].mode << " " << meas[j].speed;
    // The published values (stability_motorcycle_test: wobble 2%, weave 5%).
    EXPECT_NEAR(pred[j] / meas[j].frequencyHz, 1.0, 0.05) << meas[j].mode << " " << meas[j].speed;
  }
  // Downstream figures (GAP.md step 9): the rigid machine's weave stabilises
  // near 6 m/s (published Re +2.01 at 3.05 and -0.18 at 6.10 m/s), inside the
  // searched 4.6-73 m/s range; its wobble stays stable (stability_motorcycle_test).
  const auto m = (*p)->metrics({&theta, -1, nullptr});
  int predictions = 0;
  for (const auto& e : m.entries) {
    if (e.kind != "prediction") continue;
    ++predictions;
    if (e.label == "weave critical speed [m/s]") {
      EXPECT_EQ(e.details[0].second, 1.0);
      EXPECT_GT(e.value, 4.6);
      EXPECT_LT(e.value, 6.1);
    } else {
      EXPECT_EQ(e.label, "wobble critical speed [m/s]");
    }
  }
  EXPECT_EQ(predictions, 2);
  // Overlay: one curve per mode, against speed.
  const auto curves = (*p)->overlay({&theta, -1, nullptr});
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0].label, "weave");
  EXPECT_EQ(curves[1].label, "wobble");
  EXPECT_EQ(curves[1].x.size(), 6u);
  EXPECT_DOUBLE_EQ(curves[1].predicted[0], pred[1]);
  const auto folds = (*p)->folds();
  // Speeds 9.1 to 48.8 m/s in three equal ranges: 9.1, 15.2, 21.3 | 30.5 | 39.6, 48.8.
  const int expected[] = {0, 0, 0, 0, 0, 0, 1, 1, 2, 2, 2, 2};
  for (std::size_t j = 0; j < folds.size(); ++j) EXPECT_EQ(folds[j], expected[j]) << j;
}

TEST(StabilityGapProblem, ForkBendingAndRelaxationMoveTheWobble) {
  auto p = StabilityGapProblem::create(motorcycleModel(), sharpPublished());
  ASSERT_TRUE(p);
  const double theta = 1.0;
  const auto base = (*p)->predict({&theta, -1, nullptr});
  const double absent = 0.0, one = 1.0, longer = 1.5;
  EXPECT_EQ((*p)->predict({&theta, indexOf(**p, "fork_bending"), &absent}), base);
  EXPECT_EQ((*p)->predict({&theta, indexOf(**p, "tyre_relaxation"), &one}), base);
  const auto bend = (*p)->predict({&theta, indexOf(**p, "fork_bending"), &one});  // thesis model 1 fork
  const auto relax = (*p)->predict({&theta, indexOf(**p, "tyre_relaxation"), &longer});
  const auto& meas = (*p)->measured();
  double maxBend = 0.0, maxRelax = 0.0;
  for (std::size_t j = 0; j < meas.size(); ++j) {
    ASSERT_TRUE(std::isfinite(bend[j]) && std::isfinite(relax[j]));
    if (meas[j].mode == "wobble") {
      // A compliant fork adds a flexible element in series with the steer:
      // the wobble frequency falls (thesis §4.2, Figure 33; Sharp & Alstead 1980).
      EXPECT_LT(bend[j], base[j]) << meas[j].speed;
      maxBend = std::max(maxBend, std::abs(bend[j] / base[j] - 1.0));
      maxRelax = std::max(maxRelax, std::abs(relax[j] / base[j] - 1.0));
    }
  }
  std::printf("wobble shift: fork model 1 up to %.1f%%, relaxation x1.5 up to %.1f%%\n", 100 * maxBend, 100 * maxRelax);
  // Both effects are visible beyond the 0.1% frequency noise floor of GAP.md.
  EXPECT_GT(maxBend, 0.01);
  EXPECT_GT(maxRelax, 0.01);
}

TEST(StabilityGapProblem, BicycleForkJointsMoveTheWeave) {
  // Benchmark bicycle (Meijaard et al. 2007): weave between 5 and 8 m/s.
  std::vector<ModeFrequency> meas;
  for (double v : {5.0, 6.0, 7.0, 8.0}) meas.push_back({"weave", v, 0.5, 0.005});
  auto p = StabilityGapProblem::create(bicycleModel(), meas);
  ASSERT_TRUE(p) << p.error().describe();
  const double theta = 1.0, one = 1.0, soft = 3.0;
  const auto base = (*p)->predict({&theta, -1, nullptr});
  // Independent: eigenvalues of the benchmark at 5 m/s, weave is the
  // oscillating pair (Meijaard et al. 2007 Table 2 at 5 m/s: -0.7755 +- 4.4649i).
  EXPECT_NEAR(base[0], 4.4649 / kTwoPi, 1e-3);
  const auto bend = (*p)->predict({&theta, indexOf(**p, "fork_bending"), &soft});
  const auto tors = (*p)->predict({&theta, indexOf(**p, "fork_torsion"), &one});
  for (std::size_t j = 0; j < base.size(); ++j) {
    ASSERT_TRUE(std::isfinite(bend[j]) && std::isfinite(tors[j]));
    EXPECT_NE(bend[j], base[j]);
    EXPECT_NE(tors[j], base[j]);
  }
  std::printf("bicycle weave at 5 m/s: rigid %.4f Hz, bending (k/3) %.4f Hz, torsion %.4f Hz\n", base[0], bend[0],
              tors[0]);
  // Metrics: one row per (mode, speed), then the weave's critical speed: the
  // benchmark's weave speed 4.2924 m/s (Meijaard et al. 2007), inside the
  // searched 2.5-12 m/s; the sweep refines crossings by Brent's method (1e-3).
  const auto m = (*p)->metrics({&theta, -1, nullptr});
  ASSERT_EQ(m.entries.size(), 5u);
  EXPECT_EQ(m.entries[0].label, "weave 5 m/s");
  EXPECT_EQ(m.entries[4].kind, "prediction");
  EXPECT_NEAR(m.entries[4].value, 4.29238253634110, 1e-3);
  EXPECT_EQ(m.residualName, "frequency_residual");
  // Simulation keeps the layout and draws around the prediction.
  std::mt19937_64 rng(3);
  auto sim = (*p)->simulated({&theta, -1, nullptr}, rng);
  std::vector<double> r(4);
  ASSERT_TRUE(sim->residuals({&theta, -1, nullptr}, r.data()));
  for (double x : r) EXPECT_LT(std::abs(x), 5.0);  // N(0,1): |z| > 5 has probability 6e-7
}

// End to end on the benchmark bicycle: weave frequencies of a bicycle whose
// fork bends (k_beta = 5635 / 2 N m/rad, the thesis's steel fork made twice as
// compliant) with 0.3% noise, diagnosed against the rigid benchmark.
TEST(StabilityGapProblem, DiagnosisFindsAPlantedForkBending) {
  std::vector<ModeFrequency> meas;
  for (double v : {4.5, 5.0, 5.5, 6.0, 6.5, 7.0, 7.5, 8.0}) meas.push_back({"weave", v, 0.5, 0.005});
  auto nominal = StabilityGapProblem::create(bicycleModel(), meas);
  ASSERT_TRUE(nominal);
  const double theta = 1.0, truth = 2.0;
  const int bending = indexOf(**nominal, "fork_bending");
  const auto clean = (*nominal)->predict({&theta, bending, &truth});
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t j = 0; j < meas.size(); ++j) {
    meas[j].sigmaHz = 0.003 * clean[j];
    meas[j].frequencyHz = clean[j] + meas[j].sigmaHz * noise(rng);
  }
  auto p = StabilityGapProblem::create(bicycleModel(), meas);
  ASSERT_TRUE(p);
  DiagnosisOptions o;
  o.bootstrapSamples = 100;
  o.multistarts = 3;
  const auto d = diagnose(**p, o);
  ASSERT_TRUE(d) << d.error().describe();
  std::printf("bicycle: %s\n", d->explanation.c_str());
  EXPECT_EQ(d->verdict, Verdict::Effect);
  ASSERT_FALSE(d->ranking.empty());
  const auto& best = d->ranking[0];
  EXPECT_EQ(best.candidate.effect, "fork_bending");
  ASSERT_EQ(best.stdErrors.size(), 1u);
  EXPECT_NEAR(best.parameters[0], truth, 4 * best.stdErrors[0]);  // 4 SE: a 6e-5 two-sided event
  EXPECT_GT(best.shrinkPct, 80.0);                                // issue 10's target for a right attribution
}

TEST(StabilityGapLoader, RejectsBadInputs) {
  auto bad = [](const std::string& json) {
    auto m = parseStabilityGapModel(json, "m.json", "");
    EXPECT_FALSE(m);
    return m ? std::string() : m.error().describe();
  };
  EXPECT_NE(bad(R"({"schema": "mozzi-stability-gap/2", "vehicle": "bicycle"})").find("schema"), std::string::npos);
  EXPECT_NE(bad(R"({"schema": "mozzi-stability-gap/1", "vehicle": "tricycle"})").find("tricycle"), std::string::npos);
  EXPECT_NE(bad(R"({"schema": "mozzi-stability-gap/1", "vehicle": "motorcycle"})").find("parameters"),
            std::string::npos);
  EXPECT_NE(bad(R"({"schema": "mozzi-stability-gap/1", "vehicle": "bicycle", "speed_folds": 0})").find("speed_folds"),
            std::string::npos);
  EXPECT_NE(bad(R"({"schema": "mozzi-stability-gap/1", "vehicle": "bicycle", "fork_torsion": 3})").find("fork_torsion"),
            std::string::npos);
  EXPECT_NE(bad(R"({"schema": "mozzi-stability-gap/1", "vehicle": "bicycle", "fork_bending": {"h_w_m": "high"}})")
                .find("h_w_m"),
            std::string::npos);
  // Reference joints: given numbers replace the thesis steel fork's, the others stay (§6.5: 5635, 0.8, 0.21).
  auto carbon = parseStabilityGapModel(
      R"({"schema": "mozzi-stability-gap/1", "vehicle": "bicycle", "fork_bending": {"stiffness_n_m_per_rad": 5326}})",
      "m.json", "");
  ASSERT_TRUE(carbon) << carbon.error().describe();
  EXPECT_EQ(carbon->bicycleBending.stiffness, 5326.0);
  EXPECT_EQ(carbon->bicycleBending.damping, 0.8);
  EXPECT_EQ(carbon->bicycleBending.hW, 0.21);
  auto csv = [](const std::string& text) {
    auto r = parseModeFrequencyCsv(text, "f.csv");
    EXPECT_FALSE(r);
    return r ? std::string() : r.error().describe();
  };
  EXPECT_NE(csv("speed_m_s,frequency_hz,uncertainty_hz\n5,0.7,0.01\n").find("mode"), std::string::npos);
  EXPECT_NE(csv("speed_m_s,mode,frequency_hz,uncertainty_hz\n5,,0.7,0.01\n").find("f.csv:2"), std::string::npos);
  // A negative frequency is outside the column's stated range (docs/cli.md, input files).
  EXPECT_NE(csv("speed_m_s,mode,frequency_hz,uncertainty_hz\n5,weave,-0.7,0.01\n").find("frequency_hz"),
            std::string::npos);
  EXPECT_NE(csv("speed_m_s,mode,frequency_hz,uncertainty_hz\n5,weave,0.7,0.01\n5,weave,0.71,0.01\n").find("twice"),
            std::string::npos);
  auto ok = parseModeFrequencyCsv("speed_m_s,mode,frequency_hz,uncertainty_hz\n5,weave,0.7,0.01\n5,wobble,8.8,0.05\n",
                                  "f.csv");
  ASSERT_TRUE(ok) << ok.error().describe();
  EXPECT_EQ((*ok)[1].mode, "wobble");
  // A mode the model does not have at that speed is refused when the problem is made.
  auto p = StabilityGapProblem::create(bicycleModel(), {{"wobble", 5.0, 8.8, 0.05}});
  ASSERT_FALSE(p);
  EXPECT_NE(p.error().where.find("wobble 5 m/s"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::gap
