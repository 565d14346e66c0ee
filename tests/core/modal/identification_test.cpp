// The identification pipeline as one call (core/modal/identification.h):
// the same numbers as the steps run by hand, progress in stage order, cancel,
// and the re-selection fit against the independent synthesis of modal_model.h.
#include "core/modal/identification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/modal/pole_selection.h"
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

// identifyModes = identifyPlscf (diagram, selection, LSFD) + refineModalModel
// with the options' line budget (the band's 3,601 lines are more than the
// default 2,000: refined on the lines carrying the modes): the same code, so
// the same numbers to rounding; every mode within the issue-5 tolerances
// (0.1% frequency, 5% damping) and its standard errors set.
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
  ro.maxLines = opt.refineMaxLines;
  auto refined = refineModalModel(frf, steps->model, ro);
  ASSERT_TRUE(refined.ok());
  EXPECT_EQ(res->refined->bandLines, 3601);
  EXPECT_EQ(res->refined->fittedLines, refined->fittedLines);
  EXPECT_LT(res->refined->fittedLines, res->refined->bandLines);
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

// The page's pole-click fit: SelectionFitter gives fitSelectedPoles' model
// and relative error, the residual per FRF of residualPerFrf() on its
// synthesis, and one FRF's synthesis; clicks that alternate the mode count
// reuse workspaces and give bit for bit what a fresh fitter gives.
TEST(Identification, SelectionFitterMatchesFitSelectedPoles) {
  const FrfMatrix frf = accelerances(sixModeSystem(), {2, 4}, 0.0, 400.0, 0.1, 0.01, 7);
  auto res = identifyModes(frf, options());
  ASSERT_TRUE(res.ok()) << res.error().describe();
  std::vector<Complex> all;
  for (const auto& s : res->selected) all.push_back(s.pole);
  std::vector<Complex> fewer = all;
  fewer.erase(fewer.begin() + 3);
  LsfdOptions band;
  band.bandLowHz = 20.0;
  band.bandHighHz = 380.0;
  auto fitter = SelectionFitter::create(frf, band);
  ASSERT_TRUE(fitter.ok()) << fitter.error().describe();
  EXPECT_EQ(fitter->lineCount(), 3601);
  EXPECT_NEAR(frf.frequencyHz[fitter->firstLine()], 20.0, 1e-9);
  ComplexVector one;
  EXPECT_FALSE(fitter->synthesis(0, 0, one));  // no fit yet
  const std::vector<std::vector<Complex>> clicks = {all, fewer, all, fewer, all};
  for (std::size_t n = 0; n < clicks.size(); ++n) {
    const auto& poles = clicks[n];
    auto fit = fitter->fit(poles);
    ASSERT_TRUE(fit.ok()) << fit.error().describe();
    auto fresh = SelectionFitter::create(frf, band)->fit(poles);
    ASSERT_TRUE(fresh.ok());
    auto reference = fitSelectedPoles(frf, poles, band);
    ASSERT_TRUE(reference.ok());
    ASSERT_EQ(fit->model.modes.size(), poles.size());
    for (std::size_t r = 0; r < poles.size(); ++r) {
      EXPECT_EQ(fit->model.modes[r].residue, fresh->model.modes[r].residue) << "click " << n << ", mode " << r;
      EXPECT_EQ(fit->model.modes[r].residue, reference->model.modes[r].residue);
    }
    EXPECT_EQ(fit->model.lowerResidual, fresh->model.lowerResidual);
    EXPECT_EQ(fit->model.upperResidual, fresh->model.upperResidual);
    EXPECT_EQ(fit->residual, fresh->residual);
    EXPECT_EQ(fit->relativeError, fresh->relativeError);
    EXPECT_EQ(fit->relativeError, reference->relativeError);
    // Residual per FRF: residualPerFrf of the measured FRFs and the full synthesis.
    FrfMatrix measured = reference->synthesis;
    for (std::size_t i = 0; i < frf.h.size(); ++i)
      measured.h[i] = frf.h[i].middleRows(fitter->firstLine(), fitter->lineCount());
    auto perFrf = residualPerFrf(measured, reference->synthesis, band.bandLowHz, band.bandHighHz);
    ASSERT_TRUE(perFrf.ok());
    ASSERT_EQ(fit->residual.rows(), frf.responseCount());
    ASSERT_EQ(fit->residual.cols(), 2);
    EXPECT_LT((fit->residual - *perFrf).cwiseAbs().maxCoeff(), 1e-12 * perFrf->maxCoeff()) << "click " << n;
    EXPECT_GT(perFrf->minCoeff(), 0.0);
    for (Eigen::Index i = 0; i < 2; ++i) {
      for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
        ASSERT_TRUE(fitter->synthesis(o, i, one));
        const ComplexVector& col = reference->synthesis.h[static_cast<std::size_t>(i)].col(o);
        EXPECT_LE((one - col).cwiseAbs().maxCoeff(), 1e-13 * col.cwiseAbs().maxCoeff());
      }
    }
  }
  // A click that cannot be fitted leaves no synthesis behind.
  EXPECT_FALSE(fitter->fit({}).ok());
  EXPECT_FALSE(fitter->synthesis(0, 0, one));
  EXPECT_FALSE(fitter->fit({Complex(1.0, 10.0)}).ok());
  ASSERT_TRUE(fitter->fit(all).ok());
  EXPECT_FALSE(fitter->synthesis(frf.responseCount(), 0, one));  // no such FRF
  LsfdOptions empty;
  empty.bandLowHz = 500.0;
  empty.bandHighHz = 600.0;
  auto outside = SelectionFitter::create(frf, empty);
  ASSERT_TRUE(outside.ok());
  EXPECT_FALSE(outside->fit(all).ok());  // no line in the band
}

// Re-selection in the diagram of a previous run (the workbench's click then
// "refine"): picking, for every automatically selected mode, the diagram pole
// nearest to it at the highest order gives back the same refined modes, to
// 1% of their standard errors (the refinement converges to the same minimum
// from another start; its stop leaves < 1e-3 standard errors); the diagram is
// kept untouched; dropping a pole gives fitSelectedPoles' residues as the
// LSFD model. Bad selections are errors naming the index.
TEST(Identification, ReselectionKeepsTheDiagramAndRefinesTheChosenPoles) {
  const FrfMatrix frf = accelerances(sixModeSystem(), {2}, 0.0, 400.0, 0.1, 0.01, 7);
  const auto opt = options();
  auto full = identifyModes(frf, opt);
  ASSERT_TRUE(full.ok()) << full.error().describe();
  const auto& diagram = full->diagram;
  const int top = diagram.orders.back();
  std::vector<std::size_t> picks;
  for (const auto& s : full->selected) {
    std::size_t best = diagram.poles.size();
    for (std::size_t i = 0; i < diagram.poles.size(); ++i) {
      if (diagram.poles[i].order != top) continue;
      if (best == diagram.poles.size() ||
          std::abs(diagram.poles[i].pole - s.pole) < std::abs(diagram.poles[best].pole - s.pole))
        best = i;
    }
    ASSERT_LT(best, diagram.poles.size());
    picks.push_back(best);
  }
  std::reverse(picks.begin(), picks.end());  // any order: the result is in frequency order
  std::vector<IdentificationStage> stages;
  auto again = reselectModes(frf, diagram, picks, opt, [&](const IdentificationProgress& p) {
    if (stages.empty() || stages.back() != p.stage) stages.push_back(p.stage);
    return true;
  });
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_EQ(stages, (std::vector<IdentificationStage>{IdentificationStage::Lsfd, IdentificationStage::Refinement}));
  EXPECT_EQ(again->diagram.poles.size(), diagram.poles.size());
  ASSERT_TRUE(again->refined.has_value());
  ASSERT_EQ(again->model().modes.size(), full->model().modes.size());
  for (std::size_t r = 0; r < again->model().modes.size(); ++r) {
    const Mode& a = again->model().modes[r];
    const Mode& b = full->model().modes[r];
    EXPECT_LT(std::abs(a.frequencyHz() - b.frequencyHz()), 0.01 * full->refined->frequencyStdHz[r]) << "mode " << r;
    EXPECT_LT(std::abs(a.zeta() - b.zeta()), 0.01 * full->refined->zetaStd[r]) << "mode " << r;
    EXPECT_NEAR(again->refined->frequencyStdHz[r], full->refined->frequencyStdHz[r],
                0.01 * full->refined->frequencyStdHz[r]);
  }

  // Drop the 150 Hz mode (4th in frequency), LSFD only.
  IdentificationOptions lsfdOnly = opt;
  lsfdOnly.refine = false;
  std::vector<std::size_t> five = picks;
  std::sort(five.begin(), five.end(),
            [&](std::size_t a, std::size_t b) { return diagram.poles[a].pole.imag() < diagram.poles[b].pole.imag(); });
  five.erase(five.begin() + 3);
  auto dropped = reselectModes(frf, diagram, five, lsfdOnly);
  ASSERT_TRUE(dropped.ok()) << dropped.error().describe();
  EXPECT_FALSE(dropped->refined.has_value());
  std::vector<Complex> poles;
  for (std::size_t i : five) poles.push_back(diagram.poles[i].pole);
  LsfdOptions band;
  band.bandLowHz = 20.0;
  band.bandHighHz = 380.0;
  auto preview = fitSelectedPoles(frf, poles, band);
  ASSERT_TRUE(preview.ok());
  ASSERT_EQ(dropped->model().modes.size(), 5u);
  for (std::size_t r = 0; r < 5; ++r) {
    const ComplexMatrix& a = dropped->model().modes[r].residue;
    EXPECT_LT((a - preview->model.modes[r].residue).norm(), 1e-12 * a.norm());
  }

  EXPECT_EQ(reselectModes(frf, diagram, {}, opt).error().code, ErrorCode::InvalidArgument);
  auto outside = reselectModes(frf, diagram, {diagram.poles.size()}, opt);
  ASSERT_FALSE(outside.ok());
  EXPECT_NE(outside.error().message.find(std::to_string(diagram.poles.size())), std::string::npos);
  EXPECT_EQ(reselectModes(frf, diagram, {picks[0], picks[0]}, opt).error().code, ErrorCode::InvalidArgument);
}

}  // namespace
}  // namespace mozzi::core::modal
