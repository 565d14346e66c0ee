#include "core/gap/engine/pass.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "core/common/text.h"
#include "core/gap/engine/families.h"
#include "core/gap/engine/statistics.h"

namespace mozzi::core::gap::engine {
namespace {

// Auto null method: full refits while samples x (candidates + 1) x residuals
// stays below this; a refit costs ~5 us per residual entry on the small test
// problems (engine_bootstrap_test), more for FRF synthesis, so 1e6 keeps the
// full bootstrap within seconds to a minute; beyond it the linearised one.
constexpr double kFullRefitBudget = 1e6;

}  // namespace

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

// Scaled coordinates of fitted values (calibration, then an effect's sizes).
Eigen::VectorXd scaledPoint(const std::vector<Scaled>& theta, const std::vector<double>& thetaX,
                            const std::vector<Scaled>& phi, const std::vector<double>& phiX) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(theta.size() + phi.size()));
  for (std::size_t i = 0; i < theta.size(); ++i) u[static_cast<Eigen::Index>(i)] = theta[i].toU(thetaX[i]);
  for (std::size_t j = 0; j < phi.size(); ++j) u[static_cast<Eigen::Index>(theta.size() + j)] = phi[j].toU(phiX[j]);
  return u;
}

void gapAfter(const Pass& s, RankedEffect& e) {
  e.gapAfter = s.problem.metrics({e.theta.data(), e.candidateIndex, e.parameters.data()});
  applyHolmFlags(e.gapAfter, s.options.alpha);
  e.shrinkPct = s.d.gapBefore.overall != 0.0 ? 100.0 * (1.0 - e.gapAfter.overall / s.d.gapBefore.overall) : 0.0;
}

Pass::Pass(const GapProblem& problem_, const DiagnosisOptions& options_, const Diagnosis* warm_, bool firstOfTwo_)
    : problem(problem_),
      options(options_),
      warm(warm_),
      firstOfTwo(firstOfTwo_),
      reportTop(firstOfTwo_ ? std::min(1, options_.reportTop) : options_.reportTop),
      n(problem_.residualCount()) {}

bool Pass::keepGoing(double fraction, const std::string& step) const {
  return !options.progress || options.progress(std::clamp(fraction, 0.0, 1.0), step);
}

Error Pass::cancelled() const {
  return makeError(ErrorCode::Cancelled, "diagnosis cancelled", where);
}

double Pass::fitP(double chi2, int extra) const {
  if (!d.fitFromBootstrap) return chiSquareSurvival(chi2, std::max(1, d.dof - extra));
  const double z = (chi2 - (d.nullChiSquareMean - extra)) / d.nullChiSquareSd;
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

Result<void> prepare(Pass& s) {
  const GapProblem& problem = s.problem;
  const DiagnosisOptions& options = s.options;
  const std::string& where = s.where;
  Diagnosis& d = s.d;
  if (s.n <= 0) return makeError(ErrorCode::InvalidArgument, "the problem has no residuals", where);
  if (!(options.alpha > 0.0 && options.alpha < 0.5)) {
    return makeError(ErrorCode::InvalidArgument, "alpha must lie in (0, 0.5)", where);
  }
  if (options.multistarts < 1) return makeError(ErrorCode::InvalidArgument, "multistarts must be at least 1", where);
  if (options.bootstrapSamples < 20) {
    return makeError(ErrorCode::InvalidArgument, "bootstrapSamples must be at least 20", where);
  }
  d.dataKind = problem.dataKind();
  d.calibration = problem.calibrationParameters();
  for (const auto& p : d.calibration) {
    MOZZI_TRY_ASSIGN(const Scaled scaled, engine::scaleParameter(p, "calibration"));
    s.theta.push_back(scaled);
  }
  s.candidates = problem.candidates();
  const auto& candidates = s.candidates;
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
  std::vector<int> wanted;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    if (!options.effects.empty() &&
        std::find(options.effects.begin(), options.effects.end(), c.effect) == options.effects.end()) {
      continue;
    }
    wanted.push_back(static_cast<int>(i));
  }
  // Candidates that act on the data alike are fitted once, as a family
  // (families.h): the representative carries the others' locations.
  std::vector<int> representatives;
  for (const auto& family : engine::equalEffectFamilies(problem, s.candidates, wanted)) {
    s.candidates[static_cast<std::size_t>(family[0])] = engine::familyCandidate(s.candidates, family);
    representatives.push_back(family[0]);
  }
  std::vector<std::pair<int, std::vector<Scaled>>> selected;
  for (int i : representatives) {
    const auto& c = candidates[static_cast<std::size_t>(i)];
    std::vector<Scaled> phi;
    for (const auto& p : c.parameters) {
      MOZZI_TRY_ASSIGN(const Scaled sp, engine::scaleParameter(p, "effect '" + label(c) + "'"));
      phi.push_back(sp);
    }
    selected.emplace_back(i, std::move(phi));
  }
  s.selected = std::move(selected);
  return {};
}

Result<void> calibrate(Pass& s) {
  const GapProblem& problem = s.problem;
  const DiagnosisOptions& options = s.options;
  const std::string& where = s.where;
  Diagnosis& d = s.d;
  const auto& theta = s.theta;
  const Diagnosis* warm = s.warm;
  const int n = s.n;
  // Step 1: calibrate theta (nominal start, then seeded random starts in the box).
  if (!s.keepGoing(0.0, "calibration")) return s.cancelled();
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
  d.gapBefore = problem.metrics({d.calibrated.data(), -1, nullptr});
  applyHolmFlags(d.gapBefore, options.alpha);
  for (const auto& e : d.gapBefore.entries) {
    if (e.flagged) d.where.push_back(e);
  }
  std::stable_sort(d.where.begin(), d.where.end(),
                   [](const GapEntry& a, const GapEntry& b) { return std::abs(a.z) > std::abs(b.z); });
  s.base.emplace(std::move(base));
  s.fit0 = fit0;
  s.u0 = u0;
  return {};
}

Result<void> screenAndNull(Pass& s) {
  const DiagnosisOptions& options = s.options;
  Diagnosis& d = s.d;
  const Model& base = *s.base;
  const Eigen::VectorXd& u0 = s.u0;
  const int n = s.n;
  auto keepGoing = [&](double fraction, const std::string& step) { return s.keepGoing(fraction, step); };
  // Step 3: linear screen.
  if (!keepGoing(0.05, "screen")) return s.cancelled();
  MOZZI_TRY_ASSIGN(engine::Screen screen, engine::screenCandidates(base, u0, s.selected));
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
  MOZZI_TRY_ASSIGN(const engine::NullCalibration null, engine::calibrateNull(base, u0, screen, identifiable, no));
  d.threshold = null.threshold;
  d.thresholdLinearised = linear;
  d.bootstrapSamples = options.bootstrapSamples;
  if (d.noise.estimated && null.baselineChiSquares.size() >= 2) {
    const auto& c = null.baselineChiSquares;
    double mean = 0, var = 0;
    for (double x : c) mean += x / static_cast<double>(c.size());
    for (double x : c) var += (x - mean) * (x - mean) / static_cast<double>(c.size() - 1);
    d.fitFromBootstrap = true;
    d.nullChiSquareMean = mean;
    d.nullChiSquareSd = std::sqrt(std::max(var, 2.0 * d.dof) + d.noise.chiSquareVariance);
    d.fitPValue = s.fitP(d.chiSquare, 0);
  }
  s.screen.emplace(std::move(screen));
  s.identifiable = std::move(identifiable);
  s.linear = linear;
  s.nullFromCache = null.fromCache;
  return {};
}

}  // namespace mozzi::core::gap::engine
