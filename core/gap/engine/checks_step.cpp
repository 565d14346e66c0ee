#include <algorithm>
#include <cmath>

#include "core/gap/engine/pass.h"
#include "core/gap/engine/statistics.h"

// Steps 7, 9, the end of 4 and 6 of a diagnosis pass (pass.h): held-out
// checks with the gap after each effect, the profile-likelihood interval of
// the top effect and the ambiguity between the top two.

namespace mozzi::core::gap::engine {
namespace {

// Top-two margins LR_a - LR_b above this are not simulated: under the linear-
// Gaussian approximation the flip probability is Phi(-sqrt(D) / 2) < 0.0014.
constexpr double kObviousMargin = 36.0;

}  // namespace

Result<void> checkHeldOut(Pass& s, std::size_t count) {
  Diagnosis& d = s.d;
  std::vector<std::size_t> unchecked;
  for (std::size_t i = 0; i < std::min(s.fittedCount, count); ++i)
    if (std::isnan(d.ranking[i].heldOutImprovement)) unchecked.push_back(i);
  for (std::size_t i : unchecked) {
    RankedEffect& e = d.ranking[i];
    if (!s.heldBaseline) {
      MOZZI_TRY_ASSIGN(s.heldBaseline, engine::heldOutBaseline(s.problem, s.theta, s.u0));
    }
    MOZZI_TRY_ASSIGN(e.heldOutImprovement,
                     engine::heldOutImprovement(s.problem, s.theta, s.u0, s.alt[i], *s.heldBaseline));
    gapAfter(s, e);
  }
  return {};
}

Result<void> profileTop(Pass& s) {
  Diagnosis& d = s.d;
  if (s.fittedCount > 0 && d.ranking[0].identifiable && !d.ranking[0].stdErrors.empty()) {
    if (!s.keepGoing(0.93, "profile likelihood")) return s.cancelled();
    for (std::size_t j = 0; j < d.ranking[0].stdErrors.size(); ++j) {
      auto interval = engine::profileInterval(s.problem, s.theta, s.alt[0], static_cast<int>(j),
                                              d.ranking[0].stdErrors[j], chiSquareQuantile(0.95, 1.0));
      if (!interval) {
        d.ranking[0].profileInterval.clear();
        break;
      }
      d.ranking[0].profileInterval.push_back(*interval);
    }
  }
  return {};
}

Result<void> ambiguity(Pass& s) {
  const GapProblem& problem = s.problem;
  const DiagnosisOptions& options = s.options;
  Diagnosis& d = s.d;
  const std::size_t fittedCount = s.fittedCount;
  s.significant = fittedCount > 0 && d.ranking[0].likelihoodRatio > d.threshold;
  const bool significant = s.significant;
  const double margin = fittedCount > 1 ? d.ranking[0].likelihoodRatio - d.ranking[1].likelihoodRatio : 0.0;
  if (significant && fittedCount > 1 && margin >= kObviousMargin) {
    // Linear-Gaussian estimate: the margin's sd is ~2 sqrt(margin), so a flip
    // needs a sqrt(margin) / 2 >= 3 sd excursion.
    d.flipProbability = 0.5 * std::erfc(std::sqrt(margin) / 2.0 / std::sqrt(2.0));
    d.flipEstimated = true;
  } else if (significant && fittedCount > 1) {
    MOZZI_TRY_ASSIGN(
        d.flipProbability,
        engine::flipProbability(problem, s.theta, s.alt[0], s.alt[1],
                                d.ranking[0].likelihoodRatio - d.ranking[1].likelihoodRatio, options.ambiguitySamples,
                                options.seed, [&] { return s.keepGoing(0.95, "ambiguity check"); }));
    if (d.flipProbability > options.flipLimit) {
      const auto ma = d.ranking[0].gapAfter.entries.empty()
                          ? problem.metrics({d.ranking[0].theta.data(), d.ranking[0].candidateIndex,
                                             d.ranking[0].parameters.data()})
                          : d.ranking[0].gapAfter;
      const auto mb =
          problem.metrics({d.ranking[1].theta.data(), d.ranking[1].candidateIndex, d.ranking[1].parameters.data()});
      d.separatingMeasurement = separating(ma, mb, d.ranking[0].candidate.effect, d.ranking[1].candidate.effect);
    }
  }
  return {};
}

}  // namespace mozzi::core::gap::engine
