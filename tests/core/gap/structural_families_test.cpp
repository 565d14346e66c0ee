// Residual-mode candidates that change the FRFs alike merge into one family
// (core/gap/engine/families.h, FrfProblem::effectShape): on a modal model
// with one mode per axis, the quasi-static deflection under a load at any Y
// DOF is the Y mode's shape (its sign flipping with the DOF's component), so
// every Y reference gives the same residual mode; a second Y mode makes the
// deflections differ and nothing merges.
#include <gtest/gtest.h>

#include <cmath>

#include "core/gap/engine/families.h"
#include "core/gap/structural/structural_problem.h"

namespace mozzi::core::gap::structural {
namespace {

const char* const kAxes[] = {"X", "Y", "Z"};

// Four nodes, X, Y and Z at each (12 DOFs); modes at `hz`, each moving one
// axis (`axis` 0..2) with the components `shape` at nodes 1..4.
struct Mode {
  double hz;
  int axis;
  std::vector<double> shape;
};

StructuralModel modalModel(const std::vector<Mode>& modes) {
  StructuralModel m;
  m.name = "one mode per axis";
  for (int node = 1; node <= 4; ++node)
    for (const char* axis : kAxes) {
      const std::string label = std::to_string(node) + "+" + axis;
      m.dofs.push_back(*parseDof(label));
      m.labels.push_back(label);
    }
  const auto n = static_cast<Eigen::Index>(modes.size());
  m.t = Matrix::Zero(12, n);
  m.m = Matrix::Identity(n, n);
  m.k = Matrix::Zero(n, n);
  m.modalDamping = Vector::Constant(n, 0.02);
  for (Eigen::Index r = 0; r < n; ++r) {
    const Mode& mode = modes[static_cast<std::size_t>(r)];
    for (int node = 0; node < 4; ++node) m.t(3 * node + mode.axis, r) = mode.shape[static_cast<std::size_t>(node)];
    m.k(r, r) = std::pow(2 * M_PI * mode.hz, 2);
  }
  return m;
}

// Accelerance of the modal model, -w^2 sum_r a_r a_r^T / (w_r^2 - w^2 + 2 i zeta w_r w),
// at every DOF for the references given.
FrfMatrix accelerance(const StructuralModel& m, const std::vector<std::string>& references) {
  FrfMatrix frf;
  frf.type = FrfType::Accelerance;
  frf.responses = m.dofs;
  for (const auto& r : references) frf.references.push_back(*parseDof(r));
  frf.frequencyHz = Vector::LinSpaced(200, 5.0, 60.0);
  for (const auto& ref : frf.references) {
    const int i = m.findDof(ref);
    ComplexMatrix h(frf.lineCount(), 12);
    for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
      const double w = 2 * M_PI * frf.frequencyHz[k];
      for (int o = 0; o < 12; ++o) {
        Complex sum(0.0, 0.0);
        for (Eigen::Index r = 0; r < m.t.cols(); ++r) {
          const double wr = std::sqrt(m.k(r, r));
          sum += m.t(o, r) * m.t(i, r) / Complex(wr * wr - w * w, 2 * 0.02 * wr * w);
        }
        h(k, o) = -w * w * sum;
      }
    }
    frf.h.push_back(h);
  }
  return frf;
}

const std::vector<std::string> kReferences{"1+Y", "2+Y", "3+Y", "1+Z", "4+Y"};

// The residual-mode candidates, in the order of kReferences.
std::vector<int> residualModes(const GapProblem& p) {
  const auto all = p.candidates();
  std::vector<int> out;
  for (const auto& ref : kReferences)
    for (std::size_t c = 0; c < all.size(); ++c)
      if (all[c].effect == "residual_mode" && all[c].location == std::vector<std::string>{ref})
        out.push_back(static_cast<int>(c));
  return out;
}

std::vector<double> residuals(const GapProblem& p, int candidate, const std::vector<double>& phi) {
  std::vector<double> r(static_cast<std::size_t>(p.residualCount()));
  const std::vector<double> theta(1, 0.0);  // the model has no calibration parameters
  EXPECT_TRUE(p.residuals({theta.data(), candidate, phi.data()}, r.data()));
  return r;
}

StructuralOptions stated() {
  StructuralOptions o;
  o.noise = StructuralOptions::NoiseSource::Stated;
  o.relativeFloor = 0.01;
  return o;
}

TEST(StructuralFamilies, EveryYReferenceGivesOneResidualMode) {
  // Node 2's Y component is negative: its deflection is the others' with the
  // sign flipped, which u u^T does not see.
  const auto model = modalModel(
      {{10.0, 0, {1.0, 0.4, -0.3, 0.7}}, {20.0, 1, {0.2, -0.6, 1.0, 0.5}}, {30.0, 2, {0.9, 1.0, 0.1, -0.4}}});
  auto p = makeFrfProblem(model, accelerance(model, kReferences), stated());
  ASSERT_TRUE(p.ok()) << p.error().describe();
  const auto modes = residualModes(**p);
  ASSERT_EQ(modes.size(), kReferences.size());
  const auto families = engine::equalEffectFamilies(**p, (*p)->candidates(), modes);
  ASSERT_EQ(families.size(), 2u);
  EXPECT_EQ(families[0], (std::vector<int>{modes[0], modes[1], modes[2], modes[4]}));  // 1+Y 2+Y 3+Y 4+Y
  EXPECT_EQ(families[1], (std::vector<int>{modes[3]}));                                // 1+Z
  const Candidate rep = engine::familyCandidate((*p)->candidates(), families[0]);
  EXPECT_EQ(familyLabel(rep), "residual_mode at 1+Y (and 3 equivalent locations)");
  // The independent check that merging loses nothing: the members give the
  // same residuals at the same sizes (m/N, m/N, 1/kg), to round-off.
  const std::vector<double> phi{2e-5, -1e-5, 3.0};
  const auto r1 = residuals(**p, modes[0], phi);
  for (int member : {modes[1], modes[2], modes[4]}) {
    const auto r = residuals(**p, member, phi);
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      worst = std::max(worst, std::abs(r[i] - r1[i]));
      scale = std::max(scale, std::abs(r1[i]));
    }
    EXPECT_LE(worst, 1e-9 * scale) << member;
  }
  // And the Z one does not.
  const auto rz = residuals(**p, modes[3], phi);
  double apart = 0.0;
  for (std::size_t i = 0; i < rz.size(); ++i) apart = std::max(apart, std::abs(rz[i] - r1[i]));
  EXPECT_GT(apart, 1.0);
}

TEST(StructuralFamilies, DistinctDeflectionsStayApart) {
  // A second Y mode: the deflection under a load at a Y DOF mixes the two by
  // that DOF's components, different at every node.
  const auto model = modalModel({{10.0, 0, {1.0, 0.4, -0.3, 0.7}},
                                 {20.0, 1, {0.2, -0.6, 1.0, 0.5}},
                                 {30.0, 2, {0.9, 1.0, 0.1, -0.4}},
                                 {45.0, 1, {1.0, 0.3, -0.2, -0.8}}});
  auto p = makeFrfProblem(model, accelerance(model, kReferences), stated());
  ASSERT_TRUE(p.ok()) << p.error().describe();
  const auto modes = residualModes(**p);
  ASSERT_EQ(modes.size(), kReferences.size());
  EXPECT_EQ(engine::equalEffectFamilies(**p, (*p)->candidates(), modes).size(), kReferences.size());
  // The other effects have no shape to compare: each its own family.
  const auto all = (*p)->candidates();
  std::vector<int> every(all.size());
  for (std::size_t c = 0; c < all.size(); ++c) every[c] = static_cast<int>(c);
  EXPECT_EQ(engine::equalEffectFamilies(**p, all, every).size(), all.size());
}

}  // namespace
}  // namespace mozzi::core::gap::structural
