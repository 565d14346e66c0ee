#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

#include "core/common/parallel.h"
#include "core/common/text.h"
#include "core/gap/engine/pass.h"

namespace mozzi::core::gap::engine {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Candidate fits: nonlinear and linear-screen likelihood ratios within 10%
// (plus 1) count as "locally linear" (random restarts skipped).
constexpr double kLinearAgreement = 0.1;
// Random restarts for at most this many leading candidates (by the LR of the
// deterministic starts).
constexpr int kRestartedCandidates = 5;
// ... and only those whose first likelihood ratio is at least this share of the
// leader's: a candidate explaining less than a quarter of what the leader does
// from its linear and nominal starts does not overtake it from random ones
// (the restarts were most of a diagnosis's time on 16,000-residual problems).
constexpr double kRestartShare = 0.25;
// An LR difference below 2 (one AIC unit) does not separate two candidates;
// only then does AICc order them (Burnham and Anderson 2002, §2.6).
constexpr double kAiccTieBand = 2.0;
// Grid minima tried per candidate beside its two deterministic starts.
constexpr int kGridStarts = 2;

// 4a. Two deterministic starts per candidate: (theta_0, phi nominal) and the
// linear prediction. When both reach the same optimum and the likelihood
// ratio is what the linear screen predicted, the candidate is locally linear
// about the baseline and random restarts cannot improve on it.
Result<void> firstFits(Pass& s) {
  const GapProblem& problem = s.problem;
  const Diagnosis* warm = s.warm;
  const auto& theta = s.theta;
  const Screen& screen = *s.screen;
  const Eigen::VectorXd& u0 = s.u0;
  const FitResult& fit0 = s.fit0;
  const Eigen::VectorXd& rAug0 = s.rAug0;
  const int p = s.p;
  const std::size_t candidateCount = screen.candidates.size();
  auto& fits = s.fits;
  auto& needsRestarts = s.needsRestarts;
  auto& firstLr = s.firstLr;
  fits.assign(candidateCount, FitResult{});
  needsRestarts.assign(candidateCount, 0);
  firstLr.assign(candidateCount, -1.0);
  // The candidates' fits are independent: one task each, spread over the
  // cores (each writes its own slots; the results do not depend on the order).
  const auto mainThread = std::this_thread::get_id();
  std::atomic<bool> stopped{false};
  std::atomic<std::size_t> finished{0};
  auto progressOnMain = [&](double fraction, const char* step) {
    if (std::this_thread::get_id() == mainThread && !s.keepGoing(fraction, step)) stopped = true;
  };
  parallelFor(candidateCount, [&](std::size_t c) {
    if (stopped) return;
    progressOnMain(0.7 + 0.1 * static_cast<double>(finished++) / static_cast<double>(candidateCount), "candidate fits");
    const auto& sc = screen.candidates[c];
    if (!sc.identifiable) return;
    Model model(problem, theta, sc.index, sc.phi);
    const int q = static_cast<int>(sc.phi.size());
    Eigen::VectorXd s0 = Eigen::VectorXd::Zero(p + q), seed;
    s0.head(p) = u0;
    const double linearLr = screen.linearRatio(static_cast<int>(c), rAug0, &seed);
    const RankedEffect* before = nullptr;
    if (warm) {
      for (const auto& e : warm->ranking)
        if (e.candidateIndex == sc.index && e.fitted) before = &e;
    }
    if (before) {
      fits[c] = engine::fitModel(model, {scaledPoint(theta, before->theta, sc.phi, before->parameters)}, {});
      if (fits[c].ok) firstLr[c] = 2.0 * (fit0.nll - fits[c].nll);
      return;
    }
    Eigen::VectorXd s1 = s0;
    s1.tail(q) = seed;
    const FitResult a = engine::fitModel(model, {s0}, {}), b = engine::fitModel(model, {s1}, {});
    fits[c] = a.ok && (!b.ok || a.nll <= b.nll) ? a : b;
    // The local minima of a grid along each size that lie below the fit so
    // far: a resonance moved past a few lines (a spring at 1.8 times its
    // stiffness) leaves a minimum at nominal that neither start above leaves.
    bool gridBetter = false;
    Eigen::VectorXd work;
    const double reached = fits[c].ok ? engine::dataCost(model, fits[c].u, work) : kInf;
    if (const auto grid = engine::gridStarts(model, p, q, s0, kGridStarts, reached); !grid.empty()) {
      FitOptions staged;
      staged.startIterations = kStartIterations;
      const FitResult g = engine::fitModel(model, grid, staged);
      gridBetter = g.ok && (!fits[c].ok || g.nll < fits[c].nll - 1e-6 * (1.0 + std::abs(fits[c].nll)));
      if (gridBetter) fits[c] = g;
    }
    if (!fits[c].ok) return;
    firstLr[c] = 2.0 * (fit0.nll - fits[c].nll);
    const bool sameOptimum = a.ok && b.ok && std::abs(a.nll - b.nll) <= 1e-6 * (1.0 + std::abs(a.nll));
    needsRestarts[c] =
        gridBetter || !(sameOptimum && std::abs(firstLr[c] - linearLr) <= kLinearAgreement * linearLr + 1.0);
  });
  if (stopped) return s.cancelled();
  return {};
}

// 4b. Random restarts (multistarts - 2 seeded draws of phi in its box, 20
// iterations each, the best polished) for the leading candidates that are
// not locally linear: they decide the verdict, and restarts cost most of the
// fitting time on large FRF problems.
Result<void> restartLeaders(Pass& s) {
  const GapProblem& problem = s.problem;
  const DiagnosisOptions& options = s.options;
  const auto& theta = s.theta;
  const Screen& screen = *s.screen;
  const Eigen::VectorXd& u0 = s.u0;
  const int p = s.p;
  const std::size_t candidateCount = screen.candidates.size();
  auto& fits = s.fits;
  const auto& needsRestarts = s.needsRestarts;
  const auto& firstLr = s.firstLr;
  std::vector<std::size_t> byLr;
  for (std::size_t c = 0; c < candidateCount; ++c) {
    if (fits[c].ok) byLr.push_back(c);
  }
  std::stable_sort(byLr.begin(), byLr.end(), [&](std::size_t a, std::size_t b) { return firstLr[a] > firstLr[b]; });
  if (byLr.size() > static_cast<std::size_t>(kRestartedCandidates)) byLr.resize(kRestartedCandidates);
  // Restarts only where they could change the verdict: candidates within
  // a factor kRestartShare of the leader's likelihood ratio.
  std::vector<std::size_t> restarted;
  for (std::size_t c : byLr) {
    if (needsRestarts[c] && options.multistarts > 2 && firstLr[c] >= kRestartShare * firstLr[byLr.front()]) {
      restarted.push_back(c);
    }
  }
  if (!restarted.empty() && !s.keepGoing(0.8, "candidate restarts")) return s.cancelled();
  // One task per (candidate, start), then per candidate the best start
  // polished: the same fits as fitModel's staged multistart, spread evenly
  // over the cores (a task per candidate left one core idle at the end).
  const int randomCount = std::max(0, options.multistarts - 2);
  std::vector<Eigen::VectorXd> randomStarts;
  for (std::size_t c : restarted) {
    const auto& sc = screen.candidates[c];
    const Model model(problem, theta, sc.index, sc.phi);
    auto crng = engine::seededRng(options.seed, 10, static_cast<unsigned long long>(sc.index));
    for (int i = 0; i < randomCount; ++i) {
      Eigen::VectorXd r = engine::randomStart(model, crng);
      r.head(p) = u0;
      randomStarts.push_back(r);
    }
  }
  FitOptions staged;
  if (randomCount > 1) staged.maxIterations = kStartIterations;
  std::vector<FitResult> startFits(randomStarts.size());
  parallelFor(randomStarts.size(), [&](std::size_t t) {
    const auto& sc = screen.candidates[restarted[t / static_cast<std::size_t>(randomCount)]];
    startFits[t] = engine::fitModel(Model(problem, theta, sc.index, sc.phi), {randomStarts[t]}, staged);
  });
  parallelFor(restarted.size(), [&](std::size_t r) {
    const std::size_t c = restarted[r];
    const auto& sc = screen.candidates[c];
    const Model model(problem, theta, sc.index, sc.phi);
    const FitResult* best = nullptr;  // the lowest NLL, the first on ties
    for (int i = 0; i < randomCount; ++i) {
      const FitResult& f = startFits[r * static_cast<std::size_t>(randomCount) + static_cast<std::size_t>(i)];
      if (f.ok && (!best || f.nll < best->nll)) best = &f;
    }
    if (!best) return;
    FitResult more = *best;
    if (randomCount > 1) {
      const FitResult polished = engine::fitModel(model, {best->u}, {});
      if (polished.ok && polished.nll < more.nll) more = polished;
    }
    if (more.nll < fits[c].nll) fits[c] = more;
  });
  return {};
}

// 4c. Covariance at each optimum (a restart there converges at once), the
// ranked effects, then the rank: likelihood ratio, AICc only inside the tie
// band.
Result<void> collectAndRank(Pass& s) {
  const GapProblem& problem = s.problem;
  Diagnosis& d = s.d;
  const auto& theta = s.theta;
  const Screen& screen = *s.screen;
  const FitResult& fit0 = s.fit0;
  const int p = s.p;
  const int n = s.n;
  const auto& candidates = s.candidates;
  const auto& fits = s.fits;
  const std::size_t candidateCount = screen.candidates.size();
  std::vector<RankedEffect> fitted, unfitted;
  std::vector<engine::FittedAlternative> alternatives;  // parallel to `fitted`
  auto notIdentifiable = [&](const engine::ScreenedCandidate& sc) {
    std::ostringstream note;
    note << "not identifiable with these data: " << sc.reason << "; "
         << singularReport(sc.jointSingularValues, sc.nullDirection, "singular values of the whitened [J S] are",
                           "weakest direction");
    return note.str();
  };
  if (!s.keepGoing(0.82, "standard errors")) return s.cancelled();
  std::vector<FitResult> polishedFits(candidateCount);
  parallelFor(candidateCount, [&](std::size_t c) {
    const auto& sc = screen.candidates[c];
    if (!sc.identifiable || !fits[c].ok) return;
    Model model(problem, theta, sc.index, sc.phi);
    FitOptions fc;
    fc.covariance = true;
    polishedFits[c] = engine::fitModel(model, {fits[c].u}, fc);
  });
  for (std::size_t c = 0; c < candidateCount; ++c) {
    const auto& sc = screen.candidates[c];
    RankedEffect e;
    e.candidateIndex = sc.index;
    e.candidate = candidates[static_cast<std::size_t>(sc.index)];
    e.projectedSignature = sc.sigmaMin;
    for (std::size_t j = 0; j < sc.phi.size(); ++j) {
      // LR of a size-delta effect ~ (delta |B_j|)^2: the threshold is reached at
      // delta = sqrt(T) / |B_j| (detected about half the time).
      // A candidate the screen could not evaluate has no projected norms:
      // nothing is detectable through it.
      const double bj = j < sc.projectedNorm.size() ? sc.projectedNorm[j] : 0.0;
      e.smallestDetectable.push_back(bj > 0.0 ? std::sqrt(std::max(d.threshold, 0.0)) / bj * sc.phi[j].scale
                                              : std::numeric_limits<double>::infinity());
    }
    for (const auto& ph : sc.phi) e.parameters.push_back(ph.def.nominal);
    e.theta = d.calibrated;
    if (!sc.identifiable || !fits[c].ok) {
      e.identifiable = false;
      e.note = sc.identifiable ? "the model with this effect could not be fitted from any start" : notIdentifiable(sc);
      unfitted.push_back(std::move(e));
      continue;
    }
    Model model(problem, theta, sc.index, sc.phi);
    const int q = static_cast<int>(sc.phi.size());
    FitResult fit = fits[c];
    const FitResult& polished = polishedFits[c];
    if (polished.ok && polished.nll <= fit.nll + 1e-9 * (1.0 + fit.nll)) fit = polished;
    e.fitted = true;
    e.theta = model.thetaX(fit.u);
    e.parameters = model.phiX(fit.u);
    e.likelihoodRatio = std::max(0.0, 2.0 * (fit0.nll - fit.nll));
    const int k = freeCount(theta) + freeCount(sc.phi);
    e.aicc = aicc(fit.nll, k, n);
    e.chiSquare = fit.chiSquare;
    e.fitPValue = s.fitP(fit.chiSquare, freeCount(sc.phi));
    e.heldOutImprovement = kNaN;
    if (fit.rankDeficient) {
      e.identifiable = false;
      std::ostringstream note;
      note << "not identifiable at the fitted point: the whitened Jacobian is rank deficient (Ceres covariance "
              "refused it); "
           << singularReport(fit.singularValues, fit.nullDirection, "singular values", "null direction");
      e.note = note.str();
    } else if (static_cast<int>(fit.stdErrors.size()) != p + q) {
      e.identifiable = false;
      e.note = "no covariance at the fitted point: the model could not be evaluated next to it";
    } else {
      e.stdErrors.assign(fit.stdErrors.begin() + p, fit.stdErrors.end());
      for (int j = 0; j < q; ++j) {
        const Scaled& ph = sc.phi[static_cast<std::size_t>(j)];
        // A standard error wider than the whole admissible range: the data do
        // not pin the size down although the Jacobian is not singular.
        if (!ph.fixed && std::isfinite(ph.def.upper - ph.def.lower) &&
            e.stdErrors[static_cast<std::size_t>(j)] > ph.def.upper - ph.def.lower) {
          e.identifiable = false;
          e.note = "not identifiable in practice: the standard error of " + ph.def.name + " (" +
                   formatNumber(e.stdErrors[static_cast<std::size_t>(j)], 3) + ") exceeds its admissible range [" +
                   formatNumber(ph.def.lower, 3) + ", " + formatNumber(ph.def.upper, 3) + "]";
        }
      }
    }
    fitted.push_back(std::move(e));
    alternatives.push_back({sc.index, sc.phi, fit.u});
  }

  // Rank: likelihood ratio, AICc only inside the tie band.
  std::vector<std::size_t> order(fitted.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return fitted[a].likelihoodRatio > fitted[b].likelihoodRatio; });
  for (std::size_t i = 0; i + 1 < order.size(); ++i) {
    const auto& a = fitted[order[i]];
    const auto& b = fitted[order[i + 1]];
    // never across the threshold: significance is decided by LR alone
    const bool sameSide = (a.likelihoodRatio > d.threshold) == (b.likelihoodRatio > d.threshold);
    if (sameSide && a.likelihoodRatio - b.likelihoodRatio < kAiccTieBand && b.aicc < a.aicc) {
      std::swap(order[i], order[i + 1]);
    }
  }
  std::vector<engine::FittedAlternative> alt;
  for (std::size_t i : order) {
    d.ranking.push_back(fitted[i]);
    alt.push_back(alternatives[i]);
  }
  s.fittedCount = d.ranking.size();
  for (auto& e : unfitted) d.ranking.push_back(std::move(e));
  s.alt = std::move(alt);
  return {};
}

}  // namespace

Result<void> fitCandidates(Pass& s) {
  const std::string& where = s.where;
  const Model& base = *s.base;
  const Eigen::VectorXd& u0 = s.u0;
  Eigen::VectorXd& rAug0 = s.rAug0;
  if (!engine::Screen::augmentedResiduals(base, u0, rAug0)) {
    return makeError(ErrorCode::NumericalFailure, "the calibrated baseline cannot be evaluated", where);
  }
  s.p = base.parameterCount();
  MOZZI_TRY(firstFits(s));
  MOZZI_TRY(restartLeaders(s));
  return collectAndRank(s);
}

}  // namespace mozzi::core::gap::engine
