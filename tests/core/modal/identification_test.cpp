// The identification pipeline as one call (core/modal/identification.h):
// the same numbers as the steps run by hand, progress in stage order, cancel,
// and the re-selection fit against the independent synthesis of modal_model.h.
#include "core/modal/identification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/modal/synthetic_system.h"

namespace mozzi::core::modal {
namespace {

using testing::accelerances;
using testing::sixModeSystem;

IdentificationOptions options() {
  IdentificationOptions opt;
  opt.estimator.bandLowHz = 20.0;
  opt.estimator.bandHighHz = 380.0;
  opt.estimator.maxOrder = 40;
  return opt;
}

// identifyModes = identifyPlscf (diagram, selection, LSFD) + refineModalModel:
// the same code, so the same numbers to rounding; every mode within the
// issue-5 tolerances (0.1% frequency, 5% damping) and its standard errors set.
TEST(Identification, OneCallEqualsTheStepsAndFindsTheModes) {
  const auto sys = sixModeSystem();
  const FrfMatrix frf = accelerances(sys, {2}, 0.0, 400.0, 0.1, 0.01, 7);
  const auto opt = options();
  std::vector<IdentificationStage> stages;
  auto res = identifyModes(frf, opt, [&](const IdentificationProgress& p) {
    if (stages.empty() || stages.back() != p.stage) stages.push_back(p.stage);
    EXPECT_GE(p.fraction, 0.0);
    EXPECT_LE(p.fraction, 1.0);
    return true;
  });
  ASSERT_TRUE(res.ok()) << res.error().describe();
  ASSERT_TRUE(res->refined.has_value());
  EXPECT_EQ(stages, (std::vector<IdentificationStage>{IdentificationStage::Diagram, IdentificationStage::Selection,
                                                      IdentificationStage::Lsfd, IdentificationStage::Refinement}));
  auto steps = identifyPlscf(frf, opt.estimator);
  ASSERT_TRUE(steps.ok());
  RefineOptions ro;
  ro.bandLowHz = 20.0;
  ro.bandHighHz = 380.0;
  auto refined = refineModalModel(frf, steps->model, ro);
  ASSERT_TRUE(refined.ok());
  ASSERT_EQ(res->model().modes.size(), 6u);
  for (std::size_t r = 0; r < 6; ++r) {
    const Mode& a = res->model().modes[r];
    EXPECT_NEAR(a.frequencyHz(), refined->model.modes[r].frequencyHz(), 1e-9 * a.frequencyHz());
    EXPECT_NEAR(a.zeta(), refined->model.modes[r].zeta(), 1e-9);
    EXPECT_LT(std::abs(a.frequencyHz() - sys.fn[static_cast<Eigen::Index>(r)]) / sys.fn[static_cast<Eigen::Index>(r)],
              1e-3);
    EXPECT_LT(std::abs(a.zeta() - sys.zeta[static_cast<Eigen::Index>(r)]) / sys.zeta[static_cast<Eigen::Index>(r)],
              0.05);
    EXPECT_GT(res->refined->frequencyStdHz[r], 0.0);
    EXPECT_GT(res->refined->zetaStd[r], 0.0);
  }
}

TEST(Identification, CancelStopsInAnyStage) {
  const FrfMatrix frf = accelerances(sixModeSystem(), {2}, 0.0, 400.0, 0.1, 0.01, 7);
  for (IdentificationStage stop :
       {IdentificationStage::Diagram, IdentificationStage::Lsfd, IdentificationStage::Refinement}) {
    auto res = identifyModes(frf, options(), [&](const IdentificationProgress& p) {
      return !(p.stage == stop && (stop != IdentificationStage::Diagram || p.fraction > 0.5));
    });
    ASSERT_FALSE(res.ok());
    EXPECT_EQ(res.error().code, ErrorCode::Cancelled) << identificationStageName(stop);
  }
}

// A click in the diagram: the selected poles minus one. fitSelectedPoles'
// residues equal lsfd()'s; its synthesis equals synthesize() of modal_model.h
// (independent code: per-line sum over modes) to 1e-10 of the data; its
// relative error equals relativeFitError().
TEST(Identification, ReselectionFitMatchesLsfdAndSynthesis) {
  const FrfMatrix frf = accelerances(sixModeSystem(), {2}, 0.0, 400.0, 0.1, 0.01, 7);
  auto res = identifyModes(frf, options());
  ASSERT_TRUE(res.ok()) << res.error().describe();
  std::vector<Complex> poles;
  for (const auto& s : res->selected) poles.push_back(s.pole);
  poles.erase(poles.begin() + 3);  // the user drops the 150 Hz pole
  LsfdOptions band;
  band.bandLowHz = 20.0;
  band.bandHighHz = 380.0;
  auto fit = fitSelectedPoles(frf, poles, band);
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  auto reference = lsfd(frf, poles, band);
  ASSERT_TRUE(reference.ok());
  ASSERT_EQ(fit->model.modes.size(), 5u);
  for (std::size_t r = 0; r < 5; ++r) {
    const ComplexMatrix& a = fit->model.modes[r].residue;
    EXPECT_LT((a - reference->modes[r].residue).norm(), 1e-12 * a.norm());
  }
  ASSERT_EQ(fit->synthesis.lineCount(), 3601);  // 20.0 .. 380.0 Hz at 0.1 Hz
  EXPECT_NEAR(fit->synthesis.frequencyHz[0], 20.0, 1e-9);
  const double scale = frf.h[0].cwiseAbs().maxCoeff();
  double worst = 0.0;
  for (Eigen::Index k = 0; k < fit->synthesis.lineCount(); k += 7) {
    for (Eigen::Index o = 0; o < 6; ++o) {
      const Complex s = synthesize(fit->model, o, 0, 2 * M_PI * fit->synthesis.frequencyHz[k], frf.type);
      worst = std::max(worst, std::abs(s - fit->synthesis.h[0](k, o)));
    }
  }
  EXPECT_LT(worst, 1e-10 * scale);
  auto err = relativeFitError(frf, fit->model, 20.0, 380.0);
  ASSERT_TRUE(err.ok());
  EXPECT_NEAR(fit->relativeError, *err, 1e-9);
  EXPECT_GT(fit->relativeError, 0.05);  // a mode is missing: the fit is visibly worse
  EXPECT_FALSE(fitSelectedPoles(frf, {}, band).ok());
}

}  // namespace
}  // namespace mozzi::core::modal
