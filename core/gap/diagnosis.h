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
  // Two effects at once (issue 16): Auto fits pairs when the best single
  // effect is significant yet leaves a residual beyond noise; Always fits them
  // whenever an effect is significant (the verdict still uses them only then);
  // Never skips them. Pairs: each of the best `pairLeaders` singles with every
  // other candidate the problem can combine it with.
  enum class PairMode { Auto, Always, Never };
  PairMode pairs = PairMode::Auto;
  int pairLeaders = 3;
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

// Two effects fitted jointly (issue 16). A verdict `effect` (or `partial`)
// names both when each improves the fit beyond the attribution threshold given
// the other and the pair fits where the best single does not.
struct EffectPair {
  std::vector<RankedEffect> effects;  // the two: candidate, joint sizes and standard errors (leader first)
  std::vector<int> rankingIndex;      // their entries in Diagnosis::ranking (single fits)
  std::vector<double> theta;          // calibration refitted with both
  double likelihoodRatio = 0.0;       // 2 (NLL_baseline - NLL_pair)
  std::vector<double> eachRatio;      // per member: 2 (NLL of the other alone - NLL_pair)
  double chiSquare = 0.0;
  double fitPValue = 1.0;
  double heldOutImprovement = 0.0;  // relative drop of the held-out residual against the baseline
  GapMetrics gapAfterOne;           // after the leader alone (its single fit)
  GapMetrics gapAfterBoth;
  double shrinkOnePct = 0.0, shrinkBothPct = 0.0;
  bool significant = false;  // both members beyond the threshold
  int pairsFitted = 0;       // pairs tried
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
  double chiSquare = 0.0;  // baseline goodness of fit: |r|^2 of the whitened residuals
  int dof = 0;             // residual count minus free calibration parameters
  double fitPValue = 1.0;  // P(chi2_dof > chiSquare), or against the bootstrap's null (below)
  NoiseModel noise;        // the noise model behind the whitening (issue 16)
  // With a noise model estimated from the data, the goodness of fit is judged
  // against the baseline chi-square of the bootstrap's simulated data sets
  // (normal with their mean and standard deviation, at least sqrt(2 dof),
  // plus NoiseModel::chiSquareVariance), which carries the estimate's own
  // error; otherwise against chi2_dof.
  bool fitFromBootstrap = false;
  double nullChiSquareMean = 0.0, nullChiSquareSd = 0.0;
  bool pairFitted = false;  // pairs were fitted (pair below is the best)
  EffectPair pair;
  double flipProbability = -1.0;      // top-two ambiguity check; < 0 when not run
  bool flipEstimated = false;         // from the margin alone (LR_1 - LR_2 >= 36), not simulated
  std::string separatingMeasurement;  // where the top two differ most (ambiguous verdicts)
  std::vector<RankedEffect> ranking;  // best first
  Verdict verdict = Verdict::None;
  std::vector<int> verdictSet;  // indices into ranking (several when ambiguous, or two effects at once)
  std::string explanation;      // one paragraph a user can read (and the separating measurement)
};

Result<Diagnosis> diagnose(const GapProblem& problem, const DiagnosisOptions& options);

}  // namespace mozzi::core::gap
