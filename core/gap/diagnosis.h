#pragma once
// Diagnosis of the sim-to-real gap (shared/GAP.md steps 0 to 9): calibrate the
// model's own parameters, locate the gap, screen and fit every catalogue
// effect, compare the likelihood-ratio improvement with a threshold calibrated
// by parametric bootstrap, check ambiguity and held-out data, and give a verdict.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"

namespace mozzi::core::gap {

enum class Verdict { Effect, None, Ambiguous, Partial, Unexplained, NotIdentifiable };
const char* verdictName(Verdict verdict);  // "effect", "none", "ambiguous", ...

// How the bootstrap refits each simulated data set (docs/gap.md, "How the
// diagnosis decides"): full nonlinear refits, or the linearisation about the
// baseline (exact for linear-Gaussian problems, checked against full refits in
// tests/core/gap/engine_bootstrap_test.cpp). Auto refits fully when
// bootstrapSamples x (candidates + 1) x residualCount <= 1e6.
enum class NullMethod { Auto, FullRefit, Linearised };

struct DiagnosisOptions {
  std::vector<std::string> effects;  // restrict the catalogue to these names; empty = all
  int multistarts = 8;               // per nonlinear fit (GAP.md: 5 to 20)
  int bootstrapSamples = 200;        // null calibration of the threshold
  double alpha = 0.05;               // false-attribution level of the threshold
  unsigned long long seed = 1;       // every random draw is seeded: reproducible reports
  NullMethod nullMethod = NullMethod::Auto;
  int ambiguitySamples = 20;  // simulations from each of the top two for the flip probability
  double flipLimit = 0.10;    // flip probability above which the top two are "ambiguous" (GAP.md: 10%)
  double fitAlpha = 0.01;     // goodness-of-fit level for "the data are still far from the model"
  int reportTop = 3;          // effects that get held-out checks, gap_after and shrink_pct
  // Called now and then with the fraction done (0..1) and the current step;
  // returning false cancels (diagnose then returns ErrorCode::Cancelled).
  // The workbench runs the diagnosis off the GUI thread and uses this.
  std::function<bool(double fraction, const std::string& step)> progress;
};

struct RankedEffect {
  int candidateIndex = -1;         // index into problem.candidates()
  Candidate candidate;             // effect, location, parameter definitions
  std::vector<double> theta;       // calibration parameters refitted jointly with the effect
  std::vector<double> parameters;  // fitted sizes
  std::vector<double> stdErrors;   // from the final Jacobian; empty when not identifiable
  // 95% profile-likelihood interval per effect parameter (theta and the other
  // parameters refitted); computed for the top-ranked effect only, else empty.
  std::vector<std::pair<double, double>> profileInterval;
  double likelihoodRatio = 0.0;     // 2 (NLL_baseline - NLL_effect)
  double aicc = 0.0;                // tie-break only
  double heldOutImprovement = 0.0;  // relative drop of held-out residual (cross-validation); NaN: one fold
  bool identifiable = true;         // projected signature above the noise scale
  GapMetrics gapAfter;
  double shrinkPct = 0.0;  // 100 (1 - gap_after.overall / gap_before.overall)
  // Linear screen: smallest singular value of the projected signature over the
  // parameter box (noise standard deviations), and per parameter the smallest
  // size the threshold would detect (about half the time), in the parameter's unit.
  double projectedSignature = 0.0;
  std::vector<double> smallestDetectable;
  double chiSquare = 0.0;  // |r|^2 after the fit (whitened data residuals)
  double fitPValue = 1.0;  // chi-square goodness of fit after the fit
  bool fitted = false;     // false when screened out (not identifiable) or the fit failed
  std::string note;        // why not identifiable (singular values, null direction), in words
};

struct Diagnosis {
  std::string dataKind;
  std::vector<Parameter> calibration;  // definitions
  std::vector<double> calibrated;      // fitted theta
  GapMetrics gapBefore;                // at the calibrated baseline
  std::vector<GapEntry> where;         // the flagged rows carrying most of the gap
  double threshold = 0.0;              // bootstrap (1 - alpha) quantile of max LR under no effect
  bool thresholdLinearised = false;    // the bootstrap used the linearised refits
  int bootstrapSamples = 0;
  double chiSquare = 0.0;             // baseline goodness of fit: |r|^2 of the whitened residuals
  int dof = 0;                        // residual count minus free calibration parameters
  double fitPValue = 1.0;             // P(chi2_dof > chiSquare)
  double flipProbability = -1.0;      // top-two ambiguity check; < 0 when not run
  bool flipEstimated = false;         // from the margin alone (LR_1 - LR_2 >= 36), not simulated
  std::string separatingMeasurement;  // where the top two differ most (ambiguous verdicts)
  std::vector<RankedEffect> ranking;  // best first
  Verdict verdict = Verdict::None;
  std::vector<int> verdictSet;  // indices into ranking (several when ambiguous)
  std::string explanation;      // one paragraph a user can read (and the separating measurement)
};

Result<Diagnosis> diagnose(const GapProblem& problem, const DiagnosisOptions& options);

}  // namespace mozzi::core::gap
