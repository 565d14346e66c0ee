#include "core/modal/refine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/modal/synthetic_system.h"

namespace mozzi::core::modal {
namespace {

using testing::sixModeSystem;

// Synthetic accelerances (reference DOF 3) with additive complex Gaussian
// noise of 1% of each FRF's RMS (homoscedastic, the least-squares assumption).
FrfMatrix noisy(const testing::SyntheticSystem& sys, unsigned seed) {
  FrfMatrix frf = testing::accelerances(sys, {2}, 20.0, 380.0, 0.2, 0.0, 1);
  std::mt19937 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  for (Eigen::Index o = 0; o < 6; ++o) {
    const double rms = std::sqrt(frf.h[0].col(o).squaredNorm() / static_cast<double>(frf.lineCount()));
    for (Eigen::Index k = 0; k < frf.lineCount(); ++k)
      frf.h[0](k, o) += 0.01 * rms / std::sqrt(2.0) * Complex(nd(rng), nd(rng));
  }
  return frf;
}

ModalModel perturbedStart(const testing::SyntheticSystem& sys) {
  ModalModel m;
  m.responses = testing::sixDofs();
  m.references = {m.responses[2]};
  for (int r = 0; r < 6; ++r) {
    Mode md;
    // 0.3% off in frequency (alternating sign), 20% off in damping.
    md.pole = poleFromFrequencyDamping(sys.fn[r] * (r % 2 ? 1.003 : 0.997), sys.zeta[r] * 1.2);
    md.residue = ComplexMatrix::Zero(6, 1);
    m.modes.push_back(md);
  }
  return m;
}

// From a perturbed start Ceres returns to the true modes (within the issue's
// 0.1% / 5% tolerances), and the standard errors from the final Jacobian
// match the scatter over independent noise realisations: the empirical
// standard deviation of 10 realisations has about 24% sampling uncertainty
// (1/sqrt(2 (n-1))), so each of the 12 quantities must agree within a factor
// 2.5 (more than 3 sigma) and their pooled geometric-mean ratio (about 7%
// sampling uncertainty) within 0.75 .. 1.33.
TEST(Refine, ConvergesAndStandardErrorsMatchScatter) {
  const auto sys = sixModeSystem();
  RefineOptions opt;
  opt.bandLowHz = 20.0;
  opt.bandHighHz = 380.0;
  const int runs = 10;
  std::vector<std::vector<double>> f(6), z(6);
  std::vector<double> fStd(6), zStd(6);
  for (int s = 0; s < runs; ++s) {
    const FrfMatrix frf = noisy(sys, 100 + static_cast<unsigned>(s));
    auto res = refineModalModel(frf, perturbedStart(sys), opt);
    ASSERT_TRUE(res.ok()) << res.error().describe();
    ASSERT_EQ(res->model.modes.size(), 6u);
    EXPECT_LT(res->finalRelativeError, res->initialRelativeError);
    for (int r = 0; r < 6; ++r) {
      const auto& md = res->model.modes[static_cast<std::size_t>(r)];
      EXPECT_LT(std::abs(md.frequencyHz() - sys.fn[r]) / sys.fn[r], 1e-3) << "mode " << r + 1;
      EXPECT_LT(std::abs(md.zeta() - sys.zeta[r]) / sys.zeta[r], 0.05) << "mode " << r + 1;
      f[static_cast<std::size_t>(r)].push_back(md.frequencyHz());
      z[static_cast<std::size_t>(r)].push_back(md.zeta());
      fStd[static_cast<std::size_t>(r)] += res->frequencyStdHz[static_cast<std::size_t>(r)] / runs;
      zStd[static_cast<std::size_t>(r)] += res->zetaStd[static_cast<std::size_t>(r)] / runs;
    }
  }
  auto sd = [](const std::vector<double>& v) {
    double mu = 0, s2 = 0;
    for (double x : v) mu += x;
    mu /= static_cast<double>(v.size());
    for (double x : v) s2 += (x - mu) * (x - mu);
    return std::sqrt(s2 / static_cast<double>(v.size() - 1));
  };
  double logRatio = 0.0;
  for (std::size_t r = 0; r < 6; ++r) {
    const double ef = sd(f[r]), ez = sd(z[r]);
    logRatio += (std::log(fStd[r] / ef) + std::log(zStd[r] / ez)) / 12.0;
    std::printf("mode %zu: f std predicted %.3g Hz, scatter %.3g Hz; zeta std predicted %.3g, scatter %.3g\n", r + 1,
                fStd[r], ef, zStd[r], ez);
    EXPECT_GT(fStd[r], ef / 2.5);
    EXPECT_LT(fStd[r], ef * 2.5);
    EXPECT_GT(zStd[r], ez / 2.5);
    EXPECT_LT(zStd[r], ez * 2.5);
  }
  std::printf("pooled predicted / scatter ratio %.3f\n", std::exp(logRatio));
  EXPECT_GT(std::exp(logRatio), 0.75);
  EXPECT_LT(std::exp(logRatio), 1.33);
}

TEST(Refine, RejectsEmptyModelAndTinyBand) {
  const auto sys = sixModeSystem();
  const FrfMatrix frf = noisy(sys, 1);
  RefineOptions opt;
  opt.bandLowHz = 20.0;
  opt.bandHighHz = 380.0;
  ModalModel empty;
  empty.responses = testing::sixDofs();
  empty.references = {empty.responses[2]};
  auto a = refineModalModel(frf, empty, opt);
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().message.find("no modes"), std::string::npos);
  opt.bandLowHz = 100.0;
  opt.bandHighHz = 100.2;
  auto b = refineModalModel(frf, perturbedStart(sys), opt);
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.error().code, ErrorCode::InvalidArgument);
}

}  // namespace
}  // namespace mozzi::core::modal
