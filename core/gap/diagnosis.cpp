#include "core/gap/diagnosis.h"

#include <algorithm>
#include <string>

#include "core/common/enum_names.h"
#include "core/gap/engine/pass.h"

namespace mozzi::core::gap {

namespace {
constexpr EnumEntry<Verdict, const char*> kVerdictEntries[] = {
    {Verdict::Effect, "effect"},           {Verdict::None, "none"},
    {Verdict::Ambiguous, "ambiguous"},     {Verdict::Partial, "partial"},
    {Verdict::Unexplained, "unexplained"}, {Verdict::NotIdentifiable, "not_identifiable"}};
constexpr auto kVerdictNames = enumTable(kVerdictEntries, "none");
}  // namespace

const char* verdictName(Verdict verdict) {
  return kVerdictNames.of(verdict);
}

namespace {

// An effect was found that makes a better reference for the noise estimate
// than the nominal model: attributed, in part or ambiguously, so it holds on
// held-out data (an `unexplained` best effect may fit noise or worse).
bool wantsSecondNoisePass(const Diagnosis& d) {
  const bool found = d.verdict == Verdict::Effect || d.verdict == Verdict::Partial || d.verdict == Verdict::Ambiguous;
  return found && !d.ranking.empty() && d.ranking[0].fitted && d.ranking[0].likelihoodRatio > d.threshold;
}

// Steps 1 to 9 of GAP.md with the problem's noise model as it stands, each
// step a function of core/gap/engine/ (pass.h). With `warm` (a diagnosis of
// the same data under another noise model) every fit starts from its optimum
// there instead of searching again: the optima move little when only the
// weights change, and the search was most of the time.
Result<Diagnosis> diagnoseOnce(const GapProblem& problem, const DiagnosisOptions& options, const Diagnosis* warm,
                               bool firstOfTwo) {
  engine::Pass s(problem, options, warm, firstOfTwo);
  MOZZI_TRY(engine::prepare(s));
  MOZZI_TRY(engine::calibrate(s));
  MOZZI_TRY(engine::screenAndNull(s));
  MOZZI_TRY(engine::fitCandidates(s));
  // Steps 7 and 9: held-out checks, gap after and shrink for the top few.
  if (!s.keepGoing(0.85, "held-out checks")) return s.cancelled();
  MOZZI_TRY(engine::checkHeldOut(s, static_cast<std::size_t>(std::max(0, s.reportTop))));
  MOZZI_TRY(engine::profileTop(s));
  MOZZI_TRY(engine::ambiguity(s));
  MOZZI_TRY(engine::fitPairStep(s));
  engine::decideVerdict(s);
  if (firstOfTwo && !wantsSecondNoisePass(s.d)) {
    MOZZI_TRY(engine::checkHeldOut(s, static_cast<std::size_t>(std::max(0, options.reportTop))));
  }
  if (!s.keepGoing(1.0, "done")) return s.cancelled();
  return std::move(s.d);
}

}  // namespace

Result<Diagnosis> diagnose(const GapProblem& problem, const DiagnosisOptions& options) {
  // Step 0 again, for a noise model estimated from the data: its first
  // estimate, against the nominal model, reads as noise whatever model error
  // its estimator cannot tell from scatter (a resonance the effect moved), so
  // a second effect can hide inside it. With an effect found, the noise is
  // estimated again from the residual against that fit (the pair's when a
  // pair holds) and the diagnosis runs once more on it.
  const bool twoPasses = problem.noiseModel().source == "estimated";
  DiagnosisOptions first = options;
  if (twoPasses && options.progress) {
    first.progress = [&](double f, const std::string& step) { return options.progress(0.5 * f, step); };
  }
  auto d = diagnoseOnce(problem, first, nullptr, twoPasses);
  if (!d || !twoPasses) return d;
  if (!wantsSecondNoisePass(*d)) return d;
  const bool pairHolds = d->verdictSet.size() == 2 && d->pairFitted && d->pair.effects.size() == 2 &&
                         d->verdictSet == d->pair.rankingIndex;
  std::unique_ptr<GapProblem> again;
  std::string reference;
  if (pairHolds) {
    std::vector<double> phi = d->pair.effects[0].parameters;
    phi.insert(phi.end(), d->pair.effects[1].parameters.begin(), d->pair.effects[1].parameters.end());
    again = problem.withNoiseReference(
        d->pair.theta.data(), {d->pair.effects[0].candidateIndex, d->pair.effects[1].candidateIndex}, phi.data());
    reference = label(d->pair.effects[0].candidate) + " and " + label(d->pair.effects[1].candidate);
  } else {
    const RankedEffect& best = d->ranking[0];
    again = problem.withNoiseReference(best.theta.data(), {best.candidateIndex}, best.parameters.data());
    reference = label(best.candidate);
  }
  if (!again) return d;
  DiagnosisOptions second = options;
  if (options.progress) {
    second.progress = [&](double f, const std::string& step) { return options.progress(0.5 + 0.5 * f, step); };
  }
  auto d2 = diagnoseOnce(*again, second, &*d, false);
  if (!d2) return d2;
  d2->explanation = "The noise was estimated twice: first from the residual against the nominal model (verdict " +
                    std::string(verdictName(d->verdict)) + ", best " + label(d->ranking[0].candidate) +
                    "), then from the residual against the fit of " + reference +
                    ", which leaves less model error to be read as noise; this diagnosis uses the second. " +
                    d2->explanation;
  return d2;
}

}  // namespace mozzi::core::gap
