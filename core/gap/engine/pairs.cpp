#include "core/gap/engine/pairs.h"

#include <algorithm>
#include <set>

namespace mozzi::core::gap::engine {

ComboProblem::ComboProblem(const GapProblem& base, std::vector<int> combo) : base_(base), combo_(std::move(combo)) {
  const auto all = base_.candidates();
  for (std::size_t i = 0; i < combo_.size(); ++i) {
    const Candidate& c = all[static_cast<std::size_t>(combo_[i])];
    combined_.effect += (i ? "+" : "") + c.effect;
    combined_.location.insert(combined_.location.end(), c.location.begin(), c.location.end());
    combined_.parameters.insert(combined_.parameters.end(), c.parameters.begin(), c.parameters.end());
  }
}

bool ComboProblem::residuals(const double* theta, int candidate, const double* phi, double* r) const {
  if (candidate < 0) return base_.residuals(theta, -1, nullptr, r);
  return base_.combinedResiduals(theta, combo_, phi, r);
}

std::unique_ptr<GapProblem> ComboProblem::simulated(const double* theta, int candidate, const double* phi,
                                                    std::mt19937_64& rng) const {
  (void)candidate;
  (void)phi;
  return base_.simulated(theta, -1, nullptr, rng);
}

GapMetrics ComboProblem::metrics(const double* theta, int candidate, const double* phi) const {
  if (candidate < 0) return base_.metrics(theta, -1, nullptr);
  return base_.combinedMetrics(theta, combo_, phi);
}

std::vector<OverlayCurve> ComboProblem::overlay(const double* theta, int candidate, const double* phi) const {
  if (candidate < 0) return base_.overlay(theta, -1, nullptr);
  return base_.combinedOverlay(theta, combo_, phi);
}

Result<std::vector<PairFit>> fitPairs(const GapProblem& problem, const std::vector<Scaled>& theta,
                                      const std::vector<SingleFit>& singles, int leaders,
                                      const std::function<bool(double)>& keepGoing) {
  const std::string where = "pair fits";
  std::vector<PairFit> out;
  const auto p = static_cast<Eigen::Index>(theta.size());
  std::set<std::pair<int, int>> done;
  const int nLead = std::min<int>(leaders, static_cast<int>(singles.size()));
  const double total = std::max(1.0, static_cast<double>(nLead) * static_cast<double>(singles.size()));
  int step = 0;
  FitOptions fo;
  fo.maxIterations = 60;
  for (int l = 0; l < nLead; ++l) {
    const SingleFit& a = singles[static_cast<std::size_t>(l)];
    for (const SingleFit& b : singles) {
      ++step;
      if (keepGoing && !keepGoing(step / total)) return makeError(ErrorCode::Cancelled, "cancelled", where);
      if (a.candidate == b.candidate) continue;
      const auto key = std::minmax(a.candidate, b.candidate);
      if (done.count(key) || !problem.combinable({a.candidate, b.candidate})) continue;
      done.insert(key);
      ComboProblem combo(problem, {a.candidate, b.candidate});
      std::vector<Scaled> phi = a.phi;
      phi.insert(phi.end(), b.phi.begin(), b.phi.end());
      Model model(combo, theta, 0, phi);
      const auto qa = static_cast<Eigen::Index>(a.phi.size()), qb = static_cast<Eigen::Index>(b.phi.size());
      Eigen::VectorXd s1(p + qa + qb), s2(p + qa + qb);
      s1 << a.u.head(p), a.u.tail(qa), Eigen::VectorXd::Zero(qb);
      s2 << a.u.head(p), a.u.tail(qa), b.u.tail(qb);
      const FitResult fit = fitModel(model, {clipToBox(model, s1), clipToBox(model, s2)}, fo);
      if (!fit.ok) continue;
      PairFit pf;
      pf.a = a.candidate;
      pf.b = b.candidate;
      pf.phi = std::move(phi);
      pf.u = fit.u;
      pf.nll = fit.nll;
      pf.chiSquare = fit.chiSquare;
      pf.ok = true;
      out.push_back(std::move(pf));
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const PairFit& x, const PairFit& y) { return x.nll < y.nll; });
  return out;
}

}  // namespace mozzi::core::gap::engine
