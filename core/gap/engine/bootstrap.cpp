#include "core/gap/engine/bootstrap.h"

#include <algorithm>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>

#include "core/gap/engine/statistics.h"

namespace mozzi::core::gap::engine {

namespace {

std::mutex cacheMutex;
std::map<std::string, NullCalibration>& cache() {
  static std::map<std::string, NullCalibration> c;
  return c;
}

void describe(std::ostringstream& s, const Parameter& p) {
  s << p.name << '|' << p.unit << '|' << p.nominal << '|' << p.lower << '|' << p.upper << '|' << p.priorSigma << ';';
}

// The layout: what the threshold depends on apart from the measured values.
std::string cacheKey(const Model& baseline, const Screen& screen, const std::vector<int>& candidates,
                     const NullOptions& o) {
  const GapProblem& problem = baseline.problem();
  std::ostringstream s;
  s.precision(17);
  s << problem.dataKind() << '#' << problem.residualCount() << '#' << problem.noiseModel().source << '#';
  for (int f : problem.folds()) s << f << ',';
  s << '#';
  for (const auto& t : baseline.theta()) describe(s, t.def);
  const auto all = problem.candidates();
  for (int c : candidates) {
    const auto& cand = all[static_cast<std::size_t>(screen.candidates[static_cast<std::size_t>(c)].index)];
    s << '#' << screen.candidates[static_cast<std::size_t>(c)].index << ':' << cand.effect << '@';
    for (const auto& l : cand.location) s << l << ',';
    for (const auto& p : cand.parameters) describe(s, p);
  }
  s << "#B" << o.samples << "#a" << o.alpha << "#s" << o.seed << "#m" << static_cast<int>(o.mode) << "#i"
    << o.maxIterations;
  return s.str();
}

}  // namespace

std::mt19937_64 seededRng(unsigned long long seed, unsigned long long stream, unsigned long long index) {
  std::seed_seq seq{static_cast<unsigned>(seed), static_cast<unsigned>(seed >> 32), static_cast<unsigned>(stream),
                    static_cast<unsigned>(index), static_cast<unsigned>(index >> 32)};
  return std::mt19937_64(seq);
}

void clearNullCache() {
  std::lock_guard<std::mutex> lock(cacheMutex);
  cache().clear();
}

Result<NullCalibration> calibrateNull(const Model& baseline, const Eigen::VectorXd& u0, const Screen& screen,
                                      const std::vector<int>& candidates, const NullOptions& options) {
  const std::string where = "bootstrap null calibration";
  if (options.samples < 2) return makeError(ErrorCode::InvalidArgument, "needs at least 2 bootstrap samples", where);
  const std::string key = options.useCache ? cacheKey(baseline, screen, candidates, options) : std::string();
  if (options.useCache) {
    std::lock_guard<std::mutex> lock(cacheMutex);
    auto it = cache().find(key);
    if (it != cache().end()) {
      NullCalibration hit = it->second;
      hit.fromCache = true;
      return hit;
    }
  }
  NullCalibration out;
  out.mode = options.mode;
  // Without candidates there is no threshold, but an estimated noise model
  // still needs the baseline's null chi-square: simulate then too.
  if (candidates.empty() && !baseline.problem().noiseModel().estimated) return out;
  const GapProblem& problem = baseline.problem();
  const std::vector<double> theta0 = baseline.thetaX(u0);
  const int p = baseline.parameterCount();
  FitOptions fo;
  fo.maxIterations = options.maxIterations;
  fo.functionTolerance = 1e-8;
  for (int b = 0; b < options.samples; ++b) {
    if (options.progress && !options.progress(static_cast<double>(b) / options.samples)) {
      return makeError(ErrorCode::Cancelled, "cancelled", where);
    }
    auto rng = seededRng(options.seed, 1, static_cast<unsigned long long>(b));
    const auto sim = problem.simulated(theta0.data(), -1, nullptr, rng);
    if (!sim) return makeError(ErrorCode::NumericalFailure, "the problem could not simulate data", where);
    Model base(*sim, baseline.theta(), -1, {});
    Eigen::VectorXd rAug;
    if (!Screen::augmentedResiduals(base, u0, rAug)) {
      return makeError(ErrorCode::NumericalFailure, "simulated data cannot be evaluated at the baseline", where);
    }
    double maxRatio = 0.0;
    if (options.mode == NullMode::Linearised) {
      for (int c : candidates) maxRatio = std::max(maxRatio, screen.linearRatio(c, rAug));
      out.maxRatios.push_back(maxRatio);
      // Linear refit of theta: what the calibration cannot absorb,
      // |(I - Q Q') r|^2 (prior rows included: a handful against thousands).
      const Eigen::VectorXd absorbed =
          screen.basis.cols() > 0 ? Eigen::VectorXd(screen.basis.transpose() * rAug) : Eigen::VectorXd::Zero(0);
      out.baselineChiSquares.push_back(std::max(0.0, rAug.squaredNorm() - absorbed.squaredNorm()));
      continue;
    }
    const FitResult fit0 = fitModel(base, {u0}, fo);
    if (!fit0.ok) return makeError(ErrorCode::NumericalFailure, "baseline refit failed on simulated data", where);
    out.baselineChiSquares.push_back(fit0.chiSquare);
    for (int c : candidates) {
      const ScreenedCandidate& sc = screen.candidates[static_cast<std::size_t>(c)];
      Model model(*sim, baseline.theta(), sc.index, sc.phi);
      const int q = static_cast<int>(sc.phi.size());
      Eigen::VectorXd start = Eigen::VectorXd::Zero(p + q), seeded;
      start.head(p) = fit0.u;
      screen.linearRatio(c, rAug, &seeded);
      Eigen::VectorXd start2 = start;
      start2.head(p) = u0;
      start2.tail(q) = seeded;
      const FitResult fit = fitModel(model, {start, start2}, fo);
      if (fit.ok) maxRatio = std::max(maxRatio, 2.0 * (fit0.nll - fit.nll));
    }
    out.maxRatios.push_back(maxRatio);
  }
  out.threshold = candidates.empty() ? 0.0 : empiricalQuantile(out.maxRatios, 1.0 - options.alpha);
  if (options.useCache) {
    std::lock_guard<std::mutex> lock(cacheMutex);
    cache()[key] = out;
  }
  return out;
}

}  // namespace mozzi::core::gap::engine
