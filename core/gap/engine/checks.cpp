#include "core/gap/engine/checks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "core/common/parallel.h"
#include "core/gap/engine/bootstrap.h"

namespace mozzi::core::gap::engine {

namespace {

constexpr double kNaNValue = std::numeric_limits<double>::quiet_NaN();

// Refits from warm starts: the truth and the other alternative's optimum are
// both close, so a few dozen iterations suffice.
FitOptions warmFit() {
  FitOptions fo;
  fo.maxIterations = 40;
  fo.functionTolerance = 1e-9;
  return fo;
}

Eigen::VectorXd withPhi(const Eigen::VectorXd& theta, const Eigen::VectorXd& phi) {
  Eigen::VectorXd u(theta.size() + phi.size());
  u << theta, phi;
  return u;
}

}  // namespace

Result<double> flipProbability(const GapProblem& problem, const std::vector<Scaled>& theta, const FittedAlternative& a,
                               const FittedAlternative& b, double observedMargin, int samples, unsigned long long seed,
                               const std::function<bool()>& keepGoing) {
  const std::string where = "ambiguity check";
  const auto p = static_cast<Eigen::Index>(theta.size());
  int flips[2] = {0, 0}, total[2] = {0, 0};
  const FittedAlternative* sides[2] = {&a, &b};
  for (int side = 0; side < 2; ++side) {
    const FittedAlternative& truth = *sides[side];
    const FittedAlternative& other = *sides[1 - side];
    Model truthModel(problem, theta, truth.candidate, truth.phi);
    const auto thetaX = truthModel.thetaX(truth.u);
    const auto phiX = truthModel.phiX(truth.u);
    for (int i = 0; i < samples; ++i) {
      if (keepGoing && !keepGoing()) return makeError(ErrorCode::Cancelled, "cancelled", where);
      auto rng = seededRng(seed, 2 + static_cast<unsigned long long>(side), static_cast<unsigned long long>(i));
      const auto sim = problem.simulated({thetaX.data(), truth.candidate, phiX.empty() ? nullptr : phiX.data()}, rng);
      if (!sim) return makeError(ErrorCode::NumericalFailure, "the problem could not simulate data", where);
      Model mt(*sim, theta, truth.candidate, truth.phi), mo(*sim, theta, other.candidate, other.phi);
      const FitResult ft = fitModel(mt, {truth.u}, warmFit());
      // The other alternative from its own optimum and from the truth's theta.
      const FitResult fo =
          fitModel(mo, {other.u, withPhi(truth.u.head(p), Eigen::VectorXd::Zero(other.u.size() - p))}, warmFit());
      if (!ft.ok || !fo.ok) continue;
      ++total[side];
      // margin of a over b in this data set: 2 (NLL_b - NLL_a)
      const double margin = side == 0 ? 2.0 * (fo.nll - ft.nll) : 2.0 * (ft.nll - fo.nll);
      flips[side] += side == 0 ? margin < 0.0 : margin >= observedMargin;
    }
  }
  if (total[0] == 0 || total[1] == 0) {
    return makeError(ErrorCode::NumericalFailure, "no simulated data set could be fitted", where);
  }
  return std::max(static_cast<double>(flips[0]) / total[0], static_cast<double>(flips[1]) / total[1]);
}

namespace {

// Per fold f (in `foldIds` order), the squared whitened residual on f of
// `full` at the fit of `model` restricted to the other folds, from `starts`.
Result<std::vector<double>> foldSums(const GapProblem& problem, const std::vector<int>& foldIds,
                                     const std::function<Model(const std::vector<int>&)>& restricted, const Model& full,
                                     const std::vector<Eigen::VectorXd>& starts) {
  const std::vector<int> folds = problem.folds();
  std::vector<double> sums(foldIds.size(), 0.0);
  std::vector<char> failed(foldIds.size(), 0);
  parallelFor(foldIds.size(), [&](std::size_t i) {
    const int f = foldIds[i];
    std::vector<int> in;
    for (std::size_t j = 0; j < folds.size(); ++j) {
      if (folds[j] != f) in.push_back(static_cast<int>(j));
    }
    const Model model = restricted(in);
    Eigen::VectorXd r(problem.residualCount());
    const FitResult fit = fitModel(model, starts, warmFit());
    if (!fit.ok || !full.residuals(fit.u.data(), r.data())) {
      failed[i] = 1;
      return;
    }
    for (std::size_t j = 0; j < folds.size(); ++j) {
      if (folds[j] == f) sums[i] += r[static_cast<Eigen::Index>(j)] * r[static_cast<Eigen::Index>(j)];
    }
  });
  for (char bad : failed)
    if (bad) return makeError(ErrorCode::NumericalFailure, "a fold could not be refitted", "held-out check");
  return sums;
}

}  // namespace

Result<HeldOutBaseline> heldOutBaseline(const GapProblem& problem, const std::vector<Scaled>& theta,
                                        const Eigen::VectorXd& uBaseline) {
  HeldOutBaseline out;
  const std::vector<int> folds = problem.folds();
  const std::set<int> distinct(folds.begin(), folds.end());
  if (distinct.size() < 2 || static_cast<int>(folds.size()) != problem.residualCount()) return out;
  const std::vector<int> foldIds(distinct.begin(), distinct.end());
  const Model full(problem, theta, -1, {});
  MOZZI_TRY_ASSIGN(
      out.sumOfSquares,
      foldSums(problem, foldIds, [&](const std::vector<int>& in) { return Model(problem, theta, -1, {}, in); }, full,
               {uBaseline}));
  out.foldIds = foldIds;
  return out;
}

Result<double> heldOutImprovement(const GapProblem& problem, const std::vector<Scaled>& theta,
                                  const Eigen::VectorXd& uBaseline, const FittedAlternative& effect,
                                  const HeldOutBaseline& baseline) {
  if (baseline.foldIds.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto p = static_cast<Eigen::Index>(theta.size());
  const Model full(problem, theta, effect.candidate, effect.phi);
  MOZZI_TRY_ASSIGN(
      const std::vector<double> sums,
      foldSums(problem, baseline.foldIds,
               [&](const std::vector<int>& in) { return Model(problem, theta, effect.candidate, effect.phi, in); },
               full, {effect.u, withPhi(uBaseline, Eigen::VectorXd::Zero(effect.u.size() - p))}));
  double ss0 = 0.0, ss1 = 0.0;
  for (std::size_t i = 0; i < baseline.foldIds.size(); ++i) {
    ss0 += baseline.sumOfSquares[i];
    ss1 += sums[i];
  }
  return ss0 > 0.0 ? 1.0 - ss1 / ss0 : 0.0;
}

Result<std::pair<double, double>> profileInterval(const GapProblem& problem, const std::vector<Scaled>& theta,
                                                  const FittedAlternative& effect, int j, double stdError,
                                                  double level) {
  const std::string where = "profile likelihood";
  const auto p = static_cast<Eigen::Index>(theta.size());
  const Scaled& free = effect.phi[static_cast<std::size_t>(j)];
  if (free.fixed || !(stdError > 0.0)) return makeError(ErrorCode::InvalidArgument, "nothing to profile", where);
  Model full(problem, theta, effect.candidate, effect.phi);
  const double best = fitModel(full, {effect.u}, warmFit()).nll;
  const double xHat = free.toX(effect.u[p + j]);
  // Effect parameter j pinned at x (a fixed parameter sits at its "nominal").
  std::vector<Scaled> pinnedPhi = effect.phi;
  Eigen::VectorXd warm = effect.u;
  auto excess = [&](double x, bool& ok) {
    pinnedPhi[static_cast<std::size_t>(j)].def.nominal = x;
    pinnedPhi[static_cast<std::size_t>(j)].fixed = true;
    Model pinned(problem, theta, effect.candidate, pinnedPhi);
    Eigen::VectorXd start = warm;
    start[p + j] = 0.0;
    const FitResult f = fitModel(pinned, {start}, warmFit());
    ok = f.ok;
    if (f.ok) warm = f.u;
    return f.ok ? 2.0 * (f.nll - best) : std::numeric_limits<double>::infinity();
  };
  double ends[2];
  for (int side = 0; side < 2; ++side) {
    const double dir = side == 0 ? -1.0 : 1.0;
    const double bound = side == 0 ? free.def.lower : free.def.upper;
    warm = effect.u;
    double inside = xHat, outside = kNaNValue;
    // Steps of 0.5, 1, 2, 3, ... standard errors until the level is crossed.
    for (double k : {0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0}) {
      double x = xHat + dir * k * stdError;
      if (dir * (x - bound) >= 0.0) x = bound;
      bool ok = false;
      const double e = excess(x, ok);
      if (!ok) return makeError(ErrorCode::NumericalFailure, "a profile point could not be fitted", where);
      if (e > level) {
        outside = x;
        break;
      }
      inside = x;
      if (x == bound) break;
    }
    if (std::isnan(outside)) {
      ends[side] = inside;  // the level is not reached within the bounds (or 12 se)
      continue;
    }
    for (int it = 0; it < 30 && std::abs(outside - inside) > 1e-4 * stdError; ++it) {
      const double mid = 0.5 * (inside + outside);
      bool ok = false;
      (excess(mid, ok) > level ? outside : inside) = mid;
      if (!ok) return makeError(ErrorCode::NumericalFailure, "a profile point could not be fitted", where);
    }
    ends[side] = 0.5 * (inside + outside);
  }
  return std::make_pair(ends[0], ends[1]);
}

}  // namespace mozzi::core::gap::engine
