#pragma once
// One pass of diagnose() (core/gap/diagnosis.cpp): steps 1 to 9 of GAP.md
// with the problem's noise model as it stands. The state the steps share, and
// the steps in the order diagnosis.cpp runs them, each defined in the file of
// its name under core/gap/engine/ (pass.cpp: preparation, calibration, screen
// and null; candidate_fits.cpp; checks_step.cpp: held-out, profile and
// ambiguity; pair_step.cpp; verdict.cpp).

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"
#include "core/gap/diagnosis.h"
#include "core/gap/engine/bootstrap.h"
#include "core/gap/engine/checks.h"
#include "core/gap/engine/fit.h"
#include "core/gap/engine/screen.h"

namespace mozzi::core::gap::engine {

// Random starts run this many iterations each before the best is polished
// (the calibration's and the candidates' fits).
constexpr int kStartIterations = 20;

struct Pass {
  // With `warm` (a diagnosis of the same data under another noise model)
  // every fit starts from its optimum there instead of searching again: the
  // optima move little when only the weights change, and the search was most
  // of the time. A first pass that a second will replace (`firstOfTwo`)
  // checks the leader alone on held-out data (the rest when no second pass
  // follows, at the end).
  Pass(const GapProblem& problem, const DiagnosisOptions& options, const Diagnosis* warm, bool firstOfTwo);

  const GapProblem& problem;
  const DiagnosisOptions& options;
  const Diagnosis* warm;
  const bool firstOfTwo;
  const std::string where = "gap diagnosis";
  const int reportTop;
  const int n;  // residual count

  Diagnosis d;
  std::vector<Scaled> theta;
  std::vector<Candidate> candidates;
  std::vector<std::pair<int, std::vector<Scaled>>> selected;  // (candidate, its scaled phi)
  // Step 1: the calibrated baseline.
  std::optional<Model> base;
  FitResult fit0;
  Eigen::VectorXd u0;
  // Steps 3 and 5: the linear screen and the null calibration.
  std::optional<Screen> screen;
  std::vector<int> identifiable;
  bool linear = false;
  bool nullFromCache = false;
  // Step 4: per screened candidate.
  Eigen::VectorXd rAug0;
  int p = 0;  // parameter count of the baseline
  std::vector<FitResult> fits;
  std::vector<char> needsRestarts;
  std::vector<double> firstLr;
  std::vector<FittedAlternative> alt;  // parallel to the fitted part of d.ranking
  std::size_t fittedCount = 0;
  std::optional<HeldOutBaseline> heldBaseline;  // the baseline's fold fits, once
  bool significant = false;                     // step 6: the leader beats the threshold

  bool keepGoing(double fraction, const std::string& step) const;
  Error cancelled() const;
  // Goodness of fit of a model with `extra` free parameters beyond theta.
  double fitP(double chi2, int extra) const;
};

// Options checked, calibration parameters scaled, candidates selected.
Result<void> prepare(Pass& s);
// Steps 1 (calibrate theta) and 2 (where).
Result<void> calibrate(Pass& s);
// Steps 3 (linear screen) and 5 (null calibration, before 4 so the fits can
// report against it).
Result<void> screenAndNull(Pass& s);
// Step 4: nonlinear fit of every identifiable candidate jointly with theta,
// then the ranking.
Result<void> fitCandidates(Pass& s);
// Steps 7 and 9 for the first `count` ranks not yet checked.
Result<void> checkHeldOut(Pass& s, std::size_t count);
// Step 4, end: profile-likelihood interval of the top effect's sizes.
Result<void> profileTop(Pass& s);
// Step 6: ambiguity between the top two.
Result<void> ambiguity(Pass& s);
// Step 4, pairs: two effects at once when the best single leaves a
// significant residual (or always, when asked).
Result<void> fitPairStep(Pass& s);
// Step 8: verdict and explanation.
void decideVerdict(Pass& s);

// Shared by the steps.
std::string sizes(const RankedEffect& e);
std::string singularReport(const Eigen::VectorXd& values, const Eigen::VectorXd& direction, const char* valuesName,
                           const char* directionName);
double aicc(double nll, int k, int n);
int freeCount(const std::vector<Scaled>& s);
std::string separating(const GapMetrics& a, const GapMetrics& b, const std::string& nameA, const std::string& nameB);
Eigen::VectorXd scaledPoint(const std::vector<Scaled>& theta, const std::vector<double>& thetaX,
                            const std::vector<Scaled>& phi, const std::vector<double>& phiX);
// Gap after an effect and its shrink against the gap before (step 9).
void gapAfter(const Pass& s, RankedEffect& e);

}  // namespace mozzi::core::gap::engine
