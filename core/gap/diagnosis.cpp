#include "core/gap/diagnosis.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "core/common/parallel.h"
#include "core/common/text.h"
#include "core/gap/engine/bootstrap.h"
#include "core/gap/engine/checks.h"
#include "core/gap/engine/fit.h"
#include "core/gap/engine/pairs.h"
#include "core/gap/engine/screen.h"
#include "core/gap/engine/statistics.h"

namespace mozzi::core::gap {

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Effect: return "effect";
    case Verdict::None: return "none";
    case Verdict::Ambiguous: return "ambiguous";
    case Verdict::Partial: return "partial";
    case Verdict::Unexplained: return "unexplained";
    case Verdict::NotIdentifiable: return "not_identifiable";
  }
  return "none";
}

namespace {

using engine::FitOptions;
using engine::FitResult;
using engine::Model;
using engine::Scaled;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Auto null method: full refits while samples x (candidates + 1) x residuals
// stays below this; a refit costs ~5 us per residual entry on the small test
// problems (engine_bootstrap_test), more for FRF synthesis, so 1e6 keeps the
// full bootstrap within seconds to a minute; beyond it the linearised one.
constexpr double kFullRefitBudget = 1e6;
// A calibrated parameter this many prior sigmas from its nominal is worth a
// sentence: candidates that can stand in for it gain likelihood from the prior.
constexpr double kPriorTension = 3.0;
// Candidate fits: nonlinear and linear-screen likelihood ratios within 10%
// (plus 1) count as "locally linear" (random restarts skipped); random starts
// run 20 iterations each before the best is polished.
constexpr double kLinearAgreement = 0.1;
constexpr int kStartIterations = 20;
// Random restarts for at most this many leading candidates (by the LR of the
// deterministic starts).
constexpr int kRestartedCandidates = 5;
// ... and only those whose first likelihood ratio is at least this share of the
// leader's: a candidate explaining less than a quarter of what the leader does
// from its linear and nominal starts does not overtake it from random ones
// (the restarts were most of a diagnosis's time on 16,000-residual problems).
constexpr double kRestartShare = 0.25;
// Top-two margins LR_a - LR_b above this are not simulated: under the linear-
// Gaussian approximation the flip probability is Phi(-sqrt(D) / 2) < 0.0014.
constexpr double kObviousMargin = 36.0;
// An LR difference below 2 (one AIC unit) does not separate two candidates;
// only then does AICc order them (Burnham and Anderson 2002, §2.6).
constexpr double kAiccTieBand = 2.0;
// Grid minima tried per candidate beside its two deterministic starts.
constexpr int kGridStarts = 2;

std::string sizes(const RankedEffect& e) {
  std::string s;
  for (std::size_t i = 0; i < e.parameters.size(); ++i) {
    const Parameter& p = e.candidate.parameters[i];
    s += (i ? ", " : "") + p.name + " = " + formatNumber(e.parameters[i], 3);
    if (i < e.stdErrors.size()) s += " +- " + formatNumber(e.stdErrors[i], 2);
    if (!p.unit.empty()) s += " " + p.unit;
  }
  return s;
}

// "singular values 12.3 0.004; null direction (scaled theta, phi): 0.71 -0.71"
std::string singularReport(const Eigen::VectorXd& values, const Eigen::VectorXd& direction, const char* valuesName,
                           const char* directionName) {
  std::ostringstream s;
  s << valuesName;
  for (Eigen::Index i = 0; i < values.size(); ++i) s << ' ' << formatNumber(values[i], 3);
  s << "; " << directionName << " (scaled theta, phi):";
  for (Eigen::Index i = 0; i < direction.size(); ++i) s << ' ' << formatNumber(direction[i], 2);
  return s.str();
}

double aicc(double nll, int k, int n) {
  const double base = 2.0 * nll + 2.0 * k;
  return n - k - 1 > 0 ? base + 2.0 * k * (k + 1.0) / (n - k - 1.0) : std::numeric_limits<double>::infinity();
}

int freeCount(const std::vector<Scaled>& s) {
  return static_cast<int>(std::count_if(s.begin(), s.end(), [](const Scaled& x) { return !x.fixed; }));
}

std::string separating(const GapMetrics& a, const GapMetrics& b, const std::string& nameA, const std::string& nameB) {
  double best = -1.0;
  std::string out;
  for (const auto& ea : a.entries) {
    for (const auto& eb : b.entries) {
      if (ea.kind != eb.kind || ea.label != eb.label) continue;
      // In uncertainty units when the rows carry z-scores, else relative.
      const double scale = std::max({std::abs(ea.value), std::abs(eb.value), 1e-300});
      const double d = (ea.z != 0.0 && eb.z != 0.0) ? std::abs(ea.z - eb.z) : std::abs(ea.value - eb.value) / scale;
      if (d > best) {
        best = d;
        out = ea.kind + " " + ea.label + " (" + nameA + ": " + formatNumber(ea.value, 3) + ", " + nameB + ": " +
              formatNumber(eb.value, 3) + ")";
      }
    }
  }
  return out;
}

}  // namespace

namespace {

// Scaled coordinates of fitted values (calibration, then an effect's sizes).
Eigen::VectorXd scaledPoint(const std::vector<Scaled>& theta, const std::vector<double>& thetaX,
                            const std::vector<Scaled>& phi, const std::vector<double>& phiX) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(theta.size() + phi.size()));
  for (std::size_t i = 0; i < theta.size(); ++i) u[static_cast<Eigen::Index>(i)] = theta[i].toU(thetaX[i]);
  for (std::size_t j = 0; j < phi.size(); ++j) u[static_cast<Eigen::Index>(theta.size() + j)] = phi[j].toU(phiX[j]);
  return u;
}

// An effect was found that makes a better reference for the noise estimate
// than the nominal model: attributed, in part or ambiguously, so it holds on
// held-out data (an `unexplained` best effect may fit noise or worse).
bool wantsSecondNoisePass(const Diagnosis& d) {
  const bool found = d.verdict == Verdict::Effect || d.verdict == Verdict::Partial || d.verdict == Verdict::Ambiguous;
  return found && !d.ranking.empty() && d.ranking[0].fitted && d.ranking[0].likelihoodRatio > d.threshold;
}

// Steps 1 to 9 of GAP.md with the problem's noise model as it stands. With
// `warm` (a diagnosis of the same data under another noise model) every fit
// starts from its optimum there instead of searching again: the optima move
// little when only the weights change, and the search was most of the time.
Result<Diagnosis> diagnoseOnce(const GapProblem& problem, const DiagnosisOptions& options, const Diagnosis* warm,
                               bool firstOfTwo) {
  const std::string where = "gap diagnosis";
  // A first pass that a second will replace checks the leader alone on
  // held-out data (the rest when no second pass follows, at the end).
  const int reportTop = firstOfTwo ? std::min(1, options.reportTop) : options.reportTop;
  const int n = problem.residualCount();
  if (n <= 0) return makeError(ErrorCode::InvalidArgument, "the problem has no residuals", where);
  if (!(options.alpha > 0.0 && options.alpha < 0.5)) {
    return makeError(ErrorCode::InvalidArgument, "alpha must lie in (0, 0.5)", where);
  }
  if (options.multistarts < 1) return makeError(ErrorCode::InvalidArgument, "multistarts must be at least 1", where);
  if (options.bootstrapSamples < 20) {
    return makeError(ErrorCode::InvalidArgument, "bootstrapSamples must be at least 20", where);
  }
  auto keepGoing = [&](double fraction, const std::string& step) {
    return !options.progress || options.progress(std::clamp(fraction, 0.0, 1.0), step);
  };
  const auto cancelled = [&] { return makeError(ErrorCode::Cancelled, "diagnosis cancelled", where); };

  Diagnosis d;
  d.dataKind = problem.dataKind();
  d.calibration = problem.calibrationParameters();
  std::vector<Scaled> theta;
  for (const auto& p : d.calibration) {
    auto s = engine::scaleParameter(p, "calibration");
    if (!s) return s.error();
    theta.push_back(*s);
  }
  const auto candidates = problem.candidates();
  std::set<std::string> known;
  for (const auto& c : candidates) known.insert(c.effect);
  for (const auto& e : options.effects) {
    if (!known.count(e)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      return makeError(ErrorCode::InvalidArgument, "unknown effect '" + e + "' (this problem offers: " + list + ")",
                       where);
    }
  }
  std::vector<std::pair<int, std::vector<Scaled>>> selected;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    if (!options.effects.empty() &&
        std::find(options.effects.begin(), options.effects.end(), c.effect) == options.effects.end()) {
      continue;
    }
    std::vector<Scaled> phi;
    for (const auto& p : c.parameters) {
      auto s = engine::scaleParameter(p, "effect '" + label(c) + "'");
      if (!s) return s.error();
      phi.push_back(*s);
    }
    selected.emplace_back(static_cast<int>(i), std::move(phi));
  }

  // Step 1: calibrate theta (nominal start, then seeded random starts in the box).
  if (!keepGoing(0.0, "calibration")) return cancelled();
  Model base(problem, theta, -1, {});
  std::vector<Eigen::VectorXd> starts{Eigen::VectorXd::Zero(base.parameterCount())};
  auto rng = engine::seededRng(options.seed, 0, 0);
  if (warm) {
    starts.push_back(scaledPoint(theta, warm->calibrated, {}, {}));
  } else {
    for (int i = 1; i < options.multistarts; ++i) starts.push_back(engine::randomStart(base, rng));
  }
  FitOptions calibration;
  calibration.startIterations = kStartIterations;  // every start 20 iterations, the best polished
  const FitResult fit0 = engine::fitModel(base, starts, calibration);
  if (!fit0.ok) {
    return makeError(ErrorCode::NumericalFailure, "the model cannot be evaluated at any calibration start", where);
  }
  const Eigen::VectorXd u0 = fit0.u;
  d.calibrated = base.thetaX(u0);
  d.chiSquare = fit0.chiSquare;
  d.dof = std::max(1, n - freeCount(theta));
  d.fitPValue = chiSquareSurvival(d.chiSquare, d.dof);
  d.noise = problem.noiseModel();

  // Step 2: where (Holm over the rows of each kind).
  d.gapBefore = problem.metrics(d.calibrated.data(), -1, nullptr);
  applyHolmFlags(d.gapBefore, options.alpha);
  for (const auto& e : d.gapBefore.entries) {
    if (e.flagged) d.where.push_back(e);
  }
  std::stable_sort(d.where.begin(), d.where.end(),
                   [](const GapEntry& a, const GapEntry& b) { return std::abs(a.z) > std::abs(b.z); });

  // Step 3: linear screen.
  if (!keepGoing(0.05, "screen")) return cancelled();
  auto screened = engine::screenCandidates(base, u0, selected);
  if (!screened) return screened.error();
  const engine::Screen& screen = *screened;
  std::vector<int> identifiable;
  for (std::size_t c = 0; c < screen.candidates.size(); ++c) {
    if (screen.candidates[c].identifiable) identifiable.push_back(static_cast<int>(c));
  }

  // Step 5 (before 4 so the fits can report against it): null calibration.
  engine::NullOptions no;
  no.samples = options.bootstrapSamples;
  no.alpha = options.alpha;
  no.seed = options.seed;
  const double work = static_cast<double>(options.bootstrapSamples) * (identifiable.size() + 1.0) * n;
  const bool linear = options.nullMethod == NullMethod::Linearised ||
                      (options.nullMethod == NullMethod::Auto && work > kFullRefitBudget);
  no.mode = linear ? engine::NullMode::Linearised : engine::NullMode::FullRefit;
  no.progress = [&](double f) { return keepGoing(0.1 + 0.6 * f, "bootstrap"); };
  auto null = engine::calibrateNull(base, u0, screen, identifiable, no);
  if (!null) return null.error();
  d.threshold = null->threshold;
  d.thresholdLinearised = linear;
  d.bootstrapSamples = options.bootstrapSamples;
  // Goodness of fit of a model with `extra` free parameters beyond theta.
  auto fitP = [&](double chi2, int extra) {
    if (!d.fitFromBootstrap) return chiSquareSurvival(chi2, std::max(1, d.dof - extra));
    const double z = (chi2 - (d.nullChiSquareMean - extra)) / d.nullChiSquareSd;
    return 0.5 * std::erfc(z / std::sqrt(2.0));
  };
  if (d.noise.estimated && null->baselineChiSquares.size() >= 2) {
    const auto& c = null->baselineChiSquares;
    double mean = 0, var = 0;
    for (double x : c) mean += x / static_cast<double>(c.size());
    for (double x : c) var += (x - mean) * (x - mean) / static_cast<double>(c.size() - 1);
    d.fitFromBootstrap = true;
    d.nullChiSquareMean = mean;
    d.nullChiSquareSd = std::sqrt(std::max(var, 2.0 * d.dof) + d.noise.chiSquareVariance);
    d.fitPValue = fitP(d.chiSquare, 0);
  }

  // Step 4: nonlinear fit of every identifiable candidate jointly with theta.
  Eigen::VectorXd rAug0;
  if (!engine::Screen::augmentedResiduals(base, u0, rAug0)) {
    return makeError(ErrorCode::NumericalFailure, "the calibrated baseline cannot be evaluated", where);
  }
  const int p = base.parameterCount();
  std::vector<RankedEffect> fitted, unfitted;
  std::vector<engine::FittedAlternative> alternatives;  // parallel to `fitted`
  const std::size_t candidateCount = screen.candidates.size();
  auto notIdentifiable = [&](const engine::ScreenedCandidate& sc) {
    std::ostringstream note;
    note << "not identifiable with these data: " << sc.reason << "; "
         << singularReport(sc.jointSingularValues, sc.nullDirection, "singular values of the whitened [J S] are",
                           "weakest direction");
    return note.str();
  };

  // 4a. Two deterministic starts per candidate: (theta_0, phi nominal) and the
  // linear prediction. When both reach the same optimum and the likelihood
  // ratio is what the linear screen predicted, the candidate is locally linear
  // about the baseline and random restarts cannot improve on it.
  std::vector<FitResult> fits(candidateCount);
  std::vector<char> needsRestarts(candidateCount, 0);
  std::vector<double> firstLr(candidateCount, -1.0);
  // The candidates' fits are independent: one task each, spread over the
  // cores (each writes its own slots; the results do not depend on the order).
  const auto mainThread = std::this_thread::get_id();
  std::atomic<bool> stopped{false};
  std::atomic<std::size_t> finished{0};
  auto progressOnMain = [&](double fraction, const char* step) {
    if (std::this_thread::get_id() == mainThread && !keepGoing(fraction, step)) stopped = true;
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
  if (stopped) return cancelled();
  // 4b. Random restarts (multistarts - 2 seeded draws of phi in its box, 20
  // iterations each, the best polished) for the leading candidates that are
  // not locally linear: they decide the verdict, and restarts cost most of the
  // fitting time on large FRF problems.
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
  if (!restarted.empty() && !keepGoing(0.8, "candidate restarts")) return cancelled();
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
  // 4c. Covariance at each optimum (a restart there converges at once).
  if (!keepGoing(0.82, "standard errors")) return cancelled();
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
      const double bj = sc.projectedNorm[j];
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
    e.fitPValue = fitP(fit.chiSquare, freeCount(sc.phi));
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
  const std::size_t fittedCount = d.ranking.size();
  for (auto& e : unfitted) d.ranking.push_back(std::move(e));

  // Steps 7 and 9: held-out checks, gap after and shrink for the top few
  // (those of the first `count` ranks not yet checked).
  std::optional<engine::HeldOutBaseline> heldBaseline;  // the baseline's fold fits, once
  auto checkHeldOut = [&](std::size_t count) -> Result<void> {
    std::vector<std::size_t> unchecked;
    for (std::size_t i = 0; i < std::min(fittedCount, count); ++i)
      if (std::isnan(d.ranking[i].heldOutImprovement)) unchecked.push_back(i);
    for (std::size_t i : unchecked) {
      RankedEffect& e = d.ranking[i];
      if (!heldBaseline) {
        auto b = engine::heldOutBaseline(problem, theta, u0);
        if (!b) return b.error();
        heldBaseline = std::move(b).value();
      }
      auto held = engine::heldOutImprovement(problem, theta, u0, alt[i], *heldBaseline);
      if (!held) return held.error();
      e.heldOutImprovement = *held;
      e.gapAfter = problem.metrics(e.theta.data(), e.candidateIndex, e.parameters.data());
      applyHolmFlags(e.gapAfter, options.alpha);
      e.shrinkPct = d.gapBefore.overall != 0.0 ? 100.0 * (1.0 - e.gapAfter.overall / d.gapBefore.overall) : 0.0;
    }
    return {};
  };
  if (!keepGoing(0.85, "held-out checks")) return cancelled();
  if (auto checked = checkHeldOut(static_cast<std::size_t>(std::max(0, reportTop))); !checked) return checked.error();

  // Step 4, end: profile-likelihood interval of the top effect's sizes.
  if (fittedCount > 0 && d.ranking[0].identifiable && !d.ranking[0].stdErrors.empty()) {
    if (!keepGoing(0.93, "profile likelihood")) return cancelled();
    for (std::size_t j = 0; j < d.ranking[0].stdErrors.size(); ++j) {
      auto interval = engine::profileInterval(problem, theta, alt[0], static_cast<int>(j), d.ranking[0].stdErrors[j],
                                              chiSquareQuantile(0.95, 1.0));
      if (!interval) {
        d.ranking[0].profileInterval.clear();
        break;
      }
      d.ranking[0].profileInterval.push_back(*interval);
    }
  }

  // Step 6: ambiguity between the top two.
  const bool significant = fittedCount > 0 && d.ranking[0].likelihoodRatio > d.threshold;
  const double margin = fittedCount > 1 ? d.ranking[0].likelihoodRatio - d.ranking[1].likelihoodRatio : 0.0;
  if (significant && fittedCount > 1 && margin >= kObviousMargin) {
    // Linear-Gaussian estimate: the margin's sd is ~2 sqrt(margin), so a flip
    // needs a sqrt(margin) / 2 >= 3 sd excursion.
    d.flipProbability = 0.5 * std::erfc(std::sqrt(margin) / 2.0 / std::sqrt(2.0));
    d.flipEstimated = true;
  } else if (significant && fittedCount > 1) {
    auto flip = engine::flipProbability(
        problem, theta, alt[0], alt[1], d.ranking[0].likelihoodRatio - d.ranking[1].likelihoodRatio,
        options.ambiguitySamples, options.seed, [&] { return keepGoing(0.95, "ambiguity check"); });
    if (!flip) return flip.error();
    d.flipProbability = *flip;
    if (d.flipProbability > options.flipLimit) {
      const auto ma =
          d.ranking[0].gapAfter.entries.empty()
              ? problem.metrics(d.ranking[0].theta.data(), d.ranking[0].candidateIndex, d.ranking[0].parameters.data())
              : d.ranking[0].gapAfter;
      const auto mb =
          problem.metrics(d.ranking[1].theta.data(), d.ranking[1].candidateIndex, d.ranking[1].parameters.data());
      d.separatingMeasurement = separating(ma, mb, d.ranking[0].candidate.effect, d.ranking[1].candidate.effect);
    }
  }

  // Step 4, pairs: two effects at once when the best single leaves a
  // significant residual (or always, when asked).
  const bool wantPairs =
      options.pairs != DiagnosisOptions::PairMode::Never && significant && fittedCount >= 2 &&
      d.ranking[0].identifiable &&
      (options.pairs == DiagnosisOptions::PairMode::Always || d.ranking[0].fitPValue < options.fitAlpha);
  if (wantPairs) {
    if (!keepGoing(0.96, "pair fits")) return cancelled();
    std::vector<engine::SingleFit> singles;
    std::map<int, std::size_t> rankOf;  // candidate -> ranking index
    for (std::size_t i = 0; i < fittedCount; ++i) {
      rankOf[d.ranking[i].candidateIndex] = i;
      if (!d.ranking[i].identifiable) continue;
      singles.push_back({alt[i].candidate, alt[i].phi, alt[i].u, fit0.nll - 0.5 * d.ranking[i].likelihoodRatio});
    }
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
    auto pairs = engine::fitPairs(problem, theta, singles, options.pairLeaders, pairStarts,
                                  [&](double f) { return keepGoing(0.96 + 0.03 * f, "pair fits"); });
    if (!pairs) return pairs.error();
    d.pairFitted = true;
    EffectPair& ep = d.pair;
    ep.pairsFitted = static_cast<int>(pairs->size());
    if (!pairs->empty()) {
      const engine::PairFit& bp = pairs->front();
      std::size_t ia = rankOf.at(bp.a), ib = rankOf.at(bp.b);
      // Each member alone, refitted from the pair's optimum with the other
      // removed: a single fit that stopped short of its own optimum would
      // otherwise credit the other member with the difference and name a
      // second effect of no size. A better optimum replaces the single fit.
      auto refitAlone = [&](std::size_t m, Eigen::Index offset) {
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
        e.aicc = aicc(fit.nll, freeCount(theta) + freeCount(alt[m].phi), n);
        e.chiSquare = fit.chiSquare;
        e.fitPValue = fitP(fit.chiSquare, freeCount(alt[m].phi));
        if (m < static_cast<std::size_t>(reportTop)) {
          e.gapAfter = problem.metrics(e.theta.data(), e.candidateIndex, e.parameters.data());
          applyHolmFlags(e.gapAfter, options.alpha);
          e.shrinkPct = d.gapBefore.overall != 0.0 ? 100.0 * (1.0 - e.gapAfter.overall / d.gapBefore.overall) : 0.0;
        }
      };
      const auto qLead = static_cast<Eigen::Index>(alt[ia].phi.size());
      refitAlone(ia, 0);
      refitAlone(ib, qLead);
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
      ep.fitPValue = fitP(bp.chiSquare, freeCount(bp.phi));
      // The combination's baseline is the problem's own (ComboProblem's
      // candidate -1): the fold fits already made serve.
      if (!heldBaseline) {
        auto b = engine::heldOutBaseline(problem, theta, u0);
        if (!b) return b.error();
        heldBaseline = std::move(b).value();
      }
      auto held = engine::heldOutImprovement(combo, theta, u0, {0, bp.phi, u}, *heldBaseline);
      if (!held) return held.error();
      ep.heldOutImprovement = *held;
      for (std::size_t m : {ia, ib}) {
        RankedEffect& e = d.ranking[m];
        if (e.gapAfter.entries.empty() && e.gapAfter.overall == 0.0) {
          e.gapAfter = problem.metrics(e.theta.data(), e.candidateIndex, e.parameters.data());
          applyHolmFlags(e.gapAfter, options.alpha);
          e.shrinkPct = d.gapBefore.overall != 0.0 ? 100.0 * (1.0 - e.gapAfter.overall / d.gapBefore.overall) : 0.0;
        }
      }
      ep.gapAfterOne = d.ranking[ia].gapAfter;
      ep.shrinkOnePct = d.ranking[ia].shrinkPct;
      ep.gapAfterBoth = problem.combinedMetrics(ep.theta.data(), {bp.a, bp.b}, phi.data());
      applyHolmFlags(ep.gapAfterBoth, options.alpha);
      ep.shrinkBothPct =
          d.gapBefore.overall != 0.0 ? 100.0 * (1.0 - ep.gapAfterBoth.overall / d.gapBefore.overall) : 0.0;
    }
  }
  const bool pairHolds = d.pairFitted && d.pair.significant && !d.pair.effects.empty() &&
                         d.pair.effects[0].identifiable && d.pair.effects[1].identifiable &&
                         !(std::isfinite(d.pair.heldOutImprovement) && d.pair.heldOutImprovement <= 0.0);

  // Step 8: verdict.
  std::ostringstream ex;
  ex << "Calibrated " << d.calibration.size() << " model parameter(s); the whitened residual chi-square is "
     << formatNumber(d.chiSquare, 4) << " on " << d.dof << " degrees of freedom (p = " << formatNumber(d.fitPValue, 2)
     << "). The attribution threshold is " << formatNumber(d.threshold, 3) << ", the "
     << formatNumber(1 - options.alpha, 3) << " quantile of the largest likelihood ratio over " << identifiable.size()
     << " identifiable candidate(s) in " << d.bootstrapSamples << " data sets simulated without an effect ("
     << (linear ? "linearised refits" : "full refits") << (null->fromCache ? ", cached" : "") << "). ";
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
  if (firstOfTwo && !wantsSecondNoisePass(d)) {
    if (auto checked = checkHeldOut(static_cast<std::size_t>(std::max(0, options.reportTop))); !checked) {
      return checked.error();
    }
  }
  if (!keepGoing(1.0, "done")) return cancelled();
  return d;
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
