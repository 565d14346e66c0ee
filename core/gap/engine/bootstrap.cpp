#include "core/gap/engine/bootstrap.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/common/parallel.h"
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

// What the null depends on apart from the measured values: the layout. With
// a noise model estimated from the data the null carries that estimate (its
// baseline chi-squares above all), so then also the calibrated point and the
// data as whitened there (a digest of the residual at u0).
std::string cacheKey(const Model& baseline, const Eigen::VectorXd& u0, const Screen& screen,
                     const std::vector<int>& candidates, const NullOptions& o) {
  const GapProblem& problem = baseline.problem();
  std::ostringstream s;
  s.precision(17);
  s << problem.dataKind() << '#' << problem.residualCount() << '#' << problem.noiseModel().source << '#';
  Eigen::VectorXd r;
  if (problem.noiseModel().estimated && Screen::augmentedResiduals(baseline, u0, r)) {
    for (Eigen::Index i = 0; i < u0.size(); ++i) s << u0[i] << ',';
    const Eigen::VectorXd ramp = Eigen::VectorXd::LinSpaced(r.size(), 0.0, 1.0);
    s << '#' << r.squaredNorm() << ',' << r.sum() << ',' << r.dot(ramp);
  }
  s << '#';
  for (int f : problem.folds()) s << f << ',';
  s << '#';
  for (const auto& t : baseline.theta()) describe(s, t.def);
  const auto all = problem.candidates();
  for (int c : candidates) {
    const auto& cand = all[static_cast<std::size_t>(screen.candidates[static_cast<std::size_t>(c)].index)];
    s << '#' << screen.candidates[static_cast<std::size_t>(c)].index << ':' << cand.effect << '@';
    for (const auto& l : cand.location) s << l << ',';
    // The parameters as screened: a family's representative fits the
    // union of its members' bounds (families.h).
    for (const auto& p : screen.candidates[static_cast<std::size_t>(c)].phi) describe(s, p.def);
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
  const std::string key = options.useCache ? cacheKey(baseline, u0, screen, candidates, options) : std::string();
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
  // The simulated data sets are independent (each seeded by its index): one
  // task each on every core, results in index order.
  enum Status : char { Done, Cancelled, NoSimulation, NotEvaluable, RefitFailed };
  const auto samples = static_cast<std::size_t>(options.samples);
  std::vector<double> maxRatios(samples, 0.0), baselineChiSquares(samples, 0.0);
  std::vector<char> status(samples, Done);
  const auto mainThread = std::this_thread::get_id();
  std::atomic<bool> stopped{false};
  std::atomic<std::size_t> finished{0};
  parallelFor(samples, [&](std::size_t b) {
    if (stopped) {
      status[b] = Cancelled;
      return;
    }
    if (options.progress && std::this_thread::get_id() == mainThread &&
        !options.progress(static_cast<double>(finished) / static_cast<double>(samples))) {
      stopped = true;
      status[b] = Cancelled;
      return;
    }
    auto rng = seededRng(options.seed, 1, static_cast<unsigned long long>(b));
    const auto sim = problem.simulated({theta0.data(), -1, nullptr}, rng);
    if (!sim) {
      status[b] = NoSimulation;
      return;
    }
    Model base(*sim, baseline.theta(), -1, {});
    Eigen::VectorXd rAug;
    if (!Screen::augmentedResiduals(base, u0, rAug)) {
      status[b] = NotEvaluable;
      return;
    }
    double maxRatio = 0.0;
    if (options.mode == NullMode::Linearised) {
      for (int c : candidates) maxRatio = std::max(maxRatio, screen.linearRatio(c, rAug));
      maxRatios[b] = maxRatio;
      // Linear refit of theta: what the calibration cannot absorb,
      // |(I - Q Q') r|^2 (prior rows included: a handful against thousands).
      const Eigen::VectorXd absorbed =
          screen.basis.cols() > 0 ? Eigen::VectorXd(screen.basis.transpose() * rAug) : Eigen::VectorXd::Zero(0);
      baselineChiSquares[b] = std::max(0.0, rAug.squaredNorm() - absorbed.squaredNorm());
      ++finished;
      return;
    }
    const FitResult fit0 = fitModel(base, {u0}, fo);
    if (!fit0.ok) {
      status[b] = RefitFailed;
      return;
    }
    baselineChiSquares[b] = fit0.chiSquare;
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
    maxRatios[b] = maxRatio;
    ++finished;
  });
  for (std::size_t b = 0; b < samples; ++b) {
    switch (status[b]) {
      case Cancelled: return makeError(ErrorCode::Cancelled, "cancelled", where);
      case NoSimulation: return makeError(ErrorCode::NumericalFailure, "the problem could not simulate data", where);
      case NotEvaluable:
        return makeError(ErrorCode::NumericalFailure, "simulated data cannot be evaluated at the baseline", where);
      case RefitFailed: return makeError(ErrorCode::NumericalFailure, "baseline refit failed on simulated data", where);
      default: break;
    }
  }
  out.maxRatios = std::move(maxRatios);
  out.baselineChiSquares = std::move(baselineChiSquares);
  out.threshold = candidates.empty() ? 0.0 : empiricalQuantile(out.maxRatios, 1.0 - options.alpha);
  if (options.useCache) {
    std::lock_guard<std::mutex> lock(cacheMutex);
    cache()[key] = out;
  }
  return out;
}

}  // namespace mozzi::core::gap::engine
