#include "core/stability/motorcycle.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cstdio>
#include <fstream>

namespace mozzi::core::stability {
namespace {

const std::string kParams = std::string(MOZZI_SHARED_DATA_DIR) + "/motorcycle/sharp1971-parameters.csv";

TEST(Motorcycle, LoadsTheTrustNoteAndAllParameters) {
  auto p = loadSharpParameters(kParams);
  ASSERT_TRUE(p.ok()) << p.error().describe();
  EXPECT_NE(p->trust.find("transcription"), std::string::npos);
  EXPECT_DOUBLE_EQ(p->sigma, 0.24384);  // 0.8 ft
  EXPECT_DOUBLE_EQ(p->iry, 1.05076);
}

TEST(Motorcycle, MissingOrMalformedParameterIsNamed) {
  const std::string path = testing::TempDir() + "/sharp_bad.csv";
  {
    std::ofstream out(path);
    out << "name,value_si\nMf,30\nMr,abc\n";
  }
  auto p = loadSharpParameters(path);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("'Mr'"), std::string::npos);
  EXPECT_NE(p.error().where.find(":3"), std::string::npos);
  {
    std::ofstream out(path);
    out << "name,value_si\nMf,30\n";
  }
  p = loadSharpParameters(path);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("missing parameter"), std::string::npos);
  EXPECT_FALSE(loadSharpParameters(path + ".none").ok());
  std::remove(path.c_str());
}

TEST(Motorcycle, StiffLumpedForkTendsToTheRigidFork) {
  auto p = loadSharpParameters(kParams);
  ASSERT_TRUE(p.ok());
  auto rigid = MotorcycleModel::build(*p, std::nullopt);
  auto fork = thesisLumpedForkModel(1);
  ASSERT_TRUE(rigid.ok() && fork.ok());
  fork->stiffness = 1e10;  // the removed mass is put back on the same front assembly
  auto stiff = MotorcycleModel::build(*p, *fork);
  ASSERT_TRUE(stiff.ok());
  for (double u : {5.0, 20.0, 40.0}) {
    auto a = rigid->stateMatrix(u);
    auto b = stiff->stateMatrix(u);
    ASSERT_TRUE(a.ok() && b.ok());
    const ComplexVector la = Eigen::EigenSolver<Matrix>(*a, false).eigenvalues();
    const ComplexVector lb = Eigen::EigenSolver<Matrix>(*b, false).eigenvalues();
    // Every rigid eigenvalue reappears; the joint's influence falls like 1/k
    // (|lambda| <= 200, coupling ~1e3: error ~1e-4 at k = 1e10).
    for (int i = 0; i < la.size(); ++i) {
      double best = 1e300;
      for (int j = 0; j < lb.size(); ++j) best = std::min(best, std::abs(la(i) - lb(j)));
      EXPECT_LT(best, 1e-3 * (1.0 + std::abs(la(i)))) << "u = " << u << " lambda = " << la(i);
    }
  }
}

TEST(Motorcycle, RejectsNonPositiveSpeedAndBadForks) {
  auto p = loadSharpParameters(kParams);
  ASSERT_TRUE(p.ok());
  auto m = MotorcycleModel::build(*p, std::nullopt);
  ASSERT_TRUE(m.ok());
  EXPECT_FALSE(m->stateMatrix(0.0).ok());
  EXPECT_FALSE(m->stateMatrix(-1.0).ok());
  EXPECT_FALSE(thesisLumpedForkModel(4).ok());
  LumpedForkModel heavy{"too heavy", 1e4, 1.0, 1.0, 100.0, 0.3, 0.6};
  const auto r = MotorcycleModel::build(*p, heavy);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().where.find("too heavy"), std::string::npos);
}

TEST(Motorcycle, Table12ParametersAsPrinted) {
  // notes.md: J2 = 0.278 + 11 (0.405 + 0.846 - 0.670)^2 = 3.99 kg m^2.
  auto m2 = thesisLumpedForkModel(2);
  ASSERT_TRUE(m2.ok());
  EXPECT_NEAR(0.278 + m2->mass * m2->massArm * m2->massArm, m2->inertia, 0.01);
  auto m1 = thesisLumpedForkModel(1);
  ASSERT_TRUE(m1.ok());
  // f = sqrt(k/J)/(2 pi) = 18.4 Hz (Table 12).
  EXPECT_NEAR(std::sqrt(m1->stiffness / m1->inertia) / (2.0 * M_PI), 18.4, 0.05);
}

}  // namespace
}  // namespace mozzi::core::stability
