// Families of candidates that change the data alike (core/gap/engine/
// families.h): equal effect shapes merge into one fitted candidate that names
// the others; shapes that differ (beyond 1e-9 of their size, in sign, or in
// effect) never merge. The linear problem's effect is its signature column,
// so equal signatures give equal residuals exactly: the independent check
// that merging them loses nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/gap/diagnosis.h"
#include "core/gap/diagnosis_json.h"
#include "core/gap/engine/families.h"
#include "engine_test_problems.h"

namespace mozzi::core::gap {
namespace {

using testing::bump;
using testing::LinearCandidate;
using testing::LinearGapProblem;
using testing::polynomialBasis;

constexpr int kN = 48;
constexpr double kSigma = 0.1;

// The linear problem with its signatures as effect shapes.
class ShapedProblem : public LinearGapProblem {
 public:
  ShapedProblem(const LinearGapProblem& base, std::vector<LinearCandidate> cands)
      : LinearGapProblem(base), cands_(std::move(cands)) {}
  std::vector<double> effectShape(int candidate) const override {
    const Eigen::MatrixXd& s = cands_[static_cast<std::size_t>(candidate)].signature;
    return std::vector<double>(s.data(), s.data() + s.size());
  }
  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override {
    auto base = LinearGapProblem::simulated(at, rng);
    return std::make_unique<ShapedProblem>(static_cast<const LinearGapProblem&>(*base), cands_);
  }

 private:
  std::vector<LinearCandidate> cands_;
};

std::unique_ptr<ShapedProblem> make(std::vector<LinearCandidate> cands, int k, double size, unsigned seed) {
  std::mt19937_64 rng(seed);
  const auto base =
      LinearGapProblem::generate(polynomialBasis(kN, 3), cands, Eigen::Vector3d(1.0, -0.5, 0.3), k,
                                 Eigen::VectorXd::Constant(1, size), Eigen::VectorXd::Zero(kN), kSigma, rng);
  return std::make_unique<ShapedProblem>(*base, std::move(cands));
}

// Candidates 1, 3, 4 and 6 (locations "1+Z", "3+Z", "4+Z", "6+Z") share one
// bump, with bounds of their own; 2 is elsewhere; 5 has the same bump but is
// another effect.
std::vector<LinearCandidate> family() {
  const Eigen::VectorXd at = bump(kN, 0.5, 0.05);
  return {{"mass_loading", at, -1.0, 5.0}, {"mass_loading", bump(kN, 0.2, 0.05)}, {"mass_loading", at, -3.0, 2.0},
          {"mass_loading", at, -2.0, 4.0}, {"element_stiffness", at, -5.0, 5.0},  {"mass_loading", at, -1.0, 1.0}};
}

std::vector<int> all(const GapProblem& p) {
  std::vector<int> out(p.candidates().size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<int>(i);
  return out;
}

TEST(EngineFamilies, EqualShapesOfOneEffectMakeOneFamily) {
  const auto p = make(family(), 0, 1.0, 3);
  const auto families = engine::equalEffectFamilies(*p, p->candidates(), all(*p));
  ASSERT_EQ(families.size(), 3u);
  EXPECT_EQ(families[0], (std::vector<int>{0, 2, 3, 5}));
  EXPECT_EQ(families[1], (std::vector<int>{1}));
  EXPECT_EQ(families[2], (std::vector<int>{4}));  // same shape, another effect
  const Candidate rep = engine::familyCandidate(p->candidates(), families[0]);
  EXPECT_EQ(rep.location, (std::vector<std::string>{"1+Z"}));
  EXPECT_EQ(rep.equivalent, (std::vector<std::vector<std::string>>{{"3+Z"}, {"4+Z"}, {"6+Z"}}));
  // The members' bounds united: [-1, 5], [-3, 2], [-2, 4], [-1, 1].
  EXPECT_EQ(rep.parameters[0].lower, -3.0);
  EXPECT_EQ(rep.parameters[0].upper, 5.0);
  EXPECT_EQ(label(rep), "mass_loading at 1+Z");
  EXPECT_EQ(familyLabel(rep), "mass_loading at 1+Z (and 3 equivalent locations)");
  EXPECT_EQ(familyLabel(engine::familyCandidate(p->candidates(), {0, 2})), "mass_loading at 1+Z (equivalent at 3+Z)");
  EXPECT_EQ(familyLabel(engine::familyCandidate(p->candidates(), {1})), "mass_loading at 2+Z");
  // Merging is right only if members change the data alike: residuals at the
  // same size, compared entry by entry.
  const std::vector<double> theta{0.9, -0.4, 0.2}, phi{0.7};
  std::vector<double> r0(kN), r3(kN);
  ASSERT_TRUE(p->residuals({theta.data(), 0, phi.data()}, r0.data()));
  ASSERT_TRUE(p->residuals({theta.data(), 3, phi.data()}, r3.data()));
  EXPECT_EQ(r0, r3);
}

TEST(EngineFamilies, DifferentShapesStayApart) {
  const Eigen::VectorXd at = bump(kN, 0.5, 0.05);
  // 1e-7 apart (beyond the 1e-9 tolerance), the sign flipped (the engine
  // compares shapes as the problem gives them), and 1e-12 apart (merged).
  const std::vector<LinearCandidate> cands{{"mass_loading", at},
                                           {"mass_loading", at * (1.0 + 1e-7)},
                                           {"mass_loading", -at},
                                           {"mass_loading", at * (1.0 + 1e-12)}};
  const auto p = make(cands, 0, 1.0, 4);
  const auto families = engine::equalEffectFamilies(*p, p->candidates(), all(*p));
  ASSERT_EQ(families.size(), 3u);
  EXPECT_EQ(families[0], (std::vector<int>{0, 3}));
  EXPECT_EQ(families[1], (std::vector<int>{1}));
  EXPECT_EQ(families[2], (std::vector<int>{2}));
  EXPECT_FALSE(engine::equalShapes({}, {}));
  EXPECT_FALSE(engine::equalShapes({0.0, 0.0}, {0.0, 0.0}));
  EXPECT_FALSE(engine::equalShapes({1.0}, {1.0, 0.0}));
}

// The diagnosis fits one candidate per family: a size planted at a member
// (candidate 4, "4+Z") is found at the representative with the members named
// (the element_stiffness moved elsewhere: of the family's shape it could not
// be told apart, and the verdict would be "ambiguous").
TEST(EngineFamilies, DiagnosisFitsOnePerFamily) {
  auto cands = family();
  cands[4].signature = bump(kN, 0.8, 0.05);  // apart, so the verdict is not ambiguous
  const auto p = make(cands, 3, 1.5, 11);
  DiagnosisOptions o;
  o.bootstrapSamples = 200;
  o.multistarts = 3;
  const auto d = diagnose(*p, o);
  ASSERT_TRUE(d.ok()) << d.error().describe();
  // Three families, besides the calibration: three ranked rows, not six.
  ASSERT_EQ(d->ranking.size(), 3u);
  EXPECT_EQ(d->verdict, Verdict::Effect) << d->explanation;
  const RankedEffect& best = d->ranking[0];
  EXPECT_EQ(best.candidateIndex, 0);
  EXPECT_EQ(best.candidate.equivalent, (std::vector<std::vector<std::string>>{{"3+Z"}, {"4+Z"}, {"6+Z"}}));
  ASSERT_EQ(best.stdErrors.size(), 1u);
  EXPECT_NEAR(best.parameters[0], 1.5, 4 * best.stdErrors[0]);
  for (std::size_t r = 1; r < d->ranking.size(); ++r) EXPECT_TRUE(d->ranking[r].candidate.equivalent.empty());
  // JSON: the family's other locations on the ranked candidate.
  const nlohmann::json j = diagnosisToJson(*d);
  const auto& row = j["ranking"][0];
  ASSERT_TRUE(row.contains("equivalent_locations")) << row.dump();
  EXPECT_EQ(row["equivalent_locations"], nlohmann::json::parse(R"([["3+Z"], ["4+Z"], ["6+Z"]])"));
  EXPECT_FALSE(j["ranking"][1].contains("equivalent_locations"));
}

// Without effect shapes (the default), nothing merges.
TEST(EngineFamilies, ProblemsWithoutShapesAreNotMerged) {
  std::mt19937_64 rng(2);
  const auto p = LinearGapProblem::generate(polynomialBasis(kN, 3), family(), Eigen::Vector3d(1.0, -0.5, 0.3), -1,
                                            Eigen::VectorXd(), Eigen::VectorXd::Zero(kN), kSigma, rng);
  const auto families = engine::equalEffectFamilies(*p, p->candidates(), all(*p));
  EXPECT_EQ(families.size(), 6u);
}

}  // namespace
}  // namespace mozzi::core::gap
