#include <cmath>
#include <sstream>

#include "core/common/text.h"
#include "core/gap/engine/pass.h"

// Step 8 of a diagnosis pass (pass.h): the verdict and the explanation a user
// reads.

namespace mozzi::core::gap::engine {
namespace {

// A calibrated parameter this many prior sigmas from its nominal is worth a
// sentence: candidates that can stand in for it gain likelihood from the prior.
constexpr double kPriorTension = 3.0;

// The calibration, the threshold, the noise model and the priors in tension.
void explainBaseline(const Pass& s, std::ostringstream& ex) {
  const DiagnosisOptions& options = s.options;
  const Diagnosis& d = s.d;
  const auto& identifiable = s.identifiable;
  const bool linear = s.linear;
  ex << "Calibrated " << d.calibration.size() << " model parameter(s); the whitened residual chi-square is "
     << formatNumber(d.chiSquare, 4) << " on " << d.dof << " degrees of freedom (p = " << formatNumber(d.fitPValue, 2)
     << "). The attribution threshold is " << formatNumber(d.threshold, 3) << ", the "
     << formatNumber(1 - options.alpha, 3) << " quantile of the largest likelihood ratio over " << identifiable.size()
     << " identifiable candidate(s) in " << d.bootstrapSamples << " data sets simulated without an effect ("
     << (linear ? "linearised refits" : "full refits") << (s.nullFromCache ? ", cached" : "") << "). ";
  if (!d.noise.description.empty()) ex << "Noise model (" << d.noise.source << "): " << d.noise.description << ' ';
  if (d.fitFromBootstrap) {
    ex << "The goodness of fit is judged against the baseline chi-square of the simulated data sets (mean "
       << formatNumber(d.nullChiSquareMean, 4) << ", sd " << formatNumber(d.nullChiSquareSd, 3)
       << "), which carries the noise estimate's own error. ";
  }
  for (std::size_t i = 0; i < d.calibration.size(); ++i) {
    const Parameter& c = d.calibration[i];
    const double pull = c.priorSigma > 0.0 ? std::abs(d.calibrated[i] - c.nominal) / c.priorSigma : 0.0;
    if (pull > kPriorTension) {
      ex << c.name << " calibrates to " << formatNumber(d.calibrated[i], 4) << ", " << formatNumber(pull, 2)
         << " prior standard deviations from its nominal " << formatNumber(c.nominal, 4)
         << ": an effect that can stand in for it gains likelihood from the prior alone (the threshold includes "
            "this). ";
    }
  }
}

}  // namespace

void decideVerdict(Pass& s) {
  const DiagnosisOptions& options = s.options;
  Diagnosis& d = s.d;
  const Screen& screen = *s.screen;
  const auto& identifiable = s.identifiable;
  const std::size_t fittedCount = s.fittedCount;
  const bool significant = s.significant;
  const bool pairHolds = d.pairFitted && d.pair.significant && !d.pair.effects.empty() &&
                         d.pair.effects[0].identifiable && d.pair.effects[1].identifiable &&
                         !(std::isfinite(d.pair.heldOutImprovement) && d.pair.heldOutImprovement <= 0.0);

  // Step 8: verdict.
  std::ostringstream ex;
  explainBaseline(s, ex);
  if (screen.candidates.empty()) {
    d.verdict = d.fitPValue >= options.fitAlpha ? Verdict::None : Verdict::Unexplained;
    ex << "There are no candidate effects to test; the calibrated model "
       << (d.verdict == Verdict::None ? "fits within noise." : "does not fit within noise.");
  } else if (identifiable.empty()) {
    d.verdict = Verdict::NotIdentifiable;
    ex << "No candidate effect can be identified from these data:";
    for (const auto& e : d.ranking) ex << " " << label(e.candidate) << " (" << e.note << ").";
  } else if (!significant) {
    const bool fitsWithinNoise = d.fitPValue >= options.fitAlpha;
    d.verdict = fitsWithinNoise ? Verdict::None : Verdict::Unexplained;
    ex << (fitsWithinNoise ? "The model fits within noise and no effect improves it significantly"
                           : "The model does not fit within noise, yet no catalogue effect improves it significantly")
       << " (best likelihood ratio " << formatNumber(fittedCount ? d.ranking[0].likelihoodRatio : 0.0, 3)
       << "). Smallest detectable changes from nominal (found about half the time at the threshold):";
    for (const auto& e : d.ranking) {
      if (!e.fitted) continue;
      ex << ' ' << label(e.candidate) << ':';
      for (std::size_t j = 0; j < e.smallestDetectable.size(); ++j) {
        ex << ' ' << e.candidate.parameters[j].name << ' ' << formatNumber(e.smallestDetectable[j], 2);
      }
      ex << ';';
    }
  } else {
    const RankedEffect& best = d.ranking[0];
    ex << "Best: " << label(best.candidate) << " with " << sizes(best);
    for (std::size_t j = 0; j < best.profileInterval.size(); ++j) {
      ex << (j ? "; " : " (95% profile interval ") << best.candidate.parameters[j].name << " "
         << formatNumber(best.profileInterval[j].first, 3) << " to " << formatNumber(best.profileInterval[j].second, 3)
         << (j + 1 == best.profileInterval.size() ? ")" : "");
    }
    ex << ", likelihood ratio " << formatNumber(best.likelihoodRatio, 4) << " against " << formatNumber(d.threshold, 3);
    if (std::isfinite(best.heldOutImprovement)) {
      ex << ", held-out residual " << formatNumber(100 * best.heldOutImprovement, 3) << "% lower";
    }
    ex << ", gap shrinks by " << formatNumber(best.shrinkPct, 3) << "%. ";
    const double excess = std::max(d.chiSquare - d.dof, best.likelihoodRatio);
    const double explained = excess > 0.0 ? best.likelihoodRatio / excess : 1.0;
    const bool heldOutFails = std::isfinite(best.heldOutImprovement) && best.heldOutImprovement <= 0.0;
    if (!best.identifiable) {
      d.verdict = Verdict::NotIdentifiable;
      d.verdictSet = {0};
      ex << "Its size cannot be pinned down: " << best.note << '.';
    } else if (heldOutFails && !pairHolds) {
      d.verdict = Verdict::Unexplained;
      ex << "It does not improve the held-out data, so it is not attributed.";
    } else if (best.fitPValue < options.fitAlpha && pairHolds) {
      // (Also when the best alone fails the held-out check: what a second
      // effect leaves in one band can make the first alone worse there.)
      const EffectPair& ep = d.pair;
      d.verdict = ep.fitPValue >= options.fitAlpha ? Verdict::Effect : Verdict::Partial;
      d.verdictSet = ep.rankingIndex;
      ex << "After it the residual is still beyond noise (chi-square " << formatNumber(best.chiSquare, 4)
         << ", p = " << formatNumber(best.fitPValue, 2) << "). Two effects at once: " << label(ep.effects[0].candidate)
         << " with " << sizes(ep.effects[0]) << " and " << label(ep.effects[1].candidate) << " with "
         << sizes(ep.effects[1]) << " (fitted together; each improves the fit given the other by a likelihood ratio of "
         << formatNumber(ep.eachRatio[0], 4) << " and " << formatNumber(ep.eachRatio[1], 4) << " against "
         << formatNumber(d.threshold, 3) << "). The gap is " << formatNumber(d.gapBefore.overall, 3) << " before, "
         << formatNumber(ep.gapAfterOne.overall, 3) << " after the first alone and "
         << formatNumber(ep.gapAfterBoth.overall, 3) << " after both (shrink " << formatNumber(ep.shrinkBothPct, 3)
         << "%). "
         << (d.verdict == Verdict::Effect
                 ? "With both the residual is within noise: attributed to the two."
                 : "Even with both the residual is beyond noise (p = " + formatNumber(ep.fitPValue, 2) +
                       "): the two explain the gap only in part.");
    } else if (best.fitPValue < options.fitAlpha) {
      d.verdict = explained >= 0.5 ? Verdict::Partial : Verdict::Unexplained;
      if (d.verdict == Verdict::Partial) d.verdictSet = {0};
      ex << "After it the residual is still beyond noise (chi-square " << formatNumber(best.chiSquare, 4)
         << ", p = " << formatNumber(best.fitPValue, 2) << "); it explains " << formatNumber(100 * explained, 3)
         << "% of the excess, so the catalogue "
         << (d.verdict == Verdict::Partial ? "explains the gap only in part." : "does not hold the cause.");
    } else if (d.flipProbability > options.flipLimit) {
      d.verdict = Verdict::Ambiguous;
      d.verdictSet = {0, 1};
      ex << "It cannot be told apart from " << label(d.ranking[1].candidate) << " (" << sizes(d.ranking[1])
         << ", likelihood ratio " << formatNumber(d.ranking[1].likelihoodRatio, 4)
         << "): simulating from the fits, the ranking flips in up to " << formatNumber(100 * d.flipProbability, 3)
         << "% of the data sets. They differ most at " << d.separatingMeasurement
         << "; a more precise measurement there would separate them.";
    } else {
      d.verdict = Verdict::Effect;
      d.verdictSet = {0};
      ex << "Attributed";
      if (d.flipProbability >= 0.0) {
        ex << " (against the runner-up " << label(d.ranking[1].candidate) << " the ranking flips in "
           << formatNumber(100 * d.flipProbability, 3)
           << (d.flipEstimated ? "% of cases by the linear-Gaussian estimate for this margin)" : "% of simulations)");
      }
      ex << '.';
    }
  }
  d.explanation = ex.str();
}

}  // namespace mozzi::core::gap::engine
