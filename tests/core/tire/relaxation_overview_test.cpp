// The relaxation overview of a tyre specimen (thesis §5.4, Figure 43): the
// measured points are the stored ones exactly (tolerance 0: stored REALs round
// trip exactly), the predictions are core's eq. 48 with the inputs the header
// names, and the cornering stiffness comes from a steady-state test at the
// same pressure when there is one.

#include "core/tire/relaxation_overview.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/io/project_store.h"

namespace mozzi::core::tire {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

class RelaxationOverviewTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_relax_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    auto store = io::ProjectStore::create((dir_ / "p.mozzi").string(), "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    store_.emplace(std::move(*store));
    auto sp = store_->addSpecimen("Tyre 180/55 R17 (motorcycle rear)", "tyre", "test");
    ASSERT_TRUE(sp.ok());
    specimen_ = *sp;
  }
  void TearDown() override {
    store_.reset();
    fs::remove_all(dir_);
  }
  // A relaxation test as the tyre tester stores it: per step the frequency and
  // sigma, for the whole test the band mean and a.
  std::int64_t addRelaxation(double bar, const std::vector<std::pair<double, double>>& points, double a) {
    io::StoredTyreTest t;
    t.specimenId = specimen_;
    t.name = "relaxation " + std::to_string(bar);
    t.kind = "relaxation";
    t.inflationPressurePa = bar * 1e5;
    t.verticalLoadN = 1500.0;
    t.speedMps = 5.0 / 3.6;
    int step = 0;
    double sum = 0.0;
    for (const auto& [f, s] : points) {
      t.parameters.push_back({"frequency", f, "Hz", 0.0, step});
      t.parameters.push_back({"relaxation_length_m", s, "m", 0.001 * (step + 1), step});
      sum += s;
      ++step;
    }
    t.parameters.push_back({"relaxation_length_m", sum / points.size(), "m", 0.0005, std::nullopt});
    t.parameters.push_back({"half_length", a, "m", 0.0, std::nullopt});
    auto id = store_->addTyreTest(t);
    EXPECT_TRUE(id.ok()) << id.error().describe();
    return id.ok() ? *id : 0;
  }
  fs::path dir_;
  std::optional<io::ProjectStore> store_;
  std::int64_t specimen_ = 0;
};

TEST(FindThesisTyre, BySizeInAName) {
  ASSERT_NE(findThesisTyre("Tyre 120/70 R17 (motorcycle front)"), nullptr);
  EXPECT_EQ(findThesisTyre("Tyre 120/70 R17 (motorcycle front)")->size, "120/70 R17");
  EXPECT_EQ(findThesisTyre("130/70-12")->size, "130/70-12");
  EXPECT_EQ(findThesisTyre("12070r17")->size, "120/70 R17");
  EXPECT_EQ(findThesisTyre("Frame A"), nullptr);
}

TEST_F(RelaxationOverviewTest, MeasuredPointsAreTheStoredOnes) {
  const auto hi = addRelaxation(2.0, {{0.84, 0.171}, {1.26, 0.174}, {1.68, 0.169}}, 0.065);
  const auto lo = addRelaxation(1.0, {{0.42, 0.201}, {2.10, 0.198}}, 0.087);
  auto o = relaxationOverview(*store_, specimen_);
  ASSERT_TRUE(o.ok()) << o.error().describe();
  EXPECT_EQ(o->tyre.size, "180/55 R17");
  ASSERT_EQ(o->tests.size(), 2u);
  EXPECT_EQ(o->tests[0].testId, lo);  // sorted by pressure
  EXPECT_EQ(o->tests[1].testId, hi);
  ASSERT_EQ(o->tests[1].points.size(), 3u);
  EXPECT_EQ(o->tests[1].points[1].frequencyHz, 1.26);
  EXPECT_EQ(o->tests[1].points[1].sigma, 0.174);
  EXPECT_EQ(o->tests[1].points[1].sigmaStdError, 0.002);
  ASSERT_TRUE(o->tests[1].bandMean.has_value());
  EXPECT_EQ(*o->tests[1].bandMean, (0.171 + 0.174 + 0.169) / 3);
  EXPECT_EQ(o->tests[0].halfLengthM, 0.087);
}

TEST_F(RelaxationOverviewTest, PredictionIsEquation48WithTheNamedInputs) {
  addRelaxation(2.0, {{0.84, 0.171}}, 0.065);
  auto o = relaxationOverview(*store_, specimen_);
  ASSERT_TRUE(o.ok()) << o.error().describe();
  const ThesisTyre& t = thesisTyres()[1];  // 180/55 R17
  ASSERT_EQ(o->table17.size(), kThesisPressures.size());
  ASSERT_EQ(o->atTests.size(), 1u);
  // Eq. 48 by hand for the 2 bar bar: no steady-state test, so C = 13 F_z.
  const double C = kAssumedNormalisedCorneringStiffness * t.testLoad;
  const double m = 1.0 - C * std::tan(1.5 * kPi / 180.0) / (3.0 * kAssumedFriction * t.testLoad);  // eq. 49
  const double sigma = t.halfLength[4] * m + C / t.lateralStiffness + C / t.camberStiffness + C / t.cShapedStiffness +
                       C / t.sShapedStiffness;  // eq. 48, 50
  const auto& bar = o->table17[4];
  EXPECT_EQ(bar.corneringSource, CorneringSource::Assumed);
  EXPECT_NEAR(bar.prediction.total(), sigma, 1e-12 * sigma);
  EXPECT_NEAR(bar.prediction.contactPatch, t.halfLength[4] * m, 1e-15);
  EXPECT_NEAR(bar.prediction.camber, C / t.camberStiffness, 1e-15);
  // The test's case uses the stored a (the same as Table 17 here).
  EXPECT_NEAR(o->atTests[0].prediction.total(), sigma, 1e-12 * sigma);
  // Lower pressure, longer contact patch: the bars grow (§5.4).
  EXPECT_GT(o->table17.front().prediction.total(), o->table17.back().prediction.total());
}

TEST_F(RelaxationOverviewTest, CorneringStiffnessFromASteadyStateTestAtThatPressure) {
  addRelaxation(2.0, {{0.84, 0.171}}, 0.065);
  io::StoredTyreTest ss;
  ss.specimenId = specimen_;
  ss.name = "steady";
  ss.kind = "steady-state";
  ss.inflationPressurePa = 2e5;
  ss.verticalLoadN = 1000.0;
  ss.parameters.push_back({"cornering_stiffness", 15000.0, "N/rad", 100.0, std::nullopt});
  auto ssId = store_->addTyreTest(ss);
  ASSERT_TRUE(ssId.ok());
  auto o = relaxationOverview(*store_, specimen_);
  ASSERT_TRUE(o.ok()) << o.error().describe();
  // Measured at 1000 N, used at 1500 N: scaled by C/F_z.
  EXPECT_EQ(o->atTests[0].corneringSource, CorneringSource::SteadyStateTest);
  EXPECT_EQ(o->atTests[0].corneringTestId, *ssId);
  EXPECT_DOUBLE_EQ(o->atTests[0].contact.corneringStiffness, 15000.0 * 1.5);
  EXPECT_EQ(o->table17[4].corneringSource, CorneringSource::SteadyStateTest);
  EXPECT_EQ(o->table17[0].corneringSource, CorneringSource::Assumed);  // 0.5 bar: none measured
  auto direct = predictRelaxationLength(o->ring, o->atTests[0].contact);
  ASSERT_TRUE(direct.ok());
  EXPECT_EQ(direct->total(), o->atTests[0].prediction.total());
}

TEST_F(RelaxationOverviewTest, ErrorsSayWhat) {
  auto frame = store_->addSpecimen("Frame A", "frame", "test");
  ASSERT_TRUE(frame.ok());
  auto o = relaxationOverview(*store_, *frame);
  ASSERT_FALSE(o.ok());
  EXPECT_NE(o.error().message.find("names none of the thesis tyres"), std::string::npos);
  EXPECT_FALSE(relaxationOverview(*store_, 999).ok());
  io::StoredTyreTest steady;
  steady.kind = "steady-state";
  EXPECT_FALSE(measuredRelaxation(steady).ok());
}

}  // namespace
}  // namespace mozzi::core::tire
