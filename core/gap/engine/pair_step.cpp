#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "core/gap/engine/pairs.h"
#include "core/gap/engine/pass.h"
#include "core/gap/engine/statistics.h"

// Step 4, pairs, of a diagnosis pass (pass.h): two effects at once when the
// best single leaves a significant residual (or always, when asked).

namespace mozzi::core::gap::engine {
namespace {

// The pair of the warm diagnosis as a start, in this pass's scaling.
std::vector<PairStart> warmPairStarts(const Pass& s) {
  const Diagnosis* warm = s.warm;
  const auto& theta = s.theta;
  const Screen& screen = *s.screen;
  std::vector<engine::PairStart> pairStarts;
  if (warm && warm->pairFitted && warm->pair.effects.size() == 2) {
    const auto& w = warm->pair;
    engine::PairStart ps{w.effects[0].candidateIndex, w.effects[1].candidateIndex, {}};
    std::vector<Scaled> phi;
    std::vector<double> phiX;
    for (const auto& e : w.effects) {
      for (const auto& sc : screen.candidates)
        if (sc.index == e.candidateIndex) phi.insert(phi.end(), sc.phi.begin(), sc.phi.end());
      phiX.insert(phiX.end(), e.parameters.begin(), e.parameters.end());
    }
    if (phi.size() == phiX.size()) {
      ps.u = scaledPoint(theta, w.theta, phi, phiX);
      pairStarts.push_back(std::move(ps));
    }
  }
  return pairStarts;
}

// Each member alone, refitted from the pair's optimum with the other
// removed: a single fit that stopped short of its own optimum would
// otherwise credit the other member with the difference and name a
// second effect of no size. A better optimum replaces the single fit.
void refitAlone(Pass& s, const PairFit& bp, std::size_t m, Eigen::Index offset) {
  const GapProblem& problem = s.problem;
  Diagnosis& d = s.d;
  auto& alt = s.alt;
  const auto& theta = s.theta;
  const FitResult& fit0 = s.fit0;
  const int p = s.p;
  RankedEffect& e = d.ranking[m];
  const auto q = static_cast<Eigen::Index>(alt[m].phi.size());
  Model single(problem, theta, alt[m].candidate, alt[m].phi);
  Eigen::VectorXd start(p + q);
  start << bp.u.head(p), bp.u.segment(p + offset, q);
  FitOptions fo;
  fo.maxIterations = 60;
  const FitResult fit = engine::fitModel(single, {engine::clipToBox(single, start)}, fo);
  const double nllBefore = fit0.nll - 0.5 * e.likelihoodRatio;
  if (!fit.ok || !(fit.nll < nllBefore - 1e-6 * (1.0 + std::abs(nllBefore)))) return;
  alt[m].u = fit.u;
  e.theta = single.thetaX(fit.u);
  e.parameters = single.phiX(fit.u);
  e.likelihoodRatio = std::max(0.0, 2.0 * (fit0.nll - fit.nll));
  e.aicc = aicc(fit.nll, freeCount(theta) + freeCount(alt[m].phi), s.n);
  e.chiSquare = fit.chiSquare;
  e.fitPValue = s.fitP(fit.chiSquare, freeCount(alt[m].phi));
  if (m < static_cast<std::size_t>(s.reportTop)) gapAfter(s, e);
}

// The best pair as reported: its members (best single first, refitted
// alone), its joint fit with standard errors, the held-out check and the gap
// after one and both.
Result<void> describePair(Pass& s, const PairFit& bp, const std::map<int, std::size_t>& rankOf) {
  const GapProblem& problem = s.problem;
  const DiagnosisOptions& options = s.options;
  Diagnosis& d = s.d;
  auto& alt = s.alt;
  const auto& theta = s.theta;
  const FitResult& fit0 = s.fit0;
  const Eigen::VectorXd& u0 = s.u0;
  const int p = s.p;
  const std::size_t fittedCount = s.fittedCount;
  EffectPair& ep = d.pair;
  std::size_t ia = rankOf.at(bp.a), ib = rankOf.at(bp.b);
  const auto qLead = static_cast<Eigen::Index>(alt[ia].phi.size());
  refitAlone(s, bp, ia, 0);
  refitAlone(s, bp, ib, qLead);
  // A refit may have moved a member above the leader: the ranking stays
  // best first (the moved entry goes to the front).
  std::size_t top = 0;
  for (std::size_t i = 1; i < fittedCount; ++i)
    if (d.ranking[i].likelihoodRatio > d.ranking[top].likelihoodRatio) top = i;
  if (top != 0) {
    const auto t = static_cast<long>(top);
    std::rotate(d.ranking.begin(), d.ranking.begin() + t, d.ranking.begin() + t + 1);
    std::rotate(alt.begin(), alt.begin() + t, alt.begin() + t + 1);
    auto moved = [&](std::size_t i) { return i == top ? std::size_t{0} : (i < top ? i + 1 : i); };
    ia = moved(ia);
    ib = moved(ib);
  }
  // Members listed best single first; their sizes sit in the pair's phi
  // as bp.a's then bp.b's.
  std::array<std::pair<std::size_t, Eigen::Index>, 2> members{{{ia, 0}, {ib, qLead}}};
  if (ib < ia) std::swap(members[0], members[1]);
  ia = members[0].first;
  ib = members[1].first;
  const double nllA = fit0.nll - 0.5 * d.ranking[ia].likelihoodRatio;
  const double nllB = fit0.nll - 0.5 * d.ranking[ib].likelihoodRatio;
  ep.rankingIndex = {static_cast<int>(ia), static_cast<int>(ib)};
  ep.likelihoodRatio = std::max(0.0, 2.0 * (fit0.nll - bp.nll));
  // What each member adds beyond the other alone.
  ep.eachRatio = {std::max(0.0, 2.0 * (nllB - bp.nll)), std::max(0.0, 2.0 * (nllA - bp.nll))};
  ep.significant = ep.eachRatio[0] > d.threshold && ep.eachRatio[1] > d.threshold;
  engine::ComboProblem combo(problem, {bp.a, bp.b});
  engine::Model model(combo, theta, 0, bp.phi);
  FitOptions fc;
  fc.covariance = true;
  const FitResult polished = engine::fitModel(model, {bp.u}, fc);
  const bool usePolished = polished.ok && polished.nll <= bp.nll + 1e-9 * (1.0 + std::abs(bp.nll));
  const Eigen::VectorXd u = usePolished ? polished.u : bp.u;
  ep.theta = model.thetaX(u);
  const std::vector<double> phi = model.phiX(u);
  for (const auto& [m, start] : members) {
    const auto offset = static_cast<std::size_t>(start);
    RankedEffect e;
    e.candidateIndex = d.ranking[m].candidateIndex;
    e.candidate = d.ranking[m].candidate;
    e.theta = ep.theta;
    e.fitted = true;
    const std::size_t q = e.candidate.parameters.size();
    e.parameters.assign(phi.begin() + static_cast<long>(offset), phi.begin() + static_cast<long>(offset + q));
    if (usePolished && polished.stdErrors.size() == static_cast<std::size_t>(p) + phi.size()) {
      e.stdErrors.assign(polished.stdErrors.begin() + p + static_cast<long>(offset),
                         polished.stdErrors.begin() + p + static_cast<long>(offset + q));
    } else {
      e.identifiable = false;
      e.note = "no covariance at the joint optimum";
    }
    ep.effects.push_back(std::move(e));
  }
  ep.chiSquare = bp.chiSquare;
  ep.fitPValue = s.fitP(bp.chiSquare, freeCount(bp.phi));
  // The combination's baseline is the problem's own (ComboProblem's
  // candidate -1): the fold fits already made serve.
  if (!s.heldBaseline) {
    MOZZI_TRY_ASSIGN(s.heldBaseline, engine::heldOutBaseline(problem, theta, u0));
  }
  MOZZI_TRY_ASSIGN(ep.heldOutImprovement,
                   engine::heldOutImprovement(combo, theta, u0, {0, bp.phi, u}, *s.heldBaseline));
  for (std::size_t m : {ia, ib}) {
    RankedEffect& e = d.ranking[m];
    if (e.gapAfter.entries.empty() && e.gapAfter.overall == 0.0) gapAfter(s, e);
  }
  ep.gapAfterOne = d.ranking[ia].gapAfter;
  ep.shrinkOnePct = d.ranking[ia].shrinkPct;
  ep.gapAfterBoth = problem.combinedMetrics(ep.theta.data(), {bp.a, bp.b}, phi.data());
  applyHolmFlags(ep.gapAfterBoth, options.alpha);
  ep.shrinkBothPct = d.gapBefore.overall != 0.0 ? 100.0 * (1.0 - ep.gapAfterBoth.overall / d.gapBefore.overall) : 0.0;
  return {};
}

}  // namespace

Result<void> fitPairStep(Pass& s) {
  const GapProblem& problem = s.problem;
  const DiagnosisOptions& options = s.options;
  Diagnosis& d = s.d;
  const auto& alt = s.alt;
  const auto& theta = s.theta;
  const FitResult& fit0 = s.fit0;
  const std::size_t fittedCount = s.fittedCount;
  const bool significant = s.significant;
  const bool wantPairs =
      options.pairs != DiagnosisOptions::PairMode::Never && significant && fittedCount >= 2 &&
      d.ranking[0].identifiable &&
      (options.pairs == DiagnosisOptions::PairMode::Always || d.ranking[0].fitPValue < options.fitAlpha);
  if (wantPairs) {
    if (!s.keepGoing(0.96, "pair fits")) return s.cancelled();
    std::vector<engine::SingleFit> singles;
    std::map<int, std::size_t> rankOf;  // candidate -> ranking index
    for (std::size_t i = 0; i < fittedCount; ++i) {
      rankOf[d.ranking[i].candidateIndex] = i;
      if (!d.ranking[i].identifiable) continue;
      singles.push_back({alt[i].candidate, alt[i].phi, alt[i].u, fit0.nll - 0.5 * d.ranking[i].likelihoodRatio});
    }
    std::vector<engine::PairStart> pairStarts = warmPairStarts(s);
    MOZZI_TRY_ASSIGN(const std::vector<engine::PairFit> pairs,
                     engine::fitPairs(problem, theta, singles, options.pairLeaders, pairStarts,
                                      [&](double f) { return s.keepGoing(0.96 + 0.03 * f, "pair fits"); }));
    d.pairFitted = true;
    d.pair.pairsFitted = static_cast<int>(pairs.size());
    if (!pairs.empty()) return describePair(s, pairs.front(), rankOf);
  }
  return {};
}

}  // namespace mozzi::core::gap::engine
